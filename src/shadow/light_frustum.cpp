// Fitting the light's view and projection around the points the shadow map must cover
// (exercise W09P2a), and the clip-to-texture matrix B that turns the light's clip space into
// shadow-map lookup coordinates.
#include "shadow/light_frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/casting.h"
#include "shadow/convex.h"
#include "shadow/receiver_index.h"

namespace penumbra::shadow {

namespace {

// Half-angle cap for a perspective fit: 75 degrees (a 150 degree frustum). Beyond that the map's
// texels near the edge stretch so much (tan grows without bound) that a wider frustum buys
// nothing; a light that needs more is inside the scene and really wants a cube map.
const float kMaxTanHalfAngle = std::tan(glm::radians(75.0f));
// Smallest tangent kept, so a single point on the view axis still gives an invertible matrix.
constexpr float kMinTanHalfAngle = 1e-3f;
// Relative widening of the fitted half-angles and ortho extents: every point is strictly
// inside the clip volume, and the tightest point still lands beyond 0.99 of the edge.
constexpr float kSideMargin = 1.01f;

// The points' extent in an eye space: x and y as they are, z as the distance in front (-z).
struct Extent {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{std::numeric_limits<float>::lowest()};
};
Extent eye_extent(const glm::mat4& view, const std::vector<glm::vec3>& points) {
    Extent r;
    for (const glm::vec3& p : points) {
        glm::vec3 e = glm::vec3(view * glm::vec4(p, 1.0f));
        e.z = -e.z;
        r.lo = glm::min(r.lo, e);
        r.hi = glm::max(r.hi, e);
    }
    return r;
}

// A window of the light's view (tangents for perspective, eye-space x and y for orthographic)
// widened by the side margin around its middle, each half at least `min_half`.
void widen_window(float& lo, float& hi, float min_half) {
    const float half = std::max(0.5f * (hi - lo) * kSideMargin, min_half);
    const float mid = 0.5f * (lo + hi);
    lo = mid - half;
    hi = mid + half;
}

glm::vec3 safe_normalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float len = glm::length(v);
    if (!(len > 1e-12f) || !std::isfinite(len)) return fallback;
    return v / len;
}

// lookAt with an up vector that is never (near-)parallel to the view axis: +y normally,
// +z when the light looks (almost) straight down or up, where +y would make lookAt's cross
// product vanish and the view matrix fill with NaN.
glm::mat4 look_along(const glm::vec3& eye, const glm::vec3& dir) {
    const glm::vec3 up = std::fabs(glm::dot(dir, glm::vec3(0.0f, 1.0f, 0.0f))) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f)
                                                                                      : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAt(eye, eye + dir, up);
}

float max_abs_component(const glm::vec3& v) {
    return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z)));
}

