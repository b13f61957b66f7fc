// The shadow map (exercise W09P2c): the depth seen from the light into a map of the pool, in the
// chosen encoding, redrawn only when the light or a caster moved; the camera pass looks it up
// with the chosen filter and bias. Also the light-depth AOV, the map scaled for viewing.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plan/techniques/map_size.h"
#include "plan/techniques/reports.h"
#include "plan/techniques/shadow_lookup.h"
#include "plan/techniques/shadow_map_parts.h"
#include "plan/techniques/technique.h"
#include "shadow/cube.h"
#include "shadow/pcf.h"

namespace penumbra::render {

using namespace map_parts;

namespace {

constexpr glm::vec4 kWhite{1.0f};
constexpr int kShadowUnit = 0;
// Below 16 texels the one or few texels hold the nearest caster's depth for everything behind it
// and the whole frame falls into shadow: that is no longer a shadow map.
constexpr int kMinMap = 16;

std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

// The faces of a caster that go into the map, as the culling that leaves them: front faces (those
// towards the light) with back-face culling, back faces with front-face culling, both with none.
// Auto takes the back faces of a closed mesh (a lit surface is then compared with its object's far
// side, so it cannot shadow itself whatever the bias; half the triangles) and both faces of an open
// one (the teapot's rim, a glTF sheet must cast from either side). Against the ray-traced truth with
// the tight light frustum: as good as both faces under --bias auto, far better under the sheet's
// constant (docs/threejs.md). A mirroring world matrix turns the winding over.
gl::Cull map_cull(MapFaces faces, const scene::Scene& scene, const Draw& d) {
    if (faces == MapFaces::Auto)
        faces = scene.meshes[static_cast<size_t>(d.mesh)].closed ? MapFaces::Back : MapFaces::Both;
    if (faces == MapFaces::Both) return gl::Cull::None;
    const bool mirrored = glm::determinant(glm::mat3(d.world)) < 0.0f;
    return (faces == MapFaces::Front) != mirrored ? gl::Cull::Back : gl::Cull::Front;
}

// A pass drawing `casters` (scene objects) into a map from the light: depth in the encoding, each
// caster's faces as --map-faces says, cut-outs alpha-tested; its target, matrix and detail are the
// caller's. `cut_outs` counts the alpha-tested casters.
Pass map_pass(const PlanContext& c, const std::vector<int>& casters, int& cut_outs) {
    const Settings& s = c.settings;
    const bool depthtex = s.encoding == shadow::Encoding::DepthTex;
    Pass p;
    p.module = "shadowmap";
    // White is the farthest depth in every encoding: nothing drawn there, nothing shadows.
    p.clear = Clear{depthtex ? std::nullopt : std::optional<glm::vec4>(kWhite), true, false};
    p.state.color_write = !depthtex;
    p.object_uniforms = ObjectUniforms::Mvp;
    cut_outs = 0;
    p.draws.reserve(casters.size());
    for (int i : casters) {
        p.draws.push_back(c.mesh_draw(i));
        // A cut-out (MASK) leaves depth only where its alpha is kept: a leaf-shaped shadow.
        const AlphaTest alpha = c.caster_alpha(p.draws.back());
        cut_outs += alpha.on;
        p.draws.back().variant = depth_variant(s.encoding, c.depth_path, alpha);
        p.draws.back().cull = map_cull(s.map_faces, c.scene, p.draws.back());
    }
    // Grouped by culling, stably (one group is sorted already): at most two changes in the pass.
    const auto by = [](const Draw& a, const Draw& b) { return *a.cull < *b.cull; };
    if (!std::is_sorted(p.draws.begin(), p.draws.end(), by)) std::stable_sort(p.draws.begin(), p.draws.end(), by);
    p.state.cull = p.draws.empty() ? gl::Cull::None : *p.draws.front().cull;  // the first group's
    for (Draw& dr : p.draws) if (dr.cull == p.state.cull) dr.cull.reset();
    return p;
}

}  // namespace

namespace map_parts {

// "back 2, both 1": how many casters put which faces into the map.
std::string faces_summary(const Pass& p) {
    int n[3] = {0, 0, 0};  // front (cull back), back (cull front), both (cull none)
    for (const Draw& d : p.draws) {
        const gl::Cull c = d.cull.value_or(p.state.cull);
        ++n[c == gl::Cull::Back ? 0 : c == gl::Cull::Front ? 1 : 2];
    }
    const char* names[3] = {"front", "back", "both"};
    std::string out;
    for (int i = 0; i < 3; ++i)
        if (n[i]) out += std::string(out.empty() ? "" : ", ") + names[i] + " " + std::to_string(n[i]);
    return out;
}

std::string percent(float share) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f%%", 100.0 * static_cast<double>(share));
    return b;
}

std::string caster_count(size_t drawn, size_t all) {
    return drawn == all ? std::to_string(all) + " caster(s)"
                        : std::to_string(drawn) + " of " + std::to_string(all) + " caster(s)";
}

// A pass into one tile of an atlas (a cascade, a cube face): `fit_casters` index
// PlanContext::casters (the fits' caster lists), those `keep` flags (shadowing_casters, the
// frame's) drawn as map_pass draws them.
Pass tile_pass(const PlanContext& c, const std::vector<int>& fit_casters, const std::vector<char>& keep,
               std::string name, TargetRef target, const glm::mat4& view_proj, int& cut_outs) {
    std::vector<int> casters;
    for (int j : fit_casters)
        if (keep[static_cast<size_t>(j)]) casters.push_back(c.casters[static_cast<size_t>(j)]);
    Pass p = map_pass(c, casters, cut_outs);
    p.name = std::move(name);
    p.target = target;
    p.view_proj = view_proj;
    return p;
}

// The tiles of an atlas (cascades, a cube's faces) each clear their own region: a scissored
// clear, which some drivers can only do by drawing a quad over the region (Mesa's llvmpipe: four
// 2048 tiles cleared so cost 20 ms a frame more than one clear of their atlas). When every tile
// pass from `first` on is drawn this frame (none is kept from the last), one pass clears the whole
// atlas before them and they clear nothing.
void clear_atlas_once(PlanContext& c, size_t first) {
    std::vector<Pass>& passes = c.plan.passes;
    if (first >= passes.size()) return;
    for (size_t i = first; i < passes.size(); ++i)
        if (passes[i].skipped || !passes[i].clear) return;
    const int r = passes[first].target.resource;
    const ResourceDesc& d = c.plan.resources[static_cast<size_t>(r)].desc;
    Pass q;
    q.name = c.named(kMap) + " clear";
    q.module = passes[first].module;
    q.object_uniforms = ObjectUniforms::None;
    q.target = {r, d.width, d.height, 0, 0, false};
    q.clear = passes[first].clear;
    q.detail = "the whole " + std::to_string(d.width) + "x" + std::to_string(d.height) + " atlas at once, its " +
               std::to_string(passes.size() - first) + " tiles all drawn this frame (one clear, not one per tile)";
    for (size_t i = first; i < passes.size(); ++i) passes[i].clear.reset();
    passes.insert(passes.begin() + static_cast<std::ptrdiff_t>(first), std::move(q));
}

// The map's texture: packed colour with a 16-bit depth buffer that only keeps the nearest caster
// (docs/culling.md), or a depth texture; never interpolated (blending packed values is meaningless).
ResourceDesc map_desc(const PlanContext& c, int width, int height) {
    ResourceDesc d;
    d.name = c.named(kMap);
    d.width = width;
    d.height = height;
    d.sampling = gl::Sampling::Nearest;
    d.wrap = gl::Wrap::Clamp;
    const bool depthtex = c.settings.encoding == shadow::Encoding::DepthTex;
    d.color = !depthtex;
    d.depth_texture = depthtex;
    if (!depthtex) d.depth_buffer = gl::RenderbufferFormat::Depth16;
    return d;
}

// What a map's content depends on beside its matrices and casters: how depth is packed.
void add_packing(ContentKey& key, const PlanContext& c) {
    key.add(c.settings.encoding);
    key.add(c.settings.map_faces);
    key.add(c.depth_path.mediump);
    if (c.depth_path.lab) key.add(c.depth_path.lab);  // (plans without the lab keep their keys)
}

// The frame's cascades report (made on first use).
CascadesReport& cascades_report(PlanContext& c) {
    if (CascadesReport* r = c.plan.find<CascadesReport>()) return *r;
    return c.plan.put(CascadesReport{});
}

}  // namespace map_parts

