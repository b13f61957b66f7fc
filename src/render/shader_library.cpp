#include "render/shader_library.h"

#include "gl/check.h"
#include "render/shader_sources.h"

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
    }
    return "FILTER_HARD";
}


}  // namespace

std::string Variant::key() const {
    std::string k = vertex + "+" + fragment + "[";
    for (size_t i = 0; i < defines.size(); ++i) k += (i ? "," : "") + defines[i];
    return k + "]";
}

std::string variant_source(const std::string& file, const std::vector<std::string>& defines) {
    for (const ShaderSource& s : embedded_shaders()) {
        if (file != s.name) continue;
        std::string text = s.text;
        const std::string version = "#version 100\n";
        if (text.rfind(version, 0) != 0) throw gl::Error(file + ": must start with '#version 100'");
        std::string lines;
        for (const auto& d : defines) lines += "#define " + d + " 1\n";
        text.insert(version.size(), lines);
        return text;
    }
    throw gl::Error("shader '" + file + "' is not embedded");
}

Variant lit_variant(const LitFeatures& f) {
    Variant v{"lit.vert", "lit.frag", {}};
    if (f.shadow_map) {
        v.defines = {"SHADOW_MAP", encoding_define(f.encoding), filter_define(f.filter)};
        if (f.bias_auto) {
            v.defines.emplace_back("BIAS_AUTO");
            if (f.light_perspective) v.defines.emplace_back("LIGHT_PERSPECTIVE");
        }
        if (f.mediump) v.defines.emplace_back("EMULATE_MEDIUMP");
    } else if (f.in_shadow) {
        v.defines = {"IN_SHADOW"};
    }
    if (f.textured) v.defines.emplace_back("TEXTURED");
    if (f.spot) v.defines.emplace_back("LIGHT_SPOT");
    if (f.visibility_aov) v.defines.emplace_back("AOV_VISIBILITY");
    return v;
}

Variant depth_variant(shadow::Encoding e, const DepthPath& path) {
    Variant v{"depth.vert", "depth.frag", {encoding_define(e)}};
    if (path.mediump) v.defines.emplace_back("EMULATE_MEDIUMP");
    if (path.pack_floor) v.defines.emplace_back("PACK_FLOOR");
    return v;
}

Variant light_depth_variant(shadow::Encoding e, bool perspective, const DepthPath& path) {
    Variant v{"light_depth.vert", "light_depth.frag", {encoding_define(e)}};
    if (perspective) v.defines.emplace_back("LINEARIZE");
    if (path.mediump) v.defines.emplace_back("EMULATE_MEDIUMP");
    return v;
}

Variant probe_variant() { return {"light_depth.vert", "probe.frag", {}}; }

Variant ramp_variant(shadow::Encoding e, const DepthPath& path) {
    Variant v{"light_depth.vert", "ramp.frag", {encoding_define(e)}};
    if (path.mediump) v.defines.emplace_back("EMULATE_MEDIUMP");
    if (path.pack_floor) v.defines.emplace_back("PACK_FLOOR");
    return v;
}

std::vector<Variant> all_variants() {
    std::vector<Variant> out;
    std::vector<LitFeatures> shadowing;
    shadowing.push_back(LitFeatures{});  // no shadows
    LitFeatures planar;
    planar.in_shadow = true;
    shadowing.push_back(planar);
    for (auto e : shadow::kAllEncodings)
        for (auto f : shadow::kAllFilters)
            for (int bias = 0; bias < 3; ++bias)  // constant, auto orthographic, auto perspective
                for (bool mediump : {false, true}) {
                    LitFeatures sm;
                    sm.shadow_map = true;
                    sm.encoding = e;
                    sm.filter = f;
                    sm.bias_auto = bias > 0;
                    sm.light_perspective = bias == 2;
                    sm.mediump = mediump;
                    shadowing.push_back(sm);
                }
    for (LitFeatures base : shadowing)
        for (int bits = 0; bits < 8; ++bits) {
            base.textured = bits & 1;
            base.spot = bits & 2;
            base.visibility_aov = bits & 4;
            out.push_back(lit_variant(base));
        }
    for (auto e : shadow::kAllEncodings)
        for (bool mediump : {false, true}) {
            for (bool pack_floor : {false, true}) {
                out.push_back(depth_variant(e, {mediump, pack_floor}));
                if (e != shadow::Encoding::DepthTex) out.push_back(ramp_variant(e, {mediump, pack_floor}));
            }
            out.push_back(light_depth_variant(e, false, {mediump, false}));
            out.push_back(light_depth_variant(e, true, {mediump, false}));
        }
    out.push_back(probe_variant());
    return out;
}

const gl::Program& ShaderLibrary::get(const Variant& v) {
    const std::string key = v.key();
    auto it = programs_.find(key);
    if (it != programs_.end()) return it->second;
    gl::Program p(variant_source(v.vertex, v.defines), variant_source(v.fragment, v.defines), key);
    return programs_.emplace(key, std::move(p)).first->second;
}

}  // namespace penumbra::render
