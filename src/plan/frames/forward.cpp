// The frame of one hard shadow (the forward shape) and what every shape shares: the camera pass,
// the translucent objects' pass, the screen-space lookup, the hard visibility of a sample; and
// plan_frame_shape, the one entry to the shapes. No GL here.
#include <algorithm>
#include <cstdio>

#include "plan/frames/deferred.h"
#include "plan/frames/frame.h"
#include "plan/post.h"

namespace penumbra::render {

namespace {

constexpr glm::vec4 kWhite{1.0f};

bool forward_applies(const PlanContext&, std::string*) { return true; }

void plan_forward(Planning& p) {
    PlanContext& c = p.ctx;
    p.module.before_camera(c);
    const bool own = p.module.own_view(c);
    if (!own) add_forward_light_passes(c, c.add_pass(camera_pass(c, p.module, p.stencil())));
    p.module.after_camera(c);
    if (!own) {
        for (const Module* e : p.effects) e->after_opaque(c);
        blend_pass(c, p.module);
    }
    for (const Module* e : p.effects) e->after_camera(c);
}

}  // namespace

const FrameShape kForwardShape{"forward", forward_applies, plan_forward};

// In the browser a page's module links a shape only where its exercise names it (Exercise::frames).
PENUMBRA_WEAK_IN_PAGES const FrameShape& deferred_shape();
PENUMBRA_WEAK_IN_PAGES const FrameShape& area_light_shape();
PENUMBRA_WEAK_IN_PAGES const FrameShape& shadow_blur_shape();
PENUMBRA_WEAK_IN_PAGES const FrameShape& image_post_shape();

namespace {

using ShapeGetter = const FrameShape& (*)();

ShapeGetter shape_getter(std::string_view name) {
    if (name == "deferred") return &deferred_shape;
    if (name == "area light") return &area_light_shape;
    if (name == "shadow blur") return &shadow_blur_shape;
    if (name == "image post") return &image_post_shape;
    return nullptr;
}

}  // namespace

bool frame_shape_linked(std::string_view name) { return shape_getter(name) != nullptr; }

void plan_frame_shape(Planning& p) {
    // In the order tried: a deferred frame takes no other shape; the light samples' average is
    // soft already, so it comes before the blur; a hard frame is what is left.
    const ShapeGetter getters[] = {shape_getter("deferred"), shape_getter("area light"), shape_getter("shadow blur")};
    std::vector<const FrameShape*> shapes;
    for (ShapeGetter get : getters)
        if (get) shapes.push_back(&get());
    shapes.push_back(&kForwardShape);
    std::vector<std::string> whys;
    for (const FrameShape* shape : shapes) {
        std::string why;
        if (shape->applies(p.ctx, &why)) {
            shape->plan(p);
            break;
        }
        if (!why.empty()) whys.push_back(why);
    }
    p.plan.notes.insert(p.plan.notes.end(), whys.begin(), whys.end());
}

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

Pass camera_pass(PlanContext& c, const Module& module, bool stencil,
                 void (*extra)(PlanContext&, Pass&, std::vector<CameraItem>&)) {
    Pass cam;
    cam.name = "camera";
    cam.module = "frame";
    cam.target = c.camera_target;
    cam.clear = Clear{c.settings.aov == Aov::Visibility ? kWhite : kBackground, true, stencil};
    cam.bindings = c.lit_bindings();
    std::vector<CameraItem> items;
    cam.draws.reserve(c.drawable.size());
    items.reserve(c.drawable.size());
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
    if (module.later_pass_problem().empty()) module.shade(c, p, items);
    set_lit_draws(p, items);
    c.add_pass(std::move(p));
}

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


void plan_hard_visibility(Planning& p, const Settings& settings, const scene::Light& light, const FramePlan* previous,
                          TargetRef target, const char* name, bool light_sample) {
    PlanContext& c = p.ctx;
    PlanContext sc = c.with(settings, target);
    sc.light_sample = light_sample;
    sc.light = light;
    sc.previous = previous;
    p.module.before_camera(sc);
    Pass cam = camera_pass(sc, p.module, p.technique_stencil());
    cam.name = name;
    c.add_pass(std::move(cam));
    p.module.after_camera(sc);
}

}  // namespace penumbra::render
