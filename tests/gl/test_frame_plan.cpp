// "Model only what the scene requires": passes, targets and variants exist only when the scene
// and the settings call for them, and an unchanged shadow map is reused.
#include "gl_fixture.h"

#include <algorithm>

#include "scene/course_scene.h"
#include "scene/scene_source.h"

using namespace penumbra;

namespace {

class RendererGl : public test::GlTest {};

bool has_pass(const render::FramePlan& p, const std::string& name) {
    return std::any_of(p.passes.begin(), p.passes.end(), [&](const render::PassInfo& i) { return i.name == name; });
}

TEST_F(RendererGl, NoShadowPassWithoutCasters) {
    auto course = scene::make_course_scene(4);
    for (auto& o : course.scene.objects) o.casts_shadow = false;
    render::Settings s;
    s.width = s.height = 64;
    const auto& plan = renderer->render(course.scene, s);
    EXPECT_FALSE(plan.shadow_map);
    EXPECT_FALSE(has_pass(plan, "shadow-map"));
    EXPECT_EQ(renderer->shadow_map_bytes(), 0u);
    ASSERT_EQ(plan.passes.size(), 1u);
    EXPECT_NE(plan.passes[0].detail.find("no shadows"), std::string::npos);
}

TEST_F(RendererGl, ShadowMapIsReusedUntilTheLightOrACasterMoves) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.width = s.height = 64;
    s.map_size = 256;
    scene::animate_course(course, 1.0, 1.0);
    EXPECT_TRUE(renderer->render(course.scene, s).shadow_redrawn);
    // Same light, same casters: reused.
    const auto& again = renderer->render(course.scene, s);
    EXPECT_TRUE(again.shadow_map);
    EXPECT_FALSE(again.shadow_redrawn);
    EXPECT_NE(again.passes[0].detail.find("reused"), std::string::npos);
    // The teapot jumps, the light stays: redrawn.
    scene::animate_course(course, 1.0, 1.2);
    EXPECT_TRUE(renderer->render(course.scene, s).shadow_redrawn);
    // The light moves, the teapot stays: redrawn.
    scene::animate_course(course, 2.0, 1.2);
    EXPECT_TRUE(renderer->render(course.scene, s).shadow_redrawn);
    // A different encoding needs a different map.
    s.encoding = shadow::Encoding::R8;
    EXPECT_TRUE(renderer->render(course.scene, s).shadow_redrawn);
    // Changing only the camera-side settings keeps it.
    s.filter = shadow::Filter::PCF4x4;
    s.bias = 0.01f;
    EXPECT_FALSE(renderer->render(course.scene, s).shadow_redrawn);
}

TEST_F(RendererGl, ReusedMapGivesTheSameImage) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.width = s.height = 96;
    s.map_size = 256;
    renderer->render(course.scene, s);
    const auto first = renderer->read_image();
    ASSERT_FALSE(renderer->render(course.scene, s).shadow_redrawn);
    EXPECT_EQ(renderer->read_image(), first);
}

TEST_F(RendererGl, ASecondSceneWithAsManyMeshesIsUploadedAnew) {
    // Both scenes have two meshes: the renderer must notice the second one is different.
    auto course = scene::make_course_scene(4);
    auto other = scene::make_course_scene(6);
    render::Settings s;
    s.width = s.height = 96;
    s.map_size = 256;
    renderer->render(course.scene, s);
    renderer->render(other.scene, s);
    const auto reused = renderer->read_image();
    render::Renderer fresh(renderer->caps());
    fresh.render(other.scene, s);
    EXPECT_EQ(reused, fresh.read_image());
}

TEST_F(RendererGl, EachTechniqueRunsOnlyItsPasses) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.width = s.height = 64;
    s.technique = render::Technique::None;
    auto plan = renderer->render(course.scene, s);
    EXPECT_EQ(plan.passes.size(), 1u);
    EXPECT_FALSE(plan.shadow_map);

    s.technique = render::Technique::Planar;
    plan = renderer->render(course.scene, s);
    EXPECT_TRUE(has_pass(plan, "planar-stencil"));
    EXPECT_TRUE(has_pass(plan, "planar-shadow"));
    EXPECT_FALSE(has_pass(plan, "shadow-map"));

    s.technique = render::Technique::ShadowMap;
    plan = renderer->render(course.scene, s);
    EXPECT_TRUE(has_pass(plan, "shadow-map"));
    EXPECT_FALSE(has_pass(plan, "planar-stencil"));
}

