// The kilometre of terrain of tests/data/terrain_km.gltf, built in code from the same recipe as
// tests/data/make_large_scenes.py (the same heightfield, the same 32-bit LCG placing the same 360
// objects, the same materials, camera and sun), so the browser's cascades page, which loads no
// glTF, shows the scene that `penumbra render --scene tests/data/terrain_km.gltf` renders.
// The file's numbers are rounded as the script rounds them (node translations and scales to
// millimetres, rotations to 5 digits) and stored as 32-bit floats, so the two scenes agree to
// float precision (tests/desktop/test_terrain_scene.cpp loads the file and compares).
#pragma once

#include "scene/scene.h"

namespace penumbra::scene {

// The scene as the glTF loader would give it: one mesh per glTF mesh (terrain, unit box, unit
// cylinder, unit sphere), one object per node, the directional sun, the camera 1.9 m above the
// ground looking north.
Scene make_terrain_km_scene();

// The height of the triangulated terrain at (x, z) (within the kilometre; clamped to it outside).
float terrain_km_height(float x, float z);

}  // namespace penumbra::scene