LightFrustum fit_perspective(const scene::Light& light, const std::vector<glm::vec3>& points,
                             const glm::vec3& aim) {
    LightFrustum f;
    f.perspective = true;

    // Look at the aim point; if it coincides with the light, a spot light still has its own
    // direction and a point light looks down (any axis would do).
    const glm::vec3 fallback_dir =
        light.type == scene::LightType::Spot ? safe_normalize(light.direction, glm::vec3(0.0f, -1.0f, 0.0f))
                                             : glm::vec3(0.0f, -1.0f, 0.0f);
    const glm::vec3 dir = safe_normalize(aim - light.position, fallback_dir);
    f.view = look_along(light.position, dir);

    // Scale of the problem, for thresholds that must not depend on the scene's units.
    float max_dist = 0.0f;
    for (const auto& p : points) max_dist = std::max(max_dist, glm::length(p - light.position));
    const float scale = std::max(max_dist, 1e-6f * std::max(1.0f, max_abs_component(light.position)));

    // Depth range and half-angle tangents over the points in front of the light. A point closer
    // than this to the light's eye plane (at it, beside it, behind it) cannot be inside any one
    // perspective frustum.
    const float front_eps = 1e-4f * scale;
    float zmin = std::numeric_limits<float>::max();
    float zmax = 0.0f;
    float tx = 0.0f;
    float ty = 0.0f;
    bool some_behind = false;
    for (const auto& p : points) {
        const glm::vec3 e = glm::vec3(f.view * glm::vec4(p, 1.0f));
        const float depth = -e.z;
        if (!(depth > front_eps)) {
            some_behind = true;
            continue;
        }
        zmin = std::min(zmin, depth);
        zmax = std::max(zmax, depth);
        tx = std::max(tx, std::fabs(e.x) / depth);
        ty = std::max(ty, std::fabs(e.y) / depth);
    }

    // Half-angles beyond the cap (a light just above a wide receiver) are clamped: the points
    // at the sides fall outside, but the map keeps a usable texel density.
    tx = std::clamp(tx * kSideMargin, kMinTanHalfAngle, kMaxTanHalfAngle);
    ty = std::clamp(ty * kSideMargin, kMinTanHalfAngle, kMaxTanHalfAngle);

    if (zmax <= 0.0f) {
        // Nothing in front of the light at all (or no points): any valid frustum will do.
        f.zfar = max_dist > 0.0f ? 1.02f * max_dist : 1.0f;
        f.znear = 0.01f * f.zfar;
        tx = ty = kMaxTanHalfAngle;
    } else {
        f.zfar = 1.02f * zmax;
        f.znear = 0.98f * zmin;
        // With every point in front, the nearest depth and widest angle over the points' convex
        // hull are at its corners, so the fit covers all geometry inside. With some point at or
        // behind the light's eye plane the light is inside (or at the edge of) the bounds: no
        // single frustum holds them, geometry may pass arbitrarily close to the light, and the
        // corners say nothing about that. Fall back to the capped wide frustum and a near plane
        // of at most 1% of far; the points behind the light are not covered (that needs a cube
        // map).
        if (some_behind) f.znear = std::min(f.znear, 0.01f * f.zfar);
    }
    // Depth precision collapses as near/far -> 0; 1e-4 of far is the floor.
    f.znear = std::max(f.znear, f.zfar * 1e-4f);
    if (!(f.zfar > f.znear)) f.zfar = f.znear * 1.04f + 1e-6f;

    // Symmetric frustum with separate horizontal and vertical half-angles (the map's aspect
    // follows the points), the same as glm::perspective(2 atan(ty), tx/ty, near, far).
    f.proj = glm::frustum(-f.znear * tx, f.znear * tx, -f.znear * ty, f.znear * ty, f.znear, f.zfar);
    return f;
}

