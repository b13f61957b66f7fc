// --map-size auto (issue 56): the screen area the receivers in view cover, the size that area asks
// for at two texels a pixel, and the plan's choice as the image and the view change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "plan/techniques/reports.h"
#include "scene/gltf_loader.h"
#include "scenes/course_scene.h"
#include "shadow/light_frustum.h"
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

TEST(Resolution, OneMapAloneStepsByAnEighthOfAnOctave) {
    using shadow::SizeSteps;
    // The want 1448 (half the map used at 512 x 512): 1536, not 2048.
    shadow::MatchedSize m = shadow::matched_map_size(512.0f * 512.0f, 0.5f, 1, 128, 4096, 0.0, false, SizeSteps::Eighths);
    EXPECT_EQ(m.wanted, 1448);
    EXPECT_EQ(m.size, 1536);
    EXPECT_EQ(m.why.rfind("auto 1536: ", 0), 0u) << m.why;
    // The steps of each octave: sixteenths of its top, so at most 12.5 % over the want.
    EXPECT_EQ(shadow::map_size_step(513, 128, SizeSteps::Eighths), 576);
    EXPECT_EQ(shadow::map_size_step(576, 128, SizeSteps::Eighths), 576);
    EXPECT_EQ(shadow::map_size_step(577, 128, SizeSteps::Eighths), 640);
    EXPECT_EQ(shadow::map_size_step(657, 128, SizeSteps::Eighths), 704);
    EXPECT_EQ(shadow::map_size_step(1024, 128, SizeSteps::Eighths), 1024);
    EXPECT_EQ(shadow::map_size_step(1025, 128, SizeSteps::Eighths), 1152);
    EXPECT_EQ(shadow::map_size_step(200, 128, SizeSteps::Eighths), 208);
    for (int w = 129; w <= 4096; ++w) {
        const int e = shadow::map_size_step(w, 128, SizeSteps::Eighths);
        ASSERT_GE(e, w);
        ASSERT_LE(e, 1.125 * w) << w;
        ASSERT_LE(e, shadow::map_size_step(w, 128, SizeSteps::PowersOfTwo)) << w;
    }
    // At or under the smallest: the smallest, as with powers of two; the bounds hold.
    EXPECT_EQ(shadow::map_size_step(90, 128, SizeSteps::Eighths), 128);
    EXPECT_EQ(shadow::matched_map_size(4096.0f * 4096.0f, 1.0f, 1, 128, 2048, 0.0, false, SizeSteps::Eighths).size, 2048);
    // The control: the same want as a power of two.
    EXPECT_EQ(shadow::map_size_step(657, 128, SizeSteps::PowersOfTwo), 1024);
}

// A ground square [-1, 1]^2 (y up) and a map straight above it (orthographic, so a texel covers
// the same ground everywhere).
const scene::Bounds kGround = scene::Bounds::around({-1.0f, -0.01f, -1.0f}, {1.0f, 0.0f, 1.0f});
const glm::mat4 kMapAbove = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f) *
                            glm::lookAt(glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));

