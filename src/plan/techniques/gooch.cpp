// Gooch et al.'s soft shadow (seed 001, "Gooch's method"): the receiving plane moved towards and
// away from the light, the results averaged; the penumbra it makes is always too big. Two ways:
//
// planes (default): on the ground plane only. The ground is drawn ambient-only, marking its visible
// pixels 1 in the stencil; then for plane i = 0..K-1 the casters flattened onto the plane at offset
// o_i and moved back onto the ground (shadow::gooch_projection) turn i+1 into i+2 where they cover
// (colour and depth off, never twice), and the ground is drawn again where the stencil is still i+1
// (lit by plane i) adding the direct light times w_i (blending ONE, ONE) and turning i+1 into i+2.
// Every visible ground pixel ends at K+1 and its colour at ambient + direct x (sum of the w_i of the
// planes that light it). The weights are whole bytes summing to 255 (shadow::gooch_weight_bytes),
// so the visibility AOV of a pixel all planes light is exactly 255; otherwise each add rounds to
// 8 bits once: the result is within (K + 1) / 2 of a byte of the exact average (bounded, not exact).
// With the light's radius 0 (or --gooch-planes 1) every plane is the ground: the planar
// technique's passes, so the image is exactly the planar shadow's.
//
// texture: the casters drawn black on white from the light into a small RGBA8 texture (the light's
// frustum fitted as the shadow map's), sampled with linear filtering at K offsets (a Vogel disc)
// whose radius is the penumbra's half-width at the receiver's distance d from the light for casters
// at the distance d_c of their centre: R (1/d_c - 1/d) in tangent units (point, spot), (d - d_c)
// tan(a) (directional). Projected onto every receiver that casts no shadow (and the ground object,
// treated as a receiver only): the texture has no depth, so a caster would shadow itself all over.
// The casters themselves get no shadow at all (the limit of a shadow texture).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plan/techniques/reports.h"
#include "plan/techniques/technique.h"
#include "shadow/gooch.h"
#include "shadow/planar.h"

namespace penumbra::render {

namespace {

constexpr int kGroundVisible = 1;  // the stencil of a visible ground pixel before plane 0
constexpr const char* kUse = "gooch: planes lighting the ground";
constexpr int kGoochUnit = 0;
constexpr const char* kTexture = "gooch-texture";
constexpr int kMinTexture = 32;

std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    return b;
}

bool has_ground(const PlanContext& c) {
    const int g = c.scene.ground_object;
    return c.scene.ground_plane && g >= 0 &&
           std::find(c.drawable.begin(), c.drawable.end(), g) != c.drawable.end();
}

// The casters other than the ground object.
std::vector<int> casters_above(const PlanContext& c) {
    std::vector<int> out;
    for (int i : c.casters)
        if (i != c.scene.ground_object) out.push_back(i);
    return out;
}

// The middle of the casters' world bounds (nullopt without casters).
std::optional<glm::vec3> caster_center(const PlanContext& c) {
    scene::Bounds b;
    for (int i : casters_above(c)) b.add(scene::object_bounds(c.scene, c.scene.objects[static_cast<size_t>(i)]));
    if (b.empty()) return std::nullopt;
    return b.center();
}

// The planes' offsets for this frame: all 0 (one plane, the planar shadow) when the light has no
// radius or there is nothing above the ground to spread.
float plane_spread(const PlanContext& c) {
    const auto centre = caster_center(c);
    if (!centre || !c.scene.ground_plane) return 0.0f;
    return shadow::gooch_spread(*c.scene.ground_plane, c.light_vector(), c.light.radius, *centre);
}

bool planes_are_planar(const PlanContext& c) { return c.settings.gooch_planes <= 1 || plane_spread(c) == 0.0f; }

bool texture_method(const PlanContext& c) { return c.settings.gooch_method == GoochMethod::Texture; }

Pass overlay(const PlanContext& c, const char* name) {
    Pass p;
    p.name = name;
    p.module = "gooch";
    p.target = c.camera_target;
    p.state.depth_test = p.state.depth_write = false;
    return p;
}

// World -> distance from the light along its view axis: minus the view matrix's third row.
glm::vec4 depth_row(const shadow::LightFrustum& f) {
    return -glm::vec4(f.view[0][2], f.view[1][2], f.view[2][2], f.view[3][2]);
}

// The texture taps' radius at light distance d, as max(x d + y + z / d, 0) in tangent (perspective)
// or world (orthographic) units: the penumbra's half-width of a light of this radius for casters at
// distance dc.
glm::vec3 tap_spread(const PlanContext& c, const shadow::LightFrustum& f, float dc) {
    const float r = c.light.radius;
    if (!(r > 0.0f) || !(dc > 0.0f)) return glm::vec3(0.0f);
    if (f.perspective) return {0.0f, r / dc, -r};
    const float t = std::tan(std::min(r, 1.5f));
    return {t, -dc * t, 0.0f};
}

bool texture_receiver(const PlanContext& c, int object) {
    if (object < 0) return false;  // an effect's draw (the portal's frame): lit, never a plane's receiver
    const scene::Object& o = c.scene.objects[static_cast<size_t>(object)];
    return o.receives_shadow && (!o.casts_shadow || object == c.scene.ground_object);
}

class GoochModule : public Module {
public:
    std::string_view name() const override { return "gooch"; }
    std::string_view soft_by_itself() const override { return "its planes take the light's size"; }

