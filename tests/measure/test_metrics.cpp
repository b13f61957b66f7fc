// The metric code on tiny hand-made images: what counts as false shadow and false lit, what the
// mask leaves out, the mean absolute error for filtered (grey) results, against an area-light
// truth, the Pareto front and the median.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "measure/metrics.h"

using namespace penumbra::measure;

namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(Metrics, FalseShadowAndFalseLit) {
    // truth:    lit  lit  shadow shadow
    // rendered: dark lit  dark   lit
    const Score s = score(Bytes{0, 255, 0, 255}, Bytes{1, 1, 0, 0}, Bytes{1, 1, 1, 1});
    EXPECT_EQ(s.valid, 4u);
    EXPECT_EQ(s.false_shadow, 1u);
    EXPECT_EQ(s.false_lit, 1u);
    EXPECT_EQ(s.truth_shadowed, 2u);
    EXPECT_DOUBLE_EQ(s.false_shadow_pct, 25.0);
    EXPECT_DOUBLE_EQ(s.false_lit_pct, 25.0);
    EXPECT_DOUBLE_EQ(s.error_pct, 50.0);
    EXPECT_DOUBLE_EQ(s.mae_pct, 50.0);  // a hard image's mean absolute error is its error
    EXPECT_DOUBLE_EQ(s.mae_soft_pct, -1.0);
}

TEST(Metrics, TheMaskLeavesPixelsOut) {
    // The two wrong pixels are masked out: a perfect score over the other two.
    const Score s = score(Bytes{0, 255, 0, 255}, Bytes{1, 1, 0, 0}, Bytes{0, 1, 1, 0});
    EXPECT_EQ(s.valid, 2u);
    EXPECT_EQ(s.false_shadow + s.false_lit, 0u);
    EXPECT_DOUBLE_EQ(s.error_pct, 0.0);
    EXPECT_DOUBLE_EQ(s.mae_pct, 0.0);
    // Nothing valid: zeros, not NaN.
    const Score none = score(Bytes{0, 255}, Bytes{1, 0}, Bytes{0, 0});
    EXPECT_EQ(none.valid, 0u);
    EXPECT_DOUBLE_EQ(none.error_pct, 0.0);
    EXPECT_DOUBLE_EQ(none.mae_pct, 0.0);
}

TEST(Metrics, GreysAreDarkBelowOneHalf) {
    // 127 is dark, 128 (a PCF half, rounded) is lit.
    const Score s = score(Bytes{127, 128, 127, 128}, Bytes{1, 1, 0, 0}, Bytes{1, 1, 1, 1});
    EXPECT_EQ(s.false_shadow, 1u);  // 127 where lit
    EXPECT_EQ(s.false_lit, 1u);     // 128 where shadowed
    // |127/255 - 1| + |128/255 - 1| + 127/255 + 128/255 = 2, over 4 pixels.
    EXPECT_NEAR(s.mae_pct, 50.0, 1e-9);
    const Score g = score(Bytes{64}, Bytes{0}, Bytes{1});
    EXPECT_EQ(g.false_lit, 0u);  // dark enough
    EXPECT_NEAR(g.mae_pct, 100.0 * 64.0 / 255.0, 1e-9);
}

TEST(Metrics, AgainstAnAreaLight) {
    const std::vector<float> soft{0.5f, 1.0f, 0.0f};
    const Score s = score(Bytes{128, 255, 0}, Bytes{1, 1, 0}, Bytes{1, 1, 1}, &soft);
    EXPECT_NEAR(s.mae_soft_pct, 100.0 * std::fabs(128.0 / 255.0 - 0.5) / 3.0, 1e-9);
    const std::vector<float> empty;
    EXPECT_DOUBLE_EQ(score(Bytes{0}, Bytes{0}, Bytes{1}, &empty).mae_soft_pct, -1.0);
}

