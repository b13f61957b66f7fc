// Small convex geometry for fitting the light's frustum: half-spaces, a box clipped by them
// (the part of a receiver the camera sees, the part of a caster inside the light's window), and
// in 2D a convex hull, a polygon clipped to a rectangle and its area (the share of the shadow map
// the receivers in view cover).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::shadow {

// The half-space n.p + d >= 0 as (n, d): the normal points inside.
using HalfSpace = glm::vec4;

inline float signed_distance(const HalfSpace& h, const glm::vec3& p) { return glm::dot(glm::vec3(h), p) + h.w; }

// The six half-spaces of a view-projection matrix's clip volume (-w <= x, y, z <= w), normals of
// unit length: left, right, bottom, top, near, far. A row that gives no plane (a degenerate
// matrix) gives (0, 0, 0, 1), which holds everything.
std::array<HalfSpace, 6> clip_volume_half_spaces(const glm::mat4& view_proj);

// The points of `poly` (a planar convex polygon, in order) inside `h`, Sutherland-Hodgman; a point
// up to `eps` outside counts as inside.
std::vector<glm::vec3> clip_polygon(const std::vector<glm::vec3>& poly, const HalfSpace& h, float eps = 0.0f);

// The vertices of the convex polytope box & every half-space: each face of the box clipped by the
// half-spaces, and a polygon on each half-space's plane (wide enough to hold the box's section)
// clipped by the box and the other half-spaces. Empty when they do not meet (or the box is empty);
// a flat box gives the polygon it is. Points may repeat.
std::vector<glm::vec3> clip_box(const scene::Bounds& box, const std::vector<HalfSpace>& half_spaces);
// The half-spaces as clip_box takes them, made unit once for many boxes: those that hold
// everything dropped, `nothing` set where one holds nothing.
struct ClipPlanes {
    std::vector<HalfSpace> unit;
    bool nothing = false;
};
ClipPlanes clip_planes(const std::vector<HalfSpace>& half_spaces);
// clip_box by planes made already. `whole` (when given) says whether the box lay inside every
// half-space, unclipped: then the result is its eight corners (scene::corners), each once, instead
// of its six faces' 24 corners. The two are the same set of points; only a sum over them
// (box_face_corners) tells them apart.
std::vector<glm::vec3> clip_box_by(const scene::Bounds& box, const ClipPlanes& planes, bool* whole = nullptr);

// The section of the polytope box & `planes` by the plane of `h` (which need not be among them): a
// convex polygon on that plane, in order, as clip_box_by makes one for each plane that cuts the
// box. Empty where the plane misses the polytope. resolution.cpp cuts a receiver's part by the
// planes between a map's tiles with it, once for all the tiles along each plane.
std::vector<glm::vec3> clip_box_section(const scene::Bounds& box, const ClipPlanes& planes, const HalfSpace& h);

// The box's six faces, four corners each, in the order clip_box lists them for a box that nothing
// clips: fn(corner) 24 times.
template <typename F>
void box_face_corners(const scene::Bounds& box, F&& fn) {
    const glm::vec3 lo = box.min, hi = box.max;
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        for (const float side : {lo[a], hi[a]}) {
            const float us[4] = {lo[u], hi[u], hi[u], lo[u]};
            const float vs[4] = {lo[v], lo[v], hi[v], hi[v]};
            for (int k = 0; k < 4; ++k) {
                glm::vec3 p;
                p[a] = side;
                p[u] = us[k];
                p[v] = vs[k];
                fn(p);
            }
        }
    }
}

// ---- 2D ----------------------------------------------------------------------------------------

// The convex hull, counter-clockwise, without collinear points (Andrew's monotone chain). Fewer
// than three distinct points: those points.
std::vector<glm::vec2> convex_hull(std::vector<glm::vec2> points);

// A convex polygon clipped to the rectangle [lo, hi] (Sutherland-Hodgman).
std::vector<glm::vec2> clip_to_rect(const std::vector<glm::vec2>& poly, const glm::vec2& lo, const glm::vec2& hi);

// The points that may be on the hull, by index, in order: over 1,024 points, those not deeper
// than a thousandth of the extent inside the octagon of the extreme points along x, y, x + y and
// x - y (Akl and Toussaint); else all. convex_hull sorts only these; the hull of them is the
// hull of all, to the bit. A point that deep cannot reach the hull either after a projective
// change of view that keeps every point in front (rounding cannot move it a thousandth of the
// extent).
std::vector<std::size_t> hull_candidates(const std::vector<glm::vec2>& points);

// The area of a simple polygon (either orientation).
float polygon_area(const std::vector<glm::vec2>& poly);

}  // namespace penumbra::shadow
