#include "shadow/casting.h"

#include "shadow/convex.h"
#include "shadow/light_frustum.h"
#include "shadow/receiver_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra::shadow {

namespace {

// The unit axes may_shadow tries: x, y, z, and a directional light's own direction when it has one.
int axes_of(const glm::vec4& light, glm::vec3 (&axes)[4]) {
    axes[0] = glm::vec3(1, 0, 0);
    axes[1] = glm::vec3(0, 1, 0);
    axes[2] = glm::vec3(0, 0, 1);
    if (light.w != 0.0f) return 3;
    const float len = glm::length(glm::vec3(light));
    if (!(len > 0.0f)) return 3;
    axes[3] = glm::vec3(light) / len;
    return 4;
}

}  // namespace

PointSpans point_spans(const std::vector<glm::vec3>& points, const glm::vec4& light) {
    glm::vec3 axes[4];
    const int n = axes_of(light, axes);
    PointSpans s;
    for (const glm::vec3& q : points)
        for (int i = 0; i < n; ++i) {
            const float v = glm::dot(q, axes[i]);
            s.lo[i] = std::min(s.lo[i], v);
            s.hi[i] = std::max(s.hi[i], v);
        }
    if (light.w != 0.0f) {
        const glm::vec3 pos(light);
        for (const glm::vec3& q : points) s.farthest = std::max(s.farthest, glm::length(q - pos));
    }
    return s;
}

CasterSpans caster_spans(const scene::Bounds& caster, const glm::vec4& light) {
    glm::vec3 axes[4];
    CasterSpans c;
    c.axes = axes_of(light, axes);
    c.point = light.w != 0.0f;
    // scene::corners' eight, without a vector (this runs twice a caster).
    glm::vec3 corners[8];
    for (int k = 0; k < 8; ++k)
        corners[k] = {(k & 1) ? caster.max.x : caster.min.x, (k & 2) ? caster.max.y : caster.min.y,
                      (k & 4) ? caster.max.z : caster.min.z};
    for (int i = 0; i < c.axes; ++i) {
        float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
        for (const glm::vec3& p : corners) {
            lo = std::min(lo, glm::dot(p, axes[i]));
            hi = std::max(hi, glm::dot(p, axes[i]));
        }
        c.lo[i] = lo;
        c.hi[i] = hi;
        c.light[i] = glm::dot(glm::vec3(light), axes[i]);
    }
    if (c.point) {
        const glm::vec3 pos(light);
        c.reach = glm::length(glm::clamp(pos, caster.min, caster.max) - pos);
    }
    return c;
}

// A plane dot(x, n) = v with the caster on one side and the points and the light's segments on the
// other separates them: segment (ray) points other than the start lie strictly beyond v when the
// start is on or beyond it and the light strictly beyond, or the start strictly beyond and the
// light on or beyond (for a directional light: the ray's direction along n).
bool separated_above(const CasterSpans& c, int axis, float points_lo) {
    const float top = c.hi[axis], l = c.light[axis];
    if (c.point) return (points_lo >= top && l > top) || (points_lo > top && l >= top);
    return (points_lo >= top && l > 0.0f) || (points_lo > top && l >= 0.0f);
}

bool separated_below(const CasterSpans& c, int axis, float points_hi) {
    const float bottom = c.lo[axis], l = c.light[axis];
    if (c.point) return (points_hi <= bottom && l < bottom) || (points_hi < bottom && l <= bottom);
    return (points_hi <= bottom && l < 0.0f) || (points_hi < bottom && l <= 0.0f);
}

bool may_shadow(const CasterSpans& caster, const PointSpans& points) {
    for (int i = 0; i < caster.axes; ++i)
        if (separated_above(caster, i, points.lo[i]) || separated_below(caster, i, points.hi[i])) return false;
    return !nearer_than_caster(caster, points.farthest);
}

bool may_shadow(const scene::Bounds& caster, const std::vector<glm::vec3>& points, const glm::vec4& light) {
    if (caster.empty() || points.empty()) return false;
    return may_shadow(caster_spans(caster, light), point_spans(points, light));
}

