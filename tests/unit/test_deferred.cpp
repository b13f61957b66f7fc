// --lights and --shading as data: where the point lights stand, the screen square a light's range
// covers, the passes forward and deferred frames get on contexts with and without draw buffers
// and half floats, and the frames check() refuses with a named reason. No GL context.
#include <algorithm>
#include <stdexcept>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan_names.h"
#include "plan/frames/deferred.h"
#include "plan/lights.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"

using namespace penumbra;
using render::FramePlan;

namespace {

gl::Caps caps(bool draw_buffers, bool half_float) {
    gl::Caps c = penumbra::testing::full_caps();
    c.fragment_highp = true;
    c.draw_buffers = draw_buffers;
    c.half_float_target = half_float;
    return c;
}

render::Settings settings(const char* shading, int lights, const char* technique = "shadowmap") {
    render::Settings s;
    if (render::parse_option(s, "shading", shading) != "" || render::parse_option(s, "technique", technique) != "")
        throw std::runtime_error("bad test settings");
    s.lights = lights;
    return s;
}

using penumbra::testing::pass_named;
using penumbra::testing::pass_names;

bool has_define(const render::Variant& v, const std::string& d) {
    return std::find(v.defines.begin(), v.defines.end(), d) != v.defines.end();
}

}  // namespace

TEST(PointLights, StandOnADiscAboveTheTableShrinkingAsTheyMultiply) {
    const scene::CourseScene course = scene::make_course_scene(4);
    EXPECT_TRUE(render::point_lights(course.scene, 0).empty());
    const auto few = render::point_lights(course.scene, 4), many = render::point_lights(course.scene, 256);
    ASSERT_EQ(few.size(), 4u);
    ASSERT_EQ(many.size(), 256u);
    EXPECT_GT(few[0].range, many[0].range);
    // Above the widest receiver's top (the table), inside its extent.
    const auto bounds = render::shadow_bounds(course.scene).receivers;
    const auto widest = *std::max_element(bounds.begin(), bounds.end(), [](const auto& a, const auto& b) {
        return (a.max.x - a.min.x) * (a.max.z - a.min.z) < (b.max.x - b.min.x) * (b.max.z - b.min.z);
    });
    for (const auto& l : many) {
        EXPECT_GT(l.position.y, widest.max.y);
        EXPECT_LT(l.position.y, widest.max.y + l.range);
        EXPECT_GE(l.position.x, widest.min.x);
        EXPECT_LE(l.position.x, widest.max.x);
    }
    // The same scene and N: the same lights (forward, deferred and the bench light one scene).
    EXPECT_EQ(render::point_lights(course.scene, 4)[3].position, few[3].position);
    // The falloff: none at the range, full Lambert at the light's foot... less than the colour.
    const render::PointLight& l = few[0];
    const glm::vec3 up(0.0f, 1.0f, 0.0f), white(1.0f);
    EXPECT_EQ(render::point_light_term(l, l.position - glm::vec3(0.0f, l.range, 0.0f), up, white), glm::vec3(0.0f));
    const glm::vec3 below = render::point_light_term(l, l.position - glm::vec3(0.0f, 0.1f * l.range, 0.0f), up, white);
    EXPECT_NEAR(below.r, l.color.r * 0.99f * 0.99f, 1e-5f);
}