TEST(Resolution, TheDensestTilesAskForMoreWhereTheCameraSeesTheGroundUnevenly) {
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    const std::vector<scene::Bounds> ground = {kGround};
    // Two texels a pixel on average over the parts.
    const auto average = [](const shadow::Demand& d) { return 2.0 * std::sqrt(d.pixels / d.share); };
    // A camera that sees the ground as the map does: the whole image and the whole map, the
    // density even, so every tile wants what the average wants at one texel a pixel instead of two.
    const shadow::Demand even = shadow::receiver_demand(sun, ground, kMapAbove, 512, 512, kMapAbove);
    EXPECT_NEAR(even.pixels, 512.0 * 512.0, 512.0);
    EXPECT_NEAR(even.share, 1.0, 0.01);
    EXPECT_NEAR(even.dense, 512.0, 8.0);
    EXPECT_NEAR(average(even), 1024.0, 16.0);
    // A camera low over the ground, looking along it: the near tiles fill most of the image, the
    // far ones a sliver. The densest 90 % of the pixels want more texels than the average's half.
    const glm::mat4 low = glm::perspective(glm::radians(60.0f), 1.0f, 0.05f, 20.0f) *
                          glm::lookAt(glm::vec3(0.0f, 0.4f, 1.6f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const shadow::Demand uneven = shadow::receiver_demand(sun, ground, low, 512, 512, kMapAbove);
    EXPECT_GT(uneven.dense, 0.75 * average(uneven)) << "average " << average(uneven);
    // Many small receivers, each inside one tile: their parts summed, the same as one ground.
    std::vector<scene::Bounds> pieces;
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j) {
            const float x = -1.0f + 0.125f * static_cast<float>(i), z = -1.0f + 0.125f * static_cast<float>(j);
            pieces.push_back(scene::Bounds::around({x, -0.01f, z}, {x + 0.125f, 0.0f, z + 0.125f}));
        }
    const shadow::Demand tiled = shadow::receiver_demand(sun, pieces, kMapAbove, 512, 512, kMapAbove);
    EXPECT_NEAR(tiled.pixels, even.pixels, 0.01 * even.pixels);
    EXPECT_NEAR(tiled.share, even.share, 0.01);
    EXPECT_NEAR(tiled.dense, even.dense, 8.0);
    // Nothing in view: nothing wanted.
    const glm::mat4 away = glm::perspective(glm::radians(60.0f), 1.0f, 0.05f, 20.0f) *
                           glm::lookAt(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    const shadow::Demand none = shadow::receiver_demand(sun, ground, away, 512, 512, kMapAbove);
    EXPECT_EQ(none.pixels, 0.0);
    EXPECT_EQ(none.dense, 0.0);
}

TEST(Resolution, AnImageUnder512ASideIsMatchedAsIfThatLarge) {
    shadow::MatchedImage m = shadow::matched_image(256, 256);
    EXPECT_EQ(m.width, 512);
    EXPECT_EQ(m.height, 512);
    EXPECT_TRUE(m.scaled);
    m = shadow::matched_image(480, 320);  // sqrt(480 x 320) = 392: both sides x 1.306
    EXPECT_EQ(m.width, 627);
    EXPECT_EQ(m.height, 418);
    m = shadow::matched_image(1920, 1080);
    EXPECT_EQ(m.width, 1920);
    EXPECT_FALSE(m.scaled);
    EXPECT_FALSE(shadow::matched_image(512, 512).scaled);
}

TEST(Resolution, APartAcrossTilesIsWhatEachTilesFrustumCutsOfIt) {
    // receiver_demand cuts a receiver across tiles by the planes between tiles, once a plane. The
    // definition it must keep: the part within each tile's frustum, clipped tile by tile. A table
    // and a teapot-sized box under a point light's perspective map, a camera at a slant.
    scene::Light lamp;
    lamp.type = scene::LightType::Point;
    lamp.position = glm::vec3(1.0f, 4.0f, 0.5f);
    const std::vector<scene::Bounds> receivers = {scene::Bounds::around({-2.0f, -0.1f, -1.5f}, {2.0f, 0.0f, 1.5f}),
                                                  scene::Bounds::around({-0.5f, 0.0f, -0.4f}, {0.6f, 0.8f, 0.4f})};
    const glm::mat4 map = glm::perspective(glm::radians(80.0f), 1.0f, 1.0f, 10.0f) *
                          glm::lookAt(lamp.position, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::mat4 camera = glm::perspective(glm::radians(50.0f), 1.0f, 0.1f, 30.0f) *
                             glm::lookAt(glm::vec3(0.5f, 2.0f, 4.5f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const shadow::Demand d = shadow::receiver_demand(lamp, receivers, camera, 512, 512, map);
    // The reference: every receiver clipped again by every tile's frustum.
    constexpr int n = shadow::kDenseTiles;
    double pixels = 0.0, share = 0.0;
    std::vector<std::pair<double, double>> needs;  // (wanted, pixels)
    for (int ty = 0; ty < n; ++ty)
        for (int tx = 0; tx < n; ++tx) {
            const auto at = [](int i) { return -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(n); };
            const float x0 = at(tx), x1 = at(tx + 1), y0 = at(ty), y1 = at(ty + 1);
            glm::mat4 s(1.0f);
            s[0][0] = 2.0f / (x1 - x0);
            s[3][0] = -(x1 + x0) / (x1 - x0);
            s[1][1] = 2.0f / (y1 - y0);
            s[3][1] = -(y1 + y0) / (y1 - y0);
            const auto planes = shadow::clip_volume_half_spaces(s * map);
            std::vector<char> whole;
            double tp = 0.0, ts = 0.0;
            for (const auto& part : shadow::visible_points_each(lamp, receivers, camera, whole, {planes.begin(), planes.end()})) {
                tp += static_cast<double>(shadow::hull_share(camera, part)) * 512.0 * 512.0;
                ts += static_cast<double>(shadow::hull_share(map, part));
            }
            pixels += tp;
            share += ts;
            if (tp >= 1.0 && ts > 0.0) needs.emplace_back(std::sqrt(tp / ts), tp);
        }
    ASSERT_GT(pixels, 10000.0);
    EXPECT_NEAR(d.pixels, pixels, 1e-3 * pixels);
    EXPECT_NEAR(d.share, share, 1e-3 * share);
    std::sort(needs.begin(), needs.end());
    double served = 0.0, dense = 0.0;
    for (const auto& need : needs) {
        served += need.second;
        dense = need.first;
        if (served >= shadow::kDenseShare * pixels) break;
    }
    EXPECT_NEAR(d.dense, dense, 1e-3 * dense);
    // The control: the same receivers over a map half as wide ask for other tiles' densities.
    const glm::mat4 narrow = glm::perspective(glm::radians(45.0f), 1.0f, 1.0f, 10.0f) *
                             glm::lookAt(lamp.position, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    EXPECT_GT(std::fabs(shadow::receiver_demand(lamp, receivers, camera, 512, 512, narrow).dense - dense), 0.05 * dense);
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
    const render::FramePlan small = course_plan(512, 512, "auto"), large = course_plan(1024, 1024, "auto");
    EXPECT_EQ(map_width(large), 2 * map_width(small)) << "twice the image's side: twice the map's";
    // An image under 512 a side is matched as 512 a side.
    const render::FramePlan tiny = course_plan(128, 128, "auto");
    EXPECT_EQ(map_width(tiny), map_width(small));
    EXPECT_NE(tiny.find<render::MapSizeReport>()->why.find("the image counted as 512 pixels a side"), std::string::npos);
    ASSERT_NE(small.find<render::MapSizeReport>(), nullptr);
    EXPECT_EQ(small.find<render::MapSizeReport>()->size, map_width(small));
    EXPECT_NE(small.find<render::MapSizeReport>()->why.find("texels a pixel"), std::string::npos);
    // The control: a fixed size is the same on both, and reports no choice.
    EXPECT_EQ(map_width(course_plan(256, 256, "1024")), 1024);
    EXPECT_EQ(map_width(course_plan(1024, 1024, "1024")), 1024);
    EXPECT_EQ(course_plan(256, 256, "1024").find<render::MapSizeReport>(), nullptr);
}

TEST(ResolutionPlan, AFrameWithTheSameInputsTakesThePreviousPlansMatch) {
    // The previous plan's match, marked so that a reuse shows: a size the match would not choose.
    render::FramePlan before = course_plan(512, 512, "auto");
    render::MapSizeReport* m = before.find<render::MapSizeReport>();
    ASSERT_NE(m, nullptr);
    ASSERT_NE(m->size, 256);
    m->size = 256;
    m->why = "marked";
    const render::FramePlan still = course_plan(512, 512, "auto", &before);
    EXPECT_EQ(map_width(still), 256) << "the same light, receivers, camera and image: the match taken, not made again";
    EXPECT_EQ(still.find<render::MapSizeReport>()->why, "marked");
    // The controls: another image, or no previous plan, and the match is made.
    EXPECT_EQ(map_width(course_plan(600, 600, "auto", &before)), map_width(course_plan(600, 600, "auto")));
    EXPECT_NE(map_width(course_plan(600, 600, "auto", &before)), 256);
    EXPECT_NE(map_width(course_plan(512, 512, "auto")), 256);
}

TEST(ResolutionPlan, TheSizeGoesUpAtOnceAndDownOnlyOnceTheWantIsWellUnderTheSmallerSize) {
    // The course at t = 0.6 wants about 712 texels at 512x512, in proportion to the image's side;
    // one map's sizes step by an eighth of an octave: 1280, 1408, 1536 between 1024 and 2048.
    const render::FramePlan large = course_plan(1024, 1024, "auto");
    ASSERT_EQ(map_width(large), 1536);
    // A want just under the step below (1408) after a frame of 1536: the size stays.
    const render::FramePlan near = course_plan(960, 960, "auto", &large);
    const render::MapSizeReport* m = near.find<render::MapSizeReport>();
    ASSERT_NE(m, nullptr);
    ASSERT_GT(m->wanted, 0.9 * 1408);
    ASSERT_LE(m->wanted, 1408);
    EXPECT_EQ(map_width(near), 1536) << m->why;
    EXPECT_EQ(m->size, 1536);
    EXPECT_EQ(m->why.rfind("auto 1536: ", 0), 0u) << m->why;
    EXPECT_NE(m->why.find("kept at 1536 from the last frame: the want is within 10% under 1408"), std::string::npos) << m->why;
    // The controls: with no frame before it the same want is 1408, and a want well under 1408
    // goes down.
    EXPECT_EQ(map_width(course_plan(960, 960, "auto")), 1408);
    const render::FramePlan far = course_plan(880, 880, "auto", &large);
    ASSERT_LT(far.find<render::MapSizeReport>()->wanted, 0.9 * 1408);
    EXPECT_EQ(map_width(far), 1280);
    // Up at once: after a frame of 1280, a want just over it takes the next step.
    const render::FramePlan up = course_plan(930, 930, "auto", &far);
    ASSERT_GT(up.find<render::MapSizeReport>()->wanted, 1280);
    EXPECT_EQ(map_width(up), 1408);
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
    EXPECT_EQ(render::cube_of(small)->tile, small.find<render::MapSizeReport>()->size);
    // Within 64 MiB for the atlas of six faces: at most 1024 each.
    EXPECT_LE(render::cube_of(large)->tile, 1024);
    EXPECT_GE(large.find<render::MapSizeReport>()->wanted, 1024);
}

TEST(ResolutionPlan, AFaceSeeingTheGroundAtAGrazingAngleIsMatchedWhereItIsDensest) {
    // wide_cone.gltf's +x face sees the long ground at a grazing angle over a quarter of its map:
    // two texels a pixel on average want 482 there (a face of 512, 0.276 % of error against the
    // truth at 512x512); one a pixel over the densest tiles holding 90 % of its pixels want 869,
    // so 1024 (0.057 %).
    const scene::LoadResult r = scene::load_gltf(test::test_data_dir() + "/wide_cone.gltf");
    ASSERT_TRUE(r.ok) << r.error;
    render::Settings settings;
    ASSERT_EQ(render::parse_option(settings, "map-size", "auto"), "");
    const render::FramePlan p = render::plan(r.scene, settings, penumbra::testing::full_caps(), render::offscreen(512, 512));
    ASSERT_NE(render::cube_of(p), nullptr);
    EXPECT_EQ(render::cube_of(p)->tile, 1024);
    const render::MapSizeReport* m = p.find<render::MapSizeReport>();
    ASSERT_NE(m, nullptr);
    EXPECT_GT(m->wanted, 512) << m->why;
    EXPECT_NE(m->why.find("over 90% of them"), std::string::npos) << m->why;
}

}  // namespace
