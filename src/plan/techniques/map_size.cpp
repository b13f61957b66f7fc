// --map-size auto in the plan: the shadow map's, or a cube's faces', size from the pixels they
// serve (the maths: shadow/resolution.h), and the line `penumbra plan` prints for it.
#include "plan/techniques/map_size.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "plan/techniques/reports.h"
#include "shadow/resolution.h"

namespace penumbra::render {

namespace {

// A map below 128 texels resolves little.
constexpr int kAutoSmallest = 128;
constexpr int kAutoLargest = 4096;
constexpr double kAutoBytes = 64.0 * 1024.0 * 1024.0;

// Within the context's largest target (an atlas `across` tiles wide: a cube's 3 faces, 2
// cascades) and 64 MiB for the whole atlas of `tiles` at 6 bytes a texel (RGBA8 and a 16-bit
// depth buffer): one map or 2 cascades at most 2048, a cube's faces and 3 or 4 cascades 1024.
int auto_largest(const PlanContext& c, int across, int tiles) {
    int largest = std::min(kAutoLargest, c.caps.max_target_size() / across);
    while (largest > kAutoSmallest && 6.0 * tiles * largest * static_cast<double>(largest) > kAutoBytes) largest /= 2;
    return largest;
}

// Heckbert-Herf draws one map per light sample into the same resource, which takes the size it
// was first declared with: a later sample matched to another size would draw part of the target
// and read it at the wrong texel scale. So the frame's first match holds for its later maps.
const MapSizeReport* matched_before(const PlanContext& c) { return c.plan.find<MapSizeReport>(); }

// Everything the match reads but the maps' windows, which the callers add: the light, the
// receivers, the camera, the image and the bound. Hashing them is O(n) with a small constant,
// where the match clips each receiver again by each of a map's 64 tiles: a still frame should
// not pay for that again (docs/resolution.md has what it cost).
ContentKey match_inputs(const PlanContext& c, const ShadowBounds& b, const shadow::MatchedImage& image, int largest) {
    ContentKey key;
    key.add(c.light.type);
    key.add(c.light.position);
    key.add(c.light.direction);
    key.add(c.light.spot_outer_cone);
    key.add(c.plan.camera.view_proj);
    key.add(image.width);
    key.add(image.height);
    key.add(image.scaled);
    key.add(largest);
    if (!b.receivers.empty()) key.add(b.receivers.data(), b.receivers.size() * sizeof(scene::Bounds));
    return key;
}

// The previous plan's match of this context's map: the portal's scene (a prefix of its own) has a
// map of its own, and the plan keeps only the outer scene's match.
const MapSizeReport* previous_match(const PlanContext& c) {
    const MapSizeReport* r = c.previous ? c.previous->find<MapSizeReport>() : nullptr;
    return r && r->scope == c.prefix ? r : nullptr;
}

// The previous plan's match where its inputs were these (a still frame): the same function of the
// same inputs, so the same size and reasons, without the clipping.
const MapSizeReport* same_inputs_before(const PlanContext& c, const std::string& inputs) {
    const MapSizeReport* r = previous_match(c);
    return r && r->inputs == inputs ? r : nullptr;
}

// A want just under a step would flip the size back and forth as the light or the camera moves
// (the course at 1280x720: 1032, then 1020 down to 928 and back to 1032 within 0.4 s), each flip a
// texture made again and the shadow's edges jumping. So the size goes up as soon as the want passes
// it, and down by one step only once the want is under kDownShare of the smaller size. A margin
// reaching further back (down only to a size a tenth over the want) would make a frame's size depend
// on frames long past, so that the same frame drawn again on a restored context differs.
constexpr double kDownShare = 0.9;

void settle(const PlanContext& c, shadow::MatchedSize& m, int largest, shadow::SizeSteps steps) {
    const MapSizeReport* r = previous_match(c);
    if (!r || r->size > largest || r->size != shadow::map_size_step(m.size + 1, 1, steps) ||
        m.wanted < kDownShare * m.size)
        return;
    const std::string was = "auto " + std::to_string(m.size);
    if (m.why.rfind(was, 0) == 0) m.why.replace(0, was.size(), "auto " + std::to_string(r->size));
    m.why += "; kept at " + std::to_string(r->size) + " from the last frame: the want is within " +
             std::to_string(static_cast<int>(std::lround(100.0 * (1.0 - kDownShare)))) + "% under " + std::to_string(m.size);
    m.size = r->size;
}

// One of the maps that share a size (a cube's drawn face, a cascade): the camera as it sees
// what the map serves, the map's window, and its name for the plan.
struct Window {
    glm::mat4 camera, map;
    std::string name;
};

// Each window matched to the receivers it serves, the size the most asking one wants: a mean
// would under-sample the one that sees much of the image in little of its map (map_size.h).
int most_asking(PlanContext& c, const ShadowBounds& b, int largest, const std::vector<Window>& windows, const char* kind) {
    if (const MapSizeReport* before = matched_before(c)) return before->size;
    const shadow::MatchedImage image = shadow::matched_image(c.camera_target.width, c.camera_target.height);
    ContentKey key = match_inputs(c, b, image, largest);
    for (const Window& w : windows) {
        key.add(w.name.data(), w.name.size());
        key.add(w.camera);
        key.add(w.map);
    }
    const std::string inputs = key.str();
    if (const MapSizeReport* same = same_inputs_before(c, inputs)) return c.plan.put(*same).size;
    shadow::MatchedSize best;
    size_t most = 0;
    for (size_t i = 0; i < windows.size(); ++i) {
        const shadow::Demand d =
            shadow::receiver_demand(c.light, b.receivers, windows[i].camera, image.width, image.height, windows[i].map);
        const shadow::MatchedSize m = shadow::matched_map_size(static_cast<float>(d.pixels), static_cast<float>(d.share), 1,
                                                               kAutoSmallest, largest, d.dense, image.scaled);
        if (i == 0 || m.wanted > best.wanted) best = m, most = i;
    }
    if (!windows.empty())
        best.why += " (" + windows[most].name + ", the most of the " + std::to_string(windows.size()) + kind + ")";
    settle(c, best, largest, shadow::SizeSteps::PowersOfTwo);
    c.plan.put(MapSizeReport{best.size, best.wanted, best.why, inputs, c.prefix});
    return best.size;
}

}  // namespace

int auto_map_size(PlanContext& c, const ShadowBounds& b, const shadow::LightFrustum& f) {
    if (const MapSizeReport* before = matched_before(c)) return before->size;
    const shadow::MatchedImage image = shadow::matched_image(c.camera_target.width, c.camera_target.height);
    const int largest = auto_largest(c, 1, 1);
    ContentKey key = match_inputs(c, b, image, largest);
    key.add(f.view_proj());
    const std::string inputs = key.str();
    if (const MapSizeReport* same = same_inputs_before(c, inputs)) return c.plan.put(*same).size;
    const shadow::Demand d =
        shadow::receiver_demand(c.light, b.receivers, c.plan.camera.view_proj, image.width, image.height, f.view_proj());
    // One map alone, not a tile of an atlas: its size need not be a power of two.
    shadow::MatchedSize m = shadow::matched_map_size(static_cast<float>(d.pixels), static_cast<float>(d.share), 1,
                                                     kAutoSmallest, largest, d.dense, image.scaled, shadow::SizeSteps::Eighths);
    settle(c, m, largest, shadow::SizeSteps::Eighths);
    c.plan.put(MapSizeReport{m.size, m.wanted, m.why, inputs, c.prefix});
    return m.size;
}

int auto_map_size(PlanContext& c, const ShadowBounds& b, const shadow::CubeFit& fit) {
    std::vector<Window> windows;
    for (int i = 0; i < shadow::kCubeFaces; ++i) {
        const shadow::CubeFace& face = fit.faces[static_cast<size_t>(i)];
        if (face.drawn) windows.push_back({c.plan.camera.view_proj, face.frustum.view_proj(), std::string("face ") + shadow::cube_face_name(i)});
    }
    return most_asking(c, b, auto_largest(c, 3, shadow::kCubeFaces), windows, " drawn");
}

int auto_map_size(PlanContext& c, const ShadowBounds& b, const shadow::CascadeFit& fit) {
    std::vector<Window> windows;
    for (size_t i = 0; i < fit.cascades.size(); ++i) {
        const shadow::Cascade& k = fit.cascades[i];
        // The camera clipped to the depths the cascade serves: its slice and the previous
        // cascade's band blended into it (served by both, so counted in both).
        const glm::mat4 slice = shadow::slice_projection(c.plan.camera.proj, k.fit_begin, k.end) * c.plan.camera.view;
        windows.push_back({slice, k.frustum.view_proj(), "cascade " + std::to_string(i)});
    }
    return most_asking(c, b, auto_largest(c, fit.columns, fit.columns * fit.rows), windows, "");
}

int auto_first_guess(const PlanContext& c) {
    const MapSizeReport* r = c.previous ? c.previous->find<MapSizeReport>() : nullptr;
    return r ? r->size : c.settings.fixed_map_size();
}

}  // namespace penumbra::render
