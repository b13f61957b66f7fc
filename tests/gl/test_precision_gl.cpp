// The encodings on the GPU: a ramp of 65,536 depths plus 0, 1 and 1 - 2^-24, packed by the same
// shader code as the light's pass, read back and unpacked on the CPU, under highp and emulated
// mediump. The CPU mirror (shadow/encoding.h) must agree with what the context stored.
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

struct RampCase {
    shadow::Encoding encoding;
    shadow::Precision precision;
};

void PrintTo(const RampCase& c, std::ostream* os) {
    *os << shadow::to_string(c.encoding) << "/" << shadow::to_string(c.precision);
}

class RampRoundTrip : public test::GlTest, public ::testing::WithParamInterface<RampCase> {};

TEST_P(RampRoundTrip, EveryDepthReadsBackWithinTheQuantum) {
    const RampCase rc = GetParam();
    const shadow::PackContext ctx{rc.precision, renderer->unorm_rounding()};
    const render::DepthPath path{rc.precision == shadow::Precision::Mediump,
                                 ctx.rounding == shadow::UnormRounding::Floor};

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
    const gl::Program& p = lib.get(render::ramp_variant(rc.encoding, path));
    device.use(p);
    p.set("u_width", static_cast<float>(kWidth));
    p.set("u_count", static_cast<float>(kCount));
    p.set("u_specials", kSpecials);
    device.draw_fullscreen();
    const auto px = device.read_rgba(kWidth, kHeight);  // bottom row first: index order
    gl::check_errors("the ramp");

    const bool rgba = rc.encoding == shadow::Encoding::RGBA;
    const auto unpack = [&](size_t i) {
        if (!rgba) return shadow::unpack_r8(px[i * 4], ctx);
        return shadow::unpack_rgba({px[i * 4], px[i * 4 + 1], px[i * 4 + 2], px[i * 4 + 3]}, ctx);
    };
    const float quantum = shadow::depth_quantum(rc.encoding, rc.precision);
    float worst = 0.0f;
    int mirror_mismatch = 0;
    for (int i = 0; i < kCount; ++i) {
        const float d = static_cast<float>(i) / static_cast<float>(kCount - 1);
        const size_t k = static_cast<size_t>(i);
        worst = std::max(worst, std::fabs(unpack(k) - d));
        if (rgba) {
            const auto cpu = shadow::pack_rgba(d, ctx);
            mirror_mismatch += cpu[0] != px[k * 4] || cpu[1] != px[k * 4 + 1] || cpu[2] != px[k * 4 + 2] ||
                               cpu[3] != px[k * 4 + 3];
        } else {
            mirror_mismatch += shadow::pack_r8(d, ctx) != px[k * 4];
        }
    }
    // Truncating to the 24-bit grid costs < 2^-24 under highp; the other bounds are the quanta.
    const float bound = rgba && rc.precision == shadow::Precision::Highp ? kQ24 : quantum;
    EXPECT_LE(worst, bound + 1e-7f) << "largest |unpacked - d| over the ramp";
    // The CPU mirror predicts the GPU's bytes (mediump: the shader's log2/exp2 may round a
    // handful of values differently from frexp; allow 0.1%).
    EXPECT_LE(mirror_mismatch, rc.precision == shadow::Precision::Highp ? 0 : kCount / 1000);
    char worst_text[32];
    std::snprintf(worst_text, sizeof worst_text, "%.3g", static_cast<double>(worst));
    RecordProperty("worst_error", worst_text);
    RecordProperty("mirror_mismatches", mirror_mismatch);

    // 0, 1 and 1 - 2^-24.
    const size_t s0 = static_cast<size_t>(kCount);
    EXPECT_EQ(unpack(s0), 0.0f);
    if (rgba && rc.precision == shadow::Precision::Highp) {
        EXPECT_EQ(unpack(s0 + 1), 1.0f - kQ24) << "1 is stored one quantum below, not wrapped to 0";
        EXPECT_EQ(unpack(s0 + 2), 1.0f - kQ24);
    } else {
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

TEST_F(UnormProbe, LlvmpipeRounds) {
    // GLES 2.0 asks for rounding and Mesa's llvmpipe does it; the probe must find that.
    EXPECT_EQ(renderer->unorm_rounding(), shadow::UnormRounding::Round);
}

}  // namespace
