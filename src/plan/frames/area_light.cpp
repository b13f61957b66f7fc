// Heckbert and Herf's soft shadows, a frame shape (frame.h): the technique run from points on the
// light, the visibilities averaged. No GL here.
#include "plan/frames/area_light.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "plan/frames/frame.h"
#include "plan/json.h"
#include "plan/options.h"
#include "plan/variants.h"
#include "shadow/area_light.h"

namespace penumbra::render {

namespace {

constexpr const char* kAreaSample = "area-sample";
constexpr const char* kAreaLight = "area-light";


// Whether this frame is an area-light accumulation, and if not but asked for, why (a note).
bool area_applies(const PlanContext& c, std::string* why) {
    if (c.settings.shading == Shading::Deferred) return false;
    const Settings& s = c.settings;
    if (s.area_samples <= 1) return false;
    const auto no = [&](std::string w) {
        if (why) *why = "--area-samples " + std::to_string(s.area_samples) + ": " + std::move(w);
        return false;
    };
    const Module& m = technique_module(s.technique);
    const std::string technique = "--technique " + std::string(m.name());
    if (!m.shadows()) return no("no shadows to sample (" + technique + ")");
    if (!m.soft_by_itself().empty())
        return no(technique + " is soft by itself; " + std::string(m.soft_by_itself()));
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

// Interleaved and not yet complete: the tile's filter (lit.frag, AREA_INTERLEAVE) sums every
// class once, i.e. every sample pass once: the counts over the passes drawn. Complete: each pixel's
// own N, as without interleaving.
void area_lookup(PlanContext& c, Pass& cam, std::vector<CameraItem>& items) {
    const AreaStats& a = *area_of(c.plan);
    const bool filtered = a.interleave > 1 && a.done < a.total;
    const int over = filtered ? a.done : a.interleave > 1 ? a.samples : a.done;
    screen_lookup(c, cam, items, kAreaLight, glm::vec4(255.0f / static_cast<float>(std::max(over, 1))), "light samples");
    if (filtered)
        for (CameraItem& it : items)
            if (it.features.area_lookup) it.features.area_interleave = a.interleave;
    if (a.interleave == 1) {
        cam.detail += ", visibility averaged over " + std::to_string(a.done) + " of " + std::to_string(a.total) +
                      " light samples";
    } else if (filtered) {
        const int k = a.interleave;
        cam.detail += ", visibility averaged over " + std::to_string(a.done) + " of " + std::to_string(a.total) +
                      " sample passes, filtered over " + std::to_string(k + 1) + "x" + std::to_string(k + 1) +
                      " pixels (each of the " + std::to_string(k * k) + " classes weighing 1)";
    } else {
        cam.detail += ", visibility averaged over all " + std::to_string(a.samples) + " light samples (interleaving complete, no filter)";
    }
}

// The frame with --area-samples N: for each light sample not yet in the accumulation, the hard
// technique's visibility AOV from that point of the light into "area-sample" (its own passes:
// shadow map, stencil, volumes) and one count added where it is lit into "area-light"; then the
// camera pass shading with the average. A still frame's accumulation is kept; with area_per_frame
// K a frame adds at most K samples. The technique's stencil uses are in "area-sample"; the
// effects' in the camera's target, cleared by the last camera pass.
void plan_area(Planning& p) {
    PlanContext& c = p.ctx;
    const Settings& s = c.settings;
    const Output& out = c.inputs.output;
    AreaStats a;
    const int classes = s.area_interleave * s.area_interleave;
    a.samples = s.area_samples;
    a.interleave = s.area_interleave;
    a.total = s.area_samples * classes;
    a.key = area_key(c);
    int start = 0;
    if (const AreaStats* before = c.previous ? area_of(*c.previous) : nullptr;
        before && before->key == a.key && before->total == a.total)
        start = before->done;
    // Interleaved, "all in one frame" is one round: every pixel class gets its share of the N.
    const int per_frame = s.area_per_frame > 0 ? s.area_per_frame : classes > 1 ? s.area_samples : a.total;
    a.done = std::min(a.total, start + per_frame);
    a.added = a.done - start;
    if (classes > 1) {
        a.pixel_min = a.samples;
        for (int j = 0; j < classes; ++j) {
            const int n = area_class_samples(j, a.done, a.samples, a.interleave);
            a.pixel_min = std::min(a.pixel_min, n);
            a.pixel_max = std::max(a.pixel_max, n);
        }
    }
    p.plan.put(a);

    ResourceDesc acc;
    acc.name = kAreaLight;
    acc.width = out.width;
    acc.height = out.height;
    const int acc_r = c.add_resource(acc, a.key + "/" + std::to_string(a.done),
                                     "lit light samples counted per pixel (one channel per sample mod 4)");
    if (a.added > 0) {
        ResourceDesc one = texture_desc(Output::texture(kAreaSample, out.width, out.height, gl::Sampling::Nearest,
                                                        gl::Wrap::Clamp),
                                        c.caps, p.technique_stencil());
        const int one_r = c.add_resource(one, "", "one light sample's visibility");
        Settings hard = s;
        hard.aov = Aov::Visibility;
        hard.area_samples = 1;
        // The light's axis: from it towards the middle of what casts and receives shadows.
        const scene::Bounds b = shadowed_bounds(c.scene);
        const glm::vec3 axis = c.light.type == scene::LightType::Directional || b.empty()
                                   ? c.light.direction
                                   : b.center() - c.light.position;
        for (int step = start; step < a.done; ++step) {
            const AreaStep st = area_step(step, a.samples, a.interleave);
            const int k = st.sample;
            // No previous plan: a sample's shadow map is never taken for another's.
            plan_hard_visibility(p, hard, shadow::area_light_sample(c.light, k, a.samples, axis), nullptr,
                                 {one_r, out.width, out.height, 0, 0, false}, "area-camera", true);

            Pass add;
            add.name = "area-add";
            add.module = "area";
            add.target = {acc_r, out.width, out.height, 0, 0, false};
            if (step == 0) add.clear = Clear{glm::vec4(0.0f), false, false};
            add.state.depth_test = add.state.depth_write = false;
            add.state.cull = gl::Cull::None;
            add.state.blend = gl::Blend::Add;
            add.object_uniforms = ObjectUniforms::None;
            glm::vec4 channel(0.0f);
            channel[k % 4] = 1.0f / 255.0f;
            const int ki = a.interleave, jx = st.pixel_class % ki, jy = st.pixel_class / ki;
            add.bindings.push_back({"light sample", {{"u_sample", kAreaUnit}, {"u_channel", channel}}, {{kAreaUnit, one_r}}});
            if (ki > 1)  // the pixel class that counts this pass (area_add.frag, AREA_INTERLEAVE)
                add.bindings.back().uniforms.push_back(
                    {"u_class", glm::vec4(static_cast<float>(jx), static_cast<float>(jy), static_cast<float>(ki), 0.0f)});
            Draw d;
            d.fullscreen = true;
            d.variant = area_add_variant(ki > 1);
            d.bindings = 1u;
            add.draws.push_back(std::move(d));
            char detail[160];
            if (ki == 1)
                std::snprintf(detail, sizeof detail, "light sample %d of %d counted in channel %c", k + 1, a.total,
                              "rgba"[k % 4]);
            else
                std::snprintf(detail, sizeof detail,
                              "light sample %d of %d counted in channel %c at the pixels (%d, %d) mod %d (pass %d of %d, round %d of %d)",
                              k + 1, a.samples, "rgba"[k % 4], jx, jy, ki, step + 1, a.total, step / a.samples + 1,
                              ki * ki);
            add.detail = detail;
            c.add_pass(std::move(add));
        }
    }
    Pass cam = camera_pass(c, unshadowed_module(), p.effect_stencil(), area_lookup);
    c.add_pass(std::move(cam));
    for (const Module* e : p.effects) e->after_opaque(c);
    blend_pass(c, unshadowed_module());
    for (const Module* e : p.effects) e->after_camera(c);
    // The samples' resources (the shadow map) hold the last sample's content, not the first's
    // whose key they were declared with: nothing may reuse them.
    for (PlannedResource& r : p.plan.resources)
        if (r.desc.name != kAreaLight) r.content.clear();
}

}  // namespace

const FrameShape& area_light_shape() {
    static const FrameShape shape{"area light", area_applies, plan_area};
    return shape;
}

std::string AreaStats::text(const AreaStats& a) {
    char buf[320];
    if (a.interleave > 1) {
        const std::string has = a.pixel_min == a.pixel_max ? std::to_string(a.pixel_min)
                                                           : std::to_string(a.pixel_min) + " to " + std::to_string(a.pixel_max);
        std::snprintf(buf, sizeof buf,
                      "light samples (Heckbert-Herf, interleaved %dx%d): %d of %d sample passes in the sum (%d light "
                      "samples over %d pixel classes; each pixel has %s of them%s), %d drawn this frame%s\n",
                      a.interleave, a.interleave, a.done, a.total, a.samples, a.interleave * a.interleave, has.c_str(),
                      a.done < a.total ? ", filtered over the tile" : ": complete, unfiltered", a.added,
                      a.added == 0 ? " (still: the sum is reused)" : "");
    } else {
        std::snprintf(buf, sizeof buf, "light samples (Heckbert-Herf): %d of %d in the sum, %d drawn this frame%s\n", a.done,
                      a.total, a.added, a.added == 0 ? " (still: the sum is reused)" : "");
    }
    return buf;
}

std::string AreaStats::json(const AreaStats& a) {
    std::string interleaved;
    if (a.interleave > 1)
        interleaved = ",\"samples\":" + std::to_string(a.samples) + ",\"interleave\":" + std::to_string(a.interleave) +
                      ",\"pixel_min\":" + std::to_string(a.pixel_min) + ",\"pixel_max\":" + std::to_string(a.pixel_max);
    return "{\"total\":" + std::to_string(a.total) + ",\"done\":" + std::to_string(a.done) +
           ",\"added\":" + std::to_string(a.added) + interleaved + ",\"key\":" + json_quote(a.key) + "}";
}

AreaStep area_step(int s, int samples, int interleave) {
    const int classes = interleave * interleave;
    const int k = s % samples, round = s / samples;
    return {k, (k * classes / samples + round) % classes};
}

int area_class_samples(int j, int done, int samples, int interleave) {
    // The passes drawn so far that counted at class j (at most samples * K^2 of them).
    int n = 0;
    for (int s = 0; s < done; ++s)
        if (area_step(s, samples, interleave).pixel_class == j) ++n;
    return n;
}

}  // namespace penumbra::render