// The penumbra-only error: over the valid pixels whose area-light truth is strictly between 0 and
// 1; fully lit (1), fully shadowed (0) and invalid pixels are left out, however wrong they are.
TEST(Metrics, InsideThePenumbraOnly) {
    const std::vector<float> soft{0.25f, 0.75f, 1.0f, 0.0f, 0.5f, 0.5f};
    //                 penumbra: yes    yes    no (lit) no (shadow) yes  yes but not valid
    const Bytes rendered{0, 255, 0, 255, 255, 0};
    const Bytes valid{1, 1, 1, 1, 1, 0};
    const Score s = score(rendered, Bytes{1, 1, 1, 0, 1, 1}, valid, &soft);
    EXPECT_EQ(s.penumbra, 3u);
    // |0 - 0.25| + |1 - 0.75| + |1 - 0.5| = 1, over 3 pixels.
    EXPECT_NEAR(s.mae_penumbra_pct, 100.0 / 3.0, 1e-9);
    // Over all 5 valid pixels: 1 + |0 - 1| + |1 - 0| = 3.
    EXPECT_NEAR(s.mae_soft_pct, 60.0, 1e-9);
    // No penumbra at all: 0, and 0 pixels; no area-light truth: absent.
    const std::vector<float> hard{1.0f, 0.0f};
    const Score h = score(Bytes{0, 0}, Bytes{1, 0}, Bytes{1, 1}, &hard);
    EXPECT_EQ(h.penumbra, 0u);
    EXPECT_DOUBLE_EQ(h.mae_penumbra_pct, 0.0);
    EXPECT_NEAR(h.mae_soft_pct, 50.0, 1e-9);
    EXPECT_DOUBLE_EQ(score(Bytes{0}, Bytes{0}, Bytes{1}).mae_penumbra_pct, -1.0);
}

TEST(Metrics, SizesMustAgree) {
    EXPECT_THROW(score(Bytes{0, 0}, Bytes{0}, Bytes{1, 1}), std::invalid_argument);
    EXPECT_THROW(score(Bytes{0}, Bytes{0}, Bytes{1, 1}), std::invalid_argument);
    const std::vector<float> soft{0.0f, 0.0f};
    EXPECT_THROW(score(Bytes{0}, Bytes{0}, Bytes{1}, &soft), std::invalid_argument);
    EXPECT_THROW(classify(Bytes{0}, Bytes{0, 0}, Bytes{1}), std::invalid_argument);
}

TEST(Metrics, Classify) {
    EXPECT_EQ(classify(Bytes{0, 255, 0, 255, 9}, Bytes{1, 1, 0, 0, 1}, Bytes{1, 1, 1, 1, 0}),
              (Bytes{1, 0, 0, 2, 3}));
}

TEST(Metrics, ParetoFront) {
    // cost, error: (1, 9) (2, 5) (2, 7) (3, 5) (4, 1) (5, 2)
    const std::vector<Point2> p{{1, 9}, {2, 5}, {2, 7}, {3, 5}, {4, 1}, {5, 2}};
    EXPECT_EQ(pareto_front(p), (std::vector<std::size_t>{0, 1, 4}));
    EXPECT_TRUE(pareto_front({}).empty());
    // Identical points: the first one stands for both.
    EXPECT_EQ(pareto_front({{1, 1}, {1, 1}}), (std::vector<std::size_t>{0}));
    // With a minimum gain, a point barely better than a cheaper one stays off.
    EXPECT_EQ(pareto_front({{1, 2.0}, {2, 1.995}, {3, 1.0}}, 0.01), (std::vector<std::size_t>{0, 2}));
    EXPECT_EQ(pareto_front({{1, 2.0}, {2, 1.995}, {3, 1.0}}), (std::vector<std::size_t>{0, 1, 2}));
    // Non-finite points are never on the front.
    EXPECT_EQ(pareto_front({{NAN, 0}, {2, 3}}), (std::vector<std::size_t>{1}));
}

TEST(Metrics, Median) {
    EXPECT_DOUBLE_EQ(median({}), 0.0);
    EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
    EXPECT_DOUBLE_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
}

}  // namespace