namespace {

// --cascades N > 1 or auto (0): how many this frame has and why; the cascades report says it.
int cascade_count(PlanContext& c, const ShadowBounds& b) {
    const int asked = c.settings.cascades;
    if (asked == 0) {
        std::string why;
        const int n = shadow::auto_cascade_count(c.light, b.receivers, c.plan.camera.view, c.plan.camera.proj, why);
        cascades_report(c).why = "auto: " + why;
        return n;
    }
    cascades_report(c).why = "--cascades " + std::to_string(asked);
    return asked;
}

}  // namespace

// In the browser a page's module links a layout only where its exercise names it
// (Exercise::layouts); the others are null here.
PENUMBRA_WEAK_IN_PAGES const MapLayout& cascades_layout();
PENUMBRA_WEAK_IN_PAGES const MapLayout& cube_layout();

namespace {

using LayoutGetter = const MapLayout& (*)();
LayoutGetter cascades_getter() { return &cascades_layout; }
LayoutGetter cube_getter() { return &cube_layout; }
const MapLayout* cascades_layout_ref() { return cascades_getter() ? &cascades_getter()() : nullptr; }
const MapLayout* cube_layout_ref() { return cube_getter() ? &cube_getter()() : nullptr; }

class ShadowMapModule : public Module {
public:
    std::string_view name() const override { return "shadowmap"; }
    bool own_aov(Aov a) const override { return a == Aov::LightDepth || a == Aov::Cascades; }
    bool shades_deferred() const override { return true; }
    bool depth_map() const override { return true; }
    std::string label(const Settings& s) const override {
        return std::string(shadow::to_string(s.encoding)) + " " + std::string(shadow::to_string(s.filter));
    }
    bool representative(const Settings& s) const override { return s.map_size == 1024; }

