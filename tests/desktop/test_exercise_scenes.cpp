// The exercises with a scene of their own (cascades: the terrain; bulb: the room) without a GL
// context: the scene, the fly camera and the URL, their own keys, their settings kept from the
// others. (Split from test_exercise_options.cpp: no file over 600 lines.)
#include <gtest/gtest.h>

#include <algorithm>

#include "exercises.h"
#include "platform/platform.h"
#include "scenes/terrain_scene.h"

using penumbra::examples::CourseApp;

// The cascades exercise: its own scene (the terrain), a camera that flies and is kept in the URL,
// its keys (letters other exercises use, bound here alone) and its settings kept from the others.
TEST(ExerciseCascades, TheTerrainAndItsCamera) {
    CourseApp a("cascades");
    EXPECT_EQ(a.scene().objects.size(), 361u);
    EXPECT_FALSE(a.camera_moved());
    const penumbra::examples::FlyCamera start = a.camera();
    EXPECT_NEAR(start.yaw, 8.0f, 0.01f);     // make_large_scenes.py: 8 degrees right of north
    EXPECT_NEAR(start.pitch, -4.0f, 0.01f);  // and 4 degrees down
    EXPECT_EQ(a.query().find("camera="), std::string::npos);
    ASSERT_TRUE(a.fly(10.0, 0.0, 0.0, 0.0, 0.0));
    EXPECT_TRUE(a.camera_moved());
    // Ten metres along the view: north (-z) and a little east, down by sin(4 degrees).
    EXPECT_NEAR(glm::length(a.camera().eye - start.eye), 10.0f, 0.01f);
    EXPECT_LT(a.camera().eye.z, start.eye.z - 9.0f);
    EXPECT_GT(a.camera().eye.x, start.eye.x);
    // Never under the ground: flying down into it stops 0.3 m above.
    ASSERT_TRUE(a.fly(0.0, 0.0, -50.0, 0.0, 0.0));
    EXPECT_NEAR(a.camera().eye.y - penumbra::scene::terrain_km_height(a.camera().eye.x, a.camera().eye.z), 0.3f, 1e-3f);
    ASSERT_TRUE(a.fly(0.0, 0.0, 20.0, 190.0, -100.0));  // yaw wraps, pitch stops at -89
    EXPECT_NEAR(a.camera().pitch, -89.0f, 1e-4f);
    EXPECT_NEAR(a.camera().yaw, start.yaw + 190.0f - 360.0f, 1e-3f);
    // The URL keeps it, and a reload puts the camera back.
    const std::string q = a.query();
    EXPECT_NE(q.find("camera="), std::string::npos) << q;
    CourseApp b("cascades");
    for (const auto& [k, v] : a.options()) ASSERT_EQ(b.set_option(k, v), "") << k << "=" << v;
    EXPECT_EQ(b.query(), q);
    EXPECT_LT(glm::length(b.camera().eye - a.camera().eye), 1e-3f);
    // Bad cameras are refused and change nothing.
    for (const char* bad : {"1,2,3,4", "1,2,3,4,5,6", "1,2,x,4,5", "1,2,3,4,95", "5000,0,0,0,0", "1,2,3,4,nan", ""})
        EXPECT_NE(b.set_option("camera", bad), "") << bad;
    EXPECT_EQ(b.query(), q);
    b.reset_camera();
    EXPECT_FALSE(b.camera_moved());
    EXPECT_EQ(b.query().find("camera="), std::string::npos);
    // The course scene's exercises have no fly camera.
    CourseApp c("w09p2c");
    EXPECT_FALSE(c.fly(1.0, 0.0, 0.0, 0.0, 0.0));
    EXPECT_NE(c.set_option("camera", "0,5,0,0,0"), "");
    EXPECT_EQ(c.scene().objects.size(), CourseApp("w09p1").scene().objects.size());
}

