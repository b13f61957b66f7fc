// Cascaded shadow maps: the slices of the camera's depth range, their bounding spheres, and each
// cascade's orthographic window on the light's fixed axes, snapped to whole texels.
#include "shadow/cascades.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/convex.h"

namespace penumbra::shadow {

namespace {

// The depth range is quantised to steps of 2^(1/8) (9%) so that a slowly moving camera keeps the
// same slices, spheres and texel sizes frame after frame.
constexpr float kRangeSteps = 8.0f;

float quantise_down(float v) { return std::exp2(std::floor(std::log2(v) * kRangeSteps) / kRangeSteps); }
float quantise_up(float v) { return std::exp2(std::ceil(std::log2(v) * kRangeSteps) / kRangeSteps); }

// The camera's near and far planes from a perspective projection (glm's convention).
void planes_of(const glm::mat4& proj, float& znear, float& zfar) {
    znear = proj[3][2] / (proj[2][2] - 1.0f);
    zfar = proj[3][2] / (proj[2][2] + 1.0f);
}

bool perspective(const glm::mat4& proj) { return proj[2][3] < -0.5f && std::fabs(proj[3][3]) < 1e-6f; }

// The visible receivers' camera view depth range, [znear, zfar] at most; false when none is seen.
bool depth_range(const std::vector<glm::vec3>& visible, const glm::mat4& view, const glm::mat4& proj, float& lo,
                 float& hi) {
    if (visible.empty()) return false;
    float znear = 0.0f, zfar = 0.0f;
    planes_of(proj, znear, zfar);
    lo = std::numeric_limits<float>::max();
    hi = 0.0f;
    for (const glm::vec3& p : visible) {
        const float d = -(view * glm::vec4(p, 1.0f)).z;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    lo = std::clamp(lo, znear, zfar);
    hi = std::clamp(hi, lo, zfar);
    return hi > 0.0f;
}

}  // namespace

std::vector<float> cascade_splits(float near, float far, int count, float lambda) {
    std::vector<float> s(static_cast<size_t>(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(count);
        const float logarithmic = near * std::pow(far / near, t);
        const float uniform = near + (far - near) * t;
        s[static_cast<size_t>(i)] = lambda * logarithmic + (1.0f - lambda) * uniform;
    }
    s.front() = near;
    s.back() = far;
    return s;
}

void slice_sphere(const glm::mat4& proj, float a, float b, float& centre_depth, float& radius) {
    // The slice's corners at view depth z lie at (x, y) = z (+-tx + ox, +-ty + oy): the widest
    // squared spread k^2 = max (x^2 + y^2) / z^2 over the four. A centre c on the axis is as far
    // from the near corners, (c - a)^2 + a^2 k^2, as from the far ones, (b - c)^2 + b^2 k^2, at
    // c = (a + b)(1 + k^2) / 2; beyond b, the sphere around the far ring alone (c = b) holds all.
    const float tx = 1.0f / proj[0][0], ty = 1.0f / proj[1][1];
    const float ox = proj[2][0] / proj[0][0], oy = proj[2][1] / proj[1][1];
    float k2 = 0.0f;
    for (float sx : {-1.0f, 1.0f})
        for (float sy : {-1.0f, 1.0f}) {
            const float x = sx * tx - ox, y = sy * ty - oy;
            k2 = std::max(k2, x * x + y * y);
        }
    centre_depth = std::min(0.5f * (a + b) * (1.0f + k2), b);
    const float near_r = std::sqrt((centre_depth - a) * (centre_depth - a) + a * a * k2);
    const float far_r = std::sqrt((b - centre_depth) * (b - centre_depth) + b * b * k2);
    radius = std::max(near_r, far_r);
}

glm::mat4 slice_projection(const glm::mat4& proj, float a, float b) {
    glm::mat4 p = proj;
    p[2][2] = -(b + a) / (b - a);
    p[3][2] = -2.0f * b * a / (b - a);
    return p;
}

glm::mat4 light_axes(const glm::vec3& direction) {
    const float len = glm::length(direction);
    const glm::vec3 dir = len > 1e-12f && std::isfinite(len) ? direction / len : glm::vec3(0.0f, -1.0f, 0.0f);
    const glm::vec3 up = std::fabs(dir.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAt(glm::vec3(0.0f), dir, up);
}

void atlas_layout(int count, int& columns, int& rows) {
    columns = count >= 2 ? 2 : 1;
    rows = count >= 3 ? 2 : 1;
}

CascadeFit fit_cascades(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                        const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view,
                        const glm::mat4& camera_proj, const CascadeOptions& o, std::string* why) {
    CascadeFit fit;
    const auto fail = [&](const char* reason) {
        if (why) *why = reason;
        fit.cascades.clear();
        return fit;
    };
    if (light.type != scene::LightType::Directional) return fail("cascades need a directional light");
    if (!perspective(camera_proj)) return fail("cascades need a perspective camera");
    fit.visible = visible_receiver_points(light, receivers, camera_proj * camera_view);
    float lo = 0.0f, hi = 0.0f;
    if (!depth_range(fit.visible, camera_view, camera_proj, lo, hi)) return fail("the camera sees no receiver");
    float znear = 0.0f, zfar = 0.0f;
    planes_of(camera_proj, znear, zfar);
    fit.near = std::max(quantise_down(lo), znear);
    fit.far = std::max(std::min(quantise_up(hi), zfar), fit.near * 1.001f);

    const int n = std::clamp(o.count, 1, kMaxCascades);
    const int tile = std::max(o.tile, 1);
    atlas_layout(n, fit.columns, fit.rows);
    fit.atlas_width = fit.columns * tile;
    fit.atlas_height = fit.rows * tile;
    const glm::mat4 inv_view = glm::inverse(camera_view);
    const glm::vec3 eye = glm::vec3(inv_view[3]);
    const glm::vec3 forward = -glm::normalize(glm::vec3(inv_view[2]));
    fit.depth_axis = glm::vec4(forward, -glm::dot(forward, eye));

    const std::vector<float> splits = cascade_splits(fit.near, fit.far, n, std::clamp(o.split, 0.0f, 1.0f));
    const float blend = std::clamp(o.blend, 0.0f, 0.5f);
    const glm::mat4 axes = light_axes(light.direction);
    float prev_band = 0.0f;
    for (int i = 0; i < n; ++i) {
        Cascade c;
        c.begin = splits[static_cast<size_t>(i)];
        c.end = splits[static_cast<size_t>(i) + 1];
        c.band = i + 1 < n ? blend * (c.end - c.begin) : 0.0f;
        c.fit_begin = std::max(c.begin - prev_band, fit.near);
        prev_band = c.band;
        float centre_depth = 0.0f;
        slice_sphere(camera_proj, c.fit_begin, c.end, centre_depth, c.radius);
        c.centre = eye + forward * centre_depth;
        c.tile_x = (i % fit.columns) * tile;
        c.tile_y = (i / fit.columns) * tile;

        // The window: the sphere with room for the snap (at most half a texel each way), so
        // half = r + texel / 2 with texel = 2 half / tile.
        const float half = c.radius / (1.0f - 1.0f / static_cast<float>(tile));
        c.texel = 2.0f * half / static_cast<float>(tile);
        glm::vec3 mid = glm::vec3(axes * glm::vec4(c.centre, 1.0f));
        if (o.snap) {
            mid.x = std::round(mid.x / c.texel) * c.texel;
            mid.y = std::round(mid.y / c.texel) * c.texel;
        }
        const float xl = mid.x - half, xr = mid.x + half, yb = mid.y - half, yt = mid.y + half;
        // Depths along the light (eye space -z): the sphere's far side ends the map; its near end
        // reaches back to the nearest caster that can throw a shadow into the window, wherever
        // the camera's slice is (a caster outside the slice, towards the light, still counts).
        const float sphere_depth = -mid.z;
        const float far = sphere_depth + c.radius;
        float nearest = sphere_depth - c.radius;
        const glm::mat4 to_world = glm::transpose(axes);
        const std::vector<HalfSpace> window = {
            to_world * glm::vec4(1.0f, 0.0f, 0.0f, -xl), to_world * glm::vec4(-1.0f, 0.0f, 0.0f, xr),
            to_world * glm::vec4(0.0f, 1.0f, 0.0f, -yb), to_world * glm::vec4(0.0f, -1.0f, 0.0f, yt),
            to_world * glm::vec4(0.0f, 0.0f, 1.0f, far)};
        for (size_t k = 0; k < casters.size(); ++k) {
            const std::vector<glm::vec3> pts = clip_box(casters[k], window);
            if (pts.empty()) continue;
            c.casters.push_back(static_cast<int>(k));
            for (const glm::vec3& p : pts) nearest = std::min(nearest, -(axes * glm::vec4(p, 1.0f)).z);
        }
        const float pad = 0.01f * (far - nearest) + 1e-4f * std::max(1.0f, c.radius);
        LightFrustum& f = c.frustum;
        f.perspective = false;
        f.view = axes;
        f.znear = nearest - pad;
        f.zfar = far + pad;
        f.proj = glm::ortho(xl, xr, yb, yt, f.znear, f.zfar);
        fit.cascades.push_back(std::move(c));
    }
    if (why) why->clear();
    return fit;
}

int auto_cascade_count(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                       const glm::mat4& camera_view, const glm::mat4& camera_proj, std::string& why) {
    if (light.type != scene::LightType::Directional) {
        why = "one map: the light is not directional";
        return 1;
    }
    if (!perspective(camera_proj)) {
        why = "one map: the camera is orthographic (no perspective aliasing)";
        return 1;
    }
    float lo = 0.0f, hi = 0.0f;
    if (!depth_range(visible_receiver_points(light, receivers, camera_proj * camera_view), camera_view, camera_proj,
                     lo, hi)) {
        why = "one map: the camera sees no receiver";
        return 1;
    }
    const float ratio = hi / std::max(lo, 1e-6f);
    const int n = std::clamp(static_cast<int>(std::ceil(std::log(ratio) / std::log(8.0f) - 1e-4f)), 1, kMaxCascades);
    char b[160];
    std::snprintf(b, sizeof b, "%d %s: the receivers in view span view depths %.3g to %.3g (x%.3g; one map per x8)",
                  n, n == 1 ? "map" : "cascades", static_cast<double>(lo), static_cast<double>(hi),
                  static_cast<double>(ratio));
    why = b;
    return n;
}

}  // namespace penumbra::shadow
