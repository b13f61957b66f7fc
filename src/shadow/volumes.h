// Shadow volumes (seed 000, "Shadow volume"): the region a caster hides from the light, as
// triangles the stencil buffer counts the eye's ray through. Built per frame on the CPU from the
// mesh's welded topology (scene::Topology, made once per mesh): no GL here.
//
// Which triangles bound the volume:
//  - a closed mesh (scene::Mesh::closed): its triangles facing away from the light, turned to face
//    it (the "dark cap"). The volume starts at the far side of the object, so no lit surface lies
//    on a cap (nothing to fight in the depth buffer) and a point is inside exactly when the ray to
//    the light crosses the object.
//  - an open mesh (the teapot, a quad, a tube): every triangle, each turned to face the light.
//    The volume of a one-sided surface is counted once per layer the light ray crosses, which is
//    what the ray tracer's two-sided occlusion means.
// Silhouette edges come from counting: each chosen triangle runs its three edges in its (turned)
// order; an edge's net count, uses one way minus uses the other, is how many side quads it needs
// and which way they face. Edges inside a smooth lit region cancel; an edge of one triangle, or
// of two triangles facing the same way (a crease of an open sheet seen from both sides, or a
// silhouette of an open mesh) does not. Points are homogeneous: w = 1 on the mesh, w = 0 at
// infinity, extruded away from the light (to one point for a directional light).
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::shadow {

struct ShadowVolume {
    std::vector<glm::vec4> sides;     // the silhouette edges extruded to infinity, 3 vertices per triangle
    std::vector<glm::vec4> near_cap;  // the bounding triangles where they lie (depth-fail only)
    std::vector<glm::vec4> far_cap;   // the same at infinity, reversed (none for a directional light)
    int silhouette_edges = 0;         // side quads (an edge counted twice gives two)
    int triangles() const { return static_cast<int>((sides.size() + near_cap.size() + far_cap.size()) / 3); }
};

// The volume of a caster: `topology` placed by `world`, lit by `light` = (position, 1) or
// (direction towards the light, 0). `closed` picks the dark cap (see above); `caps` adds the near
// and far caps that depth-fail needs. Every face of the result faces out of the volume (counter-
// clockwise seen from outside).
ShadowVolume extrude_volume(const scene::Topology& topology, const glm::mat4& world, const glm::vec4& light,
                            bool closed, bool caps);

// The camera's near rectangle (world corners, in order around it) and the pyramid from it to the
// light (a prism towards a directional light): a caster can put the near plane inside its volume
// only if it meets that pyramid. Conservative (a separating-axis test over the box's and the
// pyramid's face normals): true when they meet, and possibly when they do not. Depth-pass is
// exact only for casters where this is false.
bool may_shadow_near_plane(const std::array<glm::vec3, 4>& near_corners, const glm::vec4& light,
                           const scene::Bounds& caster);

// The camera's near rectangle, in world space, from the inverse of its view-projection.
std::array<glm::vec3, 4> near_rectangle(const glm::mat4& view_proj);

// The area in pixels the triangles cover on a viewport of width x height after clipping to the
// view volume of `view_proj`, every layer counted (no depth test, no culling): the stencil
// fragments a volume pass rasterises.
double covered_pixels(const std::vector<glm::vec4>& triangles, const glm::mat4& view_proj, int width, int height);

// A perspective projection's far plane moved to infinity (Lengyel's, with a margin so points at
// infinity are not clipped by rounding): what depth-fail's far caps need, GLES 2 having no depth
// clamp. Returns false (and leaves `proj`) when the matrix is not a perspective projection.
bool infinite_far(glm::mat4& proj);

}  // namespace penumbra::shadow
