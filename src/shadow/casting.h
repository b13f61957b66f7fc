// Which casters can shadow what the camera sees: a caster whose shadow falls on no visible
// receiver (the table under the teapot, lit from above; a box behind the camera) need not be drawn
// into a shadow map or extruded into a volume. No GL; conservative: a caster is left out only
// where a plane proves it can hide no visible receiver point from the light.
#pragma once

#include <limits>
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

// What may_shadow reads of the points: their extent along the world axes x, y, z and, for a
// directional light, along its direction (w); for a point light the farthest point's distance.
struct PointSpans {
    glm::vec4 lo{std::numeric_limits<float>::max()};
    glm::vec4 hi{std::numeric_limits<float>::lowest()};
    float farthest = 0.0f;
};
PointSpans point_spans(const std::vector<glm::vec3>& points, const glm::vec4& light);

// What may_shadow reads of the caster and the light: the box's extent along the same axes, the
// light's coordinate along each, the axes in use (3, or 4 with a directional light's own), and a
// point light's reach (the distance to the box's nearest point).
struct CasterSpans {
    glm::vec4 lo{0.0f}, hi{0.0f}, light{0.0f};
    int axes = 3;
    bool point = false;
    float reach = 0.0f;
};
CasterSpans caster_spans(const scene::Bounds& caster, const glm::vec4& light);

// The three ways may_shadow proves a caster hides none of the points, each monotone in the one
// value it reads of them (so one bound decides it for a whole group of receivers): along `axis`,
// the points' lows at or above the caster's top with the light above too; their highs at or below
// its bottom with the light below; every point nearer to a point light than the caster's reach.
bool separated_above(const CasterSpans& c, int axis, float points_lo);
bool separated_below(const CasterSpans& c, int axis, float points_hi);
inline bool nearer_than_caster(const CasterSpans& c, float farthest) { return c.point && farthest < c.reach; }

// may_shadow of a caster and points read already (the points not empty, the caster's box not empty).
bool may_shadow(const CasterSpans& caster, const PointSpans& points);

// One receiver as the shadows fit sees it: the scene object, and the points whose convex hull
// holds what the camera can see of it (visible_receiver_points, per receiver).
struct SeenReceiver {
    int object = -1;
    std::vector<glm::vec3> points;
    // The whole box is in view: `points` are its eight corners (light_frustum.h: visible_points_each).
    bool whole = false;
};
// One caster: the scene object, its world bounds, and whether it cannot shadow itself
// (scene::Mesh::convex: flat, or closed and convex; its own facing darkens what it hides).
struct CasterBox {
    int object = -1;
    scene::Bounds bounds;
    bool convex = false;
};

}  // namespace penumbra::shadow