    std::string check(const PlanContext& c) const override {
        if (texture_method(c)) return {};
        if (!has_ground(c))
            return "--technique gooch --gooch-method planes: the scene has no ground plane (a flat object named "
                   "ground, floor, plane or table); --gooch-method texture needs none";
        if (!c.caps.packed_depth_stencil)
            return "--technique gooch: this context has no OES_packed_depth_stencil for the stencil buffer";
        return {};
    }

    // Planes: the values 1..K+1, counting (incr); with every plane the ground, the planar shadow's use.
    std::vector<StencilUse> stencil_uses(const PlanContext& c) const override {
        if (texture_method(c) || !has_ground(c)) return {};
        if (planes_are_planar(c)) return planar_module().stencil_uses(c);
        StencilUse u;
        u.name = kUse;
        u.module = "gooch";
        const int top = kGroundVisible + std::clamp(c.settings.gooch_planes, 1, kMaxGoochPlanes);
        while ((1 << u.bits) <= top) ++u.bits;
        u.counts = true;
        return {u};
    }

    bool keeps_out_of_camera(const PlanContext& c, int object) const override {
        return !texture_method(c) && has_ground(c) && object == c.scene.ground_object;
    }

    void before_camera(PlanContext& c) const override {
        if (!texture_method(c)) return;
        const std::vector<int> above = casters_above(c);
        if (above.empty()) {
            c.plan.notes.push_back("no shadow casters above the ground: no Gooch texture");
            return;
        }
        const shadow::TightFit fit = fit_to_view(c, true);
        const shadow::LightFrustum& f = fit.frustum;
        c.plan.put(LightViewReport{f, fit.texel_use});
        // One texture, one frustum: no cube here (issue 56 left it), so say what is lost.
        if (fit.capped)
            c.plan.notes.push_back("--gooch-method texture: the light's window is capped at 75 degrees a side: the ground "
                                   "beyond it gets no shadow (--gooch-method planes holds it)");
        std::vector<int> casters;
        for (int k : fit.casters) {
            const int i = c.casters[static_cast<size_t>(k)];
            if (i != c.scene.ground_object) casters.push_back(i);
        }

        // The texture's size: a texel about half the taps' radius at the receivers' middle, so the
        // linear filter smooths between taps (a lower resolution is a wider blur); from 32 to
        // --map-size texels, a power of two. A light of radius 0: --map-size.
        const glm::vec4 row = depth_row(f);
        const float dc = glm::dot(row, glm::vec4(*caster_center(c), 1.0f));
        const glm::vec3 spread = tap_spread(c, f, dc);
        scene::Bounds rb;
        for (int i : c.drawable)
            if (texture_receiver(c, i)) rb.add(scene::object_bounds(c.scene, c.scene.objects[static_cast<size_t>(i)]));
        const float dr = rb.empty() ? f.zfar : std::max(glm::dot(row, glm::vec4(rb.center(), 1.0f)), 1e-3f);
        const float radius_uv = 0.5f * std::min(f.proj[0][0], f.proj[1][1]) *
                                std::max(spread.x * dr + spread.y + spread.z / dr, 0.0f);
        const int max = std::min(c.settings.fixed_map_size(), c.caps.max_target_size());
        int size = max;
        if (radius_uv > 0.0f) {
            size = kMinTexture;
            while (size < max && static_cast<float>(size) * radius_uv < 2.0f) size *= 2;
        }
        size = std::max(std::min(size, max), 1);

        ResourceDesc d;
        d.name = kTexture;
        d.width = d.height = size;
        d.sampling = gl::Sampling::Linear;
        d.wrap = gl::Wrap::Clamp;
        ContentKey key;
        key.add(f.view_proj());
        for (int i : casters) key.add_placement(c.scene, i);
        const int r = c.add_resource(d, key.str(), "the casters seen from the light, black on white");

        Pass p;
        p.name = kTexture;
        p.module = "gooch";
        p.target = {r, size, size, 0, 0, false};
        p.clear = Clear{glm::vec4(1.0f), false, false};
        p.state.depth_test = p.state.depth_write = false;
        p.state.cull = gl::Cull::None;
        p.object_uniforms = ObjectUniforms::Mvp;
        p.view_proj = f.view_proj();
        p.bindings.push_back({"black", {{"u_value", glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)}}, {}});
        for (int i : casters) {
            p.draws.push_back(c.mesh_draw(i));
            p.draws.back().variant = flat_variant(c.caster_alpha(p.draws.back()));
            p.draws.back().bindings = 1u;
        }
        p.detail = std::to_string(size) + "x" + std::to_string(size) + " rgba8 linear, " +
                   (f.perspective ? "perspective" : "orthographic") + " light, " + std::to_string(casters.size()) +
                   " caster(s) black on white";
        c.add_pass(std::move(p));
    }

