#include "plan/variants.h"

#include <cstdio>

#include "plan/post.h"
#include "plan/settings.h"
#include "shadow/cascades.h"
#include "shadow/gooch.h"
#include "shadow/pcf.h"

namespace penumbra::render {

namespace {

const char* encoding_define(shadow::Encoding e) {
    switch (e) {
        case shadow::Encoding::R8: return "ENC_R8";
        case shadow::Encoding::RGBA: return "ENC_RGBA";
        case shadow::Encoding::DepthTex: return "ENC_DEPTHTEX";
    }
    return "ENC_RGBA";
}

const char* filter_define(shadow::Filter f) {
    switch (f) {
        case shadow::Filter::Hard: return "FILTER_HARD";
        case shadow::Filter::PCF2x2: return "FILTER_PCF2X2";
        case shadow::Filter::PCF4x4: return "FILTER_PCF4X4";
        case shadow::Filter::PCSS: return "FILTER_PCSS";
    }
    return "FILTER_HARD";
}

std::string glsl_float(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", static_cast<double>(v));
    return buf;
}

}  // namespace

std::string Variant::key() const {
    std::string k = vertex + "+" + fragment + "[";
    for (size_t i = 0; i < defines.size(); ++i) k += (i ? "," : "") + defines[i];
    return k + "]";
}

std::string Variant::tag() const {
    std::string t;
    for (const auto& d : defines) t += (t.empty() ? "" : "_") + d.substr(0, d.find(' '));
    return t;
}

std::string Variant::name() const {
    std::string k = vertex + "+" + fragment + "[";
    for (size_t i = 0; i < defines.size(); ++i) k += (i ? "," : "") + defines[i].substr(0, defines[i].find(' '));
    return k + "]";
}

std::vector<std::string> pcf_kernel_defines(shadow::Filter f, shadow::PcfKernel kernel) {
    if (f == shadow::Filter::PCSS) return {};  // its own loops (shadow.glsl), sized per fragment
    const auto taps = shadow::pcf_offsets(f);
    // The sum of F over the taps `pick` keeps, in pcf_offsets' order, as a function-like macro.
    const auto sum_of = [&](const std::string& name, auto pick) {
        std::string sum = name + "(F, uv, z, bias) (";
        bool first = true;
        for (const glm::vec2& t : taps) {
            if (!pick(t)) continue;
            sum += std::string(first ? "" : " + ") + "F(vec2(" + glsl_float(t.x) + ", " + glsl_float(t.y) + "), uv, z, bias)";
            first = false;
        }
        return sum + ")";
    };
    const std::string count = "PCF_TAPS " + std::to_string(taps.size());
    if (kernel == shadow::PcfKernel::EarlyExit && shadow::pcf_early_exit_applies(f))
        return {count, "PCF_EARLY_EXIT",
                sum_of("PCF_CORNERS", [&](glm::vec2 t) { return shadow::pcf_is_corner(f, t); }),
                sum_of("PCF_REST", [&](glm::vec2 t) { return !shadow::pcf_is_corner(f, t); })};
    return {count, sum_of("PCF_SUM", [](glm::vec2) { return true; })};
}

Variant lit_variant(const LitFeatures& f) {
    Variant v{"lit.vert", "lit.frag", {}};
    if (f.shadow_map) {
        v.defines = {"SHADOW_MAP", encoding_define(f.encoding), filter_define(f.filter)};
        for (auto& d : pcf_kernel_defines(f.filter, f.pcf_kernel)) v.defines.push_back(std::move(d));
        const bool pcss = f.filter == shadow::Filter::PCSS;
        if (pcss) {
            v.defines.push_back("PCSS_SEARCH_TAPS " + std::to_string(f.pcss_search));
            v.defines.push_back("PCSS_FILTER_TAPS " + std::to_string(f.pcss_taps));
            if (f.pcss_layered) v.defines.emplace_back("PCSS_LAYERED");
            // A light with a size (a filter to share) and dFdx/dFdy to share it through.
            if (f.horizon && f.derivatives) v.defines.emplace_back("PCSS_QUAD");
        }
        if (f.bias_auto) v.defines.emplace_back("BIAS_AUTO");
        // The slope term per vertex (lit.vert), exact where it is constant over each triangle: a
        // faceted mesh, one map, lit.vert's pass (not the deferred one), not PCSS (whose reach is
        // per fragment).
        if (f.bias_auto && f.faceted && f.cascades <= 1 && !f.cube && !pcss && f.gbuffer != Gbuffer::Read)
            v.defines.emplace_back("BIAS_PER_VERTEX");
        if (f.light_perspective && (f.bias_auto || pcss)) v.defines.emplace_back("LIGHT_PERSPECTIVE");
        if (f.mediump) v.defines.emplace_back("EMULATE_MEDIUMP");
        if (f.lab) v.defines.emplace_back("LAB");
        if (f.cascades > 1) v.defines.push_back("CASCADES " + std::to_string(f.cascades));
        if (f.cube) v.defines.emplace_back("CUBE");
        if (f.cube && f.cube_map) v.defines.emplace_back("CUBE_MAP");
    } else if (f.in_shadow) {
        v.defines = {"IN_SHADOW"};
    } else if (f.area_lookup) {
        v.defines = {"AREA_LOOKUP"};
        if (f.area_interleave > 1) v.defines.push_back("AREA_INTERLEAVE " + std::to_string(f.area_interleave));
    } else if (f.gooch_taps > 0) {
        v.defines = {"GOOCH_TEXTURE"};
        for (auto& d : gooch_tap_defines(f.gooch_taps)) v.defines.push_back(std::move(d));
    }
    if (f.light_term == LightTerm::Ambient) v.defines.emplace_back("LIGHT_AMBIENT");
    if (f.light_term == LightTerm::Direct) v.defines.emplace_back("LIGHT_DIRECT");
    if (f.textured) v.defines.emplace_back("TEXTURED");
    if (f.spot) v.defines.emplace_back("LIGHT_SPOT");
    if (f.visibility_aov) v.defines.emplace_back("AOV_VISIBILITY");
    if (f.horizon) v.defines.emplace_back("LIGHT_HORIZON");
    if (f.horizon && f.derivatives && f.gbuffer != Gbuffer::Read) v.defines.emplace_back("GEOMETRIC_HORIZON");
    if (f.cascades_aov) v.defines.emplace_back("AOV_CASCADES");
    if (f.alpha_test) v.defines.emplace_back("ALPHA_TEST");
    if (f.alpha_blend) v.defines.emplace_back("ALPHA_BLEND");
    if (f.double_sided) v.defines.emplace_back("DOUBLE_SIDED");
    if (f.reflected) v.defines.emplace_back("REFLECTED");
    if (f.clipped) v.defines.emplace_back("CLIPPED");
    if (f.point_lights > 0) v.defines.push_back("POINT_LIGHTS " + std::to_string(f.point_lights));
    if (f.points_only) v.defines.emplace_back("POINTS_ONLY");
    switch (f.gbuffer) {
        case Gbuffer::None: break;
        case Gbuffer::WriteAll: v.defines.emplace_back("GBUFFER_WRITE"); v.defines.emplace_back("GBUFFER_MRT"); break;
        case Gbuffer::WriteOne:
            v.defines.emplace_back("GBUFFER_WRITE");
            v.defines.push_back("GBUFFER_TARGET " + std::to_string(f.gbuffer_target));
            break;
        case Gbuffer::Read: v.vertex = "screen.vert"; v.defines.emplace_back("GBUFFER_READ"); break;
    }
    if (f.receives && (f.gbuffer == Gbuffer::WriteAll || f.gbuffer == Gbuffer::WriteOne)) v.defines.emplace_back("RECEIVES");
    return v;
}

namespace {
void add_alpha(Variant& v, AlphaTest alpha) {
    if (!alpha.on) return;
    v.defines.emplace_back("ALPHA_TEST");
    if (alpha.textured) v.defines.emplace_back("TEXTURED");
}
}  // namespace

Variant depth_variant(shadow::Encoding e, const DepthPath& path, AlphaTest alpha) {
    Variant v{"depth.vert", "depth.frag", {encoding_define(e)}};
    if (path.mediump) v.defines.emplace_back("EMULATE_MEDIUMP");
    if (path.lab && e != shadow::Encoding::DepthTex) v.defines.emplace_back("LAB");
    add_alpha(v, alpha);
    return v;
}

Variant light_depth_variant(shadow::Encoding e, bool perspective, const DepthPath& path) {
    Variant v{"light_depth.vert", "light_depth.frag", {encoding_define(e)}};
    if (perspective) v.defines.emplace_back("LINEARIZE");
    if (path.mediump) v.defines.emplace_back("EMULATE_MEDIUMP");
    return v;
}

Variant probe_variant() { return {"light_depth.vert", "probe.frag", {}}; }

Variant far_plane_variant() { return {"light_depth.vert", "probe.frag", {"AT_FAR_PLANE"}}; }

Variant volume_variant() { return {"volume.vert", "probe.frag", {}}; }

Variant flat_variant(AlphaTest alpha) {
    Variant v{"depth.vert", "probe.frag", {}};
    add_alpha(v, alpha);
    return v;
}

std::vector<std::string> gooch_tap_defines(int taps) {
    std::string sum = "GOOCH_SUM(F) (";
    bool first = true;
    for (const glm::vec2& t : shadow::gooch_disc(taps)) {
        char b[96];
        std::snprintf(b, sizeof b, "%sF(vec2(%.6f, %.6f))", first ? "" : " + ", static_cast<double>(t.x),
                      static_cast<double>(t.y));
        sum += b;
        first = false;
    }
    return {"GOOCH_TAPS " + std::to_string(taps), sum + ")"};
}

Variant outline_variant() { return {"outline.vert", "probe.frag", {}}; }

Variant area_add_variant(bool interleaved) {
    return {"light_depth.vert", "area_add.frag", interleaved ? std::vector<std::string>{"AREA_INTERLEAVE"} : std::vector<std::string>{}};
}

Variant blur_variant(int radius) {
    const std::vector<float> w = gaussian_weights(radius);
    const auto glsl_weight = [](float v) {  // every bit of the float: "1.23456789e-02"
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.8e", static_cast<double>(v));
        return std::string(buf);
    };
    std::string sum = "BLUR_SUM(F) (F(0.0, " + glsl_weight(w[0]) + ")";
    for (size_t i = 1; i < w.size(); ++i) {
        const std::string x = glsl_float(static_cast<float>(i)), weight = glsl_weight(w[i]);
        sum += " + F(" + x + ", " + weight + ") + F(-" + x + ", " + weight + ")";
    }
    return {"light_depth.vert", "post_blur.frag", {"BLUR_RADIUS " + std::to_string(radius), sum + ")"}};
}

Variant mip_down_variant(bool normal_map) {
    return {"light_depth.vert", "mip_down.frag", normal_map ? std::vector<std::string>{"MIP_NORMAL"} : std::vector<std::string>{}};
}

Variant mip_read_variant() { return {"light_depth.vert", "mip_down.frag", {"MIP_READ"}}; }

Variant bright_variant() { return {"light_depth.vert", "post_bright.frag", {}}; }
Variant bloom_add_variant() { return {"light_depth.vert", "post_bloom.frag", {}}; }

Variant gbuffer_view_variant(Aov aov) {
    const char* view = aov == Aov::GbufferColor ? "VIEW_COLOR"
                       : aov == Aov::GbufferNormal ? "VIEW_NORMAL"
                       : aov == Aov::GbufferPosition ? "VIEW_POSITION"
                                                     : "VIEW_DEPTH";
    return {"screen.vert", "gbuffer_view.frag", {view}};
}

Variant ramp_variant(shadow::Encoding e, const DepthPath& path) {
    Variant v{"light_depth.vert", "ramp.frag", {encoding_define(e)}};
    if (path.mediump) v.defines.emplace_back("EMULATE_MEDIUMP");
    return v;
}

std::vector<Variant> all_variants() {
    std::vector<Variant> out;
    std::vector<LitFeatures> shadowing;
    shadowing.push_back(LitFeatures{});  // no shadows
    LitFeatures planar;
    planar.in_shadow = true;
    shadowing.push_back(planar);
    LitFeatures area;
    area.area_lookup = true;
    shadowing.push_back(area);
    for (int k : {2, 4}) {  // --area-interleave
        area.area_interleave = k;
        shadowing.push_back(area);
    }
    // Gooch: the planes' ambient and direct terms; the texture's taps, 1..kMaxGoochPlanes.
    for (LightTerm t : {LightTerm::Ambient, LightTerm::Direct}) {
        LitFeatures g;
        g.light_term = t;
        shadowing.push_back(g);
    }
    for (int taps = 1; taps <= kMaxGoochPlanes; ++taps) {
        LitFeatures g;
        g.gooch_taps = taps;
        shadowing.push_back(g);
    }
    for (auto e : shadow::kAllEncodings)
        for (auto f : shadow::kAllFilters)
            for (auto k : shadow::kAllPcfKernels) {
                if (k != shadow::PcfKernel::Full && !shadow::pcf_early_exit_applies(f)) continue;  // the same variant
                for (bool bias_auto : {false, true})
                    for (bool perspective : {false, true})  // the light's projection: auto bias's slope, PCSS's cone
                        for (bool mediump : {false, true}) {
                            if (perspective && !bias_auto && f != shadow::Filter::PCSS) continue;  // the same variant
                            LitFeatures sm;
                            sm.shadow_map = true;
                            sm.encoding = e;
                            sm.filter = f;
                            sm.pcf_kernel = k;
                            sm.bias_auto = bias_auto;
                            sm.light_perspective = perspective;
                            sm.mediump = mediump;
                            shadowing.push_back(sm);
                            // A faceted receiver: the slope per vertex (BIAS_PER_VERTEX).
                            sm.faceted = true;
                            if (bias_auto && f != shadow::Filter::PCSS) shadowing.push_back(sm);
                        }
            }
    // Each with the textured / spot / visibility bits, and the glTF material features that the
    // camera passes ask for with them: MASK textured (one- or double-sided, any bits), BLEND
    // one-sided, textured or not (never in the visibility AOV: translucent objects are left out of
    // it). Not listed (compiled on first use, not checked by the shader tests): MASK without a
    // texture, double-sided OPAQUE or BLEND, and any of them with EMULATE_MEDIUMP, so the list
    // stays under twice its size without them (each of these multiplies ~170 bases).
    for (LitFeatures base : shadowing)
        for (int bits = 0; bits < 8; ++bits) {
            base.textured = bits & 1;
            base.spot = bits & 2;
            base.visibility_aov = bits & 4;
            base.alpha_test = base.alpha_blend = base.double_sided = false;
            out.push_back(lit_variant(base));
            if (base.mediump) continue;
            // LIGHT_HORIZON: PCSS of a light with a size (either blocker estimate); a
            // Heckbert-Herf sample's hard visibility. Each with the interpolated normal's horizon
            // and the triangle's own (GEOMETRIC_HORIZON).
            const auto with_horizon = [&out](LitFeatures h) {
                h.horizon = true;
                for (bool derivatives : {false, true}) {
                    h.derivatives = derivatives;
                    out.push_back(lit_variant(h));
                }
            };
            if (base.shadow_map && base.filter == shadow::Filter::PCSS) {
                for (bool layered : {true, false}) {
                    LitFeatures h = base;
                    h.pcss_layered = layered;
                    if (!layered) out.push_back(lit_variant(h));
                    with_horizon(h);
                }
            } else if (base.visibility_aov && !base.area_lookup && base.gooch_taps == 0) {
                with_horizon(base);
            }
            base.alpha_test = true;
            for (bool two : {false, true}) {
                base.double_sided = two;
                if (base.textured) out.push_back(lit_variant(base));
            }
            base.alpha_test = base.double_sided = false;
            base.alpha_blend = true;
            if (!base.visibility_aov) out.push_back(lit_variant(base));
        }
    // The shader lab (Settings::lab, render::lab_refusal): r8 and rgba, the hard and PCF filters with
    // every tap, a constant bias; compiled here with the sheet's answer as the snippets.
    for (auto e : {shadow::Encoding::R8, shadow::Encoding::RGBA}) {
        for (auto f : {shadow::Filter::Hard, shadow::Filter::PCF2x2, shadow::Filter::PCF4x4})
            for (int bits = 0; bits < 8; ++bits) {
                LitFeatures lab;
                lab.shadow_map = lab.lab = true;
                lab.encoding = e;
                lab.filter = f;
                lab.textured = bits & 1;
                lab.spot = bits & 2;
                lab.visibility_aov = bits & 4;
                out.push_back(lit_variant(lab));
            }
        for (bool mediump : {false, true}) {
            out.push_back(depth_variant(e, {mediump, true}));
            for (bool textured : {false, true}) out.push_back(depth_variant(e, {mediump, true}, {true, textured}));
        }
    }
    for (auto e : shadow::kAllEncodings)
        for (bool mediump : {false, true}) {
            out.push_back(depth_variant(e, {mediump}));
            for (bool textured : {false, true}) out.push_back(depth_variant(e, {mediump}, {true, textured}));
            if (e != shadow::Encoding::DepthTex) out.push_back(ramp_variant(e, {mediump}));
            out.push_back(light_depth_variant(e, false, {mediump}));
            out.push_back(light_depth_variant(e, true, {mediump}));
        }
    out.push_back(probe_variant());
    out.push_back(volume_variant());
    out.push_back(area_add_variant());
    out.push_back(area_add_variant(true));
    for (int r = 1; r <= kMaxBlurRadius; ++r) out.push_back(blur_variant(r));
    out.push_back(bright_variant());
    out.push_back(bloom_add_variant());
    out.push_back(mip_down_variant(false));
    out.push_back(mip_down_variant(true));
    out.push_back(mip_read_variant());
    out.push_back(flat_variant());
    out.push_back(flat_variant({true, false}));
    out.push_back(flat_variant({true, true}));
    out.push_back(outline_variant());
    out.push_back(far_plane_variant());
    // The mirror's reflection: no shadows, or any shadow map of the highp path with either bias,
    // plain or textured, point or spot light; MASK cut-outs with the texture; the visibility AOV
    // plain (what the bench scores).
    for (LitFeatures base : shadowing) {
        if (base.mediump || base.in_shadow || base.area_lookup || base.light_term != LightTerm::All) continue;
        base.reflected = true;
        for (int bits = 0; bits < 4; ++bits) {
            base.textured = bits & 1;
            base.spot = bits & 2;
            base.alpha_test = false;
            out.push_back(lit_variant(base));
            base.alpha_test = true;
            if (base.textured) out.push_back(lit_variant(base));
        }
        base.textured = base.spot = base.alpha_test = false;
        base.visibility_aov = true;
        out.push_back(lit_variant(base));
    }
    // The portal's other scene, shadow-mapped with any encoding, filter and bias of either
    // precision path, plain or textured (its frame is a camera pass's draw), and the visibility AOV
    // plain.
    for (LitFeatures base : shadowing) {
        if (base.in_shadow || base.area_lookup || base.light_term != LightTerm::All) continue;
        base.clipped = true;
        for (int bits = 0; bits < 3; ++bits) {
            base.textured = bits == 1;
            base.visibility_aov = bits == 2;
            out.push_back(lit_variant(base));
        }
    }
    // --lights and --shading deferred: forward's batches (1 and kLightsPerPass lights, with the
    // main light or alone), the geometry pass (all targets or one, textured, cut out,
    // double-sided, receiving or not), the lighting pass (no shadow, or the shadow map of either
    // bias, point or spot light, colour or visibility) and its per-light squares, the views.
    for (int k : {1, 16}) {
        LitFeatures f;
        f.point_lights = k;
        out.push_back(lit_variant(f));
        f.shadow_map = f.bias_auto = f.light_perspective = f.textured = true;
        out.push_back(lit_variant(f));
        f.points_only = true;
        out.push_back(lit_variant(f));
    }
    for (int target = -1; target < 3; ++target)
        for (int bits = 0; bits < 8; ++bits) {
            LitFeatures g;
            g.gbuffer = target < 0 ? Gbuffer::WriteAll : Gbuffer::WriteOne;
            g.gbuffer_target = std::max(target, 0);
            g.textured = g.alpha_test = bits & 1;
            g.double_sided = bits & 2;
            g.receives = bits & 4;
            out.push_back(lit_variant(g));
        }
    for (LitFeatures base : shadowing) {
        if (!(base.light_term == LightTerm::All && !base.in_shadow && !base.area_lookup && base.gooch_taps == 0)) continue;
        if (base.mediump || (base.shadow_map && base.pcf_kernel != shadow::PcfKernel::EarlyExit &&
                             shadow::pcf_early_exit_applies(base.filter)))
            continue;
        if (base.faceted) continue;  // no vertices: the deferred pass keeps the slope per fragment
        base.gbuffer = Gbuffer::Read;
        for (int bits = 0; bits < 4; ++bits) {
            base.spot = bits & 1;
            base.visibility_aov = bits & 2;
            out.push_back(lit_variant(base));
        }
    }
    LitFeatures square;
    square.gbuffer = Gbuffer::Read;
    square.point_lights = 1;
    square.points_only = true;
    out.push_back(lit_variant(square));
    for (Aov a : {Aov::GbufferColor, Aov::GbufferNormal, Aov::GbufferPosition, Aov::GbufferDepth})
        out.push_back(gbuffer_view_variant(a));
    // --cascades 2..4 and cube (n = kMaxCascades + 1, the light perspective): each encoding with
    // the hard, PCF 4x4 and PCSS lookups, auto bias, either precision; plain, textured, the
    // visibility and cascades AOVs, and deferred's lighting pass.
    // n = kMaxCascades + 2: the cube as a GL cube map (packed encodings only).
    for (int n = 2; n <= shadow::kMaxCascades + 2; ++n)
        for (auto e : shadow::kAllEncodings)
            for (auto f : {shadow::Filter::Hard, shadow::Filter::PCF4x4, shadow::Filter::PCSS})
                for (bool mediump : {false, true})
                    for (int bits = 0; bits < 9; ++bits) {
                        if (n > shadow::kMaxCascades + 1 && e == shadow::Encoding::DepthTex) continue;
                        // The cube of a spot light, and of a point or spot light over cut-outs,
                        // translucent and double-sided objects (auto's cube since issue 56).
                        if (bits >= 5 && n != shadow::kMaxCascades + 1) continue;
                        LitFeatures c;
                        c.shadow_map = c.bias_auto = true;
                        c.encoding = e;
                        c.filter = f;
                        c.pcf_kernel = shadow::PcfKernel::EarlyExit;
                        c.mediump = mediump;
                        c.cube = c.light_perspective = n > shadow::kMaxCascades;
                        c.cube_map = n > shadow::kMaxCascades + 1;
                        c.cascades = c.cube ? 0 : n;
                        c.textured = bits == 1;
                        c.visibility_aov = bits == 2;
                        c.cascades_aov = bits == 3;
                        if (bits == 4) c.gbuffer = Gbuffer::Read;
                        c.spot = bits == 5;
                        c.textured = c.textured || bits == 6 || bits == 7;
                        c.alpha_test = bits == 6 || bits == 7;
                        c.double_sided = bits == 7;
                        c.alpha_blend = bits == 8;
                        out.push_back(lit_variant(c));
                    }
    // PCSS's tap counts, each once (the loops' bounds).
    for (int n : {1, 8, 32, 64}) {
        LitFeatures p;
        p.shadow_map = true;
        p.filter = shadow::Filter::PCSS;
        p.pcss_search = p.pcss_taps = n;
        out.push_back(lit_variant(p));
    }
    return out;
}

}  // namespace penumbra::render
