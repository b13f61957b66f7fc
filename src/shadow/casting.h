// Which casters can shadow what the camera sees: a caster whose shadow falls on no visible
// receiver (the table under the teapot, lit from above; a box behind the camera) need not be drawn
// into a shadow map or extruded into a volume. No GL; conservative: a caster is left out only
// where a plane proves it can hide no visible receiver point from the light.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::shadow {

// Whether something inside box `caster` can lie on a segment from a point of the convex hull of
// `points` towards the light, short of that point: to the light's position (light.w = 1), or
// without end along the direction towards the light (light.w = 0, xyz that direction). False
// only where a plane separates the caster from the points and the light (from the points and
// their rays towards a directional light), tried along the world axes and the light's direction,
// or where every point is nearer to a point light than the caster's nearest point. A point on the
// plane that bounds the caster is not hidden by it (a teapot standing on the table top).
bool may_shadow(const scene::Bounds& caster, const std::vector<glm::vec3>& points, const glm::vec4& light);

// One receiver as the shadows fit sees it: the scene object, and the points whose convex hull
// holds what the camera can see of it (visible_receiver_points, per receiver).
struct SeenReceiver {
    int object = -1;
    std::vector<glm::vec3> points;
};
// One caster: the scene object, its world bounds, and whether it cannot shadow itself
// (scene::Mesh::convex: flat, or closed and convex; its own facing darkens what it hides).
struct CasterBox {
    int object = -1;
    scene::Bounds bounds;
    bool convex = false;
};

// Whether `caster` can shadow a point of any receiver in `seen` (itself only if not convex).
bool shadows_any(const CasterBox& caster, const std::vector<SeenReceiver>& seen, const glm::vec4& light);
// The points of every receiver in `seen` that `caster` can shadow, as shadows_any decides: its
// shadow falls inside their hulls (empty: it shadows none).
std::vector<glm::vec3> shadowed_points(const CasterBox& caster, const std::vector<SeenReceiver>& seen,
                                       const glm::vec4& light);

}  // namespace penumbra::shadow