LightFrustum fit_orthographic(const scene::Light& light, const std::vector<glm::vec3>& points,
                              const glm::vec3& aim) {
    LightFrustum f;
    f.perspective = false;
    const glm::vec3 dir = safe_normalize(light.direction, glm::vec3(0.0f, -1.0f, 0.0f));

    // Bounding sphere of the points (box centre, farthest point): the eye sits outside it, up
    // the light's direction, so every point is in front of the eye.
    glm::vec3 centre = aim;
    if (!points.empty()) {
        glm::vec3 lo = points.front();
        glm::vec3 hi = points.front();
        for (const auto& p : points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        centre = 0.5f * (lo + hi);
    }
    float radius = 0.0f;
    for (const auto& p : points) radius = std::max(radius, glm::length(p - centre));
    // The margin keeps the eye off the sphere, and gives all-equal points a non-zero sphere
    // (relative to the coordinates' magnitude so it survives float rounding far from the origin).
    // 5% of the radius is more than the 1% depth padding below can eat (at most 1% of the
    // sphere's diameter, 0.02 R), so znear stays positive.
    const float tiny = 1e-4f * std::max(1.0f, max_abs_component(centre));
    const float big_r = radius * 1.05f + tiny;
    f.view = look_along(centre - dir * big_r, dir);

    float xmin = 0.0f, xmax = 0.0f, ymin = 0.0f, ymax = 0.0f, zmin = big_r, zmax = big_r;
    if (!points.empty()) {
        const Extent e = eye_extent(f.view, points);
        xmin = e.lo.x, ymin = e.lo.y, zmin = e.lo.z;
        xmax = e.hi.x, ymax = e.hi.y, zmax = e.hi.z;
    }

    // Tight x/y (widened by a hair so the outermost points are strictly inside); a flat or
    // single-point extent is opened to `tiny` so the matrix stays invertible.
    widen_window(xmin, xmax, tiny);
    widen_window(ymin, ymax, tiny);
    const float zpad = std::max(0.01f * (zmax - zmin), tiny);
    f.znear = zmin - zpad;
    f.zfar = zmax + zpad;
    f.proj = glm::ortho(xmin, xmax, ymin, ymax, f.znear, f.zfar);
    return f;
}

// ---- the tight fit ----------------------------------------------------------------------------

// A half-space given in the light's eye space, in world space: (n, d).(V p) = (V^T (n, d)).p.
HalfSpace to_world(const glm::mat4& view, const glm::vec4& eye_half_space) { return glm::transpose(view) * eye_half_space; }

bool inside_box(const scene::Bounds& b, const glm::vec3& p) {
    if (b.empty()) return false;
    // A hair of slack, relative to the coordinates: a light on a face counts as inside.
    const float m = 1e-5f * std::max({1.0f, max_abs_component(b.min), max_abs_component(b.max)});
    return glm::all(glm::greaterThanEqual(p, b.min - m)) && glm::all(glm::lessThanEqual(p, b.max + m));
}

// What the shadows fit adds to the tight one (null: the tight fit): the visible receivers indexed
// (a caster that can shadow none of them is left out), the casters as the index takes them, and
// whether to cut the window to where their shadows fall.
struct Shadowing {
    ReceiverIndex* index = nullptr;
    const std::vector<scene::Bounds>* casters = nullptr;
    const CastingInfo* info = nullptr;
    bool fit_window = true;
    CasterBox caster(size_t k) const { return caster_box(*casters, *info, k); }
};

// Where one drawn caster's shadow can fall: inside its part within the window, seen from the
// light, and inside the visible receivers it may shadow (caster `k`; -1: anywhere).
struct Reach {
    std::vector<glm::vec3> caster;
    int k = -1;
};

// The casters that reach into the window (half-spaces in the light's eye space, the far one
// included) and, with `shadowing`, can shadow a receiver in view (the others counted in
// `culled`); their nearest depth from the light (eye-space -z) over the part inside, and where
// their shadows can fall (`reach`).
void select_casters(const std::vector<scene::Bounds>& casters, const glm::mat4& view,
                    const std::vector<glm::vec4>& eye_half_spaces, const Shadowing* shadowing, TightFit& out,
                    float& nearest, std::vector<Reach>& reach) {
    std::vector<HalfSpace> hs;
    for (const glm::vec4& h : eye_half_spaces) hs.push_back(to_world(view, h));
    const ClipPlanes planes = clip_planes(hs);
    for (size_t k = 0; k < casters.size(); ++k) {
        // A caster inside the window whole: its eight corners (what follows takes extents only).
        bool whole = false;
        std::vector<glm::vec3> pts = clip_box_by(casters[k], planes, &whole);
        if (pts.empty()) continue;
        if (shadowing && !shadowing->index->shadows_any(shadowing->caster(k))) {
            ++out.culled;
            continue;
        }
        out.casters.push_back(static_cast<int>(k));
        for (const glm::vec3& p : pts) nearest = std::min(nearest, -(view * glm::vec4(p, 1.0f)).z);
        reach.push_back({std::move(pts), shadowing ? static_cast<int>(k) : -1});
    }
}

// A rect of the light's window coordinates: tangents (x/depth, y/depth) for a perspective light,
// eye-space x and y for an orthographic one.
struct WindowRect {
    glm::vec4 r{std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest(),
                std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest()};  // left, right, bottom, top
    bool empty() const { return !(r.x <= r.y && r.z <= r.w); }
};
// `out` grown by the points; false for a perspective point not in front of the eye plane by
// front_eps.
bool window_rect(const glm::mat4& view, bool perspective, float front_eps, const std::vector<glm::vec3>& pts,
                 WindowRect& out) {
    for (const glm::vec3& p : pts) {
        const glm::vec3 e = glm::vec3(view * glm::vec4(p, 1.0f));
        glm::vec2 t(e);
        if (perspective) {
            if (!(-e.z > front_eps)) return false;
            t /= -e.z;
        }
        out.r = {std::min(out.r.x, t.x), std::max(out.r.y, t.x), std::min(out.r.z, t.y), std::max(out.r.w, t.y)};
    }
    return true;
}

// The window where the drawn casters' shadows can fall: the union over the casters of the rect
// of each one's part within the window, cut to the rect of the receivers it may shadow (a shadow
// falls where both are, seen from the light). false where a point lies at the light's eye plane.
bool reach_rect(const glm::mat4& view, bool perspective, float front_eps, const std::vector<Reach>& reach,
                const Shadowing& shadowing, WindowRect& out) {
    // Every receiver point is a visible point, and the window's view was fitted to put all of
    // those in front of the eye plane: no receiver fails here that the fit did not refuse first.
    if (!shadowing.index->set_window(view, perspective, front_eps)) return false;
    for (const Reach& c : reach) {
        WindowRect a;
        if (!window_rect(view, perspective, front_eps, c.caster, a)) return false;
        if (c.k >= 0) {
            shadowing.index->cut_to_reach(shadowing.caster(static_cast<size_t>(c.k)), a.r);
            if (a.empty()) continue;
        }
        out.r = {std::min(out.r.x, a.r.x), std::max(out.r.y, a.r.y), std::min(out.r.z, a.r.z), std::max(out.r.w, a.r.w)};
    }
    return true;
}

// A perspective window: the light's view along one direction and the visible points' extent in
// it (tangents x/z and y/z, widened by the margin and within the half-angle cap).
struct PerspectiveWindow {
    glm::mat4 view{1.0f};
    glm::vec4 raw{0.0f};          // the points' tangents before the margin: left, right, bottom, top
    float xl = 0.0f, xr = 0.0f, yb = 0.0f, yt = 0.0f;
    float zmin = 0.0f, zmax = 0.0f;  // the points' depth range
    bool capped = false;          // the cap cut the window: some points fall outside
    float use = 0.0f;             // the points' hull over the window's area: the texel use
};

void finish_window(PerspectiveWindow& w, std::vector<glm::vec2> tangents);

// The window along `dir` around `visible`; false when a point is not in front of the light's eye
// plane (at least front_eps). With many points, only those that may lie on the hull of their
// tangents (hull_candidates) decide the window's sides and its hull: `outline` flags them, given
// (read) or to make (written, where `make_outline`); the others count for the depth range and the
// eye plane only.
bool perspective_window(const glm::vec3& pos, const glm::vec3& dir, const std::vector<glm::vec3>& visible,
                        std::vector<char>& outline, bool make_outline, float front_eps, PerspectiveWindow& w) {
    w.view = look_along(pos, dir);
    float xl = std::numeric_limits<float>::max(), xr = std::numeric_limits<float>::lowest();
    float yb = xl, yt = xr;
    w.zmin = xl;
    w.zmax = 0.0f;
    const bool outlined = !outline.empty() && !make_outline;
    std::vector<glm::vec2> tangents;
    tangents.reserve(outlined ? visible.size() / 8 : visible.size());
    for (size_t i = 0; i < visible.size(); ++i) {
        const glm::vec3 e = glm::vec3(w.view * glm::vec4(visible[i], 1.0f));
        const float depth = -e.z;
        if (!(depth > front_eps)) return false;
        w.zmin = std::min(w.zmin, depth);
        w.zmax = std::max(w.zmax, depth);
        if (outlined && !outline[i]) continue;
        const glm::vec2 t(e.x / depth, e.y / depth);
        tangents.push_back(t);
        xl = std::min(xl, t.x);
        xr = std::max(xr, t.x);
        yb = std::min(yb, t.y);
        yt = std::max(yt, t.y);
    }
    w.raw = {xl, xr, yb, yt};
    if (make_outline && tangents.size() > 1024) {
        // The hull of the candidates is the hull of all (convex_hull takes the same ones).
        outline.assign(visible.size(), 0);
        std::vector<glm::vec2> near;
        for (std::size_t i : hull_candidates(tangents)) {
            outline[i] = 1;
            near.push_back(tangents[i]);
        }
        tangents = std::move(near);
    }
    finish_window(w, std::move(tangents));
    return true;
}

// The window around the raw tangents: widened by the margin, each side within the cap; its texel
// use by the hull of `tangents`.
void finish_window(PerspectiveWindow& w, std::vector<glm::vec2> tangents) {
    float xl = w.raw.x, xr = w.raw.y, yb = w.raw.z, yt = w.raw.w;
    widen_window(xl, xr, kMinTanHalfAngle);
    widen_window(yb, yt, kMinTanHalfAngle);
    w.capped = xl < -kMaxTanHalfAngle || xr > kMaxTanHalfAngle || yb < -kMaxTanHalfAngle || yt > kMaxTanHalfAngle;
    // Each side within the cap; the window keeps some width (the cap is far from the minimum).
    w.xl = std::clamp(xl, -kMaxTanHalfAngle, kMaxTanHalfAngle - 2.0f * kMinTanHalfAngle);
    w.xr = std::clamp(xr, w.xl + 2.0f * kMinTanHalfAngle, kMaxTanHalfAngle);
    w.yb = std::clamp(yb, -kMaxTanHalfAngle, kMaxTanHalfAngle - 2.0f * kMinTanHalfAngle);
    w.yt = std::clamp(yt, w.yb + 2.0f * kMinTanHalfAngle, kMaxTanHalfAngle);
    const glm::vec2 lo(w.xl, w.yb), hi(w.xr, w.yt);
    w.use = polygon_area(clip_to_rect(convex_hull(std::move(tangents)), lo, hi)) / ((hi.x - lo.x) * (hi.y - lo.y));
}

// The shadows fit's window: the raw window cut to where the drawn casters' shadows can fall
// (reach_rect); false (the window kept) when a point lies at the light's eye plane or no shadow
// falls in it.
bool cut_to_casters(PerspectiveWindow& w, const std::vector<Reach>& reach, const Shadowing& shadowing, float front_eps) {
    WindowRect rect;
    if (reach.empty() || !reach_rect(w.view, true, front_eps, reach, shadowing, rect) || rect.empty()) return false;
    const glm::vec4& c = rect.r;
    const glm::vec4 cut(std::max(w.raw.x, c.x), std::min(w.raw.y, c.y), std::max(w.raw.z, c.z), std::min(w.raw.w, c.w));
    if (!(cut.x <= cut.y && cut.z <= cut.w)) return false;
    w.raw = cut;
    finish_window(w, {});
    return true;
}

// Point and spot lights: false where the tight fit does not apply (the light inside a box, a
// visible point beside or behind the light's eye plane).
bool fit_tight_perspective(const scene::Light& light, const std::vector<glm::vec3>& visible, const glm::vec3& centroid,
                           const std::vector<scene::Bounds>& receivers, const std::vector<scene::Bounds>& casters,
                           const Shadowing* shadowing, TightFit& out, std::vector<char>& outline) {
    const glm::vec3 pos = light.position;
    for (const auto* boxes : {&receivers, &casters})
        for (const scene::Bounds& b : *boxes)
            if (inside_box(b, pos)) return false;

    float max_dist = 0.0f;
    for (const glm::vec3& p : visible) max_dist = std::max(max_dist, glm::length(p - pos));
    const float scale = std::max(max_dist, 1e-6f * std::max(1.0f, max_abs_component(pos)));
    const glm::vec3 to_centroid = centroid - pos;
    if (!(glm::length(to_centroid) > 1e-4f * scale)) return false;
    const float front_eps = 1e-4f * scale;

    // Two candidate axes: towards the points' centroid, and towards the middle of the angles the
    // points span seen along the first (which narrows a lopsided window, e.g. a light low over a
    // wide receiver, below the cap). The one the cap does not cut, then the one with the higher
    // texel use.
    PerspectiveWindow a, b;
    const bool has_a = perspective_window(pos, glm::normalize(to_centroid), visible, outline, true, front_eps, a);
    bool has_b = false;
    if (has_a) {
        const float ax = 0.5f * (std::atan(a.raw.x) + std::atan(a.raw.y));
        const float ay = 0.5f * (std::atan(a.raw.z) + std::atan(a.raw.w));
        const glm::vec3 eye_dir = glm::normalize(glm::vec3(std::tan(ax), std::tan(ay), -1.0f));
        const glm::vec3 dir = glm::transpose(glm::mat3(a.view)) * eye_dir;
        // The second window looks from the same point: a projective change of the first's tangents
        // that keeps every point in front, so the first's hull candidates hold the second's too.
        has_b = perspective_window(pos, safe_normalize(dir, glm::normalize(to_centroid)), visible, outline, false,
                                   front_eps, b);
    }
    if (!has_a && !has_b) return false;
    PerspectiveWindow w =
        !has_b ? a : !has_a ? b : a.capped != b.capped ? (a.capped ? b : a) : (b.use > a.use ? b : a);

    LightFrustum& f = out.frustum;
    f.perspective = true;
    f.view = w.view;

    // The casters inside the pyramid of the window, up to the farthest visible point: a caster
    // between the light and a visible point lies there.
    float nearest = w.zmin;
    std::vector<Reach> reach;
    select_casters(casters, f.view,
                   {{1.0f, 0.0f, w.xl, 0.0f}, {-1.0f, 0.0f, -w.xr, 0.0f}, {0.0f, 1.0f, w.yb, 0.0f},
                    {0.0f, -1.0f, -w.yt, 0.0f}, {0.0f, 0.0f, 1.0f, w.zmax}},
                   shadowing, out, nearest, reach);
    if (shadowing && shadowing->fit_window) out.cut = cut_to_casters(w, reach, *shadowing, front_eps);
    out.capped = w.capped;

    f.zfar = 1.02f * w.zmax;
    f.znear = std::max(0.98f * nearest, f.zfar * 1e-4f);
    if (!(f.zfar > f.znear)) f.zfar = f.znear * 1.04f + 1e-6f;
    f.proj = glm::frustum(f.znear * w.xl, f.znear * w.xr, f.znear * w.yb, f.znear * w.yt, f.znear, f.zfar);
    return true;
}

// Directional lights: the eye up the light's direction, outside the sphere around every box and
// visible point, so everything is in front of it.
void fit_tight_orthographic(const scene::Light& light, const std::vector<glm::vec3>& visible, const glm::vec3& centroid,
                            const std::vector<scene::Bounds>& receivers, const std::vector<scene::Bounds>& casters,
                            const Shadowing* shadowing, TightFit& out) {
    const glm::vec3 dir = safe_normalize(light.direction, glm::vec3(0.0f, -1.0f, 0.0f));
    float radius = 0.0f;
    for (const glm::vec3& p : visible) radius = std::max(radius, glm::length(p - centroid));
    for (const auto* boxes : {&receivers, &casters})
        for (const scene::Bounds& b : *boxes)
            if (!b.empty())
                for (const glm::vec3& c : scene::corners(b)) radius = std::max(radius, glm::length(c - centroid));
    const float tiny = 1e-4f * std::max(1.0f, max_abs_component(centroid));
    const float back = radius * 1.05f + tiny;

    LightFrustum& f = out.frustum;
    f.perspective = false;
    f.view = look_along(centroid - dir * back, dir);

    const Extent ext = eye_extent(f.view, visible);
    float xl = ext.lo.x, xr = ext.hi.x, yb = ext.lo.y, yt = ext.hi.y;
    float zmin = ext.lo.z, zmax = ext.hi.z;
    const glm::vec4 raw(xl, xr, yb, yt);
    widen_window(xl, xr, tiny);
    widen_window(yb, yt, tiny);

    float nearest = zmin;
    std::vector<Reach> reach;
    select_casters(casters, f.view,
                   {{1.0f, 0.0f, 0.0f, -xl}, {-1.0f, 0.0f, 0.0f, xr}, {0.0f, 1.0f, 0.0f, -yb}, {0.0f, -1.0f, 0.0f, yt},
                    {0.0f, 0.0f, 1.0f, zmax}},
                   shadowing, out, nearest, reach);
    WindowRect c;
    if (shadowing && shadowing->fit_window && !reach.empty() && reach_rect(f.view, false, 0.0f, reach, *shadowing, c) &&
        !c.empty()) {
        // The window cut to where the drawn casters' shadows can fall (reach_rect).
        xl = std::max(raw.x, c.r.x);
        xr = std::min(raw.y, c.r.y);
        yb = std::max(raw.z, c.r.z);
        yt = std::min(raw.w, c.r.w);
        out.cut = xl <= xr && yb <= yt;
        if (!out.cut) xl = raw.x, xr = raw.y, yb = raw.z, yt = raw.w;
        widen_window(xl, xr, tiny);
        widen_window(yb, yt, tiny);
    }

    const float zpad = std::max(0.01f * (zmax - nearest), tiny);
    f.znear = nearest - zpad;
    f.zfar = zmax + zpad;
    f.proj = glm::ortho(xl, xr, yb, yt, f.znear, f.zfar);
}

}  // namespace

