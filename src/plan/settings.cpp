// The names of the settings' values (what the option table, the plan's listing and the bench print)
// and Settings' equality.
#include "plan/settings.h"

#include <stdexcept>
#include <string>

namespace penumbra::render {

std::string_view to_string(Technique t) {
    switch (t) {
        case Technique::ShadowMap: return "shadowmap";
        case Technique::Planar: return "planar";
        case Technique::Volumes: return "volumes";
        case Technique::Gooch: return "gooch";
        case Technique::None: return "none";
    }
    return "?";
}

Technique technique_named(std::string_view name) {
    for (Technique t : kAllTechniques)
        if (to_string(t) == name) return t;
    throw std::invalid_argument("no technique named '" + std::string(name) + "'");
}

std::string_view to_string(MapFaces f) {
    switch (f) {
        case MapFaces::Auto: return "auto";
        case MapFaces::Front: return "front";
        case MapFaces::Back: return "back";
        case MapFaces::Both: return "both";
    }
    return "?";
}

std::string_view to_string(LightFit f) {
    return f == LightFit::Shadows ? "shadows" : f == LightFit::Tight ? "tight" : "scene";
}

std::string_view to_string(VolumeMethod m) {
    switch (m) {
        case VolumeMethod::Auto: return "auto";
        case VolumeMethod::ZPass: return "zpass";
        case VolumeMethod::ZFail: return "zfail";
    }
    return "?";
}

std::string_view to_string(GoochMethod m) { return m == GoochMethod::Planes ? "planes" : "texture"; }

std::string_view to_string(Effect e) {
    switch (e) {
        case Effect::Outline: return "outline";
        case Effect::Mirror: return "mirror";
        case Effect::Portal: return "portal";
    }
    return "?";
}

std::string_view to_string(Aov a) {
    switch (a) {
        case Aov::Color: return "color";
        case Aov::Visibility: return "visibility";
        case Aov::LightDepth: return "light-depth";
        case Aov::StencilCount: return "stencil-count";
        case Aov::GbufferColor: return "gbuffer-color";
        case Aov::GbufferNormal: return "gbuffer-normal";
        case Aov::GbufferPosition: return "gbuffer-position";
        case Aov::GbufferDepth: return "gbuffer-depth";
        case Aov::Cascades: return "cascades";
    }
    return "?";
}

std::string_view to_string(Shading s) { return s == Shading::Forward ? "forward" : "deferred"; }

bool Settings::operator==(const Settings& o) const {
    return technique == o.technique && encoding == o.encoding && filter == o.filter && pcf_kernel == o.pcf_kernel &&
           map_size == o.map_size && cascades == o.cascades && cascade_split == o.cascade_split &&
           cascade_snap == o.cascade_snap && cascade_blend == o.cascade_blend && cube_map == o.cube_map && bias == o.bias && bias_auto == o.bias_auto && map_faces == o.map_faces &&
           light_fit == o.light_fit && precision == o.precision && volume_method == o.volume_method &&
           show_volumes == o.show_volumes && aov == o.aov && light_radius == o.light_radius &&
           pcss_search == o.pcss_search && pcss_taps == o.pcss_taps && pcss_layered == o.pcss_layered && area_samples == o.area_samples &&
           area_per_frame == o.area_per_frame && area_interleave == o.area_interleave && gooch_planes == o.gooch_planes && gooch_method == o.gooch_method &&
           blend_shadows == o.blend_shadows &&
           effects == o.effects && outline_color == o.outline_color && outline_width == o.outline_width &&
           reflectivity == o.reflectivity && post == o.post && shading == o.shading && lights == o.lights &&
           lab == o.lab;
}

std::string lab_refusal(const Settings& s) {
    const std::string lab = "the shader lab ";
    if (s.technique != Technique::ShadowMap) return lab + "runs on the shadow map (--technique shadowmap)";
    if (s.encoding == shadow::Encoding::DepthTex)
        return lab + "packs the depth into an RGBA8 map: --encoding r8 or rgba, not depthtex";
    if (s.filter == shadow::Filter::PCSS) return lab + "runs the sheet's filters: --filter hard, pcf2x2 or pcf4x4";
    if (s.cascades != 1) return lab + "draws one map: --cascades 1";
    if (s.bias_auto) return lab + "takes a constant bias (the sheet's unless --bias says), not --bias auto";
    if (s.shading != Shading::Forward) return lab + "shades forward: --shading forward";
    if (s.area_samples > 1) return lab + "draws one light sample: --area-samples 1";
    if (s.lights > 0) return lab + "lights with the scene's light only: --lights 0";
    if (!s.effects.empty()) return lab + "draws no effects: --effects none";
    return "";
}

}  // namespace penumbra::render
