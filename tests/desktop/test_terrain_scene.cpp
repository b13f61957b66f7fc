// The terrain built in code (scene/terrain_scene.h, what the browser's cascades page draws) against
// tests/data/terrain_km.gltf loaded by the glTF loader (what `penumbra render` draws): the same
// meshes, objects, materials, camera and sun, to float precision.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "scene/gltf_loader.h"
#include "scene/terrain_scene.h"

#ifndef PENUMBRA_TEST_DATA
#error "PENUMBRA_TEST_DATA must name tests/data"
#endif

namespace {

using penumbra::scene::Scene;

float max_difference(const glm::mat4& a, const glm::mat4& b) {
    float d = 0.0f;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
    return d;
}

TEST(TerrainScene, MatchesTheGltfFile) {
    const auto loaded = penumbra::scene::load_gltf(std::string(PENUMBRA_TEST_DATA) + "/terrain_km.gltf");
    ASSERT_TRUE(loaded.ok) << loaded.error;
    const Scene& file = loaded.scene;
    const Scene made = penumbra::scene::make_terrain_km_scene();

    ASSERT_EQ(made.objects.size(), 361u);  // the terrain and 360 objects
    ASSERT_EQ(made.objects.size(), file.objects.size());
    ASSERT_EQ(made.meshes.size(), file.meshes.size());
    for (size_t i = 0; i < made.objects.size(); ++i) {
        const auto& a = made.objects[i];
        const auto& b = file.objects[i];
        ASSERT_EQ(a.name, b.name) << i;
        // Translations up to 500 m: a float's step there is 3e-5 m.
        EXPECT_LT(max_difference(a.world, b.world), 1e-4f) << a.name;
        const auto& ma = made.meshes[static_cast<size_t>(a.mesh)];
        const auto& mb = file.meshes[static_cast<size_t>(b.mesh)];
        ASSERT_EQ(ma.positions.size(), mb.positions.size()) << a.name;
        ASSERT_EQ(ma.indices, mb.indices) << a.name;
        EXPECT_EQ(ma.closed, mb.closed) << a.name;
        const auto& ca = made.materials[static_cast<size_t>(a.material)];
        const auto& cb = file.materials[static_cast<size_t>(b.material)];
        EXPECT_EQ(ca.name, cb.name) << a.name;
        EXPECT_EQ(ca.base_color, cb.base_color) << a.name;
        EXPECT_EQ(ca.specular, cb.specular) << a.name;
        EXPECT_EQ(ca.shininess, cb.shininess) << a.name;
    }
    for (size_t m = 0; m < made.meshes.size(); ++m) {
        // Meshes come in the order the nodes first use them in both.
        const auto& a = made.meshes[m];
        const auto& b = file.meshes[m];
        ASSERT_EQ(a.positions.size(), b.positions.size()) << m;
        for (size_t i = 0; i < a.positions.size(); ++i) {
            EXPECT_LT(glm::length(a.positions[i] - b.positions[i]), 1e-4f) << m << " vertex " << i;
            EXPECT_LT(glm::length(a.normals[i] - b.normals[i]), 1e-5f) << m << " normal " << i;
        }
    }
    EXPECT_LT(max_difference(made.camera.view, file.camera.view), 1e-4f);
    EXPECT_EQ(made.camera.yfov, file.camera.yfov);
    EXPECT_EQ(made.camera.znear, file.camera.znear);
    EXPECT_EQ(made.camera.zfar, file.camera.zfar);
    EXPECT_EQ(made.camera.aspect, file.camera.aspect);
    EXPECT_EQ(made.light.type, file.light.type);
    EXPECT_LT(glm::length(made.light.direction - file.light.direction), 1e-6f);
    EXPECT_LT(glm::length(made.light.position - file.light.position), 1e-4f);
    EXPECT_EQ(made.light.color, file.light.color);
    EXPECT_EQ(made.light.intensity, file.light.intensity);
    EXPECT_EQ(made.light.radius, file.light.radius);
    EXPECT_EQ(made.ground_object, file.ground_object);
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
