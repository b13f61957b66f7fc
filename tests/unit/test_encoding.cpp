// The depth encodings mirrored on the CPU: what the shader writes, what the texture keeps,
// what the lookup reads back.
#include <gtest/gtest.h>

#include <cmath>

#include "shadow/encoding.h"

using namespace penumbra::shadow;

namespace {
constexpr float kQuantum24 = 1.0f / 16777216.0f;  // 2^-24
}

TEST(Encoding, RgbaRoundTripsZeroOneAndOneMinusQuantum) {
    EXPECT_EQ(unpack_rgba(pack_rgba(0.0f)), 0.0f);
    const float one_minus = 1.0f - kQuantum24;
    EXPECT_EQ(unpack_rgba(pack_rgba(one_minus)), one_minus);
    // 1.0 itself would wrap to 0 (fract(1) = 0): it is clamped to 1 - 2^-24.
    EXPECT_NEAR(unpack_rgba(pack_rgba(1.0f)), 1.0f, kQuantum24);
    EXPECT_GT(unpack_rgba(pack_rgba(1.0f)), 0.5f);
}

TEST(Encoding, RgbaBytesAreTheBitShiftedDigits) {
    // 0.5 + 1/512 = 0x80 0x80 0x00: byte 0 holds the first 8 bits of the fraction.
    const auto b = pack_rgba(0.5f + 1.0f / 512.0f);
    EXPECT_EQ(b[0], 128);
    EXPECT_EQ(b[1], 128);
    EXPECT_EQ(b[2], 0);
    EXPECT_EQ(b[3], 0);
}

TEST(Encoding, RgbaIsExactToTwoToTheMinus24OnEveryStride) {
    // Every 97th 24-bit value (the exhaustive 2^24 sweep belongs to the precision suite).
    float worst = 0.0f;
    for (std::uint32_t i = 0; i < (1u << 24); i += 97) {
        const float d = static_cast<float>(i) * kQuantum24;
        worst = std::max(worst, std::fabs(unpack_rgba(pack_rgba(d)) - d));
    }
    EXPECT_LE(worst, kQuantum24);
}

TEST(Encoding, R8KeepsEightBits) {
    EXPECT_EQ(pack_r8(0.0f), 0);
    EXPECT_EQ(pack_r8(1.0f), 255);
    float worst = 0.0f;
    for (int i = 0; i <= 10000; ++i) {
        const float d = static_cast<float>(i) / 10000.0f;
        worst = std::max(worst, std::fabs(unpack_r8(pack_r8(d)) - d));
    }
    // Rounding to the nearest of 255 steps: error at most half a step, and the sheet's bias
    // 0.005 covers a whole step 2^-8 plus an epsilon.
    EXPECT_LE(worst, 0.5f / 255.0f + 1e-7f);
    EXPECT_GT(sheet_bias(Encoding::R8), 1.0f / 256.0f);
}

TEST(Encoding, DefaultBiasesFollowTheSheet) {
    EXPECT_FLOAT_EQ(sheet_bias(Encoding::R8), 0.005f);
    EXPECT_FLOAT_EQ(sheet_bias(Encoding::RGBA), 0.0015f);
    EXPECT_GT(sheet_bias(Encoding::RGBA), 1.0f / 1024.0f);  // mediump's 10 bits
}
