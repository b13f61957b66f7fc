#include "shadow/encoding.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadow {

std::string_view to_string(Encoding e) {
    switch (e) {
        case Encoding::R8: return "r8";
        case Encoding::RGBA: return "rgba";
        case Encoding::DepthTex: return "depthtex";
    }
    return "?";
}

std::string_view to_string(Filter f) {
    switch (f) {
        case Filter::Hard: return "hard";
        case Filter::PCF2x2: return "pcf2x2";
        case Filter::PCF4x4: return "pcf4x4";
        case Filter::PCSS: return "pcss";
    }
    return "?";
}

std::string_view to_string(PcfKernel k) { return k == PcfKernel::EarlyExit ? "early-exit" : "full"; }

std::string_view to_string(Precision p) { return p == Precision::Highp ? "highp" : "mediump"; }
std::string_view to_string(UnormRounding r) { return r == UnormRounding::Round ? "round" : "floor"; }

float sheet_bias(Encoding e) {
    switch (e) {
        case Encoding::R8: return 0.005f;
        case Encoding::RGBA: return 0.0015f;
        case Encoding::DepthTex: return 0.0015f;
    }
    return 0.005f;
}

float round_mediump(float x) {
    const float a = std::fabs(x);
    if (!(a >= 6.103515625e-05f)) return 0.0f;  // below fp16's smallest normal (and NaN): 0
    int e = 0;
    std::frexp(a, &e);                    // a = m * 2^e, m in [0.5, 1)
    const float scale = std::ldexp(1.0f, 11 - e);  // 11 significant bits
    const float r = std::min(std::floor(a * scale + 0.5f) / scale, 65504.0f);
    return std::copysign(r, x);
}

namespace {

float mp(float x, const PackContext& c) { return c.precision == Precision::Mediump ? round_mediump(x) : x; }

// pack.glsl's UNORM_OFFSET: a byte b is written as (b + 0.25) / 255.
constexpr float kUnormOffset = 0.25f;

}  // namespace

std::uint8_t store_unorm8(float v, UnormRounding r) {
    const float x = std::clamp(v, 0.0f, 1.0f) * 255.0f;
    return static_cast<std::uint8_t>(r == UnormRounding::Round ? std::lround(x) : static_cast<long>(std::floor(x)));
}

float r8_byte(float depth, PackContext c) { return std::floor(mp(depth, c) * 255.0f + 0.5f); }

std::uint8_t pack_r8(float depth, PackContext c) {
    return store_unorm8(mp((r8_byte(depth, c) + kUnormOffset) / 255.0f, c), c.rounding);
}

float unpack_r8(std::uint8_t byte, PackContext c) { return mp(static_cast<float>(byte) / 255.0f, c); }

std::array<std::uint8_t, 4> pack_rgba(float depth, PackContext c) {
    const float max = c.precision == Precision::Mediump ? kMaxPackedDepthMediump : kMaxPackedDepth;
    const float d = std::clamp(mp(depth, c), 0.0f, max);
    const float shift[4] = {1.0f, 256.0f, 65536.0f, 16777216.0f};
    std::array<std::uint8_t, 4> out{};
    for (int i = 0; i < 4; ++i) {
        const float scaled = mp(d * shift[i], c);        // exact under highp: a power-of-two scale
        const float e = mp(scaled - std::floor(scaled), c);  // fract
        const float byte = std::floor(e * 256.0f);       // exact
        out[static_cast<size_t>(i)] = store_unorm8(mp((byte + kUnormOffset) / 255.0f, c), c.rounding);
    }
    return out;
}

float unpack_rgba(const std::array<std::uint8_t, 4>& bytes, PackContext c) {
    // The shader sees texel = byte/255 and computes dot(texel, 255/256^(i+1)).
    const float weight[4] = {255.0f / 256.0f, 255.0f / 65536.0f, 255.0f / 16777216.0f, 255.0f / 4294967296.0f};
    float sum = 0.0f;
    for (int i = 0; i < 4; ++i)
        sum += mp(static_cast<float>(bytes[static_cast<size_t>(i)]) / 255.0f, c) * mp(weight[i], c);
    return mp(sum, c);
}

std::array<std::uint8_t, 4> sheet_pack_rgba(double depth, UnormRounding r) {
    double digit[5];
    for (int i = 0; i < 5; ++i) {
        const double scaled = depth * std::pow(256.0, i);
        digit[i] = scaled - std::floor(scaled);
    }
    std::array<std::uint8_t, 4> out{};
    for (int i = 0; i < 4; ++i) {
        const double c = i < 3 ? digit[i] - digit[i + 1] / 256.0 : digit[3];
        const double v = std::clamp(c, 0.0, 1.0) * 255.0;
        out[static_cast<size_t>(i)] = static_cast<std::uint8_t>(r == UnormRounding::Round ? std::floor(v + 0.5) : std::floor(v));
    }
    return out;
}

double sheet_unpack_rgba(const std::array<std::uint8_t, 4>& bytes) {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) sum += bytes[static_cast<size_t>(i)] / 255.0 / std::pow(256.0, i);
    return sum;
}

float depth_quantum(Encoding e, Precision p) {
    const float mediump_read = 1.0f / 2048.0f;  // half of fp16's 2^-10 step just below 1
    switch (e) {
        // Half a step of 1/255; under mediump the depth is rounded to a half on the way in and
        // the texel on the way out, 2^-12 each.
        case Encoding::R8: return 0.5f / 255.0f + (p == Precision::Mediump ? mediump_read : 0.0f);
        case Encoding::RGBA:
        case Encoding::DepthTex: return p == Precision::Mediump ? mediump_read : 1.0f / 16777216.0f;
    }
    return 0.5f / 255.0f;
}

float auto_bias_constant(Encoding e, Precision p) {
    // The stored depth's error, plus the same again for the fragment's own depth once it is
    // rounded for the comparison (mediump), plus a floor for the rasteriser's and the
    // interpolator's float32 noise (measured a few 1e-6 on llvmpipe; 2e-5 leaves margin).
    const float compare = p == Precision::Mediump ? 1.0f / 2048.0f : 0.0f;
    return depth_quantum(e, p) + compare + 2e-5f;
}

}  // namespace penumbra::shadow