ClipPlanes visible_clip_planes(const scene::Light& light, const glm::mat4& camera_view_proj, const std::vector<glm::vec4>& also) {
    const std::array<HalfSpace, 6> camera = clip_volume_half_spaces(camera_view_proj);
    std::vector<HalfSpace> hs(camera.begin(), camera.end());
    hs.insert(hs.end(), also.begin(), also.end());
    // A spot light lights nothing outside its outer cone: the four planes through the light that
    // touch the cone (a pyramid holding it), when the cone is under a hemisphere.
    const float theta = light.spot_outer_cone;
    if (light.type == scene::LightType::Spot && theta >= 0.0f && theta < glm::radians(89.0f)) {
        // The spot's axis, as the fits take it (a direction of no length: straight down).
        const float len = glm::length(light.direction);
        const glm::vec3 d = !(len > 1e-12f) || !std::isfinite(len) ? glm::vec3(0.0f, -1.0f, 0.0f) : light.direction / len;
        const glm::vec3 u =
            glm::normalize(glm::cross(d, std::fabs(d.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f)));
        const glm::vec3 v = glm::cross(d, u);
        const float s = std::sin(theta);
        const float c = std::cos(theta);
        for (const glm::vec3& e : {u, -u, v, -v}) {
            const glm::vec3 n = s * d - c * e;
            hs.emplace_back(n, -glm::dot(n, light.position));
        }
    }
    return clip_planes(hs);
}

std::vector<std::vector<glm::vec3>> visible_points_each(const scene::Light& light,
                                                      const std::vector<scene::Bounds>& receivers,
                                                      const glm::mat4& camera_view_proj, std::vector<char>& whole,
                                                      const std::vector<glm::vec4>& also) {
    const ClipPlanes planes = visible_clip_planes(light, camera_view_proj, also);
    std::vector<std::vector<glm::vec3>> out;
    out.reserve(receivers.size());
    whole.assign(receivers.size(), 0);
    for (size_t k = 0; k < receivers.size(); ++k) {
        bool all = false;
        out.push_back(clip_box_by(receivers[k], planes, &all));
        whole[k] = all ? 1 : 0;
    }
    return out;
}

std::vector<glm::vec3> visible_receiver_points(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                               const glm::mat4& camera_view_proj) {
    std::vector<char> whole;
    std::vector<glm::vec3> out;
    for (const std::vector<glm::vec3>& pts : visible_points_each(light, receivers, camera_view_proj, whole))
        out.insert(out.end(), pts.begin(), pts.end());
    return out;
}

std::vector<SeenReceiver> seen_receivers(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                         const glm::mat4& camera_view_proj, const CastingInfo& info) {
    std::vector<char> whole;
    std::vector<std::vector<glm::vec3>> each = visible_points_each(light, receivers, camera_view_proj, whole);
    std::vector<SeenReceiver> seen;
    seen.reserve(each.size());
    for (size_t k = 0; k < each.size(); ++k)
        seen.push_back({k < info.receiver_objects.size() ? info.receiver_objects[k] : -1, std::move(each[k]), whole[k] != 0});
    return seen;
}

glm::vec3 visible_centroid(const std::vector<SeenReceiver>& seen) {
    glm::vec3 sum(0.0f);
    std::size_t count = 0;
    for (const SeenReceiver& r : seen) {
        if (r.whole) {
            // The eight corners: min first, max last (scene::corners).
            box_face_corners(scene::Bounds{r.points.front(), r.points.back()}, [&](const glm::vec3& p) { sum += p; });
            count += 24;
        } else {
            for (const glm::vec3& p : r.points) sum += p;
            count += r.points.size();
        }
    }
    return sum / static_cast<float>(count);
}

CasterBox caster_box(const std::vector<scene::Bounds>& casters, const CastingInfo& info, size_t k) {
    return {k < info.caster_objects.size() ? info.caster_objects[k] : -1, casters[k],
            k < info.caster_convex.size() && info.caster_convex[k] != 0};
}

std::vector<char> shadowing_flags(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                  const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj,
                                  const CastingInfo& info) {
    const ReceiverIndex index(seen_receivers(light, receivers, camera_view_proj, info), light_vector(light), info.pairwise);
    std::vector<char> keep(casters.size(), 0);
    for (size_t k = 0; k < casters.size(); ++k) keep[k] = index.shadows_any(caster_box(casters, info, k)) ? 1 : 0;
    return keep;
}

}  // namespace penumbra::shadow