TEST_F(RendererGl, OnlyTheVariantsInUseAreCompiled) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.width = s.height = 64;
    s.encoding = shadow::Encoding::R8;
    s.filter = shadow::Filter::Hard;
    renderer->render(course.scene, s);
    // The start-up probe, the depth pass, the textured table and the untextured teapot.
    EXPECT_EQ(renderer->shaders().compiled(), 4u);
    s.technique = render::Technique::None;
    renderer->render(course.scene, s);
    EXPECT_EQ(renderer->shaders().compiled(), 6u);  // + the two lit variants without SHADOW_MAP
}

TEST_F(RendererGl, MapSizeBeyondTheContextIsClampedWithANote) {
    auto course = scene::make_course_scene(2);
    render::Settings s;
    s.width = s.height = 32;
    s.map_size = renderer->caps().max_target_size() * 2;
    const auto& plan = renderer->render(course.scene, s);
    EXPECT_EQ(plan.map_size, renderer->caps().max_target_size());
    ASSERT_FALSE(plan.notes.empty());
    EXPECT_NE(plan.notes[0].find("clamped"), std::string::npos);
}

TEST_F(RendererGl, ChecksNameTheProblem) {
    auto course = scene::make_course_scene(2);
    render::Settings s;
    s.width = renderer->caps().max_target_size() + 1;
    EXPECT_NE(renderer->check(course.scene, s).find("maximum"), std::string::npos);
    s = render::Settings{};
    s.technique = render::Technique::Planar;
    scene::Scene no_ground = course.scene;
    no_ground.ground_plane.reset();
    no_ground.ground_object = -1;
    EXPECT_NE(renderer->check(no_ground, s).find("ground"), std::string::npos);
    EXPECT_EQ(renderer->check(course.scene, s), "");
}

TEST_F(RendererGl, EveryCombinationRendersWithoutGlErrors) {
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(src.open("teapot", error, warnings));
    render::Settings s;
    s.width = s.height = 48;
    s.map_size = 128;
    for (auto t : {render::Technique::ShadowMap, render::Technique::Planar, render::Technique::None})
        for (auto e : shadow::kAllEncodings)
            for (auto f : shadow::kAllFilters)
                for (auto a : {render::Aov::Color, render::Aov::Visibility, render::Aov::LightDepth}) {
                    s.technique = t;
                    s.encoding = e;
                    s.filter = f;
                    s.aov = a;
                    if (!renderer->check(src.at(0.3), s).empty()) continue;
                    // Each pass ends with a glGetError check that throws naming the pass.
                    EXPECT_NO_THROW(renderer->render(src.at(0.3), s)) << render::to_args(s);
                    EXPECT_NO_THROW(gl::check_errors("after the frame")) << render::to_args(s);
                }
}

TEST_F(RendererGl, EveryShaderVariantCompilesOnTheContext) {
    const auto variants = render::all_variants();
    ASSERT_GT(variants.size(), 50u);
    for (const auto& v : variants) EXPECT_NO_THROW(renderer->shaders().get(v)) << v.key();
    EXPECT_EQ(renderer->shaders().compiled(), variants.size());
}

TEST_F(RendererGl, ABrokenShaderNamesItsStageAndLog) {
    try {
        gl::Program p("#version 100\nvoid main() { gl_Position = vec4(0.0); }\n",
                      "#version 100\nvoid main() { gl_FragColor = undefined_thing; }\n", "broken");
        FAIL() << "a broken fragment shader linked";
    } catch (const gl::Error& e) {
        EXPECT_NE(std::string(e.what()).find("broken: fragment shader failed to compile"), std::string::npos)
            << e.what();
    }
}

TEST_F(RendererGl, AnIncompleteFramebufferNamesItsStatus) {
    gl::FramebufferDesc d;  // nothing attached
    d.label = "empty";
    try {
        gl::Framebuffer fb(d);
        FAIL() << "an FBO without attachments was complete";
    } catch (const gl::Error& e) {
        EXPECT_NE(std::string(e.what()).find("GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"), std::string::npos)
            << e.what();
    }
}

TEST_F(RendererGl, GltfSceneRendersWithAShadow) {
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(src.open(std::string(PENUMBRA_TEST_DATA) + "/sphere_over_plane.gltf", error, warnings)) << error;
    render::Settings s;
    s.width = s.height = 128;
    s.aov = render::Aov::Visibility;
    const auto& plan = renderer->render(src.at(0.0), s);
    EXPECT_TRUE(plan.shadow_map);
    const auto px = renderer->read_image();
    size_t dark = 0;
    for (size_t i = 0; i < px.size(); i += 4) dark += px[i] < 128;
    EXPECT_GT(dark, 100u) << "the sphere casts a shadow on the plane";
}

}  // namespace
