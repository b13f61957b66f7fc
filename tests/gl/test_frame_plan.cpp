// "Model only what the scene requires": passes, targets and variants exist only when the scene
// and the settings call for them, and an unchanged shadow map is reused; the plan a renderer
// prints is the plan it runs, and its pool holds only what the last plan declared.
#include "gl_fixture.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "gl/gl_headers.h"
#include "gl/objects.h"
#include "plan/options.h"
#include "render/shader_library.h"
#include "scenes/course_scene.h"
#include "scene/scene_source.h"

using namespace penumbra;

namespace {

class RendererGl : public test::GlTest {};

const render::FrameInputs kSmall = render::offscreen(64, 64);
const render::FrameInputs kMedium = render::offscreen(96, 96);

TEST_F(RendererGl, NoShadowPassWithoutCasters) {
    auto course = scene::make_course_scene(4);
    for (auto& o : course.scene.objects) o.casts_shadow = false;
    render::Settings s;
    const auto& plan = renderer->render(course.scene, s, kSmall);
    EXPECT_EQ(plan.resource("shadow-map"), nullptr);
    EXPECT_FALSE(plan.has_pass("shadow-map"));
    EXPECT_FALSE(renderer->pool().has("shadow-map"));
    ASSERT_EQ(plan.passes.size(), 1u);
    EXPECT_NE(plan.passes[0].detail.find("no shadows"), std::string::npos);
}

TEST_F(RendererGl, ShadowMapIsReusedUntilTheLightOrACasterMoves) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.map_size = 256;
    const auto redrawn = [&] { return renderer->render(course.scene, s, kSmall).drawn("shadow-map"); };
    scene::animate_course(course, 1.0, 1.0);
    EXPECT_TRUE(redrawn());
    // Same light, same casters: reused.
    const auto& again = renderer->render(course.scene, s, kSmall);
    ASSERT_NE(again.resource("shadow-map"), nullptr);
    EXPECT_TRUE(again.resource("shadow-map")->reused);
    EXPECT_FALSE(again.drawn("shadow-map"));
    EXPECT_TRUE(again.passes[0].skipped);
    EXPECT_NE(again.describe().find("1. shadow-map: reused"), std::string::npos) << again.describe();
    // The teapot jumps, the light stays: redrawn.
    scene::animate_course(course, 1.0, 1.2);
    EXPECT_TRUE(redrawn());
    // The light moves, the teapot stays: redrawn.
    scene::animate_course(course, 2.0, 1.2);
    EXPECT_TRUE(redrawn());
    // A different encoding needs a different map.
    s.encoding = shadow::Encoding::R8;
    EXPECT_TRUE(redrawn());
    // Changing only the camera-side settings keeps it.
    s.filter = shadow::Filter::PCF4x4;
    s.bias = 0.01f;
    EXPECT_FALSE(redrawn());
}

TEST_F(RendererGl, ReusedMapGivesTheSameImage) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.map_size = 256;
    renderer->render(course.scene, s, kMedium);
    const auto first = renderer->read_image();
    ASSERT_FALSE(renderer->render(course.scene, s, kMedium).drawn("shadow-map"));
    EXPECT_EQ(renderer->read_image(), first);
}

TEST_F(RendererGl, ASecondSceneWithAsManyMeshesIsUploadedAnew) {
    // Both scenes have two meshes: the renderer must notice the second one is different.
    auto course = scene::make_course_scene(4);
    auto other = scene::make_course_scene(6);
    render::Settings s;
    s.map_size = 256;
    renderer->render(course.scene, s, kMedium);
    renderer->render(other.scene, s, kMedium);
    const auto reused = renderer->read_image();
    render::Renderer fresh(renderer->caps());
    fresh.render(other.scene, s, kMedium);
    EXPECT_EQ(reused, fresh.read_image());
}