    std::string check(const PlanContext& c) const override {
        if (c.settings.encoding == shadow::Encoding::DepthTex && !c.caps.depth_texture)
            return "--encoding depthtex: this context has no OES_depth_texture / WEBGL_depth_texture";
        if (c.settings.aov == Aov::LightDepth && c.casters.empty())
            return "--aov light-depth: the scene has no shadow casters, so there is no shadow map";
        return {};
    }

    void before_camera(PlanContext& c) const override {
        const Settings& s = c.settings;
        if (c.casters.empty()) {
            c.plan.notes.push_back("no shadow casters: no shadow pass");
            return;
        }
        const bool auto_size = s.map_size == Settings::kAutoMapSize;
        int size = s.fixed_map_size();
        const int max = c.caps.max_target_size();
        if (size > max) {
            c.plan.notes.push_back("--map-size " + std::to_string(size) + " clamped to " + std::to_string(max) +
                                   ", this context's maximum");
            size = max;
        }
        if (size < kMinMap) {
            c.plan.notes.push_back("--map-size " + std::to_string(size) + " raised to " + std::to_string(kMinMap) +
                                   ", the smallest map that still resolves a shadow");
            size = kMinMap;
        }
        if (cascaded(c, size)) return;
        // The light's frustum around the receivers the camera sees and the casters that can
        // shadow them; only those casters go into the map.
        const shadow::TightFit fit = fit_to_view(c, s.filter == shadow::Filter::PCSS && c.light.radius > 0.0f);
        // A point or spot light that lights receivers in view beyond what one frustum holds (75
        // degrees a side, or beside and behind the light) gets the cube instead, a spot light only
        // the faces its cone reaches: no receiver counts as lit for want of a map (issue 56).
        // (--light-fit scene fits around everything by choice: that one map stays.)
        if (s.cascades == 0 && c.light.type != scene::LightType::Directional && !fit.visible.empty() &&
            s.light_fit != LightFit::Scene && (fit.capped || !fit.tight)) {
            const std::string light = c.light.type == scene::LightType::Spot ? "spot" : "point";
            const std::string why = "auto: a cube: the " + light + " light lights receivers in view " +
                                    (fit.capped ? "beyond one frustum's 75 degrees a side"
                                                : "that no one frustum holds (beside or behind it, or around it)");
            if (cubed(c, shadow_bounds(c.scene, s.blend_shadows), size, why)) return;
        }
        if (auto_size) size = auto_map_size(c, shadow_bounds(c.scene, s.blend_shadows), fit.frustum);
        if (fit.capped)
            c.plan.notes.push_back(std::string("the light's window is capped at 75 degrees a side: receivers in view beyond it "
                                               "count as lit") +
                                   (c.light.type != scene::LightType::Directional && s.cascades != 0
                                        ? " (--cascades auto gives this light a cube)"
                                        : ""));
        const shadow::LightFrustum& f = fit.frustum;
        c.plan.put(LightViewReport{f, fit.texel_use});
        std::vector<int> casters;
        for (int k : fit.casters) casters.push_back(c.casters[static_cast<size_t>(k)]);

        // The map depends on the light's matrix, the casters and how depth is packed.
        ContentKey key;
        key.add(f.view_proj());
        for (int i : casters) key.add_placement(c.scene, i);
        add_packing(key, c);
        const int r = c.add_resource(map_desc(c, size, size), key.str(), "the depth seen from the light");

        int cut_outs = 0;
        Pass p = map_pass(c, casters, cut_outs);
        p.name = c.named(kMap);
        p.target = {r, size, size, 0, 0, false};
        p.view_proj = f.view_proj();
        p.detail = std::to_string(size) + "x" + std::to_string(size) + " " + std::string(shadow::to_string(s.encoding)) +
                   ", " + (f.perspective ? "perspective" : "orthographic") + " light, " +
                   caster_count(casters.size(), c.casters.size()) +
                   (fit.culled ? " (" + std::to_string(fit.culled) + " shadowing nothing in view left out)" : "") +
                   ", faces " + faces_summary(p) + ", texel use " + percent(fit.texel_use) +
                   (fit.cut ? ", window cut to where the casters' shadows fall" : "") +
                   (fit.tight ? "" : ", fitted around the whole scene") +
                   (fit.capped ? ", window capped at 75 degrees a side (receivers beyond it count as lit)" : "") +
                   (cut_outs ? ", " + std::to_string(cut_outs) + " alpha-tested" : "");
        c.add_pass(std::move(p));
    }

