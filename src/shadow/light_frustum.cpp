// Fitting the light's view and projection around the points the shadow map must cover
// (exercise W09P2a), and the clip-to-texture matrix B that turns the light's clip space into
// shadow-map lookup coordinates.
#include "shadow/light_frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

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
        xmin = ymin = zmin = std::numeric_limits<float>::max();
        xmax = ymax = zmax = std::numeric_limits<float>::lowest();
        for (const auto& p : points) {
            const glm::vec3 e = glm::vec3(f.view * glm::vec4(p, 1.0f));
            xmin = std::min(xmin, e.x);
            xmax = std::max(xmax, e.x);
            ymin = std::min(ymin, e.y);
            ymax = std::max(ymax, e.y);
            zmin = std::min(zmin, -e.z);
            zmax = std::max(zmax, -e.z);
        }
    }

    // Tight x/y (widened by a hair so the outermost points are strictly inside); a flat or
    // single-point extent is opened to `tiny` so the matrix stays invertible.
    const auto widen = [tiny](float& lo, float& hi) {
        const float half = std::max(0.5f * (hi - lo) * kSideMargin, tiny);
        const float mid = 0.5f * (lo + hi);
        lo = mid - half;
        hi = mid + half;
    };
    widen(xmin, xmax);
    widen(ymin, ymax);
    const float zpad = std::max(0.01f * (zmax - zmin), tiny);
    f.znear = zmin - zpad;
    f.zfar = zmax + zpad;
    f.proj = glm::ortho(xmin, xmax, ymin, ymax, f.znear, f.zfar);
    return f;
}

}  // namespace

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