TEST_F(RendererGl, EachTechniqueRunsOnlyItsPasses) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.technique = render::Technique::None;
    auto plan = renderer->render(course.scene, s, kSmall);
    EXPECT_EQ(plan.passes.size(), 1u);
    EXPECT_EQ(plan.resource("shadow-map"), nullptr);

    s.technique = render::Technique::Planar;
    plan = renderer->render(course.scene, s, kSmall);
    EXPECT_TRUE(plan.has_pass("planar-stencil"));
    EXPECT_TRUE(plan.has_pass("planar-shadow"));
    EXPECT_FALSE(plan.has_pass("shadow-map"));

    s.technique = render::Technique::ShadowMap;
    plan = renderer->render(course.scene, s, kSmall);
    EXPECT_TRUE(plan.has_pass("shadow-map"));
    EXPECT_FALSE(plan.has_pass("planar-stencil"));
}

TEST_F(RendererGl, OnlyTheVariantsInUseAreCompiled) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.encoding = shadow::Encoding::R8;
    s.filter = shadow::Filter::Hard;
    renderer->render(course.scene, s, kSmall);
    // The depth pass, the textured table and the untextured teapot.
    EXPECT_EQ(renderer->shaders().compiled(), 3u);
    s.technique = render::Technique::None;
    renderer->render(course.scene, s, kSmall);
    EXPECT_EQ(renderer->shaders().compiled(), 5u);  // + the two lit variants without SHADOW_MAP
    renderer->unorm_report();
    EXPECT_EQ(renderer->shaders().compiled(), 6u);  // + the unorm8 probe's, when its report first asks
}

TEST_F(RendererGl, MapSizeBeyondTheContextIsClampedWithANote) {
    auto course = scene::make_course_scene(2);
    render::Settings s;
    s.map_size = renderer->caps().max_target_size() * 2;
    const auto plan = renderer->plan(course.scene, s, render::offscreen(32, 32));
    ASSERT_NE(plan.resource("shadow-map"), nullptr);
    EXPECT_EQ(plan.resource("shadow-map")->desc.width, renderer->caps().max_target_size());
    ASSERT_FALSE(plan.notes.empty());
    EXPECT_NE(plan.notes[0].find("clamped"), std::string::npos);
    // Drawn: a map of the largest size the context names may still be more memory than it has
    // (softpipe: 16384^2, 2 GiB with its depth), and GLES 2.0 (2.5) lets any allocation end in
    // GL_OUT_OF_MEMORY. Either it draws, or the error names that and the pass.
    try {
        renderer->execute(course.scene, plan);
    } catch (const gl::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("GL_OUT_OF_MEMORY"), std::string::npos) << what;
        EXPECT_NE(what.find("shadow-map"), std::string::npos) << what;
        RecordProperty("largest_map", what);
    }
}

TEST_F(RendererGl, ChecksNameTheProblem) {
    auto course = scene::make_course_scene(2);
    render::Settings s;
    const int too_wide = renderer->caps().max_target_size() + 1;
    EXPECT_NE(renderer->check(course.scene, s, render::offscreen(too_wide, 8)).find("maximum"), std::string::npos);
    EXPECT_THROW(renderer->render(course.scene, s, render::offscreen(too_wide, 8)), std::invalid_argument);
    s.technique = render::Technique::Planar;
    scene::Scene no_ground = course.scene;
    no_ground.ground_plane.reset();
    no_ground.ground_object = -1;
    EXPECT_NE(renderer->check(no_ground, s).find("ground"), std::string::npos);
    EXPECT_EQ(renderer->check(course.scene, s), "");
}

// A GL error stays queued until a glGetError reads it: one left by any call before or inside a
// pass is caught by the check after that pass, which names the pass (in release builds the state
// calls are not checked one by one; in the browser the frame is checked once: gl/check.h).
TEST_F(RendererGl, AnErrorLeftQueuedIsCaughtAfterThePassNamingIt) {
    auto course = scene::make_course_scene(2);
    render::Settings s;
    const auto plan = renderer->plan(course.scene, s, kSmall);
    ASSERT_FALSE(plan.passes.empty());
    EXPECT_NO_THROW(renderer->execute(course.scene, plan));  // the control: nothing queued
    const auto first = std::find_if(plan.passes.begin(), plan.passes.end(), [](const auto& p) { return !p.skipped; });
    ASSERT_NE(first, plan.passes.end());
    glEnable(0x1234);  // not a capability: GL_INVALID_ENUM, queued
    try {
        renderer->execute(course.scene, plan);
        ADD_FAILURE() << "the queued GL_INVALID_ENUM was not reported";
    } catch (const gl::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("GL_INVALID_ENUM"), std::string::npos) << what;
        if (gl::kCheckEachCall)
            EXPECT_NE(what.find(" after "), std::string::npos) << what;  // checked builds: the first checked call
        else
            EXPECT_NE(what.find("the " + first->name + " pass"), std::string::npos) << what;
    }
    EXPECT_NO_THROW(renderer->execute(course.scene, plan));  // the check drained the queue
}