    // --cascades N > 1 with a directional light: N maps, tiles of one atlas; --cascades cube, or
    // auto with a point light among what it lights: a cube's faces (each a MapLayout in its own
    // file). false: one map (the count is 1, or the layout cannot be made here and a note says
    // why).
    bool cascaded(PlanContext& c, int& size) const {
        const Settings& s = c.settings;
        if (s.cascades == 1) return false;  // one map: nothing to decide (the default's frame does no more work)
        const ShadowBounds b = shadow_bounds(c.scene, s.blend_shadows);
        if (cubed(c, b, size)) return true;
        // A cube that could not be made, or auto with any light but a directional one: cubed()
        // said why there is one map.
        if (s.cascades == Settings::kCube || (s.cascades == 0 && c.light.type != scene::LightType::Directional))
            return false;
        const int n = cascade_count(c, b);
        if (n <= 1) return false;
        return laid_out(c, cascades_layout_ref(), b, n, size);
    }

    // Whether a cube is wanted (--cascades cube; auto with a point light among what it lights,
    // shadow::cube_wanted; `forced`: auto's reason for a spot light's cube, found by the one map's
    // fit), and then its faces. false: one map (a note says why when the cube was asked for).
    bool cubed(PlanContext& c, const ShadowBounds& b, int size, const std::string& forced = {}) const {
        const Settings& s = c.settings;
        bool want = s.cascades == Settings::kCube || !forced.empty();
        if (!forced.empty()) {
            cascades_report(c).why = forced;
        } else if (want) {
            cascades_report(c).why = "--cascades cube";
        } else if (s.cascades == 0 && c.light.type != scene::LightType::Directional) {
            std::string why;
            want = shadow::cube_wanted(c.light, b.receivers, b.casters, why);
            cascades_report(c).why = "auto: " + why;
        }
        return want && laid_out(c, cube_layout_ref(), b, 0, size);
    }

