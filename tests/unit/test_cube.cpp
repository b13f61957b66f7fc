// A point light's cube without a GL context: the faces' orientation and the face a direction
// falls in, which faces see what the camera sees and which casters each draws, auto's choice, and
// the plan's atlas, passes and per-face reuse.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan/techniques/reports.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scene/gltf_loader.h"
#include "scene/primitives.h"
#include "shadow/cube.h"
#include "../cube_passes.h"
#include "../test_paths.h"

using namespace penumbra;

namespace {

// A closed room of six inward panels (as boxes, x -4..4, y 0..3, z -3..3), a bulb at (0, 1.8, 0),
// a box on the floor beside it and one hanging above; the camera in a corner looking across.
scene::Scene room() {
    scene::Scene s;
    s.meshes = {scene::make_box(glm::vec3(0.5f))};  // a unit cube, scaled per object
    s.materials.resize(1);
    auto add = [&](const char* name, glm::vec3 centre, glm::vec3 size) {
        scene::Object o;
        o.name = name;
        o.mesh = 0;
        o.world = glm::translate(glm::mat4(1.0f), centre) * glm::scale(glm::mat4(1.0f), size);
        s.objects.push_back(o);
    };
    add("floor", {0.0f, -0.05f, 0.0f}, {8.0f, 0.1f, 6.0f});
    add("ceiling", {0.0f, 3.05f, 0.0f}, {8.0f, 0.1f, 6.0f});
    add("wall -x", {-4.05f, 1.5f, 0.0f}, {0.1f, 3.0f, 6.0f});
    add("wall +x", {4.05f, 1.5f, 0.0f}, {0.1f, 3.0f, 6.0f});
    add("wall -z", {0.0f, 1.5f, -3.05f}, {8.0f, 3.0f, 0.1f});
    add("wall +z", {0.0f, 1.5f, 3.05f}, {8.0f, 3.0f, 0.1f});
    add("crate", {1.5f, 0.4f, 0.0f}, {0.8f, 0.8f, 0.8f});
    add("lamp", {0.0f, 2.6f, 0.0f}, {0.3f, 0.3f, 0.3f});
    s.light.type = scene::LightType::Point;
    s.light.position = glm::vec3(0.0f, 1.8f, 0.0f);
    s.camera.view = glm::lookAt(glm::vec3(3.7f, 2.6f, 2.7f), glm::vec3(-1.5f, 1.1f, -1.3f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(75.0f);
    s.camera.znear = 0.05f;
    s.camera.zfar = 20.0f;
    return s;
}

std::vector<scene::Bounds> bounds_of(const scene::Scene& s) {
    std::vector<scene::Bounds> out;
    for (const scene::Object& o : s.objects) out.push_back(scene::object_bounds(s, o));
    return out;
}

glm::mat4 camera_view_proj(const scene::Scene& s, const glm::mat4& view) {
    return glm::perspective(s.camera.yfov, 1.0f, s.camera.znear, s.camera.zfar) * view;
}

TEST(CubeFaces, EachLooksAlongItsAxisAsARightHandedView) {
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < shadow::kCubeFaces; ++f) {
        const glm::mat3 r = shadow::cube_face_rotation(f);
        const glm::vec3 e = r * axes[f];
        EXPECT_NEAR(e.z, -1.0f, 1e-6f) << shadow::cube_face_name(f);
        EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-5f) << "a mirrored face would turn its triangles' winding over";
        EXPECT_EQ(shadow::cube_face_of(axes[f]), f);
    }
}

TEST(CubeFaces, ADirectionFallsInTheFaceWhoseWindowHoldsIt) {
    // The face chosen sees the direction within its 90 degrees: |x|, |y| <= -z in its eye space.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 d(u(rng), u(rng), u(rng));
        if (glm::length(d) < 1e-3f) continue;
        const int f = shadow::cube_face_of(d);
        const glm::vec3 e = shadow::cube_face_rotation(f) * d;
        EXPECT_GT(-e.z, 0.0f);
        EXPECT_LE(std::fabs(e.x), -e.z * (1.0f + 1e-5f));
        EXPECT_LE(std::fabs(e.y), -e.z * (1.0f + 1e-5f));
    }
}

