// plan(): what every frame has (the camera's view, its target and its pass) around what the
// technique in use adds (plan/techniques/). No GL here.
#include "plan/plan.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "plan/frames/deferred.h"
#include "plan/frames/frame.h"
#include "plan/options.h"
#include "plan/post.h"
#include "plan/techniques/technique.h"
#include "scene/memory_budget.h"

namespace penumbra::render {

// In the browser the post passes (post_passes.cpp) are linked only where an exercise takes them
// (frame.h: image_post_shape).
PENUMBRA_WEAK_IN_PAGES void add_post_passes(PlanContext& c, int image, const TargetRef& out);

namespace {

constexpr float kAmbient = 0.25f;

bool valid_mesh(const scene::Scene& s, int mesh) { return mesh >= 0 && mesh < static_cast<int>(s.meshes.size()); }

// Output::copy_to: the image's region copied into a texture after everything else drew into it.
void add_copy_pass(PlanContext& c, const Output& out, const TargetRef& output) {
    if (out.copy_to.empty()) return;
    const int r = c.add_resource(
        texture_desc(Output::copied_texture(out.copy_to, out.width, out.height, out.sampling, out.wrap), c.caps, false),
        "", "filled by glCopyTexImage2D from the frame's image");
    Pass p;
    p.name = "copy-to-texture";
    p.module = "frame";
    p.target = output;
    p.object_uniforms = ObjectUniforms::None;
    p.copy_to = r;
    p.detail = "the " + std::to_string(out.width) + "x" + std::to_string(out.height) + " image copied into texture " +
               out.copy_to + " (glCopyTexImage2D, RGB)";
    c.add_pass(std::move(p));
}

}  // namespace

const scene::Material& material_of(const scene::Scene& s, int material) {
    static const scene::Material fallback{};
    if (material < 0 || material >= static_cast<int>(s.materials.size())) return fallback;
    return s.materials[static_cast<size_t>(material)];
}

bool casts(const scene::Scene& scene, const scene::Object& o, bool blend_shadows) {
    return o.casts_shadow && valid_mesh(scene, o.mesh) &&
           (blend_shadows || material_of(scene, o.material).alpha_mode != scene::AlphaMode::Blend);
}

CameraView camera_view(const scene::Scene& scene, const FrameInputs& in) {
    const scene::Camera& cam = scene.camera;
    CameraView v;
    v.view = in.view ? *in.view : cam.view;
    const float aspect =
        cam.aspect > 0.0f ? cam.aspect : static_cast<float>(in.output.width) / static_cast<float>(in.output.height);
    v.proj = in.projection ? *in.projection : glm::perspective(cam.yfov, aspect, cam.znear, cam.zfar);
    v.view_proj = v.proj * v.view;
    v.position = glm::vec3(glm::inverse(v.view)[3]);
    return v;
}

// ---- the context the modules plan in -----------------------------------------------------------

int PlanContext::add_resource(ResourceDesc desc, std::string content, std::string purpose) {
    if (const int i = plan.resource_index(desc.name); i >= 0) return i;
    PlannedResource r;
    r.reused = false;
    if (previous && !content.empty())
        if (const PlannedResource* before = previous->resource(desc.name))
            r.reused = before->desc == desc && before->content == content;
    r.desc = std::move(desc);
    r.content = std::move(content);
    r.purpose = std::move(purpose);
    plan.resources.push_back(std::move(r));
    return static_cast<int>(plan.resources.size()) - 1;
}

Pass& PlanContext::add_pass(Pass pass) {
    if (pass.target.resource >= 0) {
        const PlannedResource& r = plan.resources[static_cast<size_t>(pass.target.resource)];
        pass.skipped = r.reused;
        // A region with its own key (a cube face): reused when the last plan drew or kept the
        // same there, into a resource like this one (not made again since).
        if (!pass.skipped && !pass.content.empty() && previous)
            if (const PlannedResource* before = previous->resource(r.desc.name); before && before->desc == r.desc)
                pass.skipped = std::any_of(previous->passes.begin(), previous->passes.end(), [&](const Pass& q) {
                    return q.name == pass.name && q.content == pass.content;
                });
    }
    plan.passes.push_back(std::move(pass));
    return plan.passes.back();
}

Draw PlanContext::mesh_draw(int object) const {
    const scene::Object& o = scene.objects[static_cast<size_t>(object)];
    Draw d;
    d.object = object;
    d.label = o.name;
    d.mesh = o.mesh;
    d.world = o.world;
    d.beyond = beyond;
    return d;
}

AlphaTest PlanContext::caster_alpha(Draw& d) const {
    const int material = scene.objects[static_cast<size_t>(d.object)].material;
    const scene::Material& m = material_of(scene, material);
    if (m.alpha_mode == scene::AlphaMode::Opaque) return {};
    // BLEND reaches a shadow pass only under --blend-shadows: cut out at its cutoff there.
    d.material = material;
    d.alpha = true;
    if (m.base_color_texture >= 0 && m.base_color_texture < static_cast<int>(scene.images.size()) &&
        !scene.meshes[static_cast<size_t>(d.mesh)].uvs.empty())
        d.image = m.base_color_texture;
    return {true, d.image >= 0};
}

Draw PlanContext::object_draw(int object) {
    Draw d = mesh_draw(object);
    d.material = scene.objects[static_cast<size_t>(object)].material;
    for (const ObjectOverride& ov : inputs.objects)
        if (ov.object == object) {
            if (ov.mesh >= 0) d.mesh = ov.mesh;
            if (ov.material >= 0) d.material = ov.material;
        }
    const scene::Material& m = material_of(scene, d.material);
    if (m.double_sided) d.cull = gl::Cull::None;  // a leaf seen from below
    d.alpha = m.alpha_mode != scene::AlphaMode::Opaque;
    if (m.base_color_texture >= 0 && m.base_color_texture < static_cast<int>(scene.images.size()) &&
        !scene.meshes[static_cast<size_t>(d.mesh)].uvs.empty()) {
        d.image = m.base_color_texture;
        for (const ImageOverride& io : inputs.images)
            if (io.image == d.image)
                d.image_resource = add_resource(texture_desc(io.texture, caps, false), "",
                                                "sampled where the scene has image " + std::to_string(io.image));
    }
    return d;
}

LitFeatures PlanContext::base_features(const Draw& d) const {
    LitFeatures f;
    f.textured = d.image >= 0;
    const scene::Material& m = material_of(scene, d.material);
    f.alpha_test = m.alpha_mode == scene::AlphaMode::Mask;
    f.alpha_blend = m.alpha_mode == scene::AlphaMode::Blend;
    f.double_sided = m.double_sided;
    f.spot = light.type == scene::LightType::Spot;
    f.visibility_aov = settings.aov == Aov::Visibility;
    f.horizon = light_sample;
    f.derivatives = caps.standard_derivatives;
    return f;
}

glm::vec4 PlanContext::light_vector() const { return shadow::light_vector(light); }

std::vector<Binding> PlanContext::lit_bindings() const {
    std::vector<Binding> out;
    out.push_back({"camera",
                   {{"u_view_proj", plan.camera.view_proj},
                    {"u_camera_pos", plan.camera.position},
                    {"u_ambient", kAmbient},
                    {"u_light", light_vector()},
                    {"u_light_color", light.color}},
                   {}});
    if (light.type == scene::LightType::Spot)
        out.push_back({"spot light",
                       {{"u_spot_direction", glm::normalize(light.direction)},
                        {"u_spot_cos", glm::vec2(std::cos(light.spot_outer_cone), std::cos(light.spot_inner_cone))}},
                       {}});
    if (light_sample) out.push_back({"light sample", {{"u_light_size", 0.0f}}, {}});
    return out;
}

const StencilUse& PlanContext::stencil(std::string_view name) const {
    if (const StencilUse* u = plan.stencil_use(name)) return *u;
    throw std::logic_error("no stencil use '" + std::string(name) + "' declared in this frame");
}

// ---- checking and planning ---------------------------------------------------------------------

scene::Bounds shadowed_bounds(const scene::Scene& scene) {
    const std::vector<scene::Bounds> meshes = scene::all_mesh_bounds(scene);
    scene::Bounds b;
    for (const auto& o : scene.objects)
        if (valid_mesh(scene, o.mesh) && (o.casts_shadow || o.receives_shadow)) b.add(scene::object_bounds(meshes, o));
    return b;
}

ShadowBounds shadow_bounds(const scene::Scene& scene, bool blend_shadows) {
    const std::vector<scene::Bounds> meshes = scene::all_mesh_bounds(scene);
    ShadowBounds b;
    for (const auto& o : scene.objects) {
        if (!valid_mesh(scene, o.mesh)) continue;
        const int object = static_cast<int>(&o - scene.objects.data());
        if (o.receives_shadow) {
            b.receivers.push_back(scene::object_bounds(meshes, o));
            b.casting.receiver_objects.push_back(object);
        }
        if (casts(scene, o, blend_shadows)) {
            b.casters.push_back(scene::object_bounds(meshes, o));
            b.casting.caster_objects.push_back(object);
            b.casting.caster_convex.push_back(scene.meshes[static_cast<size_t>(o.mesh)].convex ? 1 : 0);
        }
    }
    return b;
}

std::vector<char> shadowing_casters(const PlanContext& c) {
    if (c.settings.light_fit != LightFit::Shadows) return std::vector<char>(c.casters.size(), 1);
    const ShadowBounds b = shadow_bounds(c.scene, c.settings.blend_shadows);
    return shadow::shadowing_flags(c.light, b.receivers, b.casters, c.plan.camera.view_proj, b.casting);
}

shadow::TightFit fit_to_view(const PlanContext& c, bool soft) {
    ShadowBounds b = shadow_bounds(c.scene, c.settings.blend_shadows);
    const glm::mat4& vp = c.plan.camera.view_proj;
    switch (c.settings.light_fit) {
        case LightFit::Shadows:
            b.casting.fit_window = !soft;
            return shadow::fit_light_frustum_shadows(c.light, b.receivers, b.casters, vp, b.casting);
        case LightFit::Tight: return shadow::fit_light_frustum_tight(c.light, b.receivers, b.casters, vp);
        case LightFit::Scene: break;
    }
    return shadow::fit_light_frustum_scene(c.light, b.receivers, b.casters, vp);
}

shadow::LightFrustum fit_light_view(const scene::Scene& scene, const scene::Light& light, const glm::mat4& camera_view_proj) {
    const ShadowBounds b = shadow_bounds(scene);
    return shadow::fit_light_frustum_tight(light, b.receivers, b.casters, camera_view_proj).frustum;
}

Planning::Planning(const scene::Scene& scene, const Settings& s, const gl::Caps& caps, const FrameInputs& in,
                   const FramePlan* previous)
    : ctx(PlanContext::of(scene, s, caps, in, previous, plan, in.light ? *in.light : scene.light)),
      module(technique_module(s.technique)) {
    plan.settings = s;
    plan.output = in.output.describe();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const auto& o = scene.objects[i];
        if (!valid_mesh(scene, o.mesh)) continue;
        const bool blend = material_of(scene, o.material).alpha_mode == scene::AlphaMode::Blend;
        (blend ? ctx.translucent : ctx.drawable).push_back(static_cast<int>(i));
        if (casts(scene, o, s.blend_shadows)) ctx.casters.push_back(static_cast<int>(i));
    }
    ctx.depth_path = {s.precision == shadow::Precision::Mediump, s.lab};
    if (s.light_radius) ctx.light.radius = *s.light_radius;
    plan.camera = camera_view(scene, in);
    // The mirror and the portal show surfaces: in the visibility AOV, the visibility of the surface
    // seen in the mirror or through the opening (what the bench scores against the effects' truth).
    // The outline is a colour, not a surface.
    for (Effect e : s.effects) {
        const bool shown = s.aov == Aov::Color || (s.aov == Aov::Visibility && e != Effect::Outline);
        if (!shown) {
            plan.notes.push_back("--effects " + std::string(to_string(e)) + ": drawn on --aov color" +
                                 (e == Effect::Outline ? "" : " and visibility") + " only, not on " +
                                 std::string(to_string(s.aov)));
            continue;
        }
        effects.push_back(&effect_module(e));
    }
}