TEST(ScreenSquare, CoversTheProjectedRangeAndNothingOffScreen) {
    const glm::mat4 vp = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f) *
                         glm::lookAt(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::vec4 q = render::screen_square(vp, glm::vec3(0.0f), 1.0f);
    EXPECT_LT(q.x, 0.0f);
    EXPECT_GT(q.z, 0.0f);
    EXPECT_GT(q.z - q.x, 0.3f);
    EXPECT_LT(q.z - q.x, 1.0f);
    const glm::vec4 off = render::screen_square(vp, glm::vec3(40.0f, 0.0f, 0.0f), 1.0f);
    EXPECT_GE(off.x, off.z);
    const glm::vec4 around = render::screen_square(vp, glm::vec3(0.0f, 0.0f, 5.0f), 1.0f);  // the camera inside
    EXPECT_EQ(around, glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
}

TEST(DeferredPlan, OnePassWithDrawBuffersThreeWithoutSummedInHalfFloats) {
    const scene::CourseScene course = scene::make_course_scene(4);
    const FramePlan mrt = render::plan(course.scene, settings("deferred", 8), caps(true, true));
    EXPECT_EQ(pass_names(mrt), (std::vector<std::string>{"shadow-map", "gbuffer", "deferred-light", "deferred-points",
                                                         "deferred-resolve"}));
    ASSERT_NE(mrt.resource("gbuffer"), nullptr);
    EXPECT_EQ(mrt.resource("gbuffer")->desc.colors, 3);
    EXPECT_TRUE(mrt.resource("deferred-light")->desc.half_float);
    EXPECT_TRUE(has_define(pass_named(mrt, "gbuffer").draws[0].variant, "GBUFFER_MRT"));
    const render::Pass& light = pass_named(mrt, "deferred-light");
    ASSERT_EQ(light.draws.size(), 1u);
    EXPECT_TRUE(has_define(light.draws[0].variant, "GBUFFER_READ"));
    EXPECT_TRUE(has_define(light.draws[0].variant, "SHADOW_MAP"));  // the shadow map in the lighting pass
    const auto reads = light.reads();
    EXPECT_NE(std::find(reads.begin(), reads.end(), mrt.resource_index("shadow-map")), reads.end());
    EXPECT_NE(std::find(reads.begin(), reads.end(), mrt.resource_index("gbuffer")), reads.end());
    const render::Pass& points = pass_named(mrt, "deferred-points");
    EXPECT_EQ(points.state.blend, gl::Blend::Add);
    EXPECT_GT(points.draws.size(), 0u);
    EXPECT_LE(points.draws.size(), 8u);
    for (const auto& d : points.draws) EXPECT_EQ(d.uniforms.size(), 2u);

    const FramePlan split = render::plan(course.scene, settings("deferred", 8), caps(false, false));
    EXPECT_EQ(pass_names(split), (std::vector<std::string>{"shadow-map", "gbuffer-color", "gbuffer-normal", "gbuffer-depth",
                                                           "deferred-light", "deferred-points"}));
    EXPECT_TRUE(has_define(pass_named(split, "gbuffer-normal").draws[0].variant, "GBUFFER_TARGET 1"));
    EXPECT_EQ(pass_named(split, "deferred-points").target.resource, split.resource_index("camera"));
    // The notes say which G-buffer path was taken.
    EXPECT_NE(split.notes.front().find("one pass per target"), std::string::npos);
}

TEST(ForwardPlan, BatchesOfSixteenLightsAfterTheCameraPass) {
    const scene::CourseScene course = scene::make_course_scene(4);
    const FramePlan p = render::plan(course.scene, settings("forward", 40), caps(true, true));
    EXPECT_EQ(pass_names(p), (std::vector<std::string>{"shadow-map", "camera", "lights-17-32", "lights-33-40"}));
    EXPECT_TRUE(has_define(pass_named(p, "camera").draws[0].variant, "POINT_LIGHTS 16"));
    const render::Pass& last = pass_named(p, "lights-33-40");
    EXPECT_TRUE(has_define(last.draws[0].variant, "POINT_LIGHTS 8"));
    EXPECT_TRUE(has_define(last.draws[0].variant, "POINTS_ONLY"));
    EXPECT_EQ(last.state.depth_func, gl::Compare::Equal);
    EXPECT_FALSE(last.state.depth_write);
    EXPECT_EQ(last.state.blend, gl::Blend::Add);
    // No lights: the frame of before.
    EXPECT_EQ(pass_names(render::plan(course.scene, settings("forward", 0), caps(true, true))),
              (std::vector<std::string>{"shadow-map", "camera"}));
}

TEST(ShadingCheck, RefusesWhatItCannotLightWithAReason) {
    const scene::CourseScene course = scene::make_course_scene(4);
    const gl::Caps c = caps(true, true);
    EXPECT_EQ(render::check(course.scene, settings("deferred", 8), c), "");
    EXPECT_EQ(render::check(course.scene, settings("deferred", 0, "none"), c), "");
    EXPECT_NE(render::check(course.scene, settings("deferred", 0, "planar"), c).find("--shading deferred: with --technique shadowmap or none"),
              std::string::npos);
    EXPECT_NE(render::check(course.scene, settings("forward", 4, "volumes"), c).find("--lights 4: with --technique"),
              std::string::npos);
    render::Settings mirror = settings("deferred", 0);
    mirror.effects = {render::Effect::Mirror};
    EXPECT_NE(render::check(course.scene, mirror, c).find("not with --effects mirror"), std::string::npos);
    render::Settings view = settings("forward", 0);
    view.aov = render::Aov::GbufferNormal;
    EXPECT_EQ(render::check(course.scene, view, c), "--aov gbuffer-normal: needs --shading deferred");
    gl::Caps mediump = c;
    mediump.fragment_highp = false;
    EXPECT_NE(render::check(course.scene, settings("deferred", 0), mediump).find("highp"), std::string::npos);
    render::Settings blurred = settings("deferred", 0);
    EXPECT_EQ(render::parse_option(blurred, "post", "shadow-blur:4"), "");
    EXPECT_NE(render::check(course.scene, blurred, c).find("not with --post shadow-blur"), std::string::npos);
}
