// What the forward frame shares with the deferred one (deferred.h): the point lights' uniforms
// and passes over a forward camera pass, the checks of --shading and --lights, the screen square
// of a light's reach. The deferred frame itself is deferred.cpp, which a browser page links only
// where its exercise names the shape (frame.h: deferred_shape).
#include "plan/frames/deferred.h"
#include "plan/frames/frame.h"

#include <algorithm>
#include <cmath>

#include "plan/lights.h"

namespace penumbra::render {

bool near_far(const glm::mat4& proj, float& n, float& f) {
    const glm::mat4 inv = glm::inverse(proj);
    const glm::vec4 a = inv * glm::vec4(0.0f, 0.0f, -1.0f, 1.0f);
    const glm::vec4 b = inv * glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
    if (std::abs(a.w) < 1e-20f || std::abs(b.w) < 1e-20f) return false;
    n = -a.z / a.w;
    f = -b.z / b.w;
    return std::isfinite(n) && std::isfinite(f) && f > n;
}

std::string count_text(int n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

std::vector<Uniform> light_uniforms(const std::vector<PointLight>& lights, size_t first, size_t count) {
    std::vector<Uniform> u;
    for (size_t k = 0; k < count; ++k) {
        const PointLight& l = lights[first + k];
        u.push_back({"u_point_lights[" + std::to_string(2 * k) + "]", glm::vec4(l.position, l.range)});
        u.push_back({"u_point_lights[" + std::to_string(2 * k + 1) + "]", glm::vec4(l.color, 0.0f)});
    }
    return u;
}

glm::vec4 screen_square(const glm::mat4& view_proj, const glm::vec3& centre, float radius) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner =
            centre + radius * glm::vec3((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
        const glm::vec4 q = view_proj * glm::vec4(corner, 1.0f);
        if (q.w <= 1e-6f) return glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f);  // reaches the camera's plane: all of it
        const glm::vec2 p = glm::vec2(q) / q.w;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    lo = glm::max(lo, glm::vec2(-1.0f));
    hi = glm::min(hi, glm::vec2(1.0f));
    return glm::vec4(lo, hi);
}

std::string shading_problem(const PlanContext& c) {
    const Settings& s = c.settings;
    const bool deferred = s.shading == Shading::Deferred;
    if (gbuffer_aov(s.aov) && !deferred) return "--aov " + std::string(to_string(s.aov)) + ": needs --shading deferred";
    if (s.lights > 0 || deferred) {
        const std::string who = deferred ? "--shading deferred" : "--lights " + std::to_string(s.lights);
        if (!technique_module(s.technique).shades_deferred())
            return who + ": with " + techniques_that(&Module::shades_deferred) + " (" + std::string(to_string(s.technique)) +
                   " shades the shadowed pixels again, by the main light alone)";
        if (s.area_samples > 1) return who + ": not with --area-samples (the samples average the main light alone)";
        for (Effect e : s.effects)
            if (deferred || e != Effect::Outline)
                return who + ": not with --effects " + std::string(to_string(e)) +
                       (deferred ? " (the effects draw forward into the lit image)" : " (lit by the main light alone)");
    }
    if (!deferred) return {};
    if (s.post_step(PostKind::ShadowBlur))
        return "--shading deferred: not with --post shadow-blur (the lighting pass looks the shadow map up itself)";
    if (!c.translucent.empty())
        return "--shading deferred: the scene has " + count_text(static_cast<int>(c.translucent.size()), "translucent (BLEND) object") +
               ", which a G-buffer of one surface per pixel cannot hold";
    if (!c.caps.fragment_highp)
        return "--shading deferred: the G-buffer's 24-bit depth and 16-bit normals need highp floats in fragment "
               "shaders, which this context lacks";
    float n = 0.0f, f = 0.0f;
    if (!near_far(c.plan.camera.proj, n, f)) return "--shading deferred: the camera's projection has no finite far plane";
    return {};
}

void forward_lights(PlanContext& c, Pass& cam, std::vector<CameraItem>& items) {
    const Settings& s = c.settings;
    if (s.lights <= 0 || s.aov != Aov::Color) return;
    const std::vector<PointLight> lights = point_lights(c.scene, s.lights);
    const size_t k = std::min(lights.size(), static_cast<size_t>(kLightsPerPass));
    cam.bindings.push_back({"point lights 1-" + std::to_string(k), light_uniforms(lights, 0, k), {}});
    const std::uint32_t bit = 1u << (cam.bindings.size() - 1);
    for (CameraItem& it : items) {
        it.features.point_lights = static_cast<int>(k);
        it.bindings |= bit;
    }
    cam.detail += ", " + count_text(static_cast<int>(k), "point light");
}

void add_forward_light_passes(PlanContext& c, const Pass& camera) {
    const Settings& s = c.settings;
    if (s.lights <= kLightsPerPass || s.aov != Aov::Color) return;
    const Pass cam = camera;
    const std::vector<PointLight> lights = point_lights(c.scene, s.lights);
    for (size_t first = kLightsPerPass; first < lights.size(); first += kLightsPerPass) {
        const size_t k = std::min(lights.size() - first, static_cast<size_t>(kLightsPerPass));
        const std::string range = std::to_string(first + 1) + "-" + std::to_string(first + k);
        Pass p;
        p.name = "lights-" + range;
        p.module = "lights";
        p.target = cam.target;
        p.state = cam.state;
        p.state.depth_func = gl::Compare::Equal;
        p.state.depth_write = false;
        p.state.blend = gl::Blend::Add;
        p.state.stencil = {};
        p.bindings = {cam.bindings.front(), {"point lights " + range, light_uniforms(lights, first, k), {}}};
        for (Draw d : cam.draws) {
            LitFeatures f = c.base_features(d);
            f.visibility_aov = false;
            f.point_lights = static_cast<int>(k);
            f.points_only = true;
            d.variant = lit_variant(f);
            d.bindings = 3u;
            p.draws.push_back(std::move(d));
        }
        p.detail = count_text(static_cast<int>(k), "point light") + " over the camera pass's surfaces (depth equal), added";
        c.add_pass(std::move(p));
    }
}

}  // namespace penumbra::render
