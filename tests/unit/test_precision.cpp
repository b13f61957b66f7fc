// The precision model (docs/precision.md), checked exhaustively on the CPU mirror of the shaders:
// every one of the 2^24 depths through pack and unpack, under highp and emulated mediump, with a
// context that rounds and one that truncates float -> unorm8 (the same bytes either way).
#include <gtest/gtest.h>

#include <cmath>

#include "shadow/encoding.h"
#include "shadow/pcf.h"

using namespace penumbra::shadow;

namespace {

constexpr float kQ24 = 1.0f / 16777216.0f;

struct Worst {
    float error = 0.0f;
    float at = 0.0f;
};

template <typename F>
Worst sweep_all_24_bit_depths(F&& roundtrip) {
    Worst w;
    for (std::uint32_t i = 0; i < (1u << 24); ++i) {
        const float d = static_cast<float>(i) * kQ24;
        const float e = std::fabs(roundtrip(d) - d);
        if (e > w.error) w = {e, d};
    }
    return w;
}

TEST(Precision, RoundMediumpKeepsElevenSignificantBits) {
    EXPECT_EQ(round_mediump(0.0f), 0.0f);
    EXPECT_EQ(round_mediump(1.0f), 1.0f);
    EXPECT_EQ(round_mediump(-0.5f), -0.5f);
    // 1 + 2^-10 is a half; 1 + 2^-11 ties and rounds away from zero; 1 + 2^-12 rounds down.
    EXPECT_EQ(round_mediump(1.0f + 1.0f / 1024.0f), 1.0f + 1.0f / 1024.0f);
    EXPECT_EQ(round_mediump(1.0f + 1.0f / 2048.0f), 1.0f + 1.0f / 1024.0f);
    EXPECT_EQ(round_mediump(1.0f + 1.0f / 4096.0f), 1.0f);
    EXPECT_EQ(round_mediump(0.99999994f), 1.0f);  // highp's largest packable depth is 1 in mediump
    EXPECT_EQ(round_mediump(1e-5f), 0.0f);        // below the smallest normal half
    EXPECT_EQ(round_mediump(1e6f), 65504.0f);     // the largest half
    for (float x = 1.0f / 1024.0f; x < 1.0f; x *= 1.37f) {
        const float r = round_mediump(x);
        EXPECT_LE(std::fabs(r - x), x / 2048.0f + 1e-12f) << x;
        EXPECT_EQ(round_mediump(r), r) << "rounding is idempotent at " << x;
    }
}

TEST(Precision, RgbaHighpIsExactForEvery24BitDepth) {
    for (auto rounding : {UnormRounding::Round, UnormRounding::Floor}) {
        const PackContext c{Precision::Highp, rounding};
        const Worst w = sweep_all_24_bit_depths([&](float d) { return unpack_rgba(pack_rgba(d, c), c); });
        // Every d = k 2^-24 packs into its own bytes and reads back unchanged.
        EXPECT_EQ(w.error, 0.0f) << to_string(rounding) << ": worst at " << w.at;
    }
    EXPECT_EQ(unpack_rgba(pack_rgba(1.0f)), 1.0f - kQ24);  // 1 is kept one quantum below
}

TEST(Precision, RgbaMediumpIsBoundedByTheSheetsTenBits) {
    for (auto rounding : {UnormRounding::Round, UnormRounding::Floor}) {
        const PackContext c{Precision::Mediump, rounding};
        const Worst w = sweep_all_24_bit_depths([&](float d) { return unpack_rgba(pack_rgba(d, c), c); });
        // Rounding d to a half costs up to 2^-12 below 1 (2^-11 at the clamp to 1 - 2^-11); the
        // unpacked sum is rounded again: within the quantum depth_quantum reports, 2^-11, which
        // is below the sheet's 2^-10 and so below its 0.0015.
        EXPECT_LE(w.error, depth_quantum(Encoding::RGBA, Precision::Mediump)) << "worst at " << w.at;
        EXPECT_GT(w.error, 1.0f / 65536.0f) << "mediump must lose bits, or the emulation is not on";
        EXPECT_LT(w.error + 1.0f / 4096.0f, sheet_bias(Encoding::RGBA));
    }
}

TEST(Precision, R8IsBoundedByHalfAStep) {
    for (auto p : {Precision::Highp, Precision::Mediump})
        for (auto rounding : {UnormRounding::Round, UnormRounding::Floor}) {
            const PackContext c{p, rounding};
            const Worst w = sweep_all_24_bit_depths([&](float d) { return unpack_r8(pack_r8(d, c), c); });
            // Half of 1/255, plus mediump's rounding of the value on the way in and out.
            const float bound = 0.5f / 255.0f + (p == Precision::Mediump ? 2.0f / 2048.0f : 1e-7f);
            EXPECT_LE(w.error, bound) << to_string(p) << "/" << to_string(rounding) << " worst at " << w.at;
            EXPECT_GT(w.error, 0.45f / 255.0f);  // the 8-bit step really is there
        }
}

TEST(Precision, EveryStoreKeepsTheSameBytes) {
    // The packing does not depend on how the context converts float -> unorm8: for every 24-bit
    // depth, a store that rounds and one that truncates keep the same bytes (rgba and r8, highp
    // and mediump).
    for (auto p : {Precision::Highp, Precision::Mediump}) {
        const PackContext round{p, UnormRounding::Round}, floor{p, UnormRounding::Floor};
        std::uint32_t differ = 0;
        for (std::uint32_t i = 0; i < (1u << 24); ++i) {
            const float d = static_cast<float>(i) * kQ24;
            differ += pack_rgba(d, round) != pack_rgba(d, floor);
            differ += pack_r8(d, round) != pack_r8(d, floor);
        }
        EXPECT_EQ(differ, 0u) << to_string(p);
    }
}

TEST(Precision, EveryByteReachesTheStoreAQuarterIntoItsStep) {
    // Why any conversion keeps it: byte b is written as (b + 0.25)/255, which reaches the store as
    // b + 0.25 within float32's rounding (mediump's: 2^-12 of 255, 0.06 of a step), a quarter step
    // from both the tie (b + 0.5, where rounding could go up) and the byte below (where truncation
    // would go). A store whose conversion is off by less than 0.1 step (the H100 log suggests
    // NVIDIA's is about 0.06 off at the ties) keeps every byte.
    for (int b = 0; b < 256; ++b) {
        const float written = (static_cast<float>(b) + 0.25f) / 255.0f;
        for (float v : {written, round_mediump(written)}) {
            const float at = v * 255.0f - static_cast<float>(b);
            EXPECT_GE(at, 0.15f) << b;
            EXPECT_LE(at, 0.35f) << b;
        }
    }
}

TEST(Precision, ControlTruncatingByteOver255LosesBytes) {
    // The control: written as b/255 (no offset) by a shader whose output is a half (mediump), the
    // colour reaches the store below b for about half of the bytes, and a store that truncates
    // keeps b - 1 there (one that rounds keeps b). Without the offset the tests above would fail.
    int lost = 0, lost_rounding = 0;
    for (int b = 0; b < 256; ++b) {
        const float stored = round_mediump(static_cast<float>(b) / 255.0f) * 255.0f;
        lost += static_cast<int>(std::floor(stored)) != b;
        lost_rounding += static_cast<int>(std::lround(stored)) != b;
    }
    EXPECT_GT(lost, 64);
    EXPECT_EQ(lost_rounding, 0);
    RecordProperty("bytes_lost_without_offset", lost);
}

TEST(Precision, QuantaAndAutoBiasConstants) {
    EXPECT_FLOAT_EQ(depth_quantum(Encoding::R8, Precision::Highp), 0.5f / 255.0f);
    EXPECT_FLOAT_EQ(depth_quantum(Encoding::RGBA, Precision::Highp), kQ24);
    EXPECT_FLOAT_EQ(depth_quantum(Encoding::RGBA, Precision::Mediump), 1.0f / 2048.0f);
    EXPECT_FLOAT_EQ(depth_quantum(Encoding::DepthTex, Precision::Highp), kQ24);
    // The sheet's thresholds sit above the quanta: 2^-8 + e = 0.005 and 2^-10 + e = 0.0015.
    EXPECT_GT(sheet_bias(Encoding::R8), 2.0f * depth_quantum(Encoding::R8, Precision::Highp));
    EXPECT_GT(sheet_bias(Encoding::RGBA), 2.0f * depth_quantum(Encoding::RGBA, Precision::Mediump));
    for (auto e : kAllEncodings)
        for (auto p : {Precision::Highp, Precision::Mediump})
            EXPECT_GT(auto_bias_constant(e, p), depth_quantum(e, p));
    EXPECT_LT(kernel_reach_texels(Filter::Hard), kernel_reach_texels(Filter::PCF2x2));
    EXPECT_LT(kernel_reach_texels(Filter::PCF2x2), kernel_reach_texels(Filter::PCF4x4));
}

}  // namespace
