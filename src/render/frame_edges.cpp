#include "render/frame_edges.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include "plan/error_model.h"
#include "plan/techniques/reports.h"

namespace penumbra::render {

FrameEdges measure_frame_edges(Renderer& r, const scene::Scene& scene, const Settings& edges_with, const Settings& s,
                               const FrameInputs& in) {
    FrameEdges f;
    Settings matched = s;
    matched.map_size = Settings::kAutoMapSize;
    matched.aov = Aov::Color;
    const FramePlan plan = r.plan(scene, matched, in);
    if (const MapSizeReport* m = plan.find<MapSizeReport>()) f.wanted = m->wanted;
    // Covered: not the background's colour, each channel within one step (GL's conversion of the
    // clear colour to 8 bits may round either way).
    Settings colour = s;
    colour.aov = Aov::Color;
    r.render(scene, colour, in);
    const std::vector<std::uint8_t> rgba = r.read_image();
    const auto near = [](std::uint8_t v, float c) { return std::abs(static_cast<float>(v) - c * 255.0f) <= 1.5f; };
    for (size_t i = 0; i + 3 < rgba.size(); i += 4)
        if (!(near(rgba[i], kBackground.r) && near(rgba[i + 1], kBackground.g) && near(rgba[i + 2], kBackground.b))) ++f.covered;
    Settings vis = edges_with;
    vis.aov = Aov::Visibility;
    r.render(scene, vis, in);
    const std::vector<std::uint8_t> v = r.read_image();
    std::vector<std::uint8_t> red(v.size() / 4);
    for (size_t i = 0; i < red.size(); ++i) red[i] = v[4 * i];
    f.edges = shadow_edge_pixels(red, in.output.width, in.output.height);
    return f;
}

double predicted_error_pct(const FrameEdges& f, int map_size) {
    if (map_size > 0 && f.wanted < 0) return -1.0;
    return predicted_error_pct(f.edges, f.covered, map_size > 0, pixels_per_texel(f.wanted, map_size));
}

}  // namespace penumbra::render