TEST(ExerciseCascades, Keys) {
    CourseApp a("cascades");
    EXPECT_EQ(a.on_key('N', false), "cascades = auto");
    EXPECT_EQ(a.settings().cascades, 0);
    EXPECT_EQ(a.on_key('N', false), "cascades = 1");
    EXPECT_EQ(a.on_key('N', true), "cascades = auto");
    EXPECT_EQ(a.on_key('K', false), "cascade-split = 1");
    EXPECT_EQ(a.on_key('G', false), "cascade-snap = off");
    EXPECT_FALSE(a.settings().cascade_snap);
    EXPECT_EQ(a.on_key('B', false), "cascade-blend = 0.2");
    EXPECT_EQ(a.on_key('A', false), "aov = color");
    EXPECT_EQ(a.on_key('A', false), "aov = visibility");
    const auto eye = a.camera().eye;
    EXPECT_EQ(a.on_key('W', false).rfind("camera = ", 0), 0u);
    EXPECT_NEAR(glm::length(a.camera().eye - eye), 2.0f, 1e-3f);
    a.on_key('W', true);
    EXPECT_NEAR(glm::length(a.camera().eye - eye), 22.0f, 1e-2f);
    a.on_key('E', false);
    EXPECT_NEAR(a.camera().yaw, 13.0f, 1e-3f);
    a.on_key('R', false);
    EXPECT_NEAR(a.camera().pitch, -1.0f, 1e-3f);
    EXPECT_EQ(a.on_key('O', false), "camera = the scene's");
    EXPECT_FALSE(a.camera_moved());
    // Elsewhere the letters keep their own options: B is the sheet's bias, N the light samples.
    a.on_key('4', false);
    EXPECT_EQ(a.exercise().name, "w09p2c");
    EXPECT_EQ(a.on_key('B', false).rfind("bias = sheet", 0), 0u);
    // The cascades exercise has no digit (9 and 0 are controls): Tab steps through every exercise.
    EXPECT_EQ(a.on_key('9', false), "shading = deferred");
    for (int i = 0; i < 5; ++i) a.on_key(penumbra::platform::keys::Tab, false);
    EXPECT_EQ(a.exercise().name, "cascades");
    a.on_key(penumbra::platform::keys::Tab, false);
    EXPECT_EQ(a.exercise().name, "bulb");
    a.on_key(penumbra::platform::keys::Tab, false);
    EXPECT_EQ(a.exercise().name, "w09p1");
    a.on_key(penumbra::platform::keys::Tab, true);
    a.on_key(penumbra::platform::keys::Tab, true);
    EXPECT_EQ(a.exercise().name, "cascades");
    // Its settings do not follow into the course scene's exercises; they come back with it.
    ASSERT_EQ(a.set_option("cascade-snap", "off"), "");
    a.on_key('4', false);
    EXPECT_EQ(a.frame_settings().cascades, penumbra::render::Settings{}.cascades);  // the default (auto)
    EXPECT_TRUE(a.frame_settings().cascade_snap);
    const std::string help = CourseApp::key_help();
    EXPECT_NE(help.find("cascade-split"), std::string::npos) << help;
    EXPECT_NE(help.find("exercise cascades"), std::string::npos) << help;
}

// The bulb exercise: its own scene (the room), the fly camera kept inside it, its keys (N the
// shadow maps, K the filter there), its settings kept from the others.
TEST(ExerciseBulb, TheRoomAndItsCamera) {
    CourseApp a("bulb");
    EXPECT_EQ(a.scene().objects.size(), 22u);
    EXPECT_EQ(a.scene().light.type, penumbra::scene::LightType::Point);
    EXPECT_EQ(a.frame_settings().cascades, penumbra::render::Settings::kCube);
    EXPECT_DOUBLE_EQ(a.fly_step(), 0.25);
    const penumbra::examples::FlyCamera start = a.camera();
    EXPECT_NEAR(start.eye.x, 3.7f, 1e-4f);  // make_large_scenes.py: the corner under the ceiling
    EXPECT_NEAR(start.eye.y, 2.6f, 1e-4f);
    ASSERT_TRUE(a.fly(1.0, 0.0, 0.0, 0.0, 0.0));
    EXPECT_NEAR(glm::length(a.camera().eye - start.eye), 1.0f, 1e-3f);
    // The walls, the floor and the ceiling hold it 0.2 m inside the room.
    ASSERT_TRUE(a.fly(0.0, 0.0, 50.0, 0.0, 0.0));
    EXPECT_NEAR(a.camera().eye.y, 2.8f, 1e-5f);
    ASSERT_TRUE(a.fly(0.0, 0.0, -50.0, 0.0, 0.0));
    EXPECT_NEAR(a.camera().eye.y, 0.2f, 1e-5f);
    ASSERT_TRUE(a.fly(0.0, -50.0, 0.0, 0.0, 0.0));
    ASSERT_TRUE(a.fly(0.0, 0.0, 0.0, 90.0, 0.0));
    ASSERT_TRUE(a.fly(50.0, 0.0, 0.0, 0.0, 0.0));
    for (int k : {0, 2}) {
        EXPECT_LE(std::fabs(a.camera().eye[k]), (k == 0 ? 4.0f : 3.0f) - 0.2f + 1e-5f) << k;
    }
    // The URL keeps it, a reload puts it back; an eye outside the room is refused.
    const std::string q = a.query();
    EXPECT_NE(q.find("camera="), std::string::npos) << q;
    CourseApp b("bulb");
    for (const auto& [k, v] : a.options()) ASSERT_EQ(b.set_option(k, v), "") << k << "=" << v;
    EXPECT_EQ(b.query(), q);
    EXPECT_NE(b.set_option("camera", "5,1,0,0,0"), "");
    EXPECT_NE(b.set_option("camera", "0,-0.5,0,0,0"), "");
    EXPECT_EQ(b.query(), q);
    ASSERT_EQ(b.set_option("camera", "0,0.1,0,0,0"), "");  // inside, but too close to the floor: lifted
    EXPECT_NEAR(b.camera().eye.y, 0.2f, 1e-5f);
    // The terrain's camera is not the room's.
    b.on_key(penumbra::platform::keys::Tab, true);
    EXPECT_EQ(b.exercise().name, "cascades");
    EXPECT_FALSE(b.camera_moved());
    EXPECT_DOUBLE_EQ(b.fly_step(), 2.0);
    EXPECT_EQ(b.set_option("camera", "0,-50,0,0,0"), "");  // under the terrain: kept above its ground, not refused
    EXPECT_NEAR(b.camera().eye.y - penumbra::scene::terrain_km_height(0.0f, 0.0f), 0.3f, 1e-3f);
}

