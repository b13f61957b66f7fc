#include "plan/frames/deferred.h"
#include "plan/frames/frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "plan/lights.h"
#include "plan/post.h"

namespace penumbra::render {

namespace {

constexpr glm::vec4 kWhite{1.0f};
// The G-buffer's texture units in the lighting passes (the shadow map and the base texture take
// the first ones).
constexpr int kGbufferUnit = 4;
const char* const kTargetNames[3] = {"gbuffer-color", "gbuffer-normal", "gbuffer-depth"};
const char* const kTargetWhat[3] = {"the base colour, specular in alpha", "the normal, octahedral, 2 x 16 bits",
                                    "the depth along the pixel's ray (24 bits), shininess and receives-shadows"};

// The G-buffer's depth: s = dot(xyz, world) + w, 0 on the near plane, 1 on the far one.
glm::vec4 depth_map(const CameraView& cam, float n, float f) {
    const glm::mat4& v = cam.view;
    const float k = 1.0f / (f - n);
    // The view depth -(V p).z, an affine function of the world point.
    return glm::vec4(-v[0][2] * k, -v[1][2] * k, -v[2][2] * k, (-v[3][2] - n) * k);
}


// The binding that reads the G-buffer in a pass whose viewport starts at `target`'s corner.
Binding gbuffer_binding(const PlanContext& c, const int (&targets)[3], bool mrt, const TargetRef& target) {
    Binding b{"g-buffer",
              {{"u_gbuffer_color", kGbufferUnit},
               {"u_gbuffer_normal", kGbufferUnit + 1},
               {"u_gbuffer_depth", kGbufferUnit + 2},
               {"u_screen", glm::vec4(static_cast<float>(target.x), static_cast<float>(target.y),
                                      1.0f / static_cast<float>(target.width), 1.0f / static_cast<float>(target.height))},
               {"u_inv_view_proj", glm::inverse(c.plan.camera.view_proj)}},
              {}};
    for (int i = 0; i < 3; ++i) b.textures.push_back({kGbufferUnit + i, targets[i], mrt ? i : 0});
    return b;
}


// --aov gbuffer-*: one target decoded into the camera's target.
void add_view_pass(PlanContext& c, const Binding& gbuffer) {
    const Settings& s = c.settings;
    Pass v = screen_pass("gbuffer-view", "deferred", c.camera_target);
    v.clear = Clear{kBackground, true, false};
    scene::Bounds b = shadowed_bounds(c.scene);
    if (b.empty()) b = scene::Bounds::around(glm::vec3(-1.0f), glm::vec3(1.0f));
    // The depth view: the shadowed objects' range of ray depths, near white, far black.
    float n = 0.0f, f = 1.0f, lo = 1.0f, hi = 0.0f;
    near_far(c.plan.camera.proj, n, f);
    const glm::vec4 map = depth_map(c.plan.camera, n, f);
    for (const glm::vec3& p : scene::corners(b)) {
        const float d = std::clamp(glm::dot(glm::vec3(map), p) + map.w, 0.0f, 1.0f);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    v.bindings = {gbuffer,
                  {"view",
                   {{"u_bounds_min", b.min},
                    {"u_bounds_size", glm::max(b.max - b.min, glm::vec3(1e-6f))},
                    {"u_view_range", glm::vec2(lo, 1.0f / std::max(hi - lo, 1e-6f))}},
                   {}}};
    Draw d;
    d.fullscreen = true;
    d.label = "full screen";
    d.variant = gbuffer_view_variant(s.aov);
    d.bindings = 3u;
    v.draws.push_back(d);
    v.detail = "the G-buffer decoded: " + std::string(to_string(s.aov));
    c.add_pass(std::move(v));
}

}  // namespace


void plan_deferred(PlanContext& c, const Module& module) {
    const Settings& s = c.settings;
    module.before_camera(c);
    if (module.own_view(c)) return;
    const int w = c.inputs.output.width, h = c.inputs.output.height;
    const bool mrt = c.caps.draw_buffers;
    c.plan.notes.push_back(mrt ? "G-buffer: three colour attachments drawn in one pass (draw buffers)"
                               : "G-buffer: one pass per target (this context has no EXT_draw_buffers / WEBGL_draw_buffers)");

    // The geometry: every object once (or once per target) into the G-buffer.
    ResourceDesc d;
    d.width = w;
    d.height = h;
    d.depth_buffer = c.caps.depth_format();
    int targets[3] = {-1, -1, -1};
    if (mrt) {
        d.name = c.named("gbuffer");
        d.colors = 3;
        targets[0] = targets[1] = targets[2] =
            c.add_resource(d, "", "the G-buffer: colour and specular; normal (octahedral, 2 x 16 bits); depth along "
                                  "the ray (24 bits), shininess, receives-shadows");
    } else {
        for (int i = 0; i < 3; ++i) {
            d.name = c.named(kTargetNames[i]);
            targets[i] = c.add_resource(d, "", std::string("the G-buffer: ") + kTargetWhat[i]);
        }
    }
    float n = 0.0f, f = 1.0f;
    near_far(c.plan.camera.proj, n, f);
    const Binding camera = c.lit_bindings().front();
    const bool shadowed = module.shadows();
    for (int t = 0; t < (mrt ? 1 : 3); ++t) {
        Pass g;
        g.name = mrt ? "gbuffer" : kTargetNames[t];
        g.module = "deferred";
        g.target = {targets[t], w, h, 0, 0, false};
        g.clear = Clear{kWhite, true, false};  // all ones: no surface
        g.bindings = {camera, {"g-buffer write", {{"u_depth_map", depth_map(c.plan.camera, n, f)}}, {}}};
        for (int i : c.drawable) {
            if (module.keeps_out_of_camera(c, i)) continue;
            Draw draw = c.object_draw(i);
            LitFeatures lf = c.base_features(draw);
            lf.visibility_aov = lf.spot = false;
            lf.gbuffer = mrt ? Gbuffer::WriteAll : Gbuffer::WriteOne;
            lf.gbuffer_target = t;
            lf.receives = shadowed && c.receives(i);
            draw.variant = lit_variant(lf);
            draw.bindings = 3u;
            g.draws.push_back(std::move(draw));
        }
        g.detail = count_text(static_cast<int>(g.draws.size()), "object") +
                   (mrt ? std::string(" into 3 targets at once") : std::string(" into ") + kTargetWhat[t]);
        c.add_pass(std::move(g));
    }

    if (gbuffer_aov(s.aov)) {
        add_view_pass(c, gbuffer_binding(c, targets, mrt, c.camera_target));
        return;
    }

    // The lighting: the main light (and its shadow) over every pixel, then each point light over
    // its square, summed in half floats where the context renders them.
    const bool points = s.lights > 0 && s.aov == Aov::Color;
    TargetRef lit = c.camera_target;
    int sum = -1;
    if (points && c.caps.half_float_target) {
        sum = add_post_target(c, "deferred-light", w, h, "the lit image, summed light by light in half floats");
        lit = {sum, w, h, 0, 0, false};
    }
    const Binding gbuffer = gbuffer_binding(c, targets, mrt, lit);
    Pass main = screen_pass("deferred-light", "deferred", lit);
    main.clear = Clear{s.aov == Aov::Visibility ? kWhite : kBackground, true, false};
    main.bindings = c.lit_bindings();
    // screen.vert places the triangle itself: the camera's matrix is the g-buffer binding's inverse.
    std::vector<Uniform>& cam = main.bindings.front().uniforms;
    cam.erase(std::remove_if(cam.begin(), cam.end(), [](const Uniform& u) { return u.name == "u_view_proj"; }), cam.end());
    main.bindings.push_back(gbuffer);
    Draw full;
    full.fullscreen = true;
    full.label = "full screen";
    main.draws.push_back(full);
    LitFeatures lf;
    lf.gbuffer = Gbuffer::Read;
    lf.spot = c.light.type == scene::LightType::Spot;
    lf.visibility_aov = s.aov == Aov::Visibility;
    std::vector<CameraItem> items{{-1, lf, (1u << main.bindings.size()) - 1u}};
    main.detail = "the main light over every pixel of the G-buffer";
    module.shade(c, main, items);
    set_lit_draws(main, items);
    c.add_pass(std::move(main));

    if (points) {
        Pass p = screen_pass("deferred-points", "deferred", lit);
        p.state.blend = gl::Blend::Add;
        p.bindings = {gbuffer};
        LitFeatures pf;
        pf.gbuffer = Gbuffer::Read;
        pf.point_lights = 1;
        pf.points_only = true;
        const Variant variant = lit_variant(pf);
        const std::vector<PointLight> lights = point_lights(c.scene, s.lights);
        double covered = 0.0;
        for (size_t i = 0; i < lights.size(); ++i) {
            const glm::vec4 q = screen_square(c.plan.camera.view_proj, lights[i].position, lights[i].range);
            if (q.x >= q.z || q.y >= q.w) continue;  // off screen
            covered += 0.25 * static_cast<double>((q.z - q.x) * (q.w - q.y));
            Draw dl;
            dl.label = "light " + std::to_string(i + 1);
            dl.triangles = std::make_shared<std::vector<glm::vec4>>(std::vector<glm::vec4>{
                {q.x, q.y, 0.0f, 1.0f}, {q.z, q.y, 0.0f, 1.0f}, {q.z, q.w, 0.0f, 1.0f},
                {q.x, q.y, 0.0f, 1.0f}, {q.z, q.w, 0.0f, 1.0f}, {q.x, q.w, 0.0f, 1.0f}});
            dl.variant = variant;
            dl.bindings = 1u;
            dl.uniforms = light_uniforms(lights, i, 1);
            p.draws.push_back(std::move(dl));
        }
        char what[160];
        std::snprintf(what, sizeof what, "%zu of %zu point light(s) on screen, each over its range's square, added (%.2f screens in all)",
                      p.draws.size(), lights.size(), covered);
        p.detail = what;
        c.add_pass(std::move(p));
    }
    if (sum >= 0)
        c.add_pass(image_pass(c, "deferred-resolve", sum, c.camera_target, bright_variant(), {{"u_threshold", 0.0f}},
                              "the summed light into the output"));
}

namespace {

bool deferred_applies(const PlanContext& c, std::string*) { return c.settings.shading == Shading::Deferred; }
void plan_deferred_frame(Planning& p) { plan_deferred(p.ctx, p.module); }

}  // namespace

const FrameShape& deferred_shape() {
    static const FrameShape shape{"deferred", deferred_applies, plan_deferred_frame};
    return shape;
}

}  // namespace penumbra::render