TEST(CubeFit, FacesSeeingNothingInViewAreNotDrawn) {
    const scene::Scene s = room();
    const auto b = bounds_of(s);
    std::string why = "unset";
    // Looking straight down at the floor from under the ceiling.
    const glm::mat4 down = glm::lookAt(glm::vec3(-2.5f, 2.8f, 1.5f), glm::vec3(-2.5f, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    const shadow::CubeFit fit = shadow::fit_cube(s.light, b, b, camera_view_proj(s, down), 256, 2, &why);
    EXPECT_EQ(why, "");
    EXPECT_TRUE(fit.faces[3].drawn);   // -y: the floor
    EXPECT_FALSE(fit.faces[2].drawn);  // +y: the ceiling is out of view
    EXPECT_LT(fit.drawn(), 6);
    // Every face from the corner across the room.
    const shadow::CubeFit all = shadow::fit_cube(s.light, b, b, camera_view_proj(s, s.camera.view), 256, 2, &why);
    EXPECT_EQ(all.drawn(), 6);
    EXPECT_EQ(all.atlas_width, 768);
    EXPECT_EQ(all.atlas_height, 512);
    EXPECT_FLOAT_EQ(all.tangent, 256.0f / 252.0f);
    for (int f = 0; f < 6; ++f) {
        EXPECT_EQ(all.faces[static_cast<size_t>(f)].tile_x, (f % 3) * 256);
        EXPECT_EQ(all.faces[static_cast<size_t>(f)].tile_y, (f / 3) * 256);
    }
}

TEST(CubeFit, EachFaceDrawsTheCastersInItsPyramidAndTheDepthHoldsThem) {
    const scene::Scene s = room();
    const auto b = bounds_of(s);
    const shadow::CubeFit fit = shadow::fit_cube(s.light, b, b, camera_view_proj(s, s.camera.view), 256, 2, nullptr);
    auto has = [&](int face, int object) {
        const auto& c = fit.faces[static_cast<size_t>(face)].casters;
        return std::find(c.begin(), c.end(), object) != c.end();
    };
    EXPECT_TRUE(has(2, 7));   // the lamp above the bulb: +y
    EXPECT_FALSE(has(3, 7));  // not -y
    EXPECT_TRUE(has(0, 6) || has(3, 6));  // the crate: beside and below
    EXPECT_FALSE(has(1, 6));  // not -x
    EXPECT_TRUE(has(1, 2));   // wall -x in -x
    // Near: before the lamp's underside (0.65 above the bulb); far: the room's farthest corner
    // along a face's axis (4 in x) seen.
    EXPECT_LE(fit.znear, 0.65f);
    EXPECT_GT(fit.znear, 0.5f);
    EXPECT_GE(fit.zfar, 4.0f);
    EXPECT_LT(fit.zfar, 4.3f);
}

// Issue 56: a spot light's cube draws only the faces its cone reaches. Pointing down from the
// bulb's place with a 30-degree cone, that is -y alone; with an 80-degree cone the walls' faces
// too, never the ceiling's. The point light at the same place draws all six (the control).
TEST(CubeFit, ASpotLightDrawsOnlyTheFacesItsConeReaches) {
    scene::Scene s = room();
    const auto b = bounds_of(s);
    const glm::mat4 vp = camera_view_proj(s, s.camera.view);
    ASSERT_EQ(shadow::fit_cube(s.light, b, b, vp, 256, 2, nullptr).drawn(), 6);
    s.light.type = scene::LightType::Spot;
    s.light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.light.spot_outer_cone = glm::radians(30.0f);
    std::string why = "unset";
    const shadow::CubeFit narrow = shadow::fit_cube(s.light, b, b, vp, 256, 2, &why);
    EXPECT_EQ(why, "");
    EXPECT_EQ(narrow.drawn(), 1);
    EXPECT_TRUE(narrow.faces[3].drawn);
    s.light.spot_outer_cone = glm::radians(80.0f);
    const shadow::CubeFit wide = shadow::fit_cube(s.light, b, b, vp, 256, 2, &why);
    EXPECT_EQ(wide.drawn(), 5);
    EXPECT_FALSE(wide.faces[2].drawn);  // +y: behind the cone
}

TEST(CubeFit, NeedsAPointOrSpotLightAndAReceiverInView) {
    scene::Scene s = room();
    const auto b = bounds_of(s);
    std::string why;
    s.light.type = scene::LightType::Directional;
    EXPECT_EQ(shadow::fit_cube(s.light, b, b, camera_view_proj(s, s.camera.view), 256, 2, &why).drawn(), 0);
    EXPECT_EQ(why, "the light is directional");
    s.light.type = scene::LightType::Point;
    const glm::mat4 away = glm::lookAt(glm::vec3(30.0f, 1.0f, 0.0f), glm::vec3(60.0f, 1.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(shadow::fit_cube(s.light, b, b, camera_view_proj(s, away), 256, 2, &why).drawn(), 0);
    EXPECT_EQ(why, "the camera sees no receiver");
}

TEST(CubeWanted, APointLightInsideTheSceneOnly) {
    scene::Scene s = room();
    const auto b = bounds_of(s);
    std::string why;
    EXPECT_TRUE(shadow::cube_wanted(s.light, b, b, why));
    EXPECT_EQ(why, "a cube: the point light is inside the receivers' bounds");
    // Receivers only on the floor, the casters around the light: they surround it.
    EXPECT_TRUE(shadow::cube_wanted(s.light, {b[0]}, b, why));
    EXPECT_EQ(why, "a cube: the casters surround the point light");
    s.light.position = glm::vec3(0.0f, 20.0f, 0.0f);
    EXPECT_FALSE(shadow::cube_wanted(s.light, b, b, why));
    EXPECT_EQ(why, "one map: the point light is outside the scene's bounds");
    s.light.type = scene::LightType::Spot;
    EXPECT_FALSE(shadow::cube_wanted(s.light, b, b, why));
    s.light.type = scene::LightType::Directional;
    EXPECT_FALSE(shadow::cube_wanted(s.light, b, b, why));
}

struct CubePlan : ::testing::Test {
    scene::Scene s = room();
    render::Settings settings;
    gl::Caps caps = penumbra::testing::full_caps();
    render::FramePlan make(const render::FramePlan* previous = nullptr) {
        return render::plan(s, settings, caps, render::offscreen(128, 128), previous);
    }
    static int face_passes(const render::FramePlan& p, int* ran = nullptr) { return test::cube_face_passes(p, ran); }
};

TEST_F(CubePlan, OnePassPerDrawnFaceIntoItsTileOfOneAtlas) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "cube"), "");
    settings.map_size = 512;
    const render::FramePlan p = make();
    ASSERT_TRUE((render::cube_of(p) != nullptr));
    EXPECT_EQ(render::cascades_why_of(p), "--cascades cube");
    const render::PlannedResource* map = p.resource("shadow-map");
    ASSERT_NE(map, nullptr);
    EXPECT_EQ(map->desc.width, 1536);
    EXPECT_EQ(map->desc.height, 1024);
    EXPECT_EQ(face_passes(p), render::cube_of(p)->drawn());
    for (const render::Pass& pass : p.passes)
        if (pass.name.rfind("shadow-map face ", 0) == 0) {
            EXPECT_TRUE(pass.target.clip);
            EXPECT_EQ(pass.target.width, 512);
            EXPECT_FALSE(pass.content.empty());
        }
    // The atlas is cut to the context's maximum: 4096 / 3 per face.
    settings.map_size = 2048;
    const render::FramePlan cut = make();
    EXPECT_EQ(cut.resource("shadow-map")->desc.width, 3 * (4096 / 3));
    EXPECT_FALSE(cut.notes.empty());
}

TEST_F(CubePlan, ACubeMapLayoutIsOneSquareTextureOfSixFacesEachDrawnIntoItsFace) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "cube"), "");
    ASSERT_EQ(render::parse_option(settings, "cube-layout", "cubemap"), "");
    ASSERT_EQ(render::parse_option(settings, "filter", "pcf4x4"), "");
    settings.map_size = 512;
    const render::FramePlan p = make();
    ASSERT_TRUE((render::cube_of(p) != nullptr));
    EXPECT_TRUE(render::cube_of(p)->cube_map);
    // Exactly 90 degrees a face; the faces are drawn for receivers within the filter's guard.
    EXPECT_EQ(render::cube_of(p)->tangent, 1.0f);
    EXPECT_GT(render::cube_of(p)->reach, 1.0f);
    EXPECT_EQ(render::cube_of(p)->guard, 2);
    const render::PlannedResource* map = p.resource("shadow-map");
    ASSERT_NE(map, nullptr);
    EXPECT_TRUE(map->desc.cube);
    EXPECT_EQ(map->desc.width, 512);
    EXPECT_EQ(map->desc.height, 512);
    EXPECT_EQ(map->desc.describe().rfind("6 x 512x512 cube rgba8", 0), 0u) << map->desc.describe();
    std::vector<int> faces;
    for (const render::Pass& pass : p.passes)
        if (pass.name.rfind("shadow-map face ", 0) == 0) {
            faces.push_back(pass.target.face);
            EXPECT_EQ(pass.target.x, 0);
            EXPECT_EQ(pass.target.y, 0);
            EXPECT_EQ(pass.target.width, 512);
            EXPECT_NE(pass.detail.find("cube-map face"), std::string::npos) << pass.detail;
        }
    EXPECT_EQ(static_cast<int>(faces.size()), render::cube_of(p)->drawn());
    for (size_t i = 0; i < faces.size(); ++i)
        EXPECT_TRUE(render::cube_of(p)->faces[static_cast<size_t>(faces[i])].drawn) << faces[i];
    EXPECT_NE(p.to_text().find("a GL cube map"), std::string::npos);
    // A depth texture cannot be a cube map in WebGL 1: the atlas, with a note.
    ASSERT_EQ(render::parse_option(settings, "encoding", "depthtex"), "");
    const render::FramePlan atlas = make();
    ASSERT_TRUE((render::cube_of(atlas) != nullptr));
    EXPECT_FALSE(render::cube_of(atlas)->cube_map);
    EXPECT_FALSE(atlas.resource("shadow-map")->desc.cube);
    bool said = false;
    for (const std::string& n : atlas.notes) said |= n.find("no cube-map depth texture") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST_F(CubePlan, AutoPicksACubeForABulbInARoomAndSaysWhy) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "auto"), "");
    const render::FramePlan p = make();
    EXPECT_TRUE((render::cube_of(p) != nullptr));
    EXPECT_EQ(render::cascades_why_of(p), "auto: a cube: the point light is inside the receivers' bounds");
    s.light.position = glm::vec3(0.0f, 20.0f, 0.0f);
    const render::FramePlan one = make();
    EXPECT_FALSE((render::cube_of(one) != nullptr));
    EXPECT_TRUE(render::cascades_of(one).empty());
    EXPECT_EQ(render::cascades_why_of(one), "auto: one map: the point light is outside the scene's bounds");
}

