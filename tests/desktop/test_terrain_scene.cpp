// The terrain built in code (scenes/terrain_scene.h, what the browser's cascades page draws) against
// tests/data/terrain_km.gltf loaded by the glTF loader (what `penumbra render` draws): the same
// meshes, objects, materials, camera and sun, to float precision.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "scene/gltf_loader.h"
#include "scenes/terrain_scene.h"
#include "../test_paths.h"
#include "scene_match.h"

#ifndef PENUMBRA_TEST_DATA
#error "PENUMBRA_TEST_DATA must name tests/data"
#endif

namespace {

using penumbra::scene::Scene;

TEST(TerrainScene, MatchesTheGltfFile) {
    const auto loaded = penumbra::scene::load_gltf(penumbra::test::test_data_dir() + "/terrain_km.gltf");
    ASSERT_TRUE(loaded.ok) << loaded.error;
    const Scene made = penumbra::scene::make_terrain_km_scene();
    ASSERT_EQ(made.objects.size(), 361u);  // the terrain and 360 objects
    // Translations up to 500 m: a float's step there is 3e-5 m.
    penumbra::test::expect_same_scene(made, loaded.scene, 1e-4f);
}

TEST(TerrainScene, TheHeightIsTheGround) {
    // The camera stands 1.9 m above the ground (make_large_scenes.py: CAMERA_HEIGHT).
    const Scene made = penumbra::scene::make_terrain_km_scene();
    const glm::vec3 eye(glm::inverse(made.camera.view)[3]);
    EXPECT_NEAR(eye.y - penumbra::scene::terrain_km_height(eye.x, eye.z), 1.9f, 2e-3f);
    // Outside the kilometre it is clamped to the edge, not extrapolated.
    EXPECT_NEAR(penumbra::scene::terrain_km_height(5000.0f, 0.0f), penumbra::scene::terrain_km_height(499.9999f, 0.0f), 1e-3f);
}

}  // namespace