TEST(ExerciseBulb, Keys) {
    CourseApp a("bulb");
    EXPECT_EQ(a.on_key('N', false), "cascades = 1");
    EXPECT_EQ(a.frame_settings().cascades, 1);
    EXPECT_EQ(a.on_key('N', false), "cascades = auto");
    EXPECT_EQ(a.on_key('N', true), "cascades = 1");
    EXPECT_EQ(a.on_key('N', true), "cascades = cube");
    EXPECT_EQ(a.on_key('K', false), "filter = pcf4x4");
    EXPECT_EQ(a.on_key('K', false), "filter = pcss");
    EXPECT_EQ(a.on_key('C', false), "cube-layout = cubemap");
    EXPECT_TRUE(a.frame_settings().cube_map);
    EXPECT_EQ(a.on_key('C', false), "cube-layout = atlas");
    EXPECT_EQ(a.on_key('M', false), "map-size = 1024");
    EXPECT_EQ(a.on_key('M', false), "map-size = 256");
    EXPECT_EQ(a.on_key('A', false), "aov = color");
    const auto eye = a.camera().eye;
    EXPECT_EQ(a.on_key('W', false).rfind("camera = ", 0), 0u);
    EXPECT_NEAR(glm::length(a.camera().eye - eye), 0.25f, 1e-4f);
    EXPECT_EQ(a.on_key('O', false), "camera = the scene's");
    // Leaving it puts its starting settings back; the cube is its alone.
    a.on_key('1', false);
    EXPECT_EQ(a.frame_settings().cascades, penumbra::render::Settings{}.cascades);  // the default (auto)
    EXPECT_EQ(a.settings().map_size, 1024);
    const std::string help = CourseApp::key_help();
    EXPECT_NE(help.find("bulb: shadow maps cube"), std::string::npos) << help;
    EXPECT_NE(help.find("exercise bulb"), std::string::npos) << help;
}

// A page (the marble deferred) whose exercise has a scene of its own completes the course scene
// after its first frame, marble and all: switching to a course exercise then finds it whole.
TEST(ExerciseBulb, APageCompletesTheCourseSceneAfterTheRoom) {
    for (const char* own : {"bulb", "cascades"}) {
        CourseApp page(own, true);
        EXPECT_FALSE(page.scene_complete()) << own << ": the first frame is the room unshadowed";
        const size_t objects = page.scene().objects.size();
        EXPECT_TRUE(page.complete_scene()) << own;
        EXPECT_TRUE(page.scene_complete()) << own;
        EXPECT_FALSE(page.complete_scene()) << own << ": nothing left to make";
        EXPECT_EQ(page.scene().objects.size(), objects) << own << ": still its own scene";
        page.set_exercise("w09p1");
        const auto& s = page.scene();
        const auto table = std::find_if(s.materials.begin(), s.materials.end(), [](const auto& m) { return m.name == "marble"; });
        ASSERT_NE(table, s.materials.end()) << own;
        EXPECT_GE(table->base_color_texture, 0) << own << ": the marble made, not the placeholder";
        EXPECT_EQ(s.images.at(static_cast<size_t>(table->base_color_texture)).width, 512) << own;
    }
}