TEST_F(CubePlan, ACubeForALightThatIsNotAPointIsOneMapWithANote) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "cube"), "");
    s.light.type = scene::LightType::Directional;
    const render::FramePlan p = make();
    EXPECT_FALSE((render::cube_of(p) != nullptr));
    EXPECT_EQ(render::cascades_why_of(p), "--cascades cube -> one map (the light is directional)");
    ASSERT_FALSE(p.notes.empty());
    EXPECT_NE(p.notes.back().find("one map instead"), std::string::npos);
}

// Issue 56: auto gives a spot light whose cone lights receivers beyond one frustum's 75 degrees a
// side the cube (wide_cone.gltf: an 80-degree cone over a long ground), with the reason; the same
// scene with a 40-degree cone keeps one map, and so does --cascades 1, with a note that the
// window is capped.
TEST(CubeAuto, AWideSpotConeGetsTheCubeANarrowOneKeepsOneMap) {
    scene::LoadResult r = scene::load_gltf(test::test_data_dir() + "/wide_cone.gltf");
    ASSERT_TRUE(r.ok) << r.error;
    scene::Scene& s = r.scene;
    ASSERT_EQ(s.light.type, scene::LightType::Spot);
    render::Settings settings;
    const gl::Caps caps = penumbra::testing::full_caps();
    const render::FramePlan wide = render::plan(s, settings, caps, render::offscreen(256, 256));
    ASSERT_NE(render::cube_of(wide), nullptr);
    EXPECT_EQ(render::cascades_why_of(wide),
              "auto: a cube: the spot light lights receivers in view beyond one frustum's 75 degrees a side");
    EXPECT_FALSE(render::cube_of(wide)->faces[2].drawn);  // +y: the cone points down
    ASSERT_EQ(render::parse_option(settings, "cascades", "1"), "");
    const render::FramePlan one = render::plan(s, settings, caps, render::offscreen(256, 256));
    EXPECT_EQ(render::cube_of(one), nullptr);
    bool noted = false;
    for (const std::string& n : one.notes) noted = noted || n.find("capped at 75 degrees") != std::string::npos;
    EXPECT_TRUE(noted);
    ASSERT_EQ(render::parse_option(settings, "cascades", "auto"), "");
    s.light.spot_outer_cone = glm::radians(40.0f);
    const render::FramePlan narrow = render::plan(s, settings, caps, render::offscreen(256, 256));
    EXPECT_EQ(render::cube_of(narrow), nullptr);
    // A point light in the spot's place: outside every box, so not a bulb's cube, but the ground
    // it lights in view runs beside and behind it: the cube, with its reason.
    s.light.type = scene::LightType::Point;
    const render::FramePlan point = render::plan(s, settings, caps, render::offscreen(256, 256));
    ASSERT_NE(render::cube_of(point), nullptr);
    EXPECT_EQ(render::cascades_why_of(point), "auto: a cube: the point light lights receivers in view that no one frustum "
                                              "holds (beside or behind it, or around it)");
}

