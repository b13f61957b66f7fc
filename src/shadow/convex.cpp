// Half-spaces, a box clipped by them, and the 2D hull, rectangle clip and area (see convex.h).
#include "shadow/convex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

namespace penumbra::shadow {

namespace {

float max_abs_component(const glm::vec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

HalfSpace normalized(const glm::vec4& h) {
    const float len = glm::length(glm::vec3(h));
    if (!(len > 0.0f) || !std::isfinite(len)) return {0.0f, 0.0f, 0.0f, 1.0f};
    return h / len;
}

}  // namespace

std::array<HalfSpace, 6> clip_volume_half_spaces(const glm::mat4& m) {
    // Gribb & Hartmann: with the matrix's rows r0..r3, -w <= x is (r3 + r0).p >= 0, and so on.
    const auto row = [&m](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    const glm::vec4 w = row(3);
    return {normalized(w + row(0)), normalized(w - row(0)), normalized(w + row(1)),
            normalized(w - row(1)), normalized(w + row(2)), normalized(w - row(2))};
}

namespace {

// Sutherland-Hodgman into `out` (room for 2n points: each edge gives at most two), the points of
// the n at `in` inside `h`; returns how many. clip_polygon and clip_box_by share it, so both
// give the same points to the bit.
size_t clip_into(const glm::vec3* in, size_t n, const HalfSpace& h, float eps, glm::vec3* out) {
    size_t m = 0;
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3& a = in[i];
        const glm::vec3& b = in[(i + 1) % n];
        const float da = signed_distance(h, a);
        const float db = signed_distance(h, b);
        const bool ina = da >= -eps;
        const bool inb = db >= -eps;
        if (ina) out[m++] = a;
        if (ina != inb) {
            // One side is beyond eps outside, so da - db is not zero; the crossing is at the plane.
            const float t = std::clamp(da / (da - db), 0.0f, 1.0f);
            out[m++] = a + t * (b - a);
        }
    }
    return m;
}

// The box's radius and the magnitude of its coordinates, which its tolerances scale with.
float box_radius(const scene::Bounds& box) { return 0.5f * glm::length(box.max - box.min); }
float box_scale(const scene::Bounds& box) {
    return std::max({box_radius(box), max_abs_component(box.min), max_abs_component(box.max)});
}

// Tolerance for "on the plane" about `box` (float rounding).
float box_tolerance(const scene::Bounds& box) { return 1e-5f * box_scale(box); }

// The box's own six half-spaces.
std::array<HalfSpace, 6> box_half_spaces(const scene::Bounds& box) {
    const glm::vec3 lo = box.min, hi = box.max;
    return {HalfSpace(1, 0, 0, -lo.x), HalfSpace(-1, 0, 0, hi.x), HalfSpace(0, 1, 0, -lo.y),
            HalfSpace(0, -1, 0, hi.y), HalfSpace(0, 0, 1, -lo.z), HalfSpace(0, 0, -1, hi.z)};
}

// A square on the plane of unit `h` around the box centre's foot on it, larger than the box's
// section (which lies within the box's radius of that foot), in order.
std::array<glm::vec3, 4> plane_square(const scene::Bounds& box, const HalfSpace& h) {
    const float half = 1.01f * box_radius(box) + 1e-4f * box_scale(box) + 1e-30f;
    const glm::vec3 centre = box.center();
    const glm::vec3 n(h);
    const glm::vec3 foot = centre - signed_distance(h, centre) * n;
    const glm::vec3 t1 = glm::normalize(glm::cross(n, std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const glm::vec3 t2 = glm::cross(n, t1);
    return {foot - half * t1 - half * t2, foot + half * t1 - half * t2, foot + half * t1 + half * t2, foot - half * t1 + half * t2};
}

// A convex polygon clipped by one half-space after another, between two buffers swapped from clip
// to clip: reused by every polygon of a box, no allocation a clip.
struct Clipper {
    float eps = 0.0f;
    std::vector<glm::vec3> a, b;
    void start(std::initializer_list<glm::vec3> polygon) { a.assign(polygon); }
    void by(const HalfSpace& h) {
        b.resize(2 * a.size());  // clip_into's bound
        b.resize(clip_into(a.data(), a.size(), h, eps, b.data()));
        std::swap(a, b);
    }
    template <typename It>
    void by_each(It first, It last) {
        for (; first != last && !a.empty(); ++first) by(*first);
    }
};

}  // namespace

std::vector<glm::vec3> clip_polygon(const std::vector<glm::vec3>& poly, const HalfSpace& h, float eps) {
    std::vector<glm::vec3> out(2 * poly.size());
    out.resize(clip_into(poly.data(), poly.size(), h, eps, out.data()));
    return out;
}

ClipPlanes clip_planes(const std::vector<HalfSpace>& half_spaces) {
    ClipPlanes out;
    for (const HalfSpace& h : half_spaces) {
        const float len = glm::length(glm::vec3(h));
        if (!(len > 0.0f) || !std::isfinite(len)) {
            if (h.w < 0.0f) out.nothing = true;  // a half-space that holds nothing
            continue;                            // one that holds everything
        }
        out.unit.push_back(h / len);
    }
    return out;
}

std::vector<glm::vec3> clip_box(const scene::Bounds& box, const std::vector<HalfSpace>& half_spaces) {
    return clip_box_by(box, clip_planes(half_spaces));
}

std::vector<glm::vec3> clip_box_by(const scene::Bounds& box, const ClipPlanes& planes, bool* whole) {
    std::vector<glm::vec3> out;
    if (whole) *whole = false;
    if (box.empty() || planes.nothing) return out;
    const float eps = box_tolerance(box);
    const std::vector<HalfSpace>& hs = planes.unit;

    // A half-space with every corner beyond it: nothing of the box is inside.
    const std::vector<glm::vec3> corners = scene::corners(box);
    for (const HalfSpace& h : hs)
        if (std::all_of(corners.begin(), corners.end(), [&](const glm::vec3& p) { return signed_distance(h, p) < -eps; }))
            return out;

    // A half-space with every corner inside it by more than twice the tolerance clips nothing of
    // the box (what the loops below make lies within the tolerance of the box, so at least that
    // far inside it), and its own polygon, beyond the box, is clipped away whole.
    const auto holds = [&](const HalfSpace& h) {
        return std::all_of(corners.begin(), corners.end(), [&](const glm::vec3& p) { return signed_distance(h, p) > 2.0f * eps; });
    };
    // Every half-space holds it: the result is the six faces as they are, unclipped (the face loop
    // below would build them whole), or its corners.
    if (std::all_of(hs.begin(), hs.end(), holds)) {
        if (whole) {
            *whole = true;
            return corners;
        }
        box_face_corners(box, [&](const glm::vec3& p) { out.push_back(p); });
        return out;
    }
    // Otherwise only those that cut the box are clipped by and give polygons: the same points in
    // the same order as with all of them, at the cost of the planes that cut the box. A receiver
    // clipped again by a map's tile (the fits, --map-size auto) lies inside most of the camera's
    // and the tile's planes.
    std::vector<size_t> cut;
    for (size_t j = 0; j < hs.size(); ++j)
        if (!holds(hs[j])) cut.push_back(j);

    const std::array<HalfSpace, 6> box_hs = box_half_spaces(box);
    Clipper clip{eps, {}, {}};
    clip.a.reserve(2 * (10 + cut.size()));
    clip.b.reserve(2 * (10 + cut.size()));
    const auto clip_all = [&](std::initializer_list<glm::vec3> start, size_t skip, bool with_box) {
        clip.start(start);
        if (with_box) clip.by_each(box_hs.begin(), box_hs.end());
        for (size_t k = 0; k < cut.size() && !clip.a.empty(); ++k)
            if (cut[k] != skip) clip.by(hs[cut[k]]);
        out.insert(out.end(), clip.a.begin(), clip.a.end());
    };

    // The box's faces (they satisfy the box's own half-spaces already).
    std::vector<glm::vec3> faces;
    faces.reserve(24);
    box_face_corners(box, [&](const glm::vec3& p) { faces.push_back(p); });
    for (size_t f = 0; f < faces.size(); f += 4) clip_all({faces[f], faces[f + 1], faces[f + 2], faces[f + 3]}, hs.size(), false);
    // Each cutting half-space's plane: a square holding the box's section, clipped by the box and
    // the others.
    for (const size_t i : cut) {
        const std::array<glm::vec3, 4> q = plane_square(box, hs[i]);
        clip_all({q[0], q[1], q[2], q[3]}, i, true);
    }
    return out;
}

std::vector<glm::vec3> clip_box_section(const scene::Bounds& box, const ClipPlanes& planes, const HalfSpace& h) {
    if (box.empty() || planes.nothing) return {};
    const std::array<HalfSpace, 6> box_hs = box_half_spaces(box);
    const std::array<glm::vec3, 4> q = plane_square(box, normalized(h));
    Clipper clip{box_tolerance(box), {}, {}};
    clip.start({q[0], q[1], q[2], q[3]});
    clip.by_each(box_hs.begin(), box_hs.end());
    clip.by_each(planes.unit.begin(), planes.unit.end());
    return clip.a;
}

// ---- 2D ----------------------------------------------------------------------------------------

namespace {

float cross2(const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The points not deeper inside the convex polygon (counter-clockwise) than `depth` from every
// edge, by index: all of them where the polygon has under three corners.
std::vector<std::size_t> near_boundary(const std::vector<glm::vec2>& points, const std::vector<glm::vec2>& polygon,
                                       float depth) {
    std::vector<std::size_t> out;
    // Deep inside an edge: farther than `depth` from its line, inwards (the cross product with the
    // edge, over the edge's length).
    std::vector<float> margin(polygon.size());
    for (size_t i = 0; i < polygon.size(); ++i) margin[i] = depth * glm::length(polygon[(i + 1) % polygon.size()] - polygon[i]);
    for (std::size_t k = 0; k < points.size(); ++k) {
        bool deep = polygon.size() >= 3;
        for (size_t i = 0; i < polygon.size() && deep; ++i)
            deep = cross2(polygon[i], polygon[(i + 1) % polygon.size()], points[k]) > margin[i];
        if (!deep) out.push_back(k);
    }
    return out;
}

}  // namespace

// Akl and Toussaint's filter: the points deep inside the octagon of the extreme points along x, y,
// x + y and x - y (hull vertices all) cannot be on the hull, so the sort below need not see them.
// Only those farther inside every edge than a thousandth of the extent are dropped; points near
// the boundary stay, so rounding decides nothing here. A view of many objects sends about ten
// points an object, of which few remain.
std::vector<std::size_t> hull_candidates(const std::vector<glm::vec2>& p) {
    std::vector<std::size_t> all(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) all[i] = i;
    if (p.size() <= 1024) return all;
    // The extreme point along each of the eight directions, counter-clockwise from +x: x, x + y,
    // y, y - x, -x, -x - y, -y, x - y; the first point to reach each maximum, in one pass.
    const auto keys = [](const glm::vec2& v, float (&k)[8]) {
        k[0] = v.x, k[1] = v.x + v.y, k[2] = v.y, k[3] = v.y - v.x;
        k[4] = -v.x, k[5] = -v.x - v.y, k[6] = -v.y, k[7] = v.x - v.y;
    };
    size_t best[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    float top[8];
    keys(p.front(), top);
    glm::vec2 lo = p.front(), hi = p.front();
    for (size_t i = 0; i < p.size(); ++i) {
        const glm::vec2& v = p[i];
        if (!std::isfinite(v.x) || !std::isfinite(v.y)) return all;
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
        float k[8];
        keys(v, k);
        for (int d = 0; d < 8; ++d)
            if (k[d] > top[d]) top[d] = k[d], best[d] = i;
    }
    std::vector<glm::vec2> octagon;
    for (size_t b : best)
        if (octagon.empty() || (p[b] != octagon.back() && p[b] != octagon.front())) octagon.push_back(p[b]);
    const float depth = 1e-3f * std::max(hi.x - lo.x, hi.y - lo.y);
    if (octagon.size() < 3 || !(depth > 0.0f) || !std::isfinite(depth)) return all;
    return near_boundary(p, octagon, depth);
}

std::vector<glm::vec2> convex_hull(std::vector<glm::vec2> p) {
    if (p.size() > 1024) {
        std::vector<glm::vec2> kept;
        for (std::size_t i : hull_candidates(p)) kept.push_back(p[i]);
        p = std::move(kept);
    }
    std::sort(p.begin(), p.end(), [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    std::vector<glm::vec2> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {  // lower hull
        while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0f) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
        while (k >= t && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0f) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);  // the last point is the first
    return h;
}

std::vector<glm::vec2> clip_to_rect(const std::vector<glm::vec2>& poly, const glm::vec2& lo, const glm::vec2& hi) {
    std::vector<glm::vec2> cur = poly;
    // Keep sign * (p[axis] - bound) >= 0 for each of the four edges.
    const struct {
        int axis;
        float bound;
        float sign;
    } edges[4] = {{0, lo.x, 1.0f}, {0, hi.x, -1.0f}, {1, lo.y, 1.0f}, {1, hi.y, -1.0f}};
    for (const auto& e : edges) {
        if (cur.empty()) break;
        std::vector<glm::vec2> next;
        for (size_t i = 0; i < cur.size(); ++i) {
            const glm::vec2& a = cur[i];
            const glm::vec2& b = cur[(i + 1) % cur.size()];
            const float da = e.sign * (a[e.axis] - e.bound);
            const float db = e.sign * (b[e.axis] - e.bound);
            if (da >= 0.0f) next.push_back(a);
            if ((da >= 0.0f) != (db >= 0.0f)) next.push_back(a + (da / (da - db)) * (b - a));
        }
        cur = std::move(next);
    }
    return cur;
}

float polygon_area(const std::vector<glm::vec2>& poly) {
    double twice = 0.0;
    for (size_t i = 0; i < poly.size(); ++i) {
        const glm::vec2& a = poly[i];
        const glm::vec2& b = poly[(i + 1) % poly.size()];
        twice += static_cast<double>(a.x) * static_cast<double>(b.y) - static_cast<double>(b.x) * static_cast<double>(a.y);
    }
    return static_cast<float>(std::fabs(twice) * 0.5);
}

}  // namespace penumbra::shadow