    // The layout's passes where this program has its code; else one map and a note why.
    static bool laid_out(PlanContext& c, const MapLayout* layout, const ShadowBounds& b, int count, int& size) {
        if (layout) return layout->plan(c, b, count, size);
        const std::string what = count ? "cascades" : "a cube";
        c.plan.notes.push_back(cascades_report(c).why + ": one map instead, " + what + " not in this page's code");
        cascades_report(c).why += " -> one map (" + what + " not in this page's code)";
        return false;
    }

    bool own_view(PlanContext& c) const override {
        const int r = c.plan.resource_index(c.named(kMap));
        if (c.settings.aov != Aov::LightDepth || r < 0) return false;
        if (c.plan.resources[static_cast<size_t>(r)].desc.cube) {
            c.plan.notes.push_back("--aov light-depth shows a 2D map: with --cube-layout cubemap there is none (the "
                                   "atlas layout shows the six faces)");
            return false;
        }
        const shadow::LightFrustum& f = *light_frustum_of(c.plan);
        Pass p;
        p.name = "light-depth view";
        p.module = "shadowmap";
        p.target = c.camera_target;
        p.clear = Clear{kWhite, true, false};
        p.state.depth_test = false;
        p.state.depth_write = false;
        p.state.cull = gl::Cull::None;
        p.object_uniforms = ObjectUniforms::None;
        p.bindings.push_back({"shadow map",
                              {{"u_shadow_map", kShadowUnit}, {"u_near_far", glm::vec2(f.znear, f.zfar)}},
                              {{kShadowUnit, r}}});
        Draw d;
        d.fullscreen = true;
        d.variant = light_depth_variant(c.settings.encoding, f.perspective, c.depth_path);
        d.bindings = 1u;
        p.draws.push_back(std::move(d));
        p.detail = c.plan.output + ", the shadow map scaled for viewing";
        c.add_pass(std::move(p));
        return true;
    }

