// --post shadow-blur, a frame shape (frame.h): the technique's visibility blurred in screen space
// before shading (a cheap soft shadow). No GL here.
#include "plan/frames/area_light.h"
#include "plan/frames/deferred.h"
#include "plan/frames/frame.h"
#include "plan/options.h"
#include "plan/post.h"

namespace penumbra::render {

namespace {

constexpr const char* kShadowVisibility = "shadow-visibility";

// Whether this frame blurs its shadow, and if not but asked for, why (a note). Under
// --area-samples the light samples' average is soft already (area_applies comes first).
bool shadow_blur_applies(const PlanContext& c, std::string* why) {
    const Settings& s = c.settings;
    if (s.shading == Shading::Deferred) return false;
    const PostStep* step = s.post_step(PostKind::ShadowBlur);
    if (!step) return false;
    const auto no = [&](std::string w) {
        if (why) *why = "--post shadow-blur:" + shortest_float(step->value) + ": " + std::move(w);
        return false;
    };
    if (area_of(c.plan)) return no("the light samples are averaged already (--area-samples)");
    const Module& m = technique_module(s.technique);
    const std::string technique = "--technique " + std::string(m.name());
    if (!m.shadows()) return no("no shadows to blur (" + technique + ")");
    if (!m.soft_by_itself().empty()) return no(technique + " is soft by itself");
    if (s.aov != Aov::Color && s.aov != Aov::Visibility)
        return no("--aov " + std::string(to_string(s.aov)) + " shows the technique's own view");
    return true;
}

void screen_visibility_lookup(PlanContext& c, Pass& cam, std::vector<CameraItem>& items) {
    screen_lookup(c, cam, items, kShadowVisibility, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f), "blurred visibility");
    cam.detail += ", visibility from " + std::string(kShadowVisibility) + " blurred in screen space";
}

// The technique's visibility AOV into "shadow-visibility" (its own passes: shadow map, stencil,
// volumes), blurred there through "shadow-blur-tmp", and the camera pass shading with it. The
// effects after it are the technique's (shade_after_camera): hard where they look the map up.
void plan_shadow_blur(Planning& p) {
    PlanContext& c = p.ctx;
    const Output& out = c.inputs.output;
    Settings hard = c.settings;
    hard.aov = Aov::Visibility;
    const ResourceDesc vis_desc =
        texture_desc(Output::texture(kShadowVisibility, out.width, out.height, gl::Sampling::Nearest, gl::Wrap::Clamp),
                     c.caps, p.technique_stencil());
    const int vis = c.add_resource(vis_desc, "", "the hard shadow's visibility, then blurred (--post shadow-blur)");
    plan_hard_visibility(p, hard, c.light, c.previous, {vis, out.width, out.height, 0, 0, false}, "shadow-visibility");
    const int tmp = add_post_target(c, "shadow-blur-tmp", out.width, out.height, "--post shadow-blur: its first pass");
    add_blur_passes(c, "shadow-blur", vis, tmp, {vis, out.width, out.height, 0, 0, false},
                    static_cast<int>(c.settings.post_step(PostKind::ShadowBlur)->value));
    add_forward_light_passes(
        c, c.add_pass(camera_pass(c, unshadowed_module(), p.effect_stencil(), screen_visibility_lookup)));
    for (const Module* e : p.effects) e->after_opaque(c);
    blend_pass(c, p.module);
    for (const Module* e : p.effects) e->after_camera(c);
}

}  // namespace

const FrameShape& shadow_blur_shape() {
    static const FrameShape shape{"shadow blur", shadow_blur_applies, plan_shadow_blur};
    return shape;
}

}  // namespace penumbra::render
