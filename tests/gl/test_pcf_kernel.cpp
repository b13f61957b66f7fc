// PCF 4x4's early exit (--pcf-kernel early-exit, the default) against the full kernel (--pcf-kernel
// full, the course's) on the course scene: the same frames' visibility images differ only where the
// full kernel found a fraction and the early exit the corners' 0 or 1 (shadow/pcf.h), and there in
// few pixels. Which pixels those are is the GPU's business; the CPU mirror's exhaustive test
// (tests/unit/test_plan.cpp, PcfKernel.*) covers every pattern of taps.
#include "gl_fixture.h"

#include "plan/options.h"
#include "scene/scene_source.h"

using namespace penumbra;

namespace {

class PcfKernelGl : public test::GlTest {};

struct Tally {
    int differ = 0;         // pixels whose visibility differs between the kernels
    int full_fraction = 0;  // pixels the full kernel leaves strictly between 0 and 255: its penumbra
    int unexplained = 0;    // differing pixels where early is not 0 or 255, or full is
};

// The bounds: measured with this test's settings (512x512, map 1024, rgba, bias auto) at t = 0,
// 0.7, 1.5, 3 and 4.5 on llvmpipe the early exit changed 11, 36, 18, 4 and 12 pixels of 262,144,
// 0.42%, 1.01%, 1.04%, 0.38% and 0.67% of the full kernel's penumbra pixels (1056 to 3570). A changed pixel is one whose 4 corner taps agree while an inner tap
// does not: a shadow edge or a thin caster (the teapot's handle and spout seen edge-on by the
// light) narrower than the kernel's 3 texels between its corners. The bounds leave about 2x room
// for another CPU's rounding on edge pixels, not for an exit that fires inside the penumbra.
constexpr double kMaxShareOfPenumbra = 0.025;
constexpr double kMaxShareOfImage = 0.0003;  // 78 pixels of 512x512

TEST_F(PcfKernelGl, TheEarlyExitChangesFewPenumbraPixelsOfTheCourseScene) {
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(src.open("teapot", error, warnings)) << error;
    constexpr int kSize = 512;
    const render::FrameInputs in = render::offscreen(kSize, kSize);
    render::Settings s;
    s.filter = shadow::Filter::PCF4x4;
    s.bias_auto = true;
    // The course's map, as this test was measured with: the shadows fit's cut window gives the teapot's
    // shadow more texels, so fewer penumbra pixels than the 500 the comparison needs at t = 0.
    s.light_fit = render::LightFit::Tight;
    s.aov = render::Aov::Visibility;
    const auto visibility = [&](double t, shadow::PcfKernel k) {
        s.pcf_kernel = k;
        EXPECT_EQ(renderer->check(src.at(t), s, in), "");
        renderer->render(src.at(t), s, in);
        return measure::from_rgba(renderer->read_image(), kSize, kSize, 1);
    };
    int total_differ = 0;
    for (const double t : {0.0, 0.7, 1.5, 3.0, 4.5}) {
        const measure::Pixels full = visibility(t, shadow::PcfKernel::Full);
        const measure::Pixels early = visibility(t, shadow::PcfKernel::EarlyExit);
        Tally n;
        for (size_t i = 0; i < full.data.size(); ++i) {
            const int f = full.data[i], e = early.data[i];
            const bool fraction = f != 0 && f != 255;
            n.full_fraction += fraction;
            if (f == e) continue;
            ++n.differ;
            n.unexplained += !fraction || (e != 0 && e != 255);
        }
        const std::string at = "t = " + std::to_string(t) + ": " + std::to_string(n.differ) + " pixels differ, " +
                               std::to_string(n.full_fraction) + " in the full kernel's penumbra";
        EXPECT_EQ(n.unexplained, 0) << at;
        ASSERT_GT(n.full_fraction, 500) << at << ": the frame should have a penumbra to measure";
        EXPECT_LE(n.differ, kMaxShareOfPenumbra * n.full_fraction) << at;
        EXPECT_LE(n.differ, kMaxShareOfImage * kSize * kSize) << at;
        total_differ += n.differ;
    }
    // The exit is in the shader at all: somewhere over these frames it fires where the full kernel
    // has a fraction (a check that passes with both kernels the same would prove nothing).
    EXPECT_GT(total_differ, 0);
}

}  // namespace
