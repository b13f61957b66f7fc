// The encodings on the GPU: a ramp of 65,536 depths plus 0, 1 and 1 - 2^-24, packed by the same
// shader code as the light's pass, read back and unpacked on the CPU, under highp and emulated
// mediump. The CPU mirror (shadow/encoding.h) must predict the bytes the context stored, on any
// conformant GLES 2 implementation: the ramp's depths are exact in float32 (ramp.frag), and the
// packing writes bytes that every unorm8 conversion GLES allows keeps (pack.glsl). Where the rules
// leave a choice, the test allows exactly that choice and says which rule.
#include "gl_fixture.h"

#include <cmath>
#include <cstdio>

#include "gl/device.h"
#include "render/shader_library.h"

using namespace penumbra;

namespace {

constexpr int kWidth = 256;
constexpr int kHeight = 257;       // 256 rows of ramp, one row for the special values
constexpr int kCount = 65536;
constexpr float kQ24 = 1.0f / 16777216.0f;
const glm::vec4 kSpecials{0.0f, 1.0f, 1.0f - kQ24, 0.5f};

// ramp.frag's depth of pixel i: (256 i + (157 i mod 256)) 2^-24, on the 24-bit grid.
float ramp_depth(int i) { return static_cast<float>(256 * i + (157 * i) % 256) * kQ24; }

struct RampCase {
    shadow::Encoding encoding;
    shadow::Precision precision;
};

void PrintTo(const RampCase& c, std::ostream* os) {
    *os << shadow::to_string(c.encoding) << "/" << shadow::to_string(c.precision);
}

// The bytes a ramp of `encoding` packed on this context, 4 per pixel, bottom row first.
std::vector<std::uint8_t> draw_ramp(shadow::Encoding encoding, shadow::Precision precision) {
    gl::Device device;
    gl::TextureDesc td;
    td.width = kWidth;
    td.height = kHeight;
    td.label = "ramp";
    gl::Texture tex(td);
    gl::FramebufferDesc fd;
    fd.color = &tex;
    fd.label = "ramp framebuffer";
    gl::Framebuffer fb(fd);
    device.bind_target({&fb, kWidth, kHeight});
    gl::PipelineState st;
    st.depth_test = false;
    st.cull = gl::Cull::None;
    device.apply(st);
    render::ShaderLibrary lib;
    const gl::Program& p =
        lib.get(render::ramp_variant(encoding, render::DepthPath{precision == shadow::Precision::Mediump}));
    device.use(p);
    p.set("u_width", static_cast<float>(kWidth));
    p.set("u_count", static_cast<float>(kCount));
    p.set("u_specials", kSpecials);
    device.draw_fullscreen();
    auto px = device.read_rgba(kWidth, kHeight);  // bottom row first: index order
    gl::check_errors("the ramp");
    return px;
}

// r8: the shader rounds d * 255 to its byte in float (pack.glsl). GLSL ES 1.00 (4.5.2) fixes no
// rounding for * and +, and a compiler may fuse them (d * 255 + 0.5 in one step): with `bits` of
// precision the sum is known to within a few units of 2^-bits of its size (< 256), so within
// that distance of a tie both bytes are allowed. The lowest and highest byte allowed for d.
std::pair<int, int> r8_allowed(float d, shadow::Precision precision, int bits) {
    const float rounded = precision == shadow::Precision::Mediump ? shadow::round_mediump(d) : d;
    const double exact = static_cast<double>(rounded) * 255.0;  // exact in double
    const double tol = 4.0 * 256.0 * std::ldexp(1.0, -bits);
    return {static_cast<int>(std::floor(exact - tol + 0.5)), static_cast<int>(std::floor(exact + tol + 0.5))};
}

class RampRoundTrip : public test::GlTest, public ::testing::WithParamInterface<RampCase> {};

TEST_P(RampRoundTrip, EveryDepthPacksToTheMirrorsBytes) {
    const RampCase rc = GetParam();
    const bool rgba = rc.encoding == shadow::Encoding::RGBA;
    const bool highp = rc.precision == shadow::Precision::Highp;
    const shadow::PackContext ctx{rc.precision};
    // The context's highp float (glGetShaderPrecisionFormat): float32 has 23 bits after the point.
    // GLSL ES 1.00 (4.5.2) only asks for 16; the bit-shift packing is exact only with 23.
    const int bits = renderer->caps().fragment_highp_float.precision;
    if (bits < 23)
        GTEST_SKIP() << "this context's fragment highp keeps " << bits
                     << " bits; the packing is exact with float32's 23 (GLSL ES 1.00 4.5.2 asks for 16)";

    const auto px = draw_ramp(rc.encoding, rc.precision);
    const auto unpack = [&](size_t i) {
        if (!rgba) return shadow::unpack_r8(px[i * 4], ctx);
        return shadow::unpack_rgba({px[i * 4], px[i * 4 + 1], px[i * 4 + 2], px[i * 4 + 3]}, ctx);
    };
    float worst = 0.0f;
    int mismatch = 0, control = 0, ambiguous = 0;
    for (int i = 0; i < kCount; ++i) {
        const float d = ramp_depth(i);
        const size_t k = static_cast<size_t>(i);
        worst = std::max(worst, std::fabs(unpack(k) - d));
        if (rgba) {
            const auto cpu = shadow::pack_rgba(d, ctx);
            const auto same = [&](const std::array<std::uint8_t, 4>& b) {
                return b[0] == px[k * 4] && b[1] == px[k * 4 + 1] && b[2] == px[k * 4 + 2] && b[3] == px[k * 4 + 3];
            };
            mismatch += !same(cpu);
            // Control: the mirror a step off (2^-24; mediump 2^-10, two of its steps below 1)
            // must miss: the comparison sees a step.
            control += !same(shadow::pack_rgba(d + (highp ? kQ24 : 1.0f / 1024.0f), ctx));
        } else {
            const auto [lo, hi] = r8_allowed(d, rc.precision, bits);
            const int got = px[k * 4];
            ambiguous += lo != hi;
            mismatch += got < lo || got > hi;
            // Control: truncating d * 255 (what a store that truncates makes of the sheet's
            // vec4(z, 0, 0, 1)) must miss about half of the bytes.
            const int floor_byte = static_cast<int>(std::floor(static_cast<double>(d) * 255.0));
            control += floor_byte < lo || floor_byte > hi;
        }
    }
    // Bounds: rgba highp is exact on the 24-bit grid (every ramp depth is on it); r8 half a step;
    // under mediump the quanta of shadow::depth_quantum.
    // (r8: plus the float rounding of byte / 255 and of a byte taken at a tie, a few 1e-7.)
    const float bound = rgba && highp ? 0.0f : shadow::depth_quantum(rc.encoding, rc.precision) + 1e-6f;
    EXPECT_LE(worst, bound) << "largest |unpacked - d| over the ramp";
    // Highp: the mirror's bytes exactly (r8: either byte within float rounding of a tie). Mediump:
    // the emulation's log2 and exp2 (mp() in precision.glsl) have no precision GLSL ES 1.00 fixes
    // (8.2); a handful of values may round to the other half. Allow 0.1 %.
    EXPECT_LE(mismatch, highp ? 0 : kCount / 1000) << "bytes the CPU mirror does not predict";
    EXPECT_GT(control, kCount / 3) << "the control (a mirror that is wrong) must miss";
    char worst_text[32];
    std::snprintf(worst_text, sizeof worst_text, "%.3g", static_cast<double>(worst));
    RecordProperty("worst_error", worst_text);
    RecordProperty("mirror_mismatches", mismatch);
    RecordProperty("r8_near_ties", ambiguous);

    // 0, 1 and 1 - 2^-24.
    const size_t s0 = static_cast<size_t>(kCount);
    EXPECT_EQ(unpack(s0), 0.0f);
    if (rgba && highp) {
        EXPECT_EQ(unpack(s0 + 1), 1.0f - kQ24) << "1 is stored one quantum below, not wrapped to 0";
        EXPECT_EQ(unpack(s0 + 2), 1.0f - kQ24);
    } else {
        const float quantum = shadow::depth_quantum(rc.encoding, rc.precision);
        EXPECT_NEAR(unpack(s0 + 1), 1.0f, quantum + 1e-7f) << "1 must not wrap to 0";
        EXPECT_NEAR(unpack(s0 + 2), 1.0f, quantum + 1e-7f);
    }
}

INSTANTIATE_TEST_SUITE_P(Encodings, RampRoundTrip,
                         ::testing::Values(RampCase{shadow::Encoding::RGBA, shadow::Precision::Highp},
                                           RampCase{shadow::Encoding::RGBA, shadow::Precision::Mediump},
                                           RampCase{shadow::Encoding::R8, shadow::Precision::Highp},
                                           RampCase{shadow::Encoding::R8, shadow::Precision::Mediump}),
                         [](const ::testing::TestParamInfo<RampCase>& i) {
                             return std::string(shadow::to_string(i.param.encoding)) + "_" +
                                    std::string(shadow::to_string(i.param.precision));
                         });

class UnormProbe : public test::GlTest {};

TEST_F(UnormProbe, StoresOneOfTheTwoClosestBytes) {
    // GLES 2.0 (2.1.2) asks for rounding; ES 3.0 (2.1.6.2) allows either of the two closest
    // integers, preferring the nearest; llvmpipe and NVIDIA round, others may truncate. Whatever
    // the context does, each probe byte is one of the two around 0.6, 128.6 and 254.6, and the
    // report says which kind it found.
    // The probe runs when the report first asks for it, not when the renderer is made.
    EXPECT_EQ(renderer->caps().unorm_probe[0], -1);
    const std::string report = renderer->unorm_report();
    const auto& b = renderer->caps().unorm_probe;
    EXPECT_TRUE(b[0] == 0 || b[0] == 1) << b[0];
    EXPECT_TRUE(b[1] == 128 || b[1] == 129) << b[1];
    EXPECT_TRUE(b[2] == 254 || b[2] == 255) << b[2];
    EXPECT_NE(report.find("float -> unorm8 conversion: "), std::string::npos) << report;
    RecordProperty("unorm_probe", report);
}

}  // namespace
