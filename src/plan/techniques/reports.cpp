// The technique modules' reports (reports.h): their lines in `penumbra plan` and their JSON.
#include "plan/techniques/reports.h"

#include <cstdio>

#include "plan/json.h"

namespace penumbra::render {

std::string LightViewReport::text(const LightViewReport& r) {
    const shadow::LightFrustum& f = r.frustum;
    char buf[160];
    std::snprintf(buf, sizeof buf, "light: %s frustum, near %.4g, far %.4g", f.perspective ? "perspective" : "orthographic",
                  static_cast<double>(f.znear), static_cast<double>(f.zfar));
    std::string o = buf;
    if (r.texel_use) {
        std::snprintf(buf, sizeof buf, ", texel use %.1f%%", 100.0 * static_cast<double>(*r.texel_use));
        o += buf;
    }
    return o + "\n";
}

std::string LightViewReport::json(const LightViewReport& r) {
    const shadow::LightFrustum& f = r.frustum;
    return "{\"perspective\":" + json_bool(f.perspective) + ",\"near\":" + json_number(static_cast<double>(f.znear)) +
           ",\"far\":" + json_number(static_cast<double>(f.zfar)) +
           ",\"texel_use\":" + (r.texel_use ? json_number(static_cast<double>(*r.texel_use)) : std::string("null")) +
           ",\"view_proj\":" + json_floats(f.view_proj()) + "}";
}

std::string MapSizeReport::text(const MapSizeReport& r) { return "map size: " + r.why + "\n"; }

std::string MapSizeReport::json(const MapSizeReport& r) {
    return "{\"size\":" + std::to_string(r.size) + ",\"wanted\":" + std::to_string(r.wanted) + ",\"why\":" + json_quote(r.why) + "}";
}

std::string CascadesReport::text(const CascadesReport& r) {
    std::string o;
    if (!r.why.empty()) o += "cascades: " + r.why + "\n";
    for (size_t i = 0; i < r.list.size(); ++i) {
        const shadow::Cascade& c = r.list[i];
        char line[320];
        std::snprintf(line, sizeof line,
                      "  cascade %zu: view depth %.4g..%.4g (blend band %.3g), sphere radius %.4g, texel %.4g "
                      "(%.3g texels per unit), tile at (%d, %d), %zu caster(s)\n",
                      i, static_cast<double>(c.begin), static_cast<double>(c.end), static_cast<double>(c.band),
                      static_cast<double>(c.radius), static_cast<double>(c.texel), 1.0 / static_cast<double>(c.texel),
                      c.tile_x, c.tile_y, c.casters.size());
        o += line;
    }
    return o;
}

std::string CascadesReport::json(const CascadesReport& r) {
    std::string j = "{\"why\":" + json_quote(r.why) + ",\"list\":[";
    for (size_t i = 0; i < r.list.size(); ++i) {
        const shadow::Cascade& c = r.list[i];
        j += std::string(i ? "," : "") + "{\"begin\":" + json_number(static_cast<double>(c.begin)) +
             ",\"end\":" + json_number(static_cast<double>(c.end)) + ",\"band\":" + json_number(static_cast<double>(c.band)) +
             ",\"radius\":" + json_number(static_cast<double>(c.radius)) +
             ",\"texel\":" + json_number(static_cast<double>(c.texel)) + ",\"tile\":[" + std::to_string(c.tile_x) + "," +
             std::to_string(c.tile_y) + "],\"casters\":" + std::to_string(c.casters.size()) +
             ",\"view_proj\":" + json_floats(c.frustum.view_proj()) + "}";
    }
    return j + "]}";
}

std::string CubeReport::text(const CubeReport& r) {
    const shadow::CubeFit& cube = r.fit;
    char buf[160];
    std::snprintf(buf, sizeof buf, "cube: %d of 6 faces drawn (%dx%d each, %s %d texel%s), depth %.4g..%.4g:",
                  cube.drawn(), cube.tile, cube.tile, cube.cube_map ? "a GL cube map, the filter's taps up to" : "an atlas,",
                  cube.guard, cube.cube_map ? "s into the next face" : " guard", static_cast<double>(cube.znear),
                  static_cast<double>(cube.zfar));
    std::string o = buf;
    for (int f = 0; f < shadow::kCubeFaces; ++f) {
        const shadow::CubeFace& face = cube.faces[static_cast<size_t>(f)];
        o += " " + std::string(shadow::cube_face_name(f)) +
             (face.drawn ? " (" + std::to_string(face.casters.size()) + " caster(s))" : std::string(" (sees nothing in view)"));
    }
    return o + "\n";
}

std::string CubeReport::json(const CubeReport& r) {
    const shadow::CubeFit& cube = r.fit;
    std::string j = "{\"layout\":" + json_quote(cube.cube_map ? "cubemap" : "atlas") + ",\"tile\":" + std::to_string(cube.tile) +
                    ",\"guard\":" + std::to_string(cube.guard) + ",\"near\":" + json_number(static_cast<double>(cube.znear)) +
                    ",\"far\":" + json_number(static_cast<double>(cube.zfar)) + ",\"faces\":[";
    for (int f = 0; f < shadow::kCubeFaces; ++f) {
        const shadow::CubeFace& face = cube.faces[static_cast<size_t>(f)];
        j += std::string(f ? "," : "") + "{\"face\":" + json_quote(shadow::cube_face_name(f)) +
             ",\"drawn\":" + json_bool(face.drawn) + ",\"tile\":[" + std::to_string(face.tile_x) + "," +
             std::to_string(face.tile_y) + "],\"casters\":" + std::to_string(face.casters.size()) + "}";
    }
    return j + "]}";
}

std::string VolumeStats::text(const VolumeStats& v) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "shadow volumes: %d caster(s) depth-pass, %d depth-fail; %d silhouette edge(s), %d triangle(s), "
                  "fill %.0f px (%.2f per pixel)\n",
                  v.zpass_casters, v.zfail_casters, v.silhouette_edges, v.triangles, v.fill, v.fill_per_pixel);
    std::string out = buf;
    if (v.culled > 0)
        out += "shadow volumes left out: " + std::to_string(v.culled) +
               " caster(s) that shadow no receiver in view (--light-fit shadows)\n";
    if (v.kept > 0)
        out += "shadow volumes kept from the previous frame: " + std::to_string(v.kept) + " of " +
               std::to_string(v.kept + v.extruded) + " caster(s) (caster, light and method unchanged), " +
               std::to_string(v.extruded) + " extruded again; the fill of " + std::to_string(v.fill_kept) +
               " kept (camera unchanged), of " + std::to_string(v.kept + v.extruded - v.fill_kept) + " counted again\n";
    return out;
}

