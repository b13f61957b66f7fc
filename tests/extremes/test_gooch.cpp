// Gooch's soft shadow (--technique gooch) on a GL context, scored against the ray-traced
// area-light truth on the course scene with a light of radius 0.3: the planes and the texture
// variants beside the hard shadow map with PCF 4x4; a light of radius 0 (and one plane) gives
// exactly the planar technique's image; no GL error.
#include "gl_fixture.h"

#include <cstdio>

#include "measure/image_io.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "plan/options.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

constexpr int kSize = 512;
constexpr float kRadius = 0.3f;
constexpr double kTime = 0.6;
// Mean abs error against the area-light truth, % (measured on llvmpipe: planes 1.26, texture 0.80;
// shadow map PCF 4x4 1.76, planar 2.19), with margin.
constexpr double kPlanesBound = 1.6;
constexpr double kTextureBound = 1.2;

struct Frame {
    measure::Score score;
    int grey = 0;  // valid pixels strictly between 10 and 245 of 255: partly lit
};

class Gooch : public test::GlTest {
protected:
    static void SetUpTestSuite() {
        course = new scene::CourseScene(scene::make_course_scene(10));
        scene::animate_course(*course, kTime, kTime);
        measure::TruthOptions to;
        to.width = kSize;
        to.height = kSize;
        to.view_proj = render::camera_view(course->scene, render::offscreen(kSize, kSize)).view_proj;
        to.soft_samples = 64;
        to.light_radius = kRadius;
        truth = new measure::TruthImage(measure::RayTracer(course->scene).render(to));
    }
    static void TearDownTestSuite() {
        delete truth;
        delete course;
        truth = nullptr;
        course = nullptr;
    }

    std::vector<std::uint8_t> render(render::Settings s, render::Aov aov) {
        s.aov = aov;
        const render::FrameInputs in = render::offscreen(kSize, kSize);
        EXPECT_EQ(renderer->check(course->scene, s, in), "") << render::to_args(s);
        renderer->render(course->scene, s, in);
        EXPECT_EQ(gl::take_error(), 0u) << render::to_args(s);
        return renderer->read_image();
    }

    Frame score(const render::Settings& s, const char* name) {
        const std::vector<std::uint8_t> rgba = render(s, render::Aov::Visibility);
        const std::vector<std::uint8_t> red = measure::from_rgba(rgba, kSize, kSize, 1).data;  // both top row first
        Frame f;
        f.score = measure::score(red, truth->lit, truth->valid_mask(), &truth->soft);
        for (size_t i = 0; i < red.size(); ++i)
            if (truth->valid(i) && red[i] > 10 && red[i] < 245) ++f.grey;
        std::printf("course scene t = %.1f, light radius %.1f, %dx%d: %-28s mean abs error vs area-light truth %.2f %%"
                    " (vs hard truth %.2f %%), %d grey pixels\n",
                    kTime, static_cast<double>(kRadius), kSize, kSize, name, f.score.mae_soft_pct, f.score.mae_pct, f.grey);
        return f;
    }

    static scene::CourseScene* course;
    static measure::TruthImage* truth;
};

scene::CourseScene* Gooch::course = nullptr;
measure::TruthImage* Gooch::truth = nullptr;

render::Settings gooch(render::GoochMethod m, float radius, int planes = 8) {
    render::Settings s;
    s.technique = render::Technique::Gooch;
    s.gooch_method = m;
    s.gooch_planes = planes;
    s.light_radius = radius;
    return s;
}

}  // namespace

TEST_F(Gooch, SoftShadowsAgainstTheAreaLightTruth) {
    render::Settings pcf;
    pcf.filter = shadow::Filter::PCF4x4;
    pcf.light_radius = kRadius;
    render::Settings planar;
    planar.technique = render::Technique::Planar;
    const Frame hard = score(pcf, "shadowmap pcf4x4 (hard)");
    const Frame flat = score(planar, "planar (hard)");
    const Frame planes = score(gooch(render::GoochMethod::Planes, kRadius), "gooch planes, 8 planes");
    const Frame texture = score(gooch(render::GoochMethod::Texture, kRadius), "gooch texture, 8 taps");
    // Soft: visibly grey pixels where the hard techniques have (almost) none.
    EXPECT_GT(planes.grey, 4 * flat.grey + 500);
    EXPECT_GT(texture.grey, 4 * flat.grey + 500);
    // Against the soft truth: nearer than the planar technique's hard edge, and within bounds.
    EXPECT_LT(planes.score.mae_soft_pct, flat.score.mae_soft_pct);
    EXPECT_LT(planes.score.mae_soft_pct, kPlanesBound);
    EXPECT_LT(texture.score.mae_soft_pct, kTextureBound);
    EXPECT_LT(texture.score.mae_soft_pct, hard.score.mae_soft_pct);
}

// A light of radius 0: every plane is the ground, and the image is the planar technique's, byte for
// byte (colour and visibility); so is one plane under a light with a radius.
TEST_F(Gooch, RadiusZeroIsExactlyThePlanarShadow) {
    render::Settings planar;
    planar.technique = render::Technique::Planar;
    for (render::Aov aov : {render::Aov::Color, render::Aov::Visibility}) {
        const auto want = render(planar, aov);
        EXPECT_EQ(render(gooch(render::GoochMethod::Planes, 0.0f), aov), want) << render::to_string(aov);
        EXPECT_EQ(render(gooch(render::GoochMethod::Planes, kRadius, 1), aov), want) << render::to_string(aov);
    }
}

// Every plane lighting a pixel adds up to exactly 255 in the visibility AOV (the weights are whole
// bytes summing to 255): the lit ground is as white as the planar technique's.
TEST_F(Gooch, FullyLitGroundIsExactlyWhite) {
    for (int k : {3, 7, 8, 16}) {
        const auto v = render(gooch(render::GoochMethod::Planes, kRadius, k), render::Aov::Visibility);
        const auto p = [&](int x, int y) { return v[(static_cast<size_t>(y) * kSize + x) * 4]; };
        // The table near its front right corner (the image's lower right, top row first) is lit.
        EXPECT_EQ(p(kSize * 3 / 4, kSize * 7 / 8), 255) << k << " planes";
    }
}
