// The shadow-map module's pieces that its layouts share (shadow_map.cpp): the one map, cascades
// (map_cascades.cpp) and a cube's faces (map_cube.cpp) draw their maps alike.
#pragma once

#include <string>
#include <vector>

#include "plan/techniques/reports.h"
#include "plan/techniques/technique.h"

namespace penumbra::render {

// A layout of the shadow map beside one map (technique.h: cascades_layout, cube_layout).
struct MapLayout {
    // The layout's map passes at `size` texels a tile (cascades: `count` of them; a cube: its
    // faces, `count` unused). false: one map instead, a note saying why. Cascades may return
    // `size` smaller (their atlas cut to the context's largest texture), for the one map too.
    bool (*plan)(PlanContext& c, const ShadowBounds& b, int count, int& size);
};

namespace map_parts {

inline constexpr const char* kMap = "shadow-map";

// "back 2, both 1": how many casters put which faces into the map.
std::string faces_summary(const Pass& p);
// "12.5%".
std::string percent(float share);
// "3 caster(s)", "2 of 3 caster(s)".
std::string caster_count(size_t drawn, size_t all);
// A pass into one tile of an atlas (a cascade, a cube face): `fit_casters` index
// PlanContext::casters (the fits' caster lists), those `keep` flags (shadowing_casters, the
// frame's) drawn as the one map draws its casters.
Pass tile_pass(const PlanContext& c, const std::vector<int>& fit_casters, const std::vector<char>& keep,
               std::string name, TargetRef target, const glm::mat4& view_proj, int& cut_outs);
// One pass clearing the whole atlas before the tile passes from `first` on, where every one of
// them is drawn this frame (then they clear nothing).
void clear_atlas_once(PlanContext& c, size_t first);
// The map's texture, `width` x `height`.
ResourceDesc map_desc(const PlanContext& c, int width, int height);
// What a map's content depends on beside its matrices and casters: how depth is packed.
void add_packing(ContentKey& key, const PlanContext& c);
// The frame's cascades report (made on first use).
CascadesReport& cascades_report(PlanContext& c);

}  // namespace map_parts

}  // namespace penumbra::render
