// What the technique modules report in a plan (FramePlan::reports): each a value, the lines
// `penumbra plan` prints for it and its JSON. The shadow map reports its light's frustum, its
// cascades and a cube's faces; Gooch's texture its light's frustum too; the shadow volumes their
// cost. Read them with plan.find<T>() or the accessors below.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "plan/plan.h"
#include "shadow/cascades.h"
#include "shadow/cube.h"
#include "shadow/light_frustum.h"

namespace penumbra::render {

// The light's frustum when a shadow map is drawn or read (cascades: the first's; a cube: the
// first drawn face's), and the share of the map (0..1) covered by the receivers the camera sees
// (none for a cube: each face covers its own share).
struct LightViewReport {
    static constexpr const char* kKey = "light_frustum";
    shadow::LightFrustum frustum;
    std::optional<float> texel_use;
    static std::string text(const LightViewReport& r);
    static std::string json(const LightViewReport& r);
};

// --cascades: the cascades of the shadow map, tiles of its atlas (empty: one map), and how their
// count was chosen ("--cascades 4", auto's reason; "--cascades cube" for a cube).
struct CascadesReport {
    static constexpr const char* kKey = "cascades";
    std::vector<shadow::Cascade> list;
    std::string why;
    static std::string text(const CascadesReport& r);
    static std::string json(const CascadesReport& r);
};

// --map-size auto: the size chosen for one map or each cube face, and why (shadow/resolution.h).
struct MapSizeReport {
    static constexpr const char* kKey = "map_size";
    int size = 0;
    int wanted = 0;  // the texels a side two texels a pixel want (MatchedSize::wanted; 0: nothing in view)
    std::string why;
    // The match's inputs (map_size.cpp): a later plan with the same key takes this match.
    std::string inputs;
    std::string scope;  // the context's prefix (PlanContext::prefix): whose map it is
    static std::string text(const MapSizeReport& r);
    static std::string json(const MapSizeReport& r);
};

// --cascades cube (or auto's choice of it): a point light's six faces, tiles of the shadow map's
// atlas (or a GL cube map's faces); those drawn have a pass each.
struct CubeReport {
    static constexpr const char* kKey = "cube";
    shadow::CubeFit fit;
    static std::string text(const CubeReport& r);
    static std::string json(const CubeReport& r);
};

// The shadow volumes a plan drew, by caster and by what made them (plan/techniques/volumes.cpp):
// the next plan keeps those whose caster, light and method did not change.
struct VolumeCache;

// What the shadow volumes of a frame cost (technique volumes).
struct VolumeStats {
    static constexpr const char* kKey = "volumes";
    int zpass_casters = 0, zfail_casters = 0;
    int silhouette_edges = 0;
    int triangles = 0;            // sides and caps
    double fill = 0.0;            // stencil fragments rasterised (covered pixels, every layer, no depth test)
    double fill_per_pixel = 0.0;  // fill / the image's pixels
    // Casters whose volume (the same triangles, Draw::triangles the same pointer) came from the
    // previous plan, and those extruded in this one; printed only when some were kept.
    int kept = 0, extruded = 0;
    // Casters left out: they shadow no receiver in view (--light-fit shadows, shadow::ReceiverIndex::shadows_any).
    int culled = 0;
    // Casters whose fill came from the previous plan too (their volume kept and the camera still).
    int fill_kept = 0;
    std::shared_ptr<VolumeCache> cache;  // not printed; only the plan being made adds to it
    static std::string text(const VolumeStats& r);
    static std::string json(const VolumeStats& r);
};

// The reports' contents, or null / empty where the plan has none.
const shadow::LightFrustum* light_frustum_of(const FramePlan& p);
std::optional<float> texel_use_of(const FramePlan& p);
const std::vector<shadow::Cascade>& cascades_of(const FramePlan& p);
std::string cascades_why_of(const FramePlan& p);
const shadow::CubeFit* cube_of(const FramePlan& p);
const VolumeStats* volumes_of(const FramePlan& p);

}  // namespace penumbra::render