    void shade(PlanContext& c, Pass& cam, std::vector<CameraItem>& items) const override {
        const int r = c.plan.resource_index(c.named(kMap));
        if (r < 0) {
            cam.detail += ", no shadows";
            return;
        }
        const Settings& s = c.settings;
        const shadow::LightFrustum& f = *light_frustum_of(c.plan);
        const auto& cascades = cascades_of(c.plan);
        const ResourceDesc& map = c.plan.resources[static_cast<size_t>(r)].desc;
        // One texel of the map, or of a cascade's tile (its lookups work in the tile's coordinates).
        const shadow::CubeFit* cube = cube_of(c.plan);
        const float texel =
            1.0f / static_cast<float>(cube ? cube->tile : cascades.empty() ? map.width : map.width / 2);
        Binding b{"shadow lookup",
                  // A cube map is read through its own sampler (u_shadow_map is not declared then).
                  {{cube && cube->cube_map ? "u_shadow_cube" : "u_shadow_map", kShadowUnit}, {"u_texmapscale", glm::vec2(texel, texel)}, {"u_bias", s.effective_bias()}},
                  {{kShadowUnit, r}}};
        if (cube) add_cube_uniforms(*cube, c.light, b, map);
        else if (cascades.empty()) b.uniforms.push_back({"u_light_matrix", shadow::clip_to_texture() * f.view_proj()});
        else add_cascade_uniforms(c, b, map);
        const bool pcss = s.filter == shadow::Filter::PCSS;
        // A light with a size: PCSS counts the part of it above the receiver's horizon (lit.frag,
        // LIGHT_HORIZON); a point light (radius 0) leaves PCSS the hard lookup.
        const bool horizon = pcss && c.light.radius > 0.0f;
        if (cascades.empty() && (s.bias_auto || pcss))
            // 1/P[0][0] and 1/P[1][1]: tan of the half-angles (perspective) or the half-extents
            // (orthographic) of the light's frustum.
            b.uniforms.push_back({"u_bias_slope", glm::vec4(1.0f / f.proj[0][0], 1.0f / f.proj[1][1], f.znear, f.zfar)});
        if (pcss) {
            // The light's size as the cone's formula takes it (shadow::pcss_radii), and the
            // largest radius searched: an eighth of the map.
            const float radius = c.light.radius;
            const float size = f.perspective ? radius : std::tan(std::min(radius, 1.5f));
            b.uniforms.push_back({"u_pcss", glm::vec2(size, 0.125f / texel)});
            if (horizon) b.uniforms.push_back({"u_light_size", size});
        }
        if (s.bias_auto || (pcss && s.pcss_layered)) {
            // The receiver's plane in the light's eye space (the slope bias, PCSS's search). A cube
            // turns the normal by its face's rotation in the shader (cubeFaceEye).
            if (!cube) b.uniforms.push_back({"u_light_rotation", glm::mat3(f.view)});
            // The window's middle (tangents) of an asymmetric perspective frustum: P[2][0] / P[0][0].
            if (f.perspective && !cube)
                b.uniforms.push_back({"u_bias_center", glm::vec2(f.proj[2][0] / f.proj[0][0], f.proj[2][1] / f.proj[1][1])});
        }
        if (s.bias_auto)
            b.uniforms.push_back({"u_bias_kernel", glm::vec2(2.0f * texel, shadow::kernel_reach_texels(s.filter))});
        const std::uint32_t bit = 1u << cam.bindings.size();
        cam.bindings.push_back(std::move(b));
        for (CameraItem& it : items) {
            if (!c.receives(it.object)) continue;
            LitFeatures& lf = it.features;
            lf.shadow_map = true;
            lf.encoding = s.encoding;
            lf.filter = s.filter;
            lf.pcf_kernel = s.pcf_kernel;
            lf.bias_auto = s.bias_auto;
            // A scene object's mesh (-1: a full-screen pass or a draw an effect adds: per fragment).
            lf.faceted = it.object >= 0 && c.scene.meshes[static_cast<size_t>(c.scene.objects[static_cast<size_t>(it.object)].mesh)].faceted;
            lf.light_perspective = f.perspective;
            lf.mediump = s.precision == shadow::Precision::Mediump;
            lf.lab = s.lab;
            lf.pcss_search = s.pcss_search;
            lf.pcss_taps = s.pcss_taps;
            lf.pcss_layered = s.pcss_layered;
            lf.horizon = lf.horizon || horizon;  // a light sample has it already (PlanContext::light_sample)
            lf.cascades = static_cast<int>(cascades.size());
            lf.cube = cube != nullptr;
            lf.cube_map = cube && cube->cube_map;
            lf.cascades_aov = s.aov == Aov::Cascades;
            it.bindings |= bit;
        }
        // The kernel is named where it makes a difference (PCF 4x4): "pcf4x4 early-exit", "pcf4x4 full".
        std::string kernel =
            shadow::pcf_early_exit_applies(s.filter) ? " " + std::string(shadow::to_string(s.pcf_kernel)) : "";
        if (pcss)
            kernel = " (" + std::to_string(s.pcss_search) + " search + " + std::to_string(s.pcss_taps) + " filter taps, " +
                     (s.pcss_layered ? "layered" : "mean") + " blockers, light radius " +
                     number(static_cast<double>(c.light.radius)) +
                     (horizon && c.caps.standard_derivatives ? ", shared over the pixel quad" : "") + ")";
        if (cube)
            cam.detail += std::string(", a cube") + (cube->cube_map ? " map" : "") + " of " +
                          std::to_string(cube->drawn()) + " face(s) drawn of 6";
        if (!cascades.empty())
            cam.detail += ", " + std::to_string(cascades.size()) + " cascades" +
                          (s.cascade_blend > 0.0f ? ", blended over " + percent(s.cascade_blend) + " of each slice" : "");
        cam.detail += ", shadow lookup " + std::string(shadow::to_string(s.filter)) + kernel + " " +
                      std::string(shadow::to_string(s.encoding)) + ", bias " +
                      (s.bias_auto ? "auto (" + number(static_cast<double>(s.effective_bias())) + " + slope)"
                                   : number(static_cast<double>(s.effective_bias()))) +
                      (s.precision == shadow::Precision::Mediump ? ", mediump emulated" : "") +
                      (s.lab ? ", the shader lab's packDepth, unpackDepth, shadowTest and offset_lookup" : "");
    }
};

}  // namespace

const Module& shadow_map_module() {
    static const ShadowMapModule m;
    return m;
}

bool map_layout_linked(std::string_view name) {
    if (name == "cascades") return cascades_getter() != nullptr;
    if (name == "cube") return cube_getter() != nullptr;
    return false;
}

}  // namespace penumbra::render
