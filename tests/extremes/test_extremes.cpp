// The numerical extremes: each case renders the visibility AOV, checks that nothing is NaN and
// that the frame is neither all shadow nor all light where the truth has both, and bounds its error
// against the ray-traced truth (src/truth). The bounds were set from measured values with margin;
// the measured error is recorded as a test property (see the XML output) and printed.
#include "gl_fixture.h"
#include "plan/techniques/reports.h"
#include "plan/options.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "measure/metrics.h"
#include "scenes/course_scene.h"
#include "scenes/probe_scenes.h"
#include "measure/ray_tracer.h"
#include "../test_finite.h"

using namespace penumbra;

namespace {

using test::finite;

class Extremes : public test::GlTest {
protected:
    // Renders `sc` with `s` (visibility AOV), scores it against the truth, checks the invariants
    // and returns the score.
    measure::Score run(const scene::Scene& sc, render::Settings s, const char* label) {
        constexpr int kSize = 256;
        s.aov = render::Aov::Visibility;
        const render::FrameInputs in = render::offscreen(kSize, kSize);
        EXPECT_EQ(renderer->check(sc, s, in), "");
        const auto& plan = renderer->render(sc, s, in);
        notes = plan.notes;
        const render::PlannedResource* map = plan.resource("shadow-map");
        map_size = map ? map->desc.width : 0;
        const glm::mat4 view_proj = plan.camera.view_proj;
        EXPECT_TRUE(finite(view_proj)) << label;
        if (render::light_frustum_of(plan)) {
            EXPECT_TRUE(finite(render::light_frustum_of(plan)->view_proj())) << label << ": light frustum";
        }
        const auto rgba = renderer->read_image();
        std::vector<std::uint8_t> vis(rgba.size() / 4);
        for (size_t i = 0; i < vis.size(); ++i) vis[i] = rgba[i * 4];

        measure::TruthOptions to;
        to.width = kSize;
        to.height = kSize;
        to.view_proj = view_proj;
        const measure::TruthImage t = measure::RayTracer(sc).render(to);
        const measure::Score score = measure::score(vis, t.lit, t.valid_mask());
        EXPECT_GT(score.valid, static_cast<size_t>(kSize * kSize / 10)) << label << ": too few valid pixels";
        // Neither all shadow nor all light where the truth has both.
        size_t dark = 0, truth_dark = 0;
        for (size_t i = 0; i < vis.size(); ++i)
            if (t.valid(i)) {
                dark += vis[i] < measure::kDarkBelow;
                truth_dark += t.lit[i] == 0;
            }
        if (truth_dark > 0 && truth_dark < score.valid) {
            EXPECT_GT(dark, 0u) << label << ": all light";
            EXPECT_LT(dark, score.valid) << label << ": all shadow";
        }
        std::printf("%-44s valid %6zu  false shadow %6.3f%%  false lit %6.3f%%\n", label, score.valid,
                    score.false_shadow_pct, score.false_lit_pct);
        RecordProperty(std::string(label) + "_error_pct", std::to_string(score.error_pct));
        return score;
    }
    std::vector<std::string> notes;
    int map_size = 0;
};

render::Settings settings(const char* bias = "auto") {
    render::Settings s;
    EXPECT_EQ(render::parse_option(s, "bias", bias), "");
    return s;
}

TEST_F(Extremes, GrazingLightTwoToEightDegrees) {
    for (float elevation : {2.0f, 4.0f, 8.0f}) {
        const auto sc = scene::make_box_on_plane(elevation);
        const std::string label = "grazing " + std::to_string(static_cast<int>(elevation)) + " deg";
        EXPECT_LT(run(sc, settings(), (label + ", auto").c_str()).error_pct, 0.5) << label;
        EXPECT_LT(run(sc, settings("sheet"), (label + ", sheet").c_str()).error_pct, 0.5) << label;
    }
}

TEST_F(Extremes, LightStraightOverhead) {
    // A directional light along -y: the light's look-at must not take +y as its up vector.
    EXPECT_LT(run(scene::make_box_on_plane(90.0f), settings(), "overhead directional").error_pct, 0.5);
    auto course = scene::make_course_scene(10);
    scene::animate_course(course, 0.0, 0.6);
    scene::place_light(course.scene, glm::vec3(0.0f), 3.6f, 90.0f, 0.0f);
    EXPECT_LT(run(course.scene, settings(), "overhead point light").error_pct, 0.5);
}

TEST_F(Extremes, LightInsideTheScenesBounds) {
    // The point light below the top of the teapot and inside the table's extent: part of the scene
    // lies behind the light, which a single frustum cannot hold (the fit falls back to a wide one).
    auto course = scene::make_course_scene(10);
    scene::animate_course(course, 0.0, 0.6);
    course.scene.light.position = glm::vec3(1.2f, 0.5f, 0.3f);
    course.scene.light.direction = glm::normalize(-course.scene.light.position);
    const auto score = run(course.scene, settings(), "light inside the bounds");
    EXPECT_LT(score.error_pct, 1.0);
}

TEST_F(Extremes, TeapotTouchingTheTableAndAtTheTopOfItsJump) {
    auto course = scene::make_course_scene(10);
    scene::animate_course(course, 0.6, 0.0);  // t = 0: the teapot stands on the table
    EXPECT_NEAR(course.scene.objects[static_cast<size_t>(course.teapot)].world[3][1], 0.0f, 1e-6f);
    EXPECT_LT(run(course.scene, settings(), "teapot touching the table").error_pct, 0.5);
    scene::animate_course(course, 0.6, 0.75);  // the top of the jump
    EXPECT_NEAR(course.scene.objects[static_cast<size_t>(course.teapot)].world[3][1], 0.6f, 1e-5f);
    EXPECT_LT(run(course.scene, settings(), "teapot at the top of its jump").error_pct, 0.5);
}

TEST_F(Extremes, ScenesScaledByAThousandthAndAThousand) {
    for (float scale : {1e-3f, 1e3f}) {
        const std::string label = "scaled by " + std::to_string(scale);
        EXPECT_LT(run(scene::make_sphere_over_plane(scale), settings(), (label + ", sphere").c_str()).error_pct, 0.5);
        EXPECT_LT(run(scene::make_box_on_plane(30.0f, 30.0f, scale), settings(), (label + ", box").c_str()).error_pct,
                  0.5);
    }
}

TEST_F(Extremes, CameraNearAndFarOfOneHundredthAndTenThousand) {
    EXPECT_LT(run(scene::make_sphere_over_plane(1.0f, 1e-2f, 1e4f), settings(), "camera near 1e-2 far 1e4").error_pct,
              0.5);
}

TEST_F(Extremes, MapSizesOfOneAndEightThousand) {
    render::Settings s = settings();
    s.map_size = 1;
    const auto tiny = run(scene::make_sphere_over_plane(), s, "map size 1");
    EXPECT_EQ(map_size, 16) << "a map smaller than 16 texels is raised to 16";
    ASSERT_FALSE(notes.empty());
    EXPECT_NE(notes[0].find("raised"), std::string::npos);
    EXPECT_LT(tiny.error_pct, 5.0);
    s.map_size = 8192;
    EXPECT_LT(run(scene::make_sphere_over_plane(), s, "map size 8192").error_pct, 0.2);
    EXPECT_EQ(map_size, 8192);
}

}  // namespace