std::string VolumeStats::json(const VolumeStats& v) {
    return "{\"zpass_casters\":" + std::to_string(v.zpass_casters) + ",\"zfail_casters\":" + std::to_string(v.zfail_casters) +
           ",\"silhouette_edges\":" + std::to_string(v.silhouette_edges) + ",\"triangles\":" + std::to_string(v.triangles) +
           ",\"fill\":" + json_number(v.fill) + ",\"fill_per_pixel\":" + json_number(v.fill_per_pixel) +
           ",\"culled_casters\":" + std::to_string(v.culled) + "}";
}

const shadow::LightFrustum* light_frustum_of(const FramePlan& p) {
    const LightViewReport* r = p.find<LightViewReport>();
    return r ? &r->frustum : nullptr;
}

std::optional<float> texel_use_of(const FramePlan& p) {
    const LightViewReport* r = p.find<LightViewReport>();
    return r ? r->texel_use : std::nullopt;
}

const std::vector<shadow::Cascade>& cascades_of(const FramePlan& p) {
    static const std::vector<shadow::Cascade> none;
    const CascadesReport* r = p.find<CascadesReport>();
    return r ? r->list : none;
}

std::string cascades_why_of(const FramePlan& p) {
    const CascadesReport* r = p.find<CascadesReport>();
    return r ? r->why : std::string();
}

const shadow::CubeFit* cube_of(const FramePlan& p) {
    const CubeReport* r = p.find<CubeReport>();
    return r ? &r->fit : nullptr;
}

const VolumeStats* volumes_of(const FramePlan& p) { return p.find<VolumeStats>(); }

}  // namespace penumbra::render