TEST_F(CubePlan, AStillFaceIsSkippedAndAMovedCasterRedrawsItsFacesOnly) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "cube"), "");
    const render::FramePlan first = make();
    int ran = 0;
    const int faces = face_passes(first, &ran);
    EXPECT_EQ(ran, faces);
    const render::FramePlan second = make(&first);
    face_passes(second, &ran);
    EXPECT_EQ(ran, 0);
    // The lamp above the bulb moves: only the faces that draw it run.
    s.objects[7].world = glm::translate(glm::mat4(1.0f), glm::vec3(0.05f, 0.0f, 0.0f)) * s.objects[7].world;
    const render::FramePlan third = make(&second);
    face_passes(third, &ran);
    int drawing = 0;
    for (const render::Pass& pass : third.passes)
        if (pass.name.rfind("shadow-map face ", 0) == 0)
            for (const render::Draw& d : pass.draws) drawing += d.object == 7;
    EXPECT_EQ(ran, drawing);
    EXPECT_GE(ran, 1);
    EXPECT_LT(ran, faces);
    // Another packing is another content: every face runs.
    ASSERT_EQ(render::parse_option(settings, "encoding", "r8"), "");
    const render::FramePlan fourth = make(&third);
    face_passes(fourth, &ran);
    EXPECT_EQ(ran, face_passes(fourth));
}

}  // namespace
