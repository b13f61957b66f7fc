// plan(): what every frame has (the camera's view, its target and its pass) around what the
// technique in use adds (render/techniques/). No GL here.
#include "render/plan.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "render/deferred.h"
#include "render/options.h"
#include "render/post.h"
#include "render/techniques/technique.h"
#include "shadow/area_light.h"

namespace penumbra::render {

namespace {

constexpr glm::vec4 kWhite{1.0f};
constexpr float kAmbient = 0.25f;

bool valid_mesh(const scene::Scene& s, int mesh) { return mesh >= 0 && mesh < static_cast<int>(s.meshes.size()); }

// The resource behind a texture output: colour, and depth (with stencil where a technique needs it).
ResourceDesc texture_desc(const Output& o, const gl::Caps& caps, bool stencil) {
    ResourceDesc d;
    d.name = o.name;
    d.width = o.width;
    d.height = o.height;
    if (!o.copied) d.depth_buffer = stencil ? caps.depth_stencil_format() : caps.depth_format();
    d.sampling = o.sampling;
    d.wrap = o.wrap;
    return d;
}

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
    return f;
}

glm::vec4 PlanContext::light_vector() const {
    return light.type == scene::LightType::Directional ? glm::vec4(-light.direction, 0.0f)
                                                        : glm::vec4(light.position, 1.0f);
}

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
    return out;
}

const StencilUse& PlanContext::stencil(std::string_view name) const {
    if (const StencilUse* u = plan.stencil_use(name)) return *u;
    throw std::logic_error("no stencil use '" + std::string(name) + "' declared in this frame");
}

// ---- checking and planning ---------------------------------------------------------------------

scene::Bounds shadowed_bounds(const scene::Scene& scene) {
    scene::Bounds b;
    for (const auto& o : scene.objects)
        if (valid_mesh(scene, o.mesh) && (o.casts_shadow || o.receives_shadow)) b.add(scene::object_bounds(scene, o));
    return b;
}

ShadowBounds shadow_bounds(const scene::Scene& scene, bool blend_shadows) {
    ShadowBounds b;
    for (const auto& o : scene.objects) {
        if (!valid_mesh(scene, o.mesh)) continue;
        if (o.receives_shadow) b.receivers.push_back(scene::object_bounds(scene, o));
        if (casts(scene, o, blend_shadows)) b.casters.push_back(scene::object_bounds(scene, o));
    }
    return b;
}

shadow::LightFrustum fit_light_view(const scene::Scene& scene, const scene::Light& light, const glm::mat4& camera_view_proj) {
    const ShadowBounds b = shadow_bounds(scene);
    return shadow::fit_light_frustum_tight(light, b.receivers, b.casters, camera_view_proj).frustum;
}

namespace {

// Everything plan() and check() share: the context with the scene's requirements gathered.
struct Planning {
    FramePlan plan;
    PlanContext ctx;
    const Module& module;
    std::vector<const Module*> effects;  // drawn on the colour image (the mirror and portal on visibility too)
    size_t technique_uses = 0;           // plan.stencil's first uses are the technique's (allocate)

    Planning(const scene::Scene& scene, const Settings& s, const gl::Caps& caps, const FrameInputs& in,
             const FramePlan* previous)
        : ctx{scene, s, caps, in, previous, plan, in.light ? *in.light : scene.light, {}, {}, {}, {}, {}, {}, false},
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
        ctx.depth_path = {s.precision == shadow::Precision::Mediump};
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

    // The stencil uses of the technique and the effects, each with its module's name.
    static std::vector<StencilUse> uses_of(const Module& m, const PlanContext& c) {
        std::vector<StencilUse> uses = m.stencil_uses(c);
        for (StencilUse& u : uses)
            if (u.module.empty()) u.module = std::string(m.name());
        return uses;
    }