    void shade(PlanContext& c, Pass& cam, std::vector<CameraItem>& items) const override {
        if (!texture_method(c)) {
            if (!has_ground(c)) cam.detail += ", no shadows";
            return;
        }
        const int r = c.plan.resource_index(kTexture);
        if (r < 0) {
            cam.detail += ", no shadows";
            return;
        }
        const shadow::LightFrustum& f = *light_frustum_of(c.plan);
        const glm::vec4 row = depth_row(f);
        const float dc = glm::dot(row, glm::vec4(*caster_center(c), 1.0f));
        const glm::vec3 spread = tap_spread(c, f, dc);
        const int taps = std::clamp(c.settings.gooch_planes, 1, kMaxGoochPlanes);
        const std::uint32_t bit = 1u << cam.bindings.size();
        cam.bindings.push_back({"gooch texture",
                                {{"u_gooch", kGoochUnit},
                                 {"u_gooch_matrix", shadow::clip_to_texture() * f.view_proj()},
                                 {"u_gooch_depth", row},
                                 {"u_gooch_scale", glm::vec2(0.5f * f.proj[0][0], 0.5f * f.proj[1][1])},
                                 {"u_gooch_spread", spread}},
                                {{kGoochUnit, r}}});
        int n = 0;
        for (CameraItem& it : items) {
            if (!texture_receiver(c, it.object)) continue;
            it.features.gooch_taps = taps;
            it.bindings |= bit;
            ++n;
        }
        cam.detail += ", Gooch texture on " + std::to_string(n) + " receiver(s), " + std::to_string(taps) +
                      " linear tap(s) over the penumbra of light radius " +
                      number(static_cast<double>(c.light.radius)) + " (casters at light distance " +
                      number(static_cast<double>(dc)) + ")";
    }

