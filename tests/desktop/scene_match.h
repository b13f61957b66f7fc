// A scene built in code (scenes/terrain_scene.h, scenes/room_scene.h: what the browser's pages draw)
// against the glTF file it follows, as the loader reads it (what `penumbra render` draws): the same
// objects (names, matrices, meshes, materials), meshes, camera and light, to float precision.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "scene/scene.h"

namespace penumbra::test {

inline float max_difference(const glm::mat4& a, const glm::mat4& b) {
    float d = 0.0f;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
    return d;
}

// `tolerance`: for matrices and positions (a float's step at the scene's largest coordinate).
inline void expect_same_scene(const scene::Scene& made, const scene::Scene& file, float tolerance) {
    ASSERT_EQ(made.objects.size(), file.objects.size());
    ASSERT_EQ(made.meshes.size(), file.meshes.size());
    for (std::size_t i = 0; i < made.objects.size(); ++i) {
        const auto& a = made.objects[i];
        const auto& b = file.objects[i];
        ASSERT_EQ(a.name, b.name) << i;
        EXPECT_LT(max_difference(a.world, b.world), tolerance) << a.name;
        EXPECT_EQ(a.mesh, b.mesh) << a.name;
        const auto& ma = made.meshes[static_cast<std::size_t>(a.mesh)];
        const auto& mb = file.meshes[static_cast<std::size_t>(b.mesh)];
        ASSERT_EQ(ma.positions.size(), mb.positions.size()) << a.name;
        ASSERT_EQ(ma.indices, mb.indices) << a.name;
        EXPECT_EQ(ma.closed, mb.closed) << a.name;
        const auto& ca = made.materials[static_cast<std::size_t>(a.material)];
        const auto& cb = file.materials[static_cast<std::size_t>(b.material)];
        EXPECT_EQ(ca.name, cb.name) << a.name;
        EXPECT_EQ(ca.base_color, cb.base_color) << a.name;
        EXPECT_EQ(ca.specular, cb.specular) << a.name;
        EXPECT_EQ(ca.shininess, cb.shininess) << a.name;
        EXPECT_EQ(a.casts_shadow, b.casts_shadow) << a.name;
        EXPECT_EQ(a.receives_shadow, b.receives_shadow) << a.name;
    }
    for (std::size_t m = 0; m < made.meshes.size(); ++m) {
        // Meshes come in the order the nodes first use them in both.
        const auto& a = made.meshes[m];
        const auto& b = file.meshes[m];
        ASSERT_EQ(a.positions.size(), b.positions.size()) << m;
        for (std::size_t i = 0; i < a.positions.size(); ++i) {
            EXPECT_LT(glm::length(a.positions[i] - b.positions[i]), tolerance) << m << " vertex " << i;
            EXPECT_LT(glm::length(a.normals[i] - b.normals[i]), 1e-5f) << m << " normal " << i;
        }
    }
    EXPECT_LT(max_difference(made.camera.view, file.camera.view), tolerance);
    EXPECT_EQ(made.camera.yfov, file.camera.yfov);
    EXPECT_EQ(made.camera.znear, file.camera.znear);
    EXPECT_EQ(made.camera.zfar, file.camera.zfar);
    EXPECT_EQ(made.camera.aspect, file.camera.aspect);
    EXPECT_EQ(made.light.type, file.light.type);
    EXPECT_LT(glm::length(made.light.direction - file.light.direction), 1e-6f);
    EXPECT_LT(glm::length(made.light.position - file.light.position), tolerance);
    EXPECT_EQ(made.light.color, file.light.color);
    EXPECT_EQ(made.light.intensity, file.light.intensity);
    EXPECT_EQ(made.light.radius, file.light.radius);
    EXPECT_EQ(made.ground_object, file.ground_object);
    EXPECT_EQ(made.ground_plane.has_value(), file.ground_plane.has_value());
    if (made.ground_plane && file.ground_plane) {
        EXPECT_EQ(*made.ground_plane, *file.ground_plane);
    }
}

}  // namespace penumbra::test
