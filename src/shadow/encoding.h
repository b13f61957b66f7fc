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
    PCF4x4,  // 16 taps at +-0.5, +-1.5 texel (Bunnell & Pellacini, GPU Gems ch. 11)
    PCSS     // percentage-closer soft shadows (Fernando 2005): a blocker search, then a PCF whose
             // width follows from the light's size and the blocker's and receiver's depths
};

// How a PCF kernel with taps inside its corners (PCF 4x4) is evaluated (shadow/pcf.h).
enum class PcfKernel {
    EarlyExit,  // the 4 corner taps first; where they agree (all lit or all shadowed), that is the answer
    Full        // every tap, always (the course's kernel)
};

// Every value, in the order they are listed to users and swept.
inline constexpr Encoding kAllEncodings[] = {Encoding::R8, Encoding::RGBA, Encoding::DepthTex};
inline constexpr Filter kAllFilters[] = {Filter::Hard, Filter::PCF2x2, Filter::PCF4x4, Filter::PCSS};
inline constexpr PcfKernel kAllPcfKernels[] = {PcfKernel::EarlyExit, PcfKernel::Full};

std::string_view to_string(Encoding e);
std::string_view to_string(Filter f);
std::string_view to_string(PcfKernel k);

// The sheet's thresholds: 8 bits -> 2^-8 + e = 0.005; bit-shift packing read under mediump,
// whose 10-bit mantissa bounds the unpacked value -> 2^-10 + e = 0.0015. The depth texture is
// 24-bit but the comparison still happens in the fragment shader's float: same bound as rgba.
float sheet_bias(Encoding e);

// Largest depth that packs without wrapping: 1 - 2^-24 (fract(1.0 * 256^i) would be 0), and
// under mediump the largest half below 1, 1 - 2^-11.
inline constexpr float kMaxPackedDepth = 0.99999994f;
inline constexpr float kMaxPackedDepthMediump = 0.99951171875f;

// The float precision the depth path is computed in. Highp: float32 (or whatever the context's
// highp is). Mediump: emulated half precision (see round_mediump), so a desktop whose mediump is
// float32 (llvmpipe, SwiftShader) shows what a phone's fp16 mediump does.
enum class Precision { Highp, Mediump };
std::string_view to_string(Precision p);

// How a context may turn a float colour into a unorm8 byte: GLES 2.0 (2.1.2) asks for
// round(c * 255), ES 3.0 (2.1.6.2) allows either of the two closest integers, and some
// implementations truncate. The packing does not depend on it: every byte is written as
// (byte + 0.25) / 255 (pack.glsl's UNORM_OFFSET), which each of these stores keeps as that byte.
// The renderer still probes what its context does (`penumbra caps` prints it), and the CPU mirror
// takes the store as a parameter so the tests can show the bytes are the same under both.
enum class UnormRounding { Round, Floor };
std::string_view to_string(UnormRounding r);

// What a store of this kind keeps of the colour v: round(clamp(v) * 255) or floor(clamp(v) * 255).
std::uint8_t store_unorm8(float v, UnormRounding r);

struct PackContext {
    Precision precision = Precision::Highp;
    UnormRounding rounding = UnormRounding::Round;
};

// Half precision as the shaders emulate it (EMULATE_MEDIUMP): round to 11 significant bits,
// ties away from zero; magnitudes below 2^-14 (fp16's smallest normal) flush to 0; clamp at 65504.
float round_mediump(float x);

// r8: the byte the shader rounds d to (floor(d * 255 + 0.5), in float32; not left to the
// store, whose rounding at the ties differs between contexts), what a unorm8 red channel
// stores for d, and what the shader reads back.
float r8_byte(float depth, PackContext c = {});
std::uint8_t pack_r8(float depth, PackContext c = {});
float unpack_r8(std::uint8_t byte, PackContext c = {});

// rgba bit-shift packing: byte i = floor(fract(d * 256^i) * 256), i = 0 most significant,
// written as (byte + 0.25)/255 so any unorm8 conversion keeps it exactly; unpacked as
// dot(texel, 255 / 256^(i+1)). Exact to 2^-24 for every d in [0,1] under float32; under
// mediump every step is rounded as the shader's emulation rounds it.
std::array<std::uint8_t, 4> pack_rgba(float depth, PackContext c = {});
float unpack_rgba(const std::array<std::uint8_t, 4>& bytes, PackContext c = {});

// The sheet's answer's bit-shift packing as the sheet prints it (render::sheet_answer, the shader
// lab's reference): channel i = fract(d 256^i) - fract(d 256^(i+1)) / 256 (the last keeps its
// fraction), multiples of 1/256 that the store turns into bytes of 1/255; read back as
// dot(texel, 1/256^i). Not exact: a store that rounds keeps up to half a step less or more per
// channel, so depths read back up to 0.00195 nearer or farther (docs/snippets.md); a store that
// truncates, up to 0.0039 nearer. In double precision, as exact arithmetic would give.
std::array<std::uint8_t, 4> sheet_pack_rgba(double depth, UnormRounding r);
double sheet_unpack_rgba(const std::array<std::uint8_t, 4>& bytes);

// The depth quantum of an encoding under a precision: the largest error of a stored-then-read
// depth (r8: half a step of 1/255, plus 2^-11 under mediump; rgba: 2^-24 under highp, 2^-11 under mediump (half of fp16's
// 2^-10 step below 1); depthtex: 2^-24 for a 24-bit depth, 2^-11 once the read is mediump).
float depth_quantum(Encoding e, Precision p);

// --bias auto: the constant part (the encoding's quantum plus the rounding of the comparison
// itself); the slope part scales with the kernel's reach (shadow/pcf.h).
float auto_bias_constant(Encoding e, Precision p);

}  // namespace penumbra::shadow
