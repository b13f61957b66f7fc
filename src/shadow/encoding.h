// How a depth in [0,1] is stored in the shadow map, mirrored on the CPU so tests can check the
// shader's arithmetic without a context. The shaders in shaders_gles2/include/pack.glsl do the same
// operations in the same order.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace penumbra::shadow {

enum class Encoding {
    R8,       // depth in the red channel of an RGBA8 texture: 8 bits
    RGBA,     // depth bit-shift packed into four bytes of an RGBA8 texture
    DepthTex  // OES/WEBGL_depth_texture: the depth attachment sampled directly
};

enum class Filter {
    Hard,    // one tap
    PCF2x2,  // 4 taps at +-0.5 texel
    PCF4x4   // 16 taps at +-0.5, +-1.5 texel (Bunnell & Pellacini, GPU Gems ch. 11)
};

// Every value, in the order they are listed to users and swept.
inline constexpr Encoding kAllEncodings[] = {Encoding::R8, Encoding::RGBA, Encoding::DepthTex};
inline constexpr Filter kAllFilters[] = {Filter::Hard, Filter::PCF2x2, Filter::PCF4x4};

std::string_view to_string(Encoding e);
std::string_view to_string(Filter f);

// The sheet's thresholds: 8 bits -> 2^-8 + e = 0.005; bit-shift packing read under mediump,
// whose 10-bit mantissa bounds the unpacked value -> 2^-10 + e = 0.0015. The depth texture is
// 24-bit but the comparison still happens in the fragment shader's float: same bound as rgba.
float default_bias(Encoding e);

// Largest depth that packs without wrapping: 1 - 2^-24 (fract(1.0 * 256^i) would be 0).
inline constexpr float kMaxPackedDepth = 0.99999994f;

// r8: what a unorm8 red channel stores for d, and what the shader reads back.
std::uint8_t pack_r8(float depth);
float unpack_r8(std::uint8_t byte);

// rgba bit-shift packing: byte i = floor(fract(d * 256^i) * 256), i = 0 most significant,
// written as byte/255 so the unorm8 conversion keeps it exactly; unpacked as
// dot(texel, 255 / 256^(i+1)). Exact to 2^-24 for every d in [0,1] under float32.
std::array<std::uint8_t, 4> pack_rgba(float depth);
float unpack_rgba(const std::array<std::uint8_t, 4>& bytes);

}  // namespace penumbra::shadow