namespace {

// The stencil uses of a module, each with its module's name.
std::vector<StencilUse> uses_of(const Module& m, const PlanContext& c) {
    std::vector<StencilUse> uses = m.stencil_uses(c);
    for (StencilUse& u : uses)
        if (u.module.empty()) u.module = std::string(m.name());
    return uses;
}

}  // namespace

std::string Planning::allocate() {
    plan.stencil = uses_of(module, ctx);
    technique_uses = plan.stencil.size();
    for (const Module* e : effects) {
        std::vector<StencilUse> more = uses_of(*e, ctx);
        plan.stencil.insert(plan.stencil.end(), more.begin(), more.end());
    }
    plan.stencil_bits = ctx.caps.stencil_bits;
    return allocate_stencil(plan.stencil, plan.stencil_bits);
}

std::string check(const scene::Scene& scene, const Settings& s, const gl::Caps& caps, const FrameInputs& in) {
    memory::Guard guard("planning the frame");
    const Output& out = in.output;
    const int max = caps.max_target_size();
    if (!out.window && (out.width > max || out.height > max))
        return "--size " + std::to_string(out.width) + "x" + std::to_string(out.height) + ": beyond this context's maximum of " + std::to_string(max);
    for (const ObjectOverride& ov : in.objects)
        if (ov.object < 0 || ov.object >= static_cast<int>(scene.objects.size()) ||
            (ov.mesh >= 0 && !valid_mesh(scene, ov.mesh)) || ov.material >= static_cast<int>(scene.materials.size()))
            return "an object override names an object, mesh or material the scene does not have";
    if (std::string why = aov_problem(s.technique, s.aov); !why.empty()) return why;
    if (s.lab)
        if (std::string why = lab_refusal(s); !why.empty()) return why;
    Planning p(scene, s, caps, in, nullptr);
    if (std::string why = shading_problem(p.ctx); !why.empty()) return why;
    if (std::string why = p.module.check(p.ctx); !why.empty()) return why;
    for (const Module* e : p.effects)
        if (std::string why = e->check(p.ctx); !why.empty()) return why;
    return p.allocate();
}