TEST_F(RendererGl, EveryCombinationRendersWithoutGlErrors) {
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(src.open("teapot", error, warnings));
    render::Settings s;
    s.map_size = 128;
    const render::FrameInputs in = render::offscreen(48, 48);
    for (auto t : {render::Technique::ShadowMap, render::Technique::Planar, render::Technique::None})
        for (auto e : shadow::kAllEncodings)
            for (auto f : shadow::kAllFilters)
                for (auto a : {render::Aov::Color, render::Aov::Visibility, render::Aov::LightDepth}) {
                    s.technique = t;
                    s.encoding = e;
                    s.filter = f;
                    s.aov = a;
                    if (!renderer->check(src.at(0.3), s, in).empty()) continue;
                    // Each pass ends with a glGetError check that throws naming the pass.
                    EXPECT_NO_THROW(renderer->render(src.at(0.3), s, in)) << render::to_args(s);
                    EXPECT_NO_THROW(gl::check_errors("after the frame")) << render::to_args(s);
                }
}

// Every variant compiles and links on the context, as ShaderLibrary::get builds it; each stage's
// distinct code compiled once (5413 variants, 896 of them GEOMETRIC_HORIZON), in batches the driver
// may compile in parallel (GL_KHR_parallel_shader_compile), nothing kept. Through get(), one by
// one and all kept, it took 45 s on llvmpipe with Mesa's shader cache cold; this way 31 s.
TEST_F(RendererGl, EveryShaderVariantCompilesOnTheContext) {
    const auto variants = render::all_variants();
    ASSERT_GT(variants.size(), 50u);
    std::set<std::string> keys;
    for (const auto& v : variants) keys.insert(v.key());
    EXPECT_EQ(keys.size(), variants.size()) << "two variants with one key: the library would compile one of them";
    // A variant that requires an extension the context lacks is never asked of it: GBUFFER_MRT's
    // `#extension GL_EXT_draw_buffers : require` must fail to compile there (GLSL ES 1.00 3.4), and
    // the plan draws one G-buffer pass per target instead (NVIDIA's GLES 2 has no EXT_draw_buffers);
    // GEOMETRIC_HORIZON's OES_standard_derivatives likewise (the interpolated normal's horizon then).
    std::vector<render::Variant> wanted;
    const auto has = [](const render::Variant& v, const char* d) {
        return std::find(v.defines.begin(), v.defines.end(), d) != v.defines.end();
    };
    for (const auto& v : variants) {
        if (has(v, "GBUFFER_MRT") && !renderer->caps().draw_buffers) continue;
        if (has(v, "GEOMETRIC_HORIZON") && !renderer->caps().standard_derivatives) continue;
        wanted.push_back(v);
    }
    RecordProperty("variants_checked", static_cast<int>(wanted.size()));
    RecordProperty("variants_without_their_extension", static_cast<int>(variants.size() - wanted.size()));
    const std::vector<std::string> failed = render::check_variants(wanted);
    for (const auto& f : failed) ADD_FAILURE() << f;
    EXPECT_EQ(failed.size(), 0u) << "of " << wanted.size() << " variants";
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

// The framebuffer's failure classes (the course notes' FBO validation): each incomplete status
// provoked, and the error naming it, saying what it means and listing what was attached. Missing
// and attachment failures every GLES2 context produces; differing sizes and separate depth and
// stencil buffers are allowed by some (GLES3 lifted the first; a driver may support the second):
// there the framebuffer must be complete, and the test says which the context did.
std::string incomplete(const gl::FramebufferDesc& d) {
    try {
        gl::Framebuffer fb(d);
    } catch (const gl::Error& e) {
        return e.what();
    }
    return "";
}

TEST_F(RendererGl, AnIncompleteFramebufferNamesItsStatus) {
    gl::FramebufferDesc d;  // nothing attached
    d.label = "empty";
    const std::string e = incomplete(d);
    EXPECT_NE(e.find("empty: framebuffer incomplete: GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: nothing is attached"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("(attached: nothing)"), std::string::npos) << e;
}

TEST_F(RendererGl, AnUnrenderableAttachmentIsNamed) {
    if (!renderer->caps().depth_texture) GTEST_SKIP() << "no OES_depth_texture: no depth texture to misplace";
    gl::TextureDesc td;
    td.width = td.height = 32;
    td.format = gl::TextureFormat::Depth;
    td.label = "depth as colour";
    const gl::Texture depth(td);
    gl::FramebufferDesc d;
    d.color = &depth;  // a depth format at the colour attachment
    d.label = "misplaced";
    const std::string e = incomplete(d);
    EXPECT_NE(e.find("GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: an attachment cannot be rendered to"), std::string::npos) << e;
    EXPECT_NE(e.find("(attached: colour texture depth 32x32)"), std::string::npos) << e;
}

TEST_F(RendererGl, DifferingSizesAreNamedWhereTheContextRefusesThem) {
    gl::TextureDesc td;
    td.width = td.height = 64;
    const gl::Texture color(td);
    const gl::Renderbuffer depth(gl::RenderbufferFormat::Depth16, 32, 32, "small depth");
    gl::FramebufferDesc d;
    d.color = &color;
    d.depth = &depth;
    d.label = "mismatched";
    const std::string e = incomplete(d);
    std::printf("colour 64x64 + depth 32x32 on %s: %s\n", renderer->caps().renderer.c_str(),
                e.empty() ? "complete (this context allows differing sizes)" : e.c_str());
    if (!e.empty()) {
        EXPECT_NE(e.find("GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS: the attachments differ in size"), std::string::npos) << e;
        EXPECT_NE(e.find("(attached: colour texture rgba8 64x64, depth renderbuffer depth16 32x32)"), std::string::npos) << e;
    }
}

TEST_F(RendererGl, SeparateDepthAndStencilAreNamedWhereUnsupported) {
    gl::TextureDesc td;
    td.width = td.height = 32;
    const gl::Texture color(td);
    const gl::Renderbuffer depth(gl::RenderbufferFormat::Depth16, 32, 32, "depth");
    const gl::Renderbuffer stencil(gl::RenderbufferFormat::Stencil8, 32, 32, "stencil");
    gl::FramebufferDesc d;
    d.color = &color;
    d.depth = &depth;
    d.stencil = &stencil;
    d.label = "separate";
    const std::string e = incomplete(d);
    std::printf("depth16 + stencil8 apart on %s: %s\n", renderer->caps().renderer.c_str(),
                e.empty() ? "complete (this context supports them apart)" : e.c_str());
    if (!e.empty()) {
        EXPECT_NE(e.find("GL_FRAMEBUFFER_UNSUPPORTED: this implementation does not support"), std::string::npos) << e;
    }
}

TEST(FramebufferStatus, EveryIncompleteStatusHasAMeaning) {
    for (unsigned int s : {0x8CD6u, 0x8CD7u, 0x8CD9u, 0x8CDDu})  // attachment, missing, dimensions, unsupported
        EXPECT_FALSE(gl::framebuffer_status_meaning(s).empty()) << std::hex << s;
    EXPECT_TRUE(gl::framebuffer_status_meaning(0x8CD5u).empty());  // complete
}

TEST_F(RendererGl, GltfSceneRendersWithAShadow) {
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(src.open(test::test_data_dir() + "/sphere_over_plane.gltf", error, warnings)) << error;
    render::Settings s;
    s.aov = render::Aov::Visibility;
    const auto& plan = renderer->render(src.at(0.0), s, render::offscreen(128, 128));
    EXPECT_TRUE(plan.drawn("shadow-map"));
    const auto px = renderer->read_image();
    // The shadow on the plane: dark pixels in the lower rows (top row first), below the sphere.
    // (The sphere's own underside faces away from the light; with its back faces in the map it
    // reads lit in the visibility AOV, and the truth leaves such pixels out of every score.)
    size_t dark = 0;
    for (size_t y = 80; y < 128; ++y)
        for (size_t x = 0; x < 128; ++x) dark += px[(y * 128 + x) * 4] < 128;
    EXPECT_GT(dark, 60u) << "the sphere casts a shadow on the plane";
}

TEST_F(RendererGl, ThePrintedPlanIsThePlanThatRuns) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.map_size = 256;
    for (auto t : render::kAllTechniques) {
        s.technique = t;
        const render::FramePlan planned = renderer->plan(course.scene, s, kSmall);
        const render::FramePlan& ran = renderer->render(course.scene, s, kSmall);
        EXPECT_EQ(planned.to_json(), ran.to_json()) << render::to_string(t);
        // Planned again now, the same frame reuses what the first one drew.
        const render::FramePlan next = renderer->plan(course.scene, s, kSmall);
        if (t == render::Technique::ShadowMap) {
            EXPECT_TRUE(next.passes[0].skipped);
        }
    }
}

TEST_F(RendererGl, ThePoolHoldsOnlyWhatTheLastPlanDeclared) {
    auto course = scene::make_course_scene(4);
    render::Settings s;
    s.map_size = 512;
    renderer->render(course.scene, s, kSmall);
    EXPECT_TRUE(renderer->pool().has("shadow-map"));
    EXPECT_TRUE(renderer->pool().has("camera"));
    EXPECT_EQ(renderer->pool().bytes(), renderer->last_plan()->resource("shadow-map")->desc.bytes() +
                                            renderer->last_plan()->resource("camera")->desc.bytes());
    // 512 x 512 RGBA8 + a 16-bit depth buffer (a packed map's depth only keeps the nearest caster).
    EXPECT_EQ(renderer->last_plan()->resource("shadow-map")->desc.bytes(), 512u * 512u * 6u);
    s.technique = render::Technique::None;
    renderer->render(course.scene, s, kSmall);
    EXPECT_FALSE(renderer->pool().has("shadow-map"));
    EXPECT_EQ(renderer->pool().count(), 1u);
    // Two maps under two names are two resources; a bigger map replaces the smaller one.
    s.technique = render::Technique::ShadowMap;
    renderer->render(course.scene, s, kSmall);
    s.map_size = 1024;
    renderer->render(course.scene, s, kSmall);
    EXPECT_EQ(renderer->pool().count(), 2u);
    EXPECT_EQ(renderer->last_plan()->resource("shadow-map")->desc.width, 1024);
    EXPECT_TRUE(renderer->last_plan()->drawn("shadow-map"));
}

// W09P2b's pattern: one plan renders into a texture of the pool, the next samples it where the
// scene has an image, and the scene itself is not edited.
TEST_F(RendererGl, ATextureOutputIsSampledByTheNextPlan) {
    auto course = scene::make_course_scene(4);
    scene::Scene& sc = course.scene;
    const int image = static_cast<int>(sc.images.size());
    sc.images.push_back(scene::Image{1, 1, {0, 0, 0, 255}});  // a black placeholder
    scene::Material m;
    m.base_color_texture = image;
    sc.materials.push_back(m);
    const int material = static_cast<int>(sc.materials.size()) - 1;
    const int table_material = sc.objects[static_cast<size_t>(course.table)].material;
    render::Settings s;
    s.technique = render::Technique::None;
    s.aov = render::Aov::Color;
    const render::Output tex = render::Output::texture("picture", 64, 64, gl::Sampling::Linear, gl::Wrap::Clamp);
    render::FrameInputs into;
    into.output = tex;
    renderer->render(sc, s, into);
    // The table drawn with the textured material: it shows the picture instead of black.
    render::FrameInputs in = kSmall;
    in.objects.push_back({course.table, -1, material});
    in.images.push_back({image, tex});
    const auto& plan = renderer->render(sc, s, in);
    EXPECT_TRUE(renderer->pool().has("picture"));
    ASSERT_EQ(plan.passes.size(), 1u);
    EXPECT_EQ(plan.passes[0].reads().size(), 1u);
    const auto with_picture = renderer->read_image();
    in.images.clear();
    renderer->render(sc, s, in);
    EXPECT_NE(renderer->read_image(), with_picture);
    EXPECT_EQ(sc.objects[static_cast<size_t>(course.table)].material, table_material);  // the scene is not edited
}

// W09P2b's rtt=copy: the first plan draws into its image and copies it into a texture
// (glCopyTexImage2D, the copy-to-texture pass), the next samples that texture: the same frame as
// through a texture output (an FBO), and the copy holds the image byte for byte (RGB).
TEST_F(RendererGl, ACopiedImageIsSampledLikeARenderedTexture) {
    auto course = scene::make_course_scene(4);
    scene::Scene& sc = course.scene;
    const int image = static_cast<int>(sc.images.size());
    sc.images.push_back(scene::Image{1, 1, {0, 0, 0, 255}});
    scene::Material m;
    m.base_color_texture = image;
    sc.materials.push_back(m);
    const int material = static_cast<int>(sc.materials.size()) - 1;
    render::Settings s;
    s.technique = render::Technique::None;
    s.aov = render::Aov::Color;
    const auto frame_with = [&](const render::Output& picture) {
        render::FrameInputs in = kSmall;
        in.objects.push_back({course.table, -1, material});
        in.images.push_back({image, picture});
        renderer->render(sc, s, in);
        return renderer->read_image();
    };
    const render::Output fbo = render::Output::texture("picture", 64, 64, gl::Sampling::Linear, gl::Wrap::Clamp);
    render::FrameInputs into;
    into.output = fbo;
    renderer->render(sc, s, into);
    const auto through_fbo = frame_with(fbo);

    render::FrameInputs copy;
    copy.output = render::Output::offscreen(64, 64);
    copy.output.copy_to = "copied";
    copy.output.sampling = gl::Sampling::Linear;
    const auto& plan = renderer->render(sc, s, copy);
    ASSERT_EQ(plan.passes.back().name, "copy-to-texture");
    const render::PlannedResource* copied = plan.resource("copied");
    ASSERT_NE(copied, nullptr);
    EXPECT_FALSE(copied->desc.depth_buffer.has_value());  // colour only: the copy brings no depth
    const auto camera = renderer->read_image("camera");
    const auto in_texture = renderer->read_image("copied");
    ASSERT_EQ(camera.size(), in_texture.size());
    for (size_t i = 0; i < camera.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha: the copy is RGB (a window may have no alpha)
        ASSERT_EQ(camera[i], in_texture[i]) << "byte " << i;
    }
    const auto through_copy =
        frame_with(render::Output::copied_texture("copied", 64, 64, gl::Sampling::Linear, gl::Wrap::Clamp));
    EXPECT_EQ(through_copy, through_fbo);
    // ...and it shows the picture: the table with the black placeholder differs.
    render::FrameInputs plain = kSmall;
    plain.objects.push_back({course.table, -1, material});
    renderer->render(sc, s, plain);
    EXPECT_NE(renderer->read_image(), through_copy);
}

TEST_F(RendererGl, AMisspeltUniformFailsInDebugBuilds) {
    if (!gl::kStrictUniforms) GTEST_SKIP() << "release build: unknown uniforms are ignored";
    gl::Device device;
    const gl::Program& p = renderer->shaders().get(render::probe_variant());
    device.use(p);
    EXPECT_NO_THROW(p.set("u_value", glm::vec4(0.0f)));
    try {
        p.set("u_valeu", glm::vec4(0.0f));
        FAIL() << "a misspelt uniform was set silently";
    } catch (const gl::Error& e) {
        EXPECT_NE(std::string(e.what()).find("u_valeu"), std::string::npos) << e.what();
    }
    // A uniform of a feature the variant lacks is no better than a misspelt one.
    render::LitFeatures f;
    const gl::Program& lit = renderer->shaders().get(render::lit_variant(f));
    EXPECT_THROW(lit.set("u_shadow_map", 0), gl::Error);
    f.shadow_map = true;
    const gl::Program& shadowed = renderer->shaders().get(render::lit_variant(f));
    device.use(shadowed);
    EXPECT_NO_THROW(shadowed.set("u_shadow_map", 0));
}

}  // namespace
