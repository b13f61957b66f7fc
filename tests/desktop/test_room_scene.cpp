// The bulb room built in code (scenes/room_scene.h, what the browser's bulb page draws) against
// tests/data/bulb_room.gltf loaded by the glTF loader (what `penumbra render` draws).
#include <gtest/gtest.h>

#include <string>

#include "scene/gltf_loader.h"
#include "scenes/room_scene.h"
#include "../test_paths.h"
#include "scene_match.h"

#ifndef PENUMBRA_TEST_DATA
#error "PENUMBRA_TEST_DATA must name tests/data"
#endif

namespace {

using penumbra::scene::Scene;

TEST(RoomScene, MatchesTheGltfFile) {
    const auto loaded = penumbra::scene::load_gltf(penumbra::test::test_data_dir() + "/bulb_room.gltf");
    ASSERT_TRUE(loaded.ok) << loaded.error;
    const Scene made = penumbra::scene::make_bulb_room_scene();
    // Six panels, four objects on the floor, four on stands and two hanging (each with its stand or rod).
    ASSERT_EQ(made.objects.size(), 22u);
    ASSERT_EQ(made.meshes.size(), 8u);
    penumbra::test::expect_same_scene(made, loaded.scene, 1e-5f);
}

TEST(RoomScene, TheBulbAndTheCameraAreInTheRoom) {
    const Scene made = penumbra::scene::make_bulb_room_scene();
    EXPECT_EQ(made.light.type, penumbra::scene::LightType::Point);
    EXPECT_EQ(made.light.position, glm::vec3(0.2f, 1.8f, -0.1f));
    const auto room = penumbra::scene::scene_bounds(made);
    EXPECT_EQ(room.min, glm::vec3(-4.0f, 0.0f, -3.0f));
    EXPECT_EQ(room.max, glm::vec3(4.0f, 3.0f, 3.0f));
    const glm::vec3 eye(glm::inverse(made.camera.view)[3]);
    EXPECT_NEAR(eye.x, 3.7f, 1e-5f);
    EXPECT_NEAR(eye.y, 2.6f, 1e-5f);
    EXPECT_NEAR(eye.z, 2.7f, 1e-5f);
}

}  // namespace
