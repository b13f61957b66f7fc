// The golden comparison (measure/image_compare.h) on hand-made images: what a conformant
// implementation may do differently passes (a small step everywhere, an edge one pixel over, a few
// isolated pixels), and what a regression does fails (a shadow moved by two pixels or more, an area
// changed, everything brighter by more than the step). Each passing case has a failing control.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "measure/image_compare.h"

using namespace penumbra::measure;

namespace {

constexpr int kSize = 128;

// A lit grey floor (200) with a dark elliptic shadow (40) whose centre is `cx` pixels from the left.
Pixels shadow_image(double cx, int channels = 1) {
    Pixels p;
    p.width = p.height = kSize;
    p.channels = channels;
    p.data.resize(static_cast<size_t>(kSize * kSize * channels));
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double dx = (x + 0.5 - cx) / 30.0, dy = (y + 0.5 - 64.0) / 20.0;
            const std::uint8_t v = dx * dx + dy * dy < 1.0 ? 40 : 200;
            for (int c = 0; c < channels; ++c) p.data[static_cast<size_t>((y * kSize + x) * channels + c)] = v;
        }
    return p;
}

TEST(ImageCompare, TheSameImagePasses) {
    const Pixels a = shadow_image(64.0);
    const ImageComparison r = compare_images(a, a);
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_EQ(r.off, 0);
    EXPECT_EQ(r.max, 0);
}

TEST(ImageCompare, ASmallStepEverywherePassesAndALargerOneFails) {
    const Pixels golden = shadow_image(64.0, 3);
    Pixels noisy = golden, bright = golden;
    for (size_t i = 0; i < noisy.data.size(); ++i) {
        noisy.data[i] = static_cast<std::uint8_t>(noisy.data[i] + (i % 7 < 3 ? 3 : -3));  // dithering, filtering
        bright.data[i] = static_cast<std::uint8_t>(bright.data[i] + 12);                  // the control
    }
    const ImageComparison ok = compare_images(noisy, golden);
    EXPECT_TRUE(ok.passed) << ok.summary();
    EXPECT_EQ(ok.off, 0);
    const ImageComparison bad = compare_images(bright, golden);
    EXPECT_FALSE(bad.passed) << bad.summary();
    EXPECT_EQ(bad.off, kSize * kSize);
}

TEST(ImageCompare, AnEdgeOnePixelOverPassesTwoPixelsFails) {
    const Pixels golden = shadow_image(64.0);
    const ImageComparison one = compare_images(shadow_image(65.0), golden);
    EXPECT_TRUE(one.passed) << one.summary();
    EXPECT_GT(one.off, 0) << "the edge did move";
    EXPECT_EQ(one.unexplained, 0);
    // The control: two pixels over is a shadow that moved: lines of unexplained pixels.
    const ImageComparison two = compare_images(shadow_image(66.0), golden);
    EXPECT_FALSE(two.passed) << two.summary();
    EXPECT_GT(two.largest_cluster, CompareRules{}.max_cluster);
}

TEST(ImageCompare, AFewIsolatedPixelsPassAnAreaFails) {
    const Pixels golden = shadow_image(64.0);
    Pixels specks = golden, block = golden;
    // Three isolated pixels inside the lit floor turned dark (an edge seen through a flipped
    // texel): 0.018 % of the image, under the 0.02 % allowed.
    for (int k = 0; k < 3; ++k) specks.data[static_cast<size_t>((10 + 20 * k) * kSize + 5)] = 40;
    const ImageComparison ok = compare_images(specks, golden);
    EXPECT_TRUE(ok.passed) << ok.summary();
    EXPECT_EQ(ok.unexplained, 3);
    EXPECT_EQ(ok.largest_cluster, 1);
    // The control: a 4 x 4 block turned dark (16 pixels, the same share as a few specks in a big
    // image, but together).
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) block.data[static_cast<size_t>((10 + y) * kSize + 5 + x)] = 40;
    const ImageComparison bad = compare_images(block, golden);
    EXPECT_FALSE(bad.passed) << bad.summary();
    EXPECT_EQ(bad.largest_cluster, 16);
}

TEST(ImageCompare, ManyScatteredPixelsFailOnTheShare) {
    const Pixels golden = shadow_image(64.0);
    Pixels scattered = golden;
    // One pixel in 64 flipped, each alone: groups of one, but 1.6 % of the image unexplained.
    for (int y = 1; y < kSize; y += 8)
        for (int x = 1; x < kSize; x += 8) {
            auto& v = scattered.data[static_cast<size_t>(y * kSize + x)];
            v = v == 40 ? 200 : 40;
        }
    const ImageComparison r = compare_images(scattered, golden);
    EXPECT_FALSE(r.passed) << r.summary();
    EXPECT_EQ(r.largest_cluster, 1);
}

TEST(ImageCompare, TheMapMarksExplainedAndUnexplainedPixels) {
    const Pixels golden = shadow_image(64.0);
    const Pixels m = comparison_map(shadow_image(66.0), golden);
    ASSERT_EQ(m.channels, 1);
    int grey = 0, white = 0;
    for (std::uint8_t v : m.data) {
        grey += v == 128;
        white += v == 255;
    }
    EXPECT_GT(grey, 0);
    EXPECT_GT(white, 0);
    Pixels other = golden;
    other.width = 64;
    EXPECT_THROW(compare_images(other, golden), std::invalid_argument);
}

}  // namespace
