// --map-size auto (issue 56): the screen area the receivers in view cover, the size that area asks
// for at two texels a pixel, and the plan's choice as the image and the view change.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "plan/techniques/reports.h"
#include "scene/gltf_loader.h"
#include "scenes/course_scene.h"
#include "shadow/resolution.h"
#include "../test_paths.h"

using namespace penumbra;

namespace {

TEST(Resolution, ScreenPixelsOfAQuadFillingTheViewAndOfAQuarterOfIt) {
    // Orthographic camera over [-1, 1]^2: NDC is world x and y.
    const glm::mat4 vp = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -1.0f, 1.0f);
    const std::vector<glm::vec3> whole = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    EXPECT_FLOAT_EQ(shadow::screen_pixels(whole, vp, 640, 480), 640.0f * 480.0f);
    const std::vector<glm::vec3> quarter = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    EXPECT_FLOAT_EQ(shadow::screen_pixels(quarter, vp, 640, 480), 640.0f * 480.0f / 4.0f);
    // Beyond the view: clipped to it.
    const std::vector<glm::vec3> wide = {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
    EXPECT_FLOAT_EQ(shadow::screen_pixels(wide, vp, 100, 100), 10000.0f);
    EXPECT_EQ(shadow::screen_pixels({}, vp, 100, 100), 0.0f);
}

TEST(Resolution, TwoTexelsAPixelRoundedUpToAPowerOfTwoWithinTheBounds) {
    // 512 x 512 pixels over the whole map: 1024 wanted, 1024 chosen.
    shadow::MatchedSize m = shadow::matched_map_size(512.0f * 512.0f, 1.0f, 1, 128, 4096);
    EXPECT_EQ(m.wanted, 1024);
    EXPECT_EQ(m.size, 1024);
    // Half the map used: 1448 wanted, rounded up.
    m = shadow::matched_map_size(512.0f * 512.0f, 0.5f, 1, 128, 4096);
    EXPECT_EQ(m.size, 2048);
    // Four times the pixels: twice the size; bounded by the largest allowed, which the line says.
    EXPECT_EQ(shadow::matched_map_size(1024.0f * 1024.0f, 1.0f, 1, 128, 4096).size, 2048);
    m = shadow::matched_map_size(4096.0f * 4096.0f, 1.0f, 1, 128, 2048);
    EXPECT_EQ(m.size, 2048);
    EXPECT_NE(m.why.find("the largest allowed"), std::string::npos) << m.why;
    // A bound that is no power of two (a cube's atlas: 4096 / 3): the power of two below it.
    EXPECT_EQ(shadow::matched_map_size(4096.0f * 4096.0f, 1.0f, 1, 128, 1365).size, 1024);
    m = shadow::matched_map_size(10.0f, 1.0f, 1, 128, 2048);
    EXPECT_EQ(m.size, 128);
    EXPECT_NE(m.why.find("the smallest allowed"), std::string::npos) << m.why;
    // Nothing in view: the smallest, said so.
    m = shadow::matched_map_size(0.0f, 0.0f, 1, 128, 2048);
    EXPECT_EQ(m.size, 128);
    EXPECT_NE(m.why.find("no receiver in view"), std::string::npos) << m.why;
    // Six faces sharing the pixels: each face's use summed.
    EXPECT_EQ(shadow::matched_map_size(512.0f * 512.0f, 6.0f * 0.25f, 6, 128, 1024).size, 1024);
}

render::FramePlan course_plan(int width, int height, const char* map_size, const render::FramePlan* previous = nullptr) {
    static const scene::Scene s = [] {
        scene::CourseScene course = scene::make_course_scene(4, false);
        scene::animate_course(course, 0.6, 0.6);
        return course.scene;
    }();
    render::Settings settings;
    EXPECT_EQ(render::parse_option(settings, "map-size", map_size), "");
    return render::plan(s, settings, penumbra::testing::full_caps(), render::offscreen(width, height), previous);
}

int map_width(const render::FramePlan& p) {
    const render::PlannedResource* r = p.resource("shadow-map");
    return r ? r->desc.width : 0;
}

TEST(ResolutionPlan, AutoFollowsTheImagesSizeAndAFixedSizeDoesNot) {
    const render::FramePlan small = course_plan(256, 256, "auto"), large = course_plan(1024, 1024, "auto");
    EXPECT_EQ(map_width(large), 4 * map_width(small)) << "four times the image's side: four times the map's";
    ASSERT_NE(small.find<render::MapSizeReport>(), nullptr);
    EXPECT_EQ(small.find<render::MapSizeReport>()->size, map_width(small));
    EXPECT_NE(small.find<render::MapSizeReport>()->why.find("texels a pixel"), std::string::npos);
    // The control: a fixed size is the same on both, and reports no choice.
    EXPECT_EQ(map_width(course_plan(256, 256, "1024")), 1024);
    EXPECT_EQ(map_width(course_plan(1024, 1024, "1024")), 1024);
    EXPECT_EQ(course_plan(256, 256, "1024").find<render::MapSizeReport>(), nullptr);
}

TEST(ResolutionPlan, ACubesFacesAreMatchedToo) {
    const scene::LoadResult r = scene::load_gltf(test::test_data_dir() + "/bulb_room.gltf");
    ASSERT_TRUE(r.ok) << r.error;
    render::Settings settings;
    ASSERT_EQ(render::parse_option(settings, "map-size", "auto"), "");
    const auto caps = penumbra::testing::full_caps();
    const render::FramePlan small = render::plan(r.scene, settings, caps, render::offscreen(256, 256));
    const render::FramePlan large = render::plan(r.scene, settings, caps, render::offscreen(1024, 1024));
    ASSERT_NE(render::cube_of(small), nullptr);
    ASSERT_NE(render::cube_of(large), nullptr);
    EXPECT_LT(render::cube_of(small)->tile, render::cube_of(large)->tile);
    EXPECT_EQ(render::cube_of(small)->tile, small.find<render::MapSizeReport>()->size);
    // Within 64 MiB for the atlas of six faces: at most 1024 each.
    EXPECT_LE(render::cube_of(large)->tile, 1024);
}

}  // namespace
