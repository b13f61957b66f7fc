// --max-error's model (plan/error_model.h): the shadow edges counted in a visibility image, the
// pixels a texel spans, and the prediction's shape (more edges, coarser texels: more error).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "plan/error_model.h"

using namespace penumbra;

namespace {

// A w x h image, lit (255) but for a shadowed (0) rectangle [x0, x1) x [y0, y1).
std::vector<std::uint8_t> with_shadow(int w, int h, int x0, int y0, int x1, int y1) {
    std::vector<std::uint8_t> v(static_cast<size_t>(w) * static_cast<size_t>(h), 255);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) v[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)] = 0;
    return v;
}

TEST(ErrorModel, EdgesAreThePixelsBesideTheOtherSide) {
    // A 10x10 shadow in a 32x32 image: a pixel counts when its right or lower neighbour differs.
    // Inside the shadow: its last column (10 pixels, right neighbour lit) and last row (10, lower
    // neighbour lit), sharing one corner: 19. Outside: the column left of it (10) and the row
    // above it (10): 20.
    EXPECT_EQ(render::shadow_edge_pixels(with_shadow(32, 32, 8, 8, 18, 18), 32, 32), 39);
    // The control: all lit, or all in shadow, has no edge.
    EXPECT_EQ(render::shadow_edge_pixels(with_shadow(32, 32, 0, 0, 0, 0), 32, 32), 0);
    EXPECT_EQ(render::shadow_edge_pixels(with_shadow(32, 32, 0, 0, 32, 32), 32, 32), 0);
    // Half is the threshold: a PCF's 127 is shadow, 128 lit.
    std::vector<std::uint8_t> grey(16, 128);
    grey[5] = 127;
    EXPECT_EQ(render::shadow_edge_pixels(grey, 4, 4), 3);  // itself (right and below differ), left of it, above it
    // A short buffer counts nothing rather than reading past it.
    EXPECT_EQ(render::shadow_edge_pixels(std::vector<std::uint8_t>(10, 0), 4, 4), 0);
}

TEST(ErrorModel, TexelsSpanWhatTheResolutionMatchSays) {
    // Two texels a pixel want 1024: a 1024 map gives two texels a pixel, so a texel spans half.
    EXPECT_DOUBLE_EQ(render::pixels_per_texel(1024, 1024), 0.5);
    EXPECT_DOUBLE_EQ(render::pixels_per_texel(1024, 256), 2.0);
    EXPECT_DOUBLE_EQ(render::pixels_per_texel(1024, 0), 0.0);  // shadow volumes: no texels
    EXPECT_DOUBLE_EQ(render::pixels_per_texel(0, 512), 0.0);   // nothing in view
}

TEST(ErrorModel, ThePredictionGrowsWithEdgesAndTexels) {
    const double exact = render::predicted_error_pct(1000, 100000, false, 0.0);
    EXPECT_DOUBLE_EQ(exact, 100.0 * 0.01 * render::ErrorModel::kExactEdge);
    // However fine, a map is predicted less accurate than shadow volumes: its bias and its
    // rasterised silhouette move an edge where volumes do not.
    const double finest = render::predicted_error_pct(1000, 100000, true, 0.0);
    EXPECT_DOUBLE_EQ(finest, 100.0 * 0.01 * render::ErrorModel::kMapEdge);
    EXPECT_GT(finest, exact);
    EXPECT_GT(render::predicted_error_pct(1000, 100000, true, 1.0), finest);
    EXPECT_GT(render::predicted_error_pct(1000, 100000, true, 2.0), render::predicted_error_pct(1000, 100000, true, 1.0));
    EXPECT_DOUBLE_EQ(render::predicted_error_pct(2000, 100000, true, 1.0), 2.0 * render::predicted_error_pct(1000, 100000, true, 1.0));
    EXPECT_DOUBLE_EQ(render::predicted_error_pct(0, 100000, true, 4.0), 0.0);  // no shadow edge: nothing to get wrong
    EXPECT_DOUBLE_EQ(render::predicted_error_pct(10, 0, true, 4.0), 0.0);      // nothing covered
}

}  // namespace
