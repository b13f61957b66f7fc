#include "plan/error_model.h"

#include "shadow/resolution.h"

namespace penumbra::render {

long shadow_edge_pixels(const std::vector<std::uint8_t>& visibility, int width, int height) {
    if (width <= 0 || height <= 0 || visibility.size() < static_cast<size_t>(width) * static_cast<size_t>(height)) return 0;
    const auto lit = [&](int x, int y) { return visibility[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] >= 128; };
    long edges = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const bool here = lit(x, y);
            if ((x + 1 < width && lit(x + 1, y) != here) || (y + 1 < height && lit(x, y + 1) != here)) ++edges;
        }
    return edges;
}

double pixels_per_texel(int wanted, int size) {
    if (size <= 0 || wanted <= 0) return 0.0;
    return static_cast<double>(wanted) / (static_cast<double>(shadow::kTexelsPerPixel) * size);
}

double predicted_error_pct(long edges, long pixels, bool map, double texel_pixels) {
    if (pixels <= 0 || edges <= 0) return 0.0;
    const double per_edge = map ? ErrorModel::kMapEdge + ErrorModel::kPerTexel * texel_pixels : ErrorModel::kExactEdge;
    return 100.0 * static_cast<double>(edges) / static_cast<double>(pixels) * per_edge;
}

}  // namespace penumbra::render