FramePlan plan(const scene::Scene& scene, const Settings& s, const gl::Caps& caps, const FrameInputs& in,
               const FramePlan* previous) {
    memory::Guard guard("planning the frame");
    Planning p(scene, s, caps, in, previous);
    PlanContext& c = p.ctx;
    const Output& out = in.output;
    if (const std::string problem = p.allocate(); !problem.empty())
        p.plan.notes.push_back(problem + " (check() refuses this frame)");
    const bool stencil = p.stencil();
    c.camera_target = {-1, out.width, out.height, out.x, out.y, out.clip};
    if (!out.window)
        c.camera_target = {c.add_resource(texture_desc(out, caps, stencil), "", "the camera's image"), out.width,
                           out.height, 0, 0, false};
    // --post blur, bloom: the camera draws into an image of its own, which the post passes read.
    const TargetRef output = c.camera_target;
    const bool post = image_post(s) && frame_shape_linked("image post");
    if (post)
        c.camera_target = {c.add_resource(texture_desc(Output::texture("post-scene", out.width, out.height,
                                                                       gl::Sampling::Linear, gl::Wrap::Clamp),
                                                       caps, stencil),
                                          "", "the camera's image before --post"),
                           out.width, out.height, 0, 0, false};
    plan_frame_shape(p);
    if (post) add_post_passes(c, c.camera_target.resource, output);
    add_copy_pass(c, out, output);
    return std::move(p.plan);
}

}  // namespace penumbra::render
