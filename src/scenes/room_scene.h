// The bulb room of tests/data/bulb_room.gltf, built in code from the same recipe as
// tests/data/make_large_scenes.py (the room's six inward-facing panels, the boxes and spheres on the
// floor, on stands and hanging from the ceiling, the bare bulb and the camera in a corner), so the
// browser's bulb page, which loads no glTF, shows the scene that `penumbra render --scene
// tests/data/bulb_room.gltf` renders. The numbers are rounded as the script rounds them and stored
// as 32-bit floats (scenes/recipe.h); tests/desktop/test_room_scene.cpp loads the file and compares.
#pragma once

#include "scene/scene.h"

namespace penumbra::scene {

// The room: x -4..4, y 0..3, z -3..3 (the file's ROOM), and the bulb (BULB).
inline constexpr float kBulbRoomHalfWidth = 4.0f, kBulbRoomHeight = 3.0f, kBulbRoomHalfDepth = 3.0f;

// The scene as the glTF loader would give it: one mesh per glTF mesh in the order the nodes first
// use them, one object per node, the point light 1.8 m up near the middle (aimed, as the loader
// aims a point light, at the scene's centre), the floor as the ground, the camera under the
// ceiling in the +x +z corner.
Scene make_bulb_room_scene();

}  // namespace penumbra::scene
