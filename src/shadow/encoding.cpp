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
    }
    return "?";
}

float default_bias(Encoding e) {
    switch (e) {
        case Encoding::R8: return 0.005f;
        case Encoding::RGBA: return 0.0015f;
        case Encoding::DepthTex: return 0.0015f;
    }
    return 0.005f;
}

namespace {
// GLES 2.0 section 2.1.2: a float written to a normalized fixed-point channel becomes
// round(clamp(c,0,1) * 255).
std::uint8_t to_unorm8(float c) {
    const float v = std::clamp(c, 0.0f, 1.0f) * 255.0f;
    return static_cast<std::uint8_t>(std::lround(v));
}
}  // namespace

std::uint8_t pack_r8(float depth) { return to_unorm8(depth); }

float unpack_r8(std::uint8_t byte) { return static_cast<float>(byte) / 255.0f; }

std::array<std::uint8_t, 4> pack_rgba(float depth) {
    const float d = std::clamp(depth, 0.0f, kMaxPackedDepth);
    const float shift[4] = {1.0f, 256.0f, 65536.0f, 16777216.0f};
    std::array<std::uint8_t, 4> out{};
    for (int i = 0; i < 4; ++i) {
        const float scaled = d * shift[i];                       // exact: a power-of-two scale
        const float e = scaled - std::floor(scaled);             // fract
        const float byte = std::floor(e * 256.0f);               // exact
        out[static_cast<size_t>(i)] = to_unorm8(byte / 255.0f);  // what the texture stores
    }
    return out;
}

float unpack_rgba(const std::array<std::uint8_t, 4>& bytes) {
    // The shader sees texel = byte/255 and computes dot(texel, 255/256^(i+1)).
    const float weight[4] = {255.0f / 256.0f, 255.0f / 65536.0f, 255.0f / 16777216.0f, 255.0f / 4294967296.0f};
    float sum = 0.0f;
    for (int i = 0; i < 4; ++i) sum += (static_cast<float>(bytes[static_cast<size_t>(i)]) / 255.0f) * weight[i];
    return sum;
}

}  // namespace penumbra::shadow