    void after_camera(PlanContext& c) const override {
        if (texture_method(c) || !has_ground(c)) return;
        if (planes_are_planar(c)) {
            c.plan.notes.push_back(c.settings.gooch_planes <= 1
                                       ? "--gooch-planes 1: one plane, the ground: the planar shadow"
                                       : "--technique gooch: the light has no radius (or nothing casts above the "
                                         "ground), so every plane is the ground: the planar shadow");
            planar_module().after_camera(c);
            return;
        }
        const int ground = c.scene.ground_object;
        const int k = std::clamp(c.settings.gooch_planes, 1, kMaxGoochPlanes);
        const float spread = plane_spread(c);
        const std::vector<float> offsets = shadow::gooch_offsets(k, spread);
        const std::vector<int> weights = shadow::gooch_weight_bytes(k);
        const glm::vec4 light = c.light_vector();
        const StencilUse& use = c.stencil(kUse);

        Pass mark;
        mark.name = "gooch-ground";
        mark.module = "gooch";
        mark.target = c.camera_target;
        mark.state.stencil = use.test(gl::Compare::Always, kGroundVisible, gl::StencilOp::Replace);
        mark.bindings = c.lit_bindings();
        const std::uint32_t all = (1u << mark.bindings.size()) - 1u;
        Draw g = c.object_draw(ground);
        LitFeatures f = c.base_features(g);
        f.light_term = LightTerm::Ambient;
        g.variant = lit_variant(f);
        g.bindings = all;
        mark.draws.push_back(g);
        mark.detail = "the ground, ambient only, marking its pixels " + std::to_string(kGroundVisible) +
                      " in the stencil; " + std::to_string(k) + " planes offset +-" + number(static_cast<double>(spread)) +
                      " from the light's radius " + number(static_cast<double>(c.light.radius));
        c.add_pass(std::move(mark));

        f.light_term = LightTerm::Direct;
        const Variant direct = lit_variant(f);
        const std::vector<int> above = casters_above(c);
        for (int i = 0; i < k; ++i) {
            const int before = kGroundVisible + i, after = before + 1;
            Pass project = overlay(c, "gooch-stencil");
            project.state.color_write = false;
            project.state.cull = gl::Cull::None;
            project.state.stencil = use.test(gl::Compare::Equal, before, gl::StencilOp::Incr);
            project.object_uniforms = ObjectUniforms::Mvp;
            project.view_proj = c.plan.camera.view_proj * shadow::gooch_projection(*c.scene.ground_plane, light,
                                                                                   offsets[static_cast<size_t>(i)]);
            for (int o : above) {
                project.draws.push_back(c.mesh_draw(o));
                project.draws.back().variant =
                    depth_variant(shadow::Encoding::DepthTex, c.depth_path, c.caster_alpha(project.draws.back()));
            }
            project.detail = "plane " + std::to_string(i + 1) + " of " + std::to_string(k) + " at offset " +
                             number(static_cast<double>(offsets[static_cast<size_t>(i)])) + ": " +
                             std::to_string(above.size()) + " caster(s) flattened and moved back to the ground, stencil " +
                             std::to_string(before) + " -> " + std::to_string(after) + " where shadowed";
            c.add_pass(std::move(project));

            Pass light_pass = overlay(c, "gooch-light");
            light_pass.state.stencil = use.test(gl::Compare::Equal, before, gl::StencilOp::Incr);
            light_pass.state.blend = gl::Blend::Add;
            light_pass.bindings = c.lit_bindings();
            const int w = weights[static_cast<size_t>(i)];
            light_pass.bindings.push_back({"plane weight", {{"u_light_weight", static_cast<float>(w) / 255.0f}}, {}});
            Draw lit = g;
            lit.variant = direct;
            lit.bindings = (1u << light_pass.bindings.size()) - 1u;
            light_pass.draws.push_back(lit);
            light_pass.detail = "the ground's direct light x " + std::to_string(w) + "/255 added where plane " +
                                std::to_string(i + 1) + " lights it (stencil " + std::to_string(before) + " -> " +
                                std::to_string(after) + ")";
            c.add_pass(std::move(light_pass));
        }
    }
};

}  // namespace

const Module& gooch_module() {
    static const GoochModule m;
    return m;
}

}  // namespace penumbra::render