glm::vec4 light_vector(const scene::Light& light) {
    return light.type == scene::LightType::Directional ? glm::vec4(-light.direction, 0.0f)
                                                        : glm::vec4(light.position, 1.0f);
}

float texel_use(const LightFrustum& f, const std::vector<glm::vec3>& points) { return hull_share(f.view_proj(), points); }

float hull_share(const glm::mat4& vp, const std::vector<glm::vec3>& points) {
    std::vector<glm::vec2> ndc;
    ndc.reserve(points.size());
    for (const glm::vec3& p : points) {
        const glm::vec4 c = vp * glm::vec4(p, 1.0f);
        if (!(c.w > 0.0f)) continue;
        const glm::vec2 n = glm::vec2(c) / c.w;
        if (std::isfinite(n.x) && std::isfinite(n.y)) ndc.push_back(n);
    }
    const float area = polygon_area(clip_to_rect(convex_hull(std::move(ndc)), glm::vec2(-1.0f), glm::vec2(1.0f)));
    return std::clamp(area / 4.0f, 0.0f, 1.0f);
}

namespace {

TightFit fit_tight(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                   const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj,
                   const Shadowing* shadowing) {
    TightFit r;
    std::vector<char> outline;  // the points near the hull, where there are many (empty: all)
    // The shadows fit's index holds the receivers clipped already; the tight fit clips them here.
    std::vector<SeenReceiver> own;
    if (!shadowing) own = seen_receivers(light, receivers, camera_view_proj, CastingInfo{});
    const std::vector<SeenReceiver>& seen = shadowing ? shadowing->index->seen() : own;
    std::size_t count = 0;
    for (const SeenReceiver& each : seen) count += each.points.size();
    r.visible.reserve(count);
    for (const SeenReceiver& each : seen) r.visible.insert(r.visible.end(), each.points.begin(), each.points.end());
    if (!r.visible.empty()) {
        const glm::vec3 centroid = visible_centroid(seen);
        if (light.type == scene::LightType::Directional) {
            fit_tight_orthographic(light, r.visible, centroid, receivers, casters, shadowing, r);
            r.tight = true;
        } else {
            r.tight = fit_tight_perspective(light, r.visible, centroid, receivers, casters, shadowing, r, outline);
        }
    }
    if (!r.tight) return fit_light_frustum_scene(light, receivers, casters, camera_view_proj);
    if (outline.empty()) {
        r.texel_use = texel_use(r.frustum, r.visible);
    } else {  // the points near the hull give the same hull (fit_tight_perspective)
        std::vector<glm::vec3> near;
        for (std::size_t i = 0; i < r.visible.size(); ++i)
            if (outline[i]) near.push_back(r.visible[i]);
        r.texel_use = texel_use(r.frustum, near);
    }
    return r;
}

}  // namespace