    // Declares every use of the frame in the plan and gives each its bits: "" or why they do not fit.
    std::string allocate() {
        plan.stencil = uses_of(module, ctx);
        technique_uses = plan.stencil.size();
        for (const Module* e : effects) {
            std::vector<StencilUse> more = uses_of(*e, ctx);
            plan.stencil.insert(plan.stencil.end(), more.begin(), more.end());
        }
        plan.stencil_bits = ctx.caps.stencil_bits;
        return allocate_stencil(plan.stencil, plan.stencil_bits);
    }
};

// The camera pass into c.camera_target: every drawable object the module leaves in, shaded with
// the module's features; `extra` (may be null) adds features and bindings after the module's.
Pass camera_pass(PlanContext& c, const Module& module, bool stencil,
                 void (*extra)(PlanContext&, Pass&, std::vector<CameraItem>&) = nullptr) {
    Pass cam;
    cam.name = "camera";
    cam.module = "frame";
    cam.target = c.camera_target;
    cam.clear = Clear{c.settings.aov == Aov::Visibility ? kWhite : kBackground, true, stencil};
    cam.bindings = c.lit_bindings();
    std::vector<CameraItem> items;
    const std::uint32_t all = (1u << cam.bindings.size()) - 1u;
    for (int i : c.drawable) {
        if (module.keeps_out_of_camera(c, i)) continue;
        cam.draws.push_back(c.object_draw(i));
        items.push_back({i, c.base_features(cam.draws.back()), all});
    }
    cam.detail = c.plan.output + ", " + std::to_string(cam.draws.size()) + " object(s)";
    module.shade(c, cam, items);
    if (extra) extra(c, cam, items);
    forward_lights(c, cam, items);
    set_lit_draws(cam, items);
    if (c.settings.aov == Aov::Visibility) cam.detail += ", visibility AOV";
    return cam;
}

// The glTF BLEND objects (PlanContext::translucent) after everything else has been drawn into the
// camera's target: sorted back to front by the view depth of their bounds' centres, blended by
// their alpha over what is there, depth-tested against it but writing no depth (so one behind
// another still shows). The technique shades them where it can by a lookup (the shadow map, Gooch's
// texture); the stencil techniques' shadows are drawn already, so translucent objects get none of
// theirs. Not in the visibility or other AOVs: those show the opaque surfaces.
void blend_pass(PlanContext& c, const Module& module) {
    if (c.translucent.empty()) return;
    if (c.settings.aov != Aov::Color) {
        c.plan.notes.push_back(std::to_string(c.translucent.size()) + " translucent (BLEND) object(s) left out of --aov " +
                               std::string(to_string(c.settings.aov)));
        return;
    }
    std::vector<std::pair<float, int>> order;  // (view depth, object)
    for (int i : c.translucent) {
        const glm::vec3 centre = scene::object_bounds(c.scene, c.scene.objects[static_cast<size_t>(i)]).center();
        order.emplace_back(-(c.plan.camera.view * glm::vec4(centre, 1.0f)).z, i);
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    Pass p;
    p.name = "camera-blend";
    p.module = "frame";
    p.target = c.camera_target;
    p.state.depth_write = false;
    p.state.blend = gl::Blend::Alpha;
    p.bindings = c.lit_bindings();
    const std::uint32_t all = (1u << p.bindings.size()) - 1u;
    std::vector<CameraItem> items;
    std::string names;
    for (const auto& [depth, i] : order) {
        p.draws.push_back(c.object_draw(i));
        items.push_back({i, c.base_features(p.draws.back()), all});
        char b[48];
        std::snprintf(b, sizeof b, " (depth %.3g)", static_cast<double>(depth));
        names += (names.empty() ? "" : ", ") + p.draws.back().label + b;
    }
    p.detail = std::to_string(order.size()) + " translucent object(s) back to front: " + names +
               "; blend alpha, depth test, no depth writes";
    if (c.settings.technique != Technique::Volumes) module.shade(c, p, items);
    set_lit_draws(p, items);
    c.add_pass(std::move(p));
}

// ---- Heckbert and Herf: the technique run from points on the light, averaged -------------------

constexpr const char* kAreaSample = "area-sample";
constexpr const char* kAreaLight = "area-light";
constexpr int kAreaUnit = 0;

// Whether this frame is an area-light accumulation, and if not but asked for, why (a note).
bool area_applies(const PlanContext& c, std::string* why) {
    const Settings& s = c.settings;
    if (s.area_samples <= 1) return false;
    const auto no = [&](std::string w) {
        if (why) *why = "--area-samples " + std::to_string(s.area_samples) + ": " + std::move(w);
        return false;
    };
    if (s.technique == Technique::None) return no("no shadows to sample (--technique none)");
    if (s.technique == Technique::Gooch) return no("--technique gooch is soft by itself; its planes take the light's size");
    if (s.aov != Aov::Color && s.aov != Aov::Visibility)
        return no("--aov " + std::string(to_string(s.aov)) + " shows one hard sample, the light's centre");
    if (!(c.light.radius > 0.0f)) return no("the light has no radius (--light-radius), so one sample is the whole light");
    return true;
}

// Everything the accumulated visibility depends on: the camera, the light, every object, the
// settings (but how many samples a frame adds, and what is shown from them), the image's size.
std::string area_key(const PlanContext& c) {
    ContentKey key;
    key.add(c.plan.camera.view_proj);
    const scene::Light& l = c.light;
    key.add(l.type);
    key.add(l.position);
    key.add(l.direction);
    key.add(l.radius);
    key.add(l.spot_outer_cone);
    for (int i : c.drawable) {
        const scene::Object& o = c.scene.objects[static_cast<size_t>(i)];
        key.add_placement(c.scene, i);
        key.add(o.casts_shadow);
        key.add(o.receives_shadow);
    }
    for (int i : c.casters) key.add_placement(c.scene, i);  // BLEND casters too (--blend-shadows)
    Settings s = c.settings;
    s.area_per_frame = 0;
    s.aov = Aov::Color;
    const std::string args = to_args(s);
    key.add(args.data(), args.size());
    key.add(c.inputs.output.width);
    key.add(c.inputs.output.height);
    return key.str();
}

// The lit shader's screen-space visibility (AREA_LOOKUP) for every receiver of the camera pass:
// dot(the texel of `resource` under the pixel, `weights`), bound as `binding`.
void screen_lookup(PlanContext& c, Pass& cam, std::vector<CameraItem>& items, const char* resource,
                   const glm::vec4& weights, const char* binding) {
    const TargetRef& t = c.camera_target;
    const std::uint32_t bit = 1u << cam.bindings.size();
    cam.bindings.push_back({binding,
                            {{"u_area", kAreaUnit},
                             {"u_area_window", glm::vec4(static_cast<float>(t.x), static_cast<float>(t.y),
                                                         1.0f / static_cast<float>(t.width), 1.0f / static_cast<float>(t.height))},
                             {"u_area_weights", weights}},
                            {{kAreaUnit, c.plan.resource_index(resource)}}});
    for (CameraItem& it : items) {
        if (!c.receives(it.object)) continue;
        it.features.area_lookup = true;
        it.bindings |= bit;
    }
}

void area_lookup(PlanContext& c, Pass& cam, std::vector<CameraItem>& items) {
    const AreaStats& a = *c.plan.area;
    screen_lookup(c, cam, items, kAreaLight, glm::vec4(255.0f / static_cast<float>(std::max(a.done, 1))), "light samples");
    cam.detail += ", visibility averaged over " + std::to_string(a.done) + " of " + std::to_string(a.total) +
                  " light samples";
}

// The frame with --area-samples N: for each light sample not yet in the accumulation, the hard
// technique's visibility AOV from that point of the light into "area-sample" (its own passes:
// shadow map, stencil, volumes) and one count added where it is lit into "area-light"; then the
// camera pass shading with the average. A still frame's accumulation is kept; with area_per_frame
// K a frame adds at most K samples. `stencil`: the technique's passes use it (in "area-sample");
// `effect_stencil`: the effects do (in the camera's target, cleared by the last camera pass).
void plan_area(Planning& p, bool stencil, bool effect_stencil) {
    PlanContext& c = p.ctx;
    const Settings& s = c.settings;
    const Output& out = c.inputs.output;
    AreaStats a;
    a.total = s.area_samples;
    a.key = area_key(c);
    int start = 0;
    if (c.previous && c.previous->area && c.previous->area->key == a.key && c.previous->area->total == a.total)
        start = c.previous->area->done;
    a.done = s.area_per_frame > 0 ? std::min(a.total, start + s.area_per_frame) : a.total;
    a.added = a.done - start;
    p.plan.area = a;

    ResourceDesc acc;
    acc.name = kAreaLight;
    acc.width = out.width;
    acc.height = out.height;
    const int acc_r = c.add_resource(acc, a.key + "/" + std::to_string(a.done),
                                     "lit light samples counted per pixel (one channel per sample mod 4)");
    if (a.added > 0) {
        ResourceDesc one = texture_desc(Output::texture(kAreaSample, out.width, out.height, gl::Sampling::Nearest,
                                                        gl::Wrap::Clamp),
                                        c.caps, stencil);
        const int one_r = c.add_resource(one, "", "one light sample's visibility");
        Settings hard = s;
        hard.aov = Aov::Visibility;
        hard.area_samples = 1;
        // The light's axis: from it towards the middle of what casts and receives shadows.
        const scene::Bounds b = shadowed_bounds(c.scene);
        const glm::vec3 axis = c.light.type == scene::LightType::Directional || b.empty()
                                   ? c.light.direction
                                   : b.center() - c.light.position;
        for (int k = start; k < a.done; ++k) {
            // No previous plan: a sample's shadow map is never taken for another's.
            PlanContext sc{c.scene, hard, c.caps, c.inputs, nullptr, p.plan,
                           shadow::area_light_sample(c.light, k, axis), c.drawable, c.casters, c.depth_path,
                           {one_r, out.width, out.height, 0, 0, false}, {}, {}, false};
            p.module.before_camera(sc);
            Pass cam = camera_pass(sc, p.module, stencil);
            cam.name = "area-camera";
            c.add_pass(std::move(cam));
            p.module.after_camera(sc);

            Pass add;
            add.name = "area-add";
            add.module = "area";
            add.target = {acc_r, out.width, out.height, 0, 0, false};
            if (k == 0) add.clear = Clear{glm::vec4(0.0f), false, false};
            add.state.depth_test = add.state.depth_write = false;
            add.state.cull = gl::Cull::None;
            add.state.blend = gl::Blend::Add;
            add.object_uniforms = ObjectUniforms::None;
            glm::vec4 channel(0.0f);
            channel[k % 4] = 1.0f / 255.0f;
            add.bindings.push_back({"light sample", {{"u_sample", kAreaUnit}, {"u_channel", channel}}, {{kAreaUnit, one_r}}});
            Draw d;
            d.fullscreen = true;
            d.variant = area_add_variant();
            d.bindings = 1u;
            add.draws.push_back(std::move(d));
            char detail[96];
            std::snprintf(detail, sizeof detail, "light sample %d of %d counted in channel %c", k + 1, a.total,
                          "rgba"[k % 4]);
            add.detail = detail;
            c.add_pass(std::move(add));
        }
    }
    Pass cam = camera_pass(c, technique_module(Technique::None), effect_stencil, area_lookup);
    c.add_pass(std::move(cam));
    for (const Module* e : p.effects) e->after_opaque(c);
    blend_pass(c, technique_module(Technique::None));
    for (const Module* e : p.effects) e->after_camera(c);
    // The samples' resources (the shadow map) hold the last sample's content, not the first's
    // whose key they were declared with: nothing may reuse them.
    for (PlannedResource& r : p.plan.resources)
        if (r.desc.name != kAreaLight) r.content.clear();
}

// ---- the frame of one hard shadow -------------------------------------------------------------

void plan_frame(Planning& p, bool stencil) {
    PlanContext& c = p.ctx;
    p.module.before_camera(c);
    const bool own = p.module.own_view(c);
    if (!own) add_forward_light_passes(c, c.add_pass(camera_pass(c, p.module, stencil)));
    p.module.after_camera(c);
    if (!own) {
        for (const Module* e : p.effects) e->after_opaque(c);
        blend_pass(c, p.module);
    }
    for (const Module* e : p.effects) e->after_camera(c);
}

// ---- --post shadow-blur: the visibility blurred in screen space before shading -------------------

constexpr const char* kShadowVisibility = "shadow-visibility";

// Whether this frame blurs its shadow, and if not but asked for, why (a note). Under
// --area-samples the light samples' average is soft already (area_applies comes first).
bool shadow_blur_applies(const PlanContext& c, std::string* why) {
    const Settings& s = c.settings;
    const PostStep* step = s.post_step(PostKind::ShadowBlur);
    if (!step) return false;
    const auto no = [&](std::string w) {
        if (why) *why = "--post shadow-blur:" + shortest_float(step->value) + ": " + std::move(w);
        return false;
    };
    if (c.plan.area) return no("the light samples are averaged already (--area-samples)");
    if (s.technique == Technique::None) return no("no shadows to blur (--technique none)");
    if (s.technique == Technique::Gooch) return no("--technique gooch is soft by itself");
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
void plan_shadow_blur(Planning& p, bool stencil, bool effect_stencil) {
    PlanContext& c = p.ctx;
    const Output& out = c.inputs.output;
    Settings hard = c.settings;
    hard.aov = Aov::Visibility;
    const ResourceDesc vis_desc =
        texture_desc(Output::texture(kShadowVisibility, out.width, out.height, gl::Sampling::Nearest, gl::Wrap::Clamp),
                     c.caps, stencil);
    const int vis = c.add_resource(vis_desc, "", "the hard shadow's visibility, then blurred (--post shadow-blur)");
    PlanContext sc{c.scene, hard, c.caps, c.inputs, c.previous, p.plan, c.light, c.drawable, c.casters, c.depth_path,
                   {vis, out.width, out.height, 0, 0, false}, {}, {}, false};
    p.module.before_camera(sc);
    Pass hard_cam = camera_pass(sc, p.module, stencil);
    hard_cam.name = "shadow-visibility";
    c.add_pass(std::move(hard_cam));
    p.module.after_camera(sc);
    const int tmp = add_post_target(c, "shadow-blur-tmp", out.width, out.height, "--post shadow-blur: its first pass");
    add_blur_passes(c, "shadow-blur", vis, tmp, {vis, out.width, out.height, 0, 0, false},
                    static_cast<int>(c.settings.post_step(PostKind::ShadowBlur)->value));
    add_forward_light_passes(
        c, c.add_pass(camera_pass(c, technique_module(Technique::None), effect_stencil, screen_visibility_lookup)));
    for (const Module* e : p.effects) e->after_opaque(c);
    blend_pass(c, p.module);
    for (const Module* e : p.effects) e->after_camera(c);
}

}  // namespace

std::string check(const scene::Scene& scene, const Settings& s, const gl::Caps& caps, const FrameInputs& in) {
    const Output& out = in.output;
    const int max = caps.max_target_size();
    if (!out.window && (out.width > max || out.height > max))
        return "--size " + std::to_string(out.width) + "x" + std::to_string(out.height) + ": beyond this context's maximum of " + std::to_string(max);
    for (const ObjectOverride& ov : in.objects)
        if (ov.object < 0 || ov.object >= static_cast<int>(scene.objects.size()) ||
            (ov.mesh >= 0 && !valid_mesh(scene, ov.mesh)) || ov.material >= static_cast<int>(scene.materials.size()))
            return "an object override names an object, mesh or material the scene does not have";
    if (s.aov == Aov::LightDepth && s.technique != Technique::ShadowMap)
        return "--aov light-depth: needs --technique shadowmap";
    if (s.aov == Aov::StencilCount && s.technique != Technique::Volumes)
        return "--aov stencil-count: needs --technique volumes";
    if (s.aov == Aov::Cascades && s.technique != Technique::ShadowMap)
        return "--aov cascades: needs --technique shadowmap";
    Planning p(scene, s, caps, in, nullptr);
    if (std::string why = shading_problem(p.ctx); !why.empty()) return why;
    if (std::string why = p.module.check(p.ctx); !why.empty()) return why;
    for (const Module* e : p.effects)
        if (std::string why = e->check(p.ctx); !why.empty()) return why;
    return p.allocate();
}

FramePlan plan(const scene::Scene& scene, const Settings& s, const gl::Caps& caps, const FrameInputs& in,
               const FramePlan* previous) {
    Planning p(scene, s, caps, in, previous);
    PlanContext& c = p.ctx;
    const Output& out = in.output;
    if (const std::string problem = p.allocate(); !problem.empty())
        p.plan.notes.push_back(problem + " (check() refuses this frame)");
    const bool technique_stencil = p.technique_uses > 0;
    const bool effect_stencil = p.plan.stencil.size() > p.technique_uses;
    const bool stencil = !p.plan.stencil.empty();
    c.camera_target = {-1, out.width, out.height, out.x, out.y, out.clip};
    if (!out.window)
        c.camera_target = {c.add_resource(texture_desc(out, caps, stencil), "", "the camera's image"), out.width,
                           out.height, 0, 0, false};
    // --post blur, bloom: the camera draws into an image of its own, which the post passes read.
    const TargetRef output = c.camera_target;
    if (image_post(s))
        c.camera_target = {c.add_resource(texture_desc(Output::texture("post-scene", out.width, out.height,
                                                                       gl::Sampling::Linear, gl::Wrap::Clamp),
                                                       caps, stencil),
                                          "", "the camera's image before --post"),
                           out.width, out.height, 0, 0, false};

    if (s.shading == Shading::Deferred) {
        plan_deferred(c, p.module);
        if (image_post(s)) add_post_passes(c, c.camera_target.resource, output);
        add_copy_pass(c, out, output);
        return std::move(p.plan);
    }
    std::string why;
    if (area_applies(c, &why)) {
        plan_area(p, technique_stencil, effect_stencil);
    } else if (!why.empty()) {
        p.plan.notes.push_back(why);
    }
    std::string blur_why;
    if (!p.plan.area && shadow_blur_applies(c, &blur_why)) {
        plan_shadow_blur(p, technique_stencil, effect_stencil);
    } else if (!p.plan.area) {
        plan_frame(p, stencil);
    }
    if (!blur_why.empty()) p.plan.notes.push_back(blur_why);
    if (image_post(s)) add_post_passes(c, c.camera_target.resource, output);
    add_copy_pass(c, out, output);
    return std::move(p.plan);
}

}  // namespace penumbra::render
