// A cube of six shadow maps (the bulb exercise): a point light's faces, or the faces a wide spot
// light's cone reaches, tiles of one atlas or the faces of a GL cube map. Reached through the
// shadow-map module's weak reference in a page (shadow_map_parts.h): linked where an exercise
// names it.
#include <algorithm>
#include <cstdio>

#include "plan/techniques/map_size.h"
#include "plan/techniques/shadow_lookup.h"
#include "plan/techniques/shadow_map_parts.h"
#include "shadow/cube.h"

namespace penumbra::render {

using namespace map_parts;

namespace {

// Six faces of `size` (an atlas of 3 x 2 tiles, or a cube map), one pass into each face that sees
// a visible receiver, each with its own content key (a still face is not drawn again).
// The one map that follows a cube not made keeps the size asked for: `size` is not written.
bool plan_cube(PlanContext& c, const ShadowBounds& b, int, int& asked) {
    const Settings& s = c.settings;
    int size = asked;
    bool cube_map = s.cube_map;
    if (cube_map && s.encoding == shadow::Encoding::DepthTex) {
        c.plan.notes.push_back("--cube-layout cubemap with --encoding depthtex: the atlas instead (WebGL 1 and GLES 2 "
                               "have no cube-map depth texture)");
        cube_map = false;
    }
    const int across = cube_map ? 1 : 3;  // faces side by side in the texture
    int max = c.caps.max_target_size();
    if (cube_map && c.caps.max_cube_map_size > 0) max = std::min(max, c.caps.max_cube_map_size);
    if (size * across > max) {
        c.plan.notes.push_back("--map-size " + std::to_string(size) + " with a cube: each face cut to " +
                               std::to_string(max / across) +
                               (cube_map ? " (this context's largest cube map)"
                                         : " so the atlas (3 x 2 faces) fits this context's maximum of " +
                                               std::to_string(max)));
        size = max / across;
    }
    std::string why;
    shadow::CubeFit fit = shadow::fit_cube(c.light, b.receivers, b.casters, c.plan.camera.view_proj, size,
                                           cube_guard(s, size), &why, cube_map);
    if (s.map_size == Settings::kAutoMapSize && fit.drawn() > 0) {
        // The faces' size from what each serves, then the cube again at that size where it
        // differs (the guard band, and so each face's field of view, follows the size).
        const int first = size;
        size = auto_map_size(c, b, fit);
        if (size != first)
            fit = shadow::fit_cube(c.light, b.receivers, b.casters, c.plan.camera.view_proj, size, cube_guard(s, size),
                                   &why, cube_map);
    }
    if (fit.drawn() == 0) {
        c.plan.notes.push_back(cascades_report(c).why + ": one map instead, " + why);
        cascades_report(c).why += " -> one map (" + why + ")";
        return false;
    }
    ResourceDesc desc = map_desc(c, fit.atlas_width, fit.atlas_height);
    desc.cube = cube_map;
    const int r = c.add_resource(desc, "",
                                 cube_map ? "the depth seen from the light, the six faces of a cube map"
                                          : "the depth seen from the light, the six faces of a cube side by side (3 x 2)");
    const size_t first = c.plan.passes.size();
    const std::vector<char> keep = shadowing_casters(c);
    for (int f = 0; f < shadow::kCubeFaces; ++f) {
        const shadow::CubeFace& face = fit.faces[static_cast<size_t>(f)];
        if (!face.drawn) continue;
        if (!light_frustum_of(c.plan)) c.plan.put(LightViewReport{face.frustum, std::nullopt});
        int cut_outs = 0;
        Pass p = tile_pass(c, face.casters, keep, c.named(kMap) + " face " + shadow::cube_face_name(f),
                           {r, size, size, face.tile_x, face.tile_y, true, f}, face.frustum.view_proj(), cut_outs);
        ContentKey key;
        key.add(p.view_proj);
        for (const Draw& d : p.draws) key.add_placement(c.scene, d.object);
        add_packing(key, c);
        p.content = key.str();
        char depths[64];
        std::snprintf(depths, sizeof depths, "depth %.3g..%.3g", static_cast<double>(fit.znear),
                      static_cast<double>(fit.zfar));
        const std::string where = cube_map ? "cube-map face"
                                           : "tile at (" + std::to_string(face.tile_x) + ", " +
                                                 std::to_string(face.tile_y) + ")";
        const std::string wide = cube_map ? "perspective 90 degrees (drawn for receivers within " +
                                                std::to_string(fit.guard) + " texels of it)"
                                          : "perspective " + percent(fit.tangent - 1.0f) + " wider than 90 degrees (" +
                                                std::to_string(fit.guard) + " texel guard)";
        p.detail = std::to_string(size) + "x" + std::to_string(size) + " " + where + " " +
                   std::string(shadow::to_string(s.encoding)) + ", " + wide + ", " + depths + ", " +
                   caster_count(p.draws.size(), c.casters.size()) + ", faces " + faces_summary(p) +
                   (cut_outs ? ", " + std::to_string(cut_outs) + " alpha-tested" : "");
        c.add_pass(std::move(p));
    }
    if (!cube_map) clear_atlas_once(c, first);  // a cube map's faces are whole framebuffers
    c.plan.put(CubeReport{std::move(fit)});
    return true;
}

}  // namespace

const MapLayout& cube_layout() {
    static const MapLayout layout{plan_cube};
    return layout;
}

}  // namespace penumbra::render