TightFit fit_light_frustum_tight(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                 const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj) {
    return fit_tight(light, receivers, casters, camera_view_proj, nullptr);
}

TightFit fit_light_frustum_shadows(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                   const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj,
                                   const CastingInfo& info) {
    ReceiverIndex index(seen_receivers(light, receivers, camera_view_proj, info), light_vector(light), info.pairwise);
    const Shadowing s{&index, &casters, &info, info.fit_window};
    return fit_tight(light, receivers, casters, camera_view_proj, &s);
}

TightFit fit_light_frustum_scene(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                 const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj) {
    TightFit r;
    scene::Bounds all;
    for (const auto* boxes : {&receivers, &casters})
        for (const scene::Bounds& b : *boxes) all.add(b);
    r.frustum = all.empty() ? fit_light_frustum(light, {}, light.position + light.direction)
                            : fit_light_frustum(light, scene::corners(all), all.center());
    for (size_t k = 0; k < casters.size(); ++k) r.casters.push_back(static_cast<int>(k));
    r.visible = visible_receiver_points(light, receivers, camera_view_proj);
    r.texel_use = texel_use(r.frustum, r.visible);
    return r;
}

LightFrustum fit_light_frustum(const scene::Light& light, const std::vector<glm::vec3>& points,
                               const glm::vec3& aim) {
    if (light.type == scene::LightType::Directional) return fit_orthographic(light, points, aim);
    return fit_perspective(light, points, aim);
}

glm::mat4 clip_to_texture() {
    // x_tex = 0.5 x_clip + 0.5 for x, y and z (after the divide by w, which the lookup does).
    const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    return glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * scale;
}

}  // namespace penumbra::shadow
