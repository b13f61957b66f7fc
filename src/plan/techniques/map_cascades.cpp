// Cascaded shadow maps (the cascades exercise): a directional light's view depth range split into
// N maps, tiles of one atlas, each fitted to its slice. Reached through the shadow-map module's
// weak reference in a page (shadow_map_parts.h): linked where an exercise names it.
#include <algorithm>
#include <cstdio>

#include "plan/techniques/map_size.h"
#include "plan/techniques/shadow_map_parts.h"
#include "shadow/cascades.h"

namespace penumbra::render {

using namespace map_parts;

namespace {

// N maps, tiles of one atlas (2x1 or 2x2 tiles of `size`), one pass each into its tile.
bool plan_cascades(PlanContext& c, const ShadowBounds& b, int n, int& size) {
    const Settings& s = c.settings;
    int columns = 1, rows = 1;
    shadow::atlas_layout(n, columns, rows);
    const int max = c.caps.max_target_size();
    const bool auto_size = s.map_size == Settings::kAutoMapSize;
    if (auto_size) size = std::min(auto_first_guess(c), max / columns);
    if (size * columns > max) {
        c.plan.notes.push_back("--map-size " + std::to_string(size) + " with " + std::to_string(n) +
                               " cascades: each map cut to " + std::to_string(max / columns) +
                               " so the atlas fits this context's maximum of " + std::to_string(max));
        size = max / columns;
    }
    shadow::CascadeOptions o;
    o.count = n;
    o.split = s.cascade_split;
    o.snap = s.cascade_snap;
    o.blend = s.cascade_blend;
    o.tile = size;
    std::string why;
    shadow::CascadeFit fit =
        shadow::fit_cascades(c.light, b.receivers, b.casters, c.plan.camera.view, c.plan.camera.proj, o, &why);
    if (auto_size && !fit.cascades.empty()) {
        // The tiles' size from what each cascade serves, then the cascades again at that size
        // where it differs (each window's snap and texel follow the size).
        const int first = size;
        size = auto_map_size(c, b, fit);
        if (size != first) {
            o.tile = size;
            fit = shadow::fit_cascades(c.light, b.receivers, b.casters, c.plan.camera.view, c.plan.camera.proj, o, &why);
        }
    }
    if (fit.cascades.empty()) {
        c.plan.notes.push_back(cascades_report(c).why + ": one map instead, " + why);
        cascades_report(c).why += " -> one map (" + why + ")";
        return false;
    }
    c.plan.put(LightViewReport{fit.cascades.front().frustum, shadow::texel_use(fit.cascades.front().frustum, fit.visible)});

    // Each cascade's tile has its own key: one whose window and casters are where they were in
    // the last frame is not drawn again, so a caster that moves redraws only the cascades that
    // draw it.
    const int r = c.add_resource(map_desc(c, fit.atlas_width, fit.atlas_height), "",
                                 "the depth seen from the light, " + std::to_string(n) + " cascades side by side");
    const size_t first = c.plan.passes.size();
    const std::vector<char> keep = shadowing_casters(c);
    for (size_t i = 0; i < fit.cascades.size(); ++i) {
        const shadow::Cascade& k = fit.cascades[i];
        int cut_outs = 0;
        Pass p = tile_pass(c, k.casters, keep, c.named(kMap) + " cascade " + std::to_string(i), {r, size, size, k.tile_x, k.tile_y, true},
                           k.frustum.view_proj(), cut_outs);
        ContentKey key;
        key.add(p.view_proj);
        for (const Draw& d : p.draws) key.add_placement(c.scene, d.object);
        add_packing(key, c);
        p.content = key.str();
        char depths[96];
        std::snprintf(depths, sizeof depths, "view depth %.3g..%.3g, texel %.3g", static_cast<double>(k.begin),
                      static_cast<double>(k.end), static_cast<double>(k.texel));
        p.detail = std::to_string(size) + "x" + std::to_string(size) + " tile at (" + std::to_string(k.tile_x) +
                   ", " + std::to_string(k.tile_y) + ") " + std::string(shadow::to_string(s.encoding)) + ", " +
                   depths + ", " + caster_count(p.draws.size(), c.casters.size()) + ", faces " + faces_summary(p) +
                   (s.cascade_snap ? ", snapped" : ", not snapped") +
                   (cut_outs ? ", " + std::to_string(cut_outs) + " alpha-tested" : "");
        c.add_pass(std::move(p));
    }
    clear_atlas_once(c, first);
    cascades_report(c).list = std::move(fit.cascades);
    return true;
}

}  // namespace

const MapLayout& cascades_layout() {
    static const MapLayout layout{plan_cascades};
    return layout;
}

}  // namespace penumbra::render
