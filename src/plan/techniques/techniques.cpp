// The technique modules by Technique value, the module of no shadows, and the content key.
#include <cstdio>
#include <stdexcept>

#include "plan/techniques/technique.h"

#include "plan/frames/area_light.h"
#include "plan/frames/frame.h"
#include "plan/post.h"

namespace penumbra::render {

// In the browser a page's module links a technique's code only where its exercise names the module
// (Exercise::modules); the others are null here.
PENUMBRA_WEAK_IN_PAGES const Module& shadow_map_module();
PENUMBRA_WEAK_IN_PAGES const Module& planar_module();
PENUMBRA_WEAK_IN_PAGES const Module& volumes_module();
PENUMBRA_WEAK_IN_PAGES const Module& gooch_module();
PENUMBRA_WEAK_IN_PAGES const Module& outline_module();
PENUMBRA_WEAK_IN_PAGES const Module& mirror_module();
PENUMBRA_WEAK_IN_PAGES const Module& portal_module();

namespace {

using Getter = const Module& (*)();

Getter technique_getter(Technique t) {
    switch (t) {
        case Technique::ShadowMap: return &shadow_map_module;
        case Technique::Planar: return &planar_module;
        case Technique::Volumes: return &volumes_module;
        case Technique::Gooch: return &gooch_module;
        case Technique::None: return &unshadowed_module;
    }
    return &unshadowed_module;
}

Getter effect_getter(Effect e) {
    switch (e) {
        case Effect::Outline: return &outline_module;
        case Effect::Mirror: return &mirror_module;
        case Effect::Portal: return &portal_module;
    }
    return &outline_module;
}

std::string not_linked(std::string_view option, std::string_view value) {
    return "--" + std::string(option) + " " + std::string(value) +
           ": not in this page's code (each page loads only what it offers; an exercise page that offers it has it)";
}

class NoShadows : public Module {
public:
    std::string_view name() const override { return "none"; }
    void shade(PlanContext&, Pass& cam, std::vector<CameraItem>&) const override { cam.detail += ", no shadows"; }
    bool shadows() const override { return false; }
    bool shades_deferred() const override { return true; }
};

const NoShadows kNone;

}  // namespace

bool technique_linked(Technique t) { return technique_getter(t) != nullptr; }
bool effect_linked(Effect e) { return effect_getter(e) != nullptr; }

std::string unlinked_problem(const Settings& s, std::string_view option) {
    if (option == "technique" && !technique_linked(s.technique)) return not_linked(option, to_string(s.technique));
    if (option == "effects")
        for (Effect e : s.effects)
            if (!effect_linked(e)) return not_linked(option, to_string(e));
    // The frame shapes a page may lack (frame.h): the light samples' average, deferred shading, the
    // blurred visibility.
    if (option == "area-samples" && s.area_samples > 1 && !frame_shape_linked("area light"))
        return not_linked(option, std::to_string(s.area_samples));
    if (option == "shading" && s.shading == Shading::Deferred && !frame_shape_linked("deferred"))
        return not_linked(option, to_string(s.shading));
    if (option == "post" && s.post_step(PostKind::ShadowBlur) && !frame_shape_linked("shadow blur"))
        return not_linked(option, "shadow-blur");
    if (option == "post" && image_post(s) && !frame_shape_linked("image post")) return not_linked(option, post_text(s.post));
    return {};
}

const Module& technique_module(Technique t) {
    const Getter g = technique_getter(t);
    if (!g) throw std::invalid_argument(not_linked("technique", to_string(t)));
    return g();
}

const Module& unshadowed_module() { return kNone; }

const std::vector<ReportSlot>& report_slots() {
    // The shadow map's (Gooch's texture has a light frustum too), the volumes', the light samples'.
    static const std::vector<ReportSlot> slots{{"light_frustum", "null"},
                                               {"cascades", "{\"why\":\"\",\"list\":[]}"},
                                               {"cube", "null"},
                                               {"volumes", "null"},
                                               {"area", "null"}};
    return slots;
}

std::string aov_problem(Technique t, Aov aov) {
    if (technique_module(t).own_aov(aov)) return {};
    for (Technique other : kAllTechniques)
        if (technique_linked(other) && technique_module(other).own_aov(aov))
            return "--aov " + std::string(to_string(aov)) + ": needs --technique " + std::string(to_string(other));
    return {};
}

std::string techniques_that(bool (Module::*question)() const) {
    std::string names;
    for (Technique t : kAllTechniques)
        if (technique_linked(t) && (technique_module(t).*question)()) names += (names.empty() ? "" : " or ") + std::string(to_string(t));
    return "--technique " + names;
}

const Module& effect_module(Effect e) {
    const Getter g = effect_getter(e);
    if (!g) throw std::invalid_argument(not_linked("effects", to_string(e)));
    return g();
}

void set_lit_draws(Pass& p, const std::vector<CameraItem>& items) {
    for (size_t k = 0; k < items.size(); ++k) {
        p.draws[k].variant = lit_variant(items[k].features);
        p.draws[k].bindings = items[k].bindings;
    }
}

std::string shade_after_camera(PlanContext& c, Pass& p, std::vector<CameraItem>& items) {
    if (area_of(c.plan)) return "the light samples are averaged for the camera pass's pixels";
    const Module& m = technique_module(c.settings.technique);
    if (const std::string_view why = m.later_pass_problem(); !why.empty()) return std::string(why);
    m.shade(c, p, items);
    return {};
}

std::string stencil_buffer_problem(const PlanContext& c, std::string_view who) {
    // With --post blur or bloom the camera draws into a texture even when the output is a window.
    if ((c.inputs.output.window && !image_post(c.settings)) || c.caps.packed_depth_stencil) return {};
    return std::string(who) + ": this context has no OES_packed_depth_stencil for the stencil buffer";
}

StencilUse marking_use(std::string name, std::string module) {
    StencilUse u;
    u.name = std::move(name);
    u.module = std::move(module);
    u.bits = 1;
    return u;
}

Pass far_plane_pass(const PlanContext& c, std::string name, std::string module, const StencilUse& use, int value,
                    const glm::vec4& colour) {
    Pass p;
    p.name = std::move(name);
    p.module = std::move(module);
    p.target = c.camera_target;
    p.state.cull = gl::Cull::None;
    p.state.depth_func = gl::Compare::Always;
    p.state.stencil = use.test(gl::Compare::Equal, value);
    p.object_uniforms = ObjectUniforms::None;
    p.bindings.push_back({"colour", {{"u_value", colour}}, {}});
    Draw d;
    d.fullscreen = true;
    d.variant = far_plane_variant();
    d.bindings = 1u;
    p.draws.push_back(std::move(d));
    return p;
}

void ContentKey::add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
        h_ ^= p[i];
        h_ *= 1099511628211ull;
    }
}

std::string ContentKey::str() const {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
    return buf;
}

}  // namespace penumbra::render
