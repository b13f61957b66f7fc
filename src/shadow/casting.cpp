#include "shadow/casting.h"

#include "shadow/light_frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra::shadow {

namespace {

// The extent of a set along unit-free axis n.
struct Span {
    float lo = std::numeric_limits<float>::max();
    float hi = std::numeric_limits<float>::lowest();
    void add(float v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
};

Span box_span(const scene::Bounds& b, const glm::vec3& n) {
    Span s;
    for (const glm::vec3& c : scene::corners(b)) s.add(glm::dot(c, n));
    return s;
}

// Whether the plane dot(x, n) = v, with the caster on or below it and the points and the light's
// segments above it, separates them: segment (ray) points other than the start lie strictly
// above v when the start is on or above it and the light strictly above, or the start strictly
// above and the light on or above (for a directional light: the ray's direction along n).
bool separated_along(const scene::Bounds& caster, const std::vector<glm::vec3>& points, const glm::vec4& light,
                     const glm::vec3& n) {
    const Span c = box_span(caster, n);
    Span p;
    for (const glm::vec3& q : points) p.add(glm::dot(q, n));
    const float l = glm::dot(glm::vec3(light), n);
    // The caster below: the points above it and the light's side above too.
    if (light.w != 0.0f) {
        if ((p.lo >= c.hi && l > c.hi) || (p.lo > c.hi && l >= c.hi)) return true;
        if ((p.hi <= c.lo && l < c.lo) || (p.hi < c.lo && l <= c.lo)) return true;
    } else {
        if ((p.lo >= c.hi && l > 0.0f) || (p.lo > c.hi && l >= 0.0f)) return true;
        if ((p.hi <= c.lo && l < 0.0f) || (p.hi < c.lo && l <= 0.0f)) return true;
    }
    return false;
}

}  // namespace

bool may_shadow(const scene::Bounds& caster, const std::vector<glm::vec3>& points, const glm::vec4& light) {
    if (caster.empty() || points.empty()) return false;
    for (const glm::vec3& axis : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)})
        if (separated_along(caster, points, light, axis)) return false;
    if (light.w == 0.0f) {
        const float len = glm::length(glm::vec3(light));
        if (len > 0.0f && separated_along(caster, points, light, glm::vec3(light) / len)) return false;
        return true;
    }
    // A point light: every point nearer to it than the box's nearest point.
    const glm::vec3 pos(light);
    const glm::vec3 nearest = glm::clamp(pos, caster.min, caster.max);
    const float reach = glm::length(nearest - pos);
    float farthest = 0.0f;
    for (const glm::vec3& q : points) farthest = std::max(farthest, glm::length(q - pos));
    return !(farthest < reach);
}

namespace {

// Whether `caster` can shadow a point of receiver `r` (never itself when convex).
bool may_shadow_receiver(const CasterBox& caster, const SeenReceiver& r, const glm::vec4& light) {
    return !r.points.empty() && !(caster.convex && r.object == caster.object) && may_shadow(caster.bounds, r.points, light);
}

}  // namespace

bool shadows_any(const CasterBox& caster, const std::vector<SeenReceiver>& seen, const glm::vec4& light) {
    return std::any_of(seen.begin(), seen.end(),
                       [&](const SeenReceiver& r) { return may_shadow_receiver(caster, r, light); });
}

std::vector<glm::vec3> shadowed_points(const CasterBox& caster, const std::vector<SeenReceiver>& seen,
                                       const glm::vec4& light) {
    std::vector<glm::vec3> out;
    for (const SeenReceiver& r : seen)
        if (may_shadow_receiver(caster, r, light)) out.insert(out.end(), r.points.begin(), r.points.end());
    return out;
}

namespace {

// The receivers the camera sees, each with its scene object, and caster box k with its object and
// convexity: what shadows_any and shadowed_points take.
std::vector<SeenReceiver> seen_receivers(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                         const glm::mat4& camera_view_proj, const CastingInfo& info) {
    const std::vector<std::vector<glm::vec3>> each = visible_points_each(light, receivers, camera_view_proj);
    std::vector<SeenReceiver> seen;
    for (size_t k = 0; k < each.size(); ++k)
        seen.push_back({k < info.receiver_objects.size() ? info.receiver_objects[k] : -1, each[k]});
    return seen;
}
CasterBox caster_box(const std::vector<scene::Bounds>& casters, const CastingInfo& info, size_t k) {
    return {k < info.caster_objects.size() ? info.caster_objects[k] : -1, casters[k],
            k < info.caster_convex.size() && info.caster_convex[k] != 0};
}

}  // namespace

// The shadows fit's per-caster questions (declared in light_frustum.h, beside the fit).
std::vector<std::vector<glm::vec3>> shadowed_each(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                                  const std::vector<scene::Bounds>& casters,
                                                  const glm::mat4& camera_view_proj, const CastingInfo& info) {
    const std::vector<SeenReceiver> seen = seen_receivers(light, receivers, camera_view_proj, info);
    const glm::vec4 l = light_vector(light);
    std::vector<std::vector<glm::vec3>> out;
    for (size_t k = 0; k < casters.size(); ++k) out.push_back(shadowed_points(caster_box(casters, info, k), seen, l));
    return out;
}

std::vector<char> shadowing_flags(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                  const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj,
                                  const CastingInfo& info) {
    const std::vector<SeenReceiver> seen = seen_receivers(light, receivers, camera_view_proj, info);
    const glm::vec4 l = light_vector(light);
    std::vector<char> keep;
    for (size_t k = 0; k < casters.size(); ++k) keep.push_back(shadows_any(caster_box(casters, info, k), seen, l) ? 1 : 0);
    return keep;
}

}  // namespace penumbra::shadow
