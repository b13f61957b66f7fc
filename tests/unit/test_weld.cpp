// scene::weld finds each position's first equal (rounded to 1e-6 of the mesh's size) through a
// hash table (src/scene/scene.cpp); checked here against the definition, pair by pair, on a soup
// of positions repeated with jitter below and above the rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "scene/primitives.h"
#include "scene/scene.h"

using namespace penumbra;

namespace {

// The definition, pair by pair: a position is welded to the first position with the same rounded
// cell, and welded vertices are numbered in the order they first come.
scene::Topology weld_by_definition(const scene::Mesh& m) {
    scene::Topology t;
    const scene::Bounds b = scene::mesh_bounds(m);
    const float cell = 1e-6f * glm::length(b.max - b.min);
    std::vector<std::uint32_t> id(m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec3 qi = glm::round(m.positions[i] / cell);
        size_t j = 0;
        while (j < i && glm::round(m.positions[j] / cell) != qi) ++j;
        if (j == i) {
            id[i] = static_cast<std::uint32_t>(t.positions.size());
            t.positions.push_back(m.positions[i]);
        } else {
            id[i] = id[j];
        }
    }
    for (size_t k = 0; k + 2 < m.indices.size(); k += 3) {
        if (m.indices[k] >= id.size() || m.indices[k + 1] >= id.size() || m.indices[k + 2] >= id.size()) continue;
        const std::uint32_t a = id[m.indices[k]], b2 = id[m.indices[k + 1]], c = id[m.indices[k + 2]];
        if (a != b2 && b2 != c && c != a) t.triangles.insert(t.triangles.end(), {a, b2, c});
    }
    return t;
}

// 3,000 positions over 300 distinct points, each off its point by `jitter` of the mesh's size on
// every axis; 3,000 random triangles and one with an index out of range.
scene::Mesh soup(float jitter) {
    scene::Mesh m;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<glm::vec3> points(300);
    for (glm::vec3& p : points) p = glm::vec3(u(rng), u(rng), u(rng));
    for (int i = 0; i < 3000; ++i) {
        m.positions.push_back(points[rng() % points.size()] + jitter * glm::vec3(u(rng), u(rng), u(rng)));
        m.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
    for (int i = 0; i < 9000; ++i) m.indices.push_back(static_cast<std::uint32_t>(rng() % 3000));
    m.indices.insert(m.indices.end(), {3000, 1, 2});
    return m;
}

}  // namespace

TEST(Weld, MatchesTheDefinition) {
    for (float jitter : {0.0f, 1e-8f, 1e-3f}) {
        const scene::Mesh m = soup(jitter);
        const scene::Topology got = scene::weld(m), want = weld_by_definition(m);
        EXPECT_EQ(got.positions, want.positions) << "jitter " << jitter;
        EXPECT_EQ(got.triangles, want.triangles) << "jitter " << jitter;
        // The control: welding happened where the jitter is below the rounding (all but the few
        // copies that a cell's edge splits), and not above it.
        if (jitter < 1e-6f)
            EXPECT_LT(got.positions.size(), 310u) << "jitter " << jitter;
        else
            EXPECT_GT(got.positions.size(), 2900u);
        EXPECT_LT(got.triangles.size(), 3u * 3000u) << "degenerate triangles and the one out of range dropped";
    }
    // The meshes the scenes make: a sphere's seam and poles, a box's split corners.
    for (const scene::Mesh& m : {scene::make_sphere(1.0f, 32, 16), scene::make_box(glm::vec3(1.0f, 2.0f, 0.5f))}) {
        const scene::Topology got = scene::weld(m), want = weld_by_definition(m);
        EXPECT_EQ(got.positions, want.positions);
        EXPECT_EQ(got.triangles, want.triangles);
        EXPECT_LT(got.positions.size(), m.positions.size());
    }
}
