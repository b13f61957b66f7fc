// Simple meshes made in code: the table top quad, a UV sphere, an open bowl, a box.
#pragma once

#include "scene/scene.h"

namespace penumbra::scene {

// A square of side `size` in the plane y = 0, centred on the origin, normal +y, uvs 0..uv_repeat.
Mesh make_quad(float size, float uv_repeat = 1.0f);
// A UV sphere of `radius` around the origin with `slices` x `stacks` quads; unit normals,
// no degenerate triangles at the poles.
Mesh make_sphere(float radius, int slices, int stacks);
// An open bowl: the triangles of make_sphere(radius, slices, stacks) at or below y = 0 (stacks even
// gives a clean rim).
Mesh make_bowl(float radius, int slices, int stacks);
// An axis-aligned box from -half to +half, flat-shaded (24 vertices).
Mesh make_box(const glm::vec3& half_extent);

}  // namespace penumbra::scene
