// scene::is_convex decides edge by edge (src/scene/convexity.cpp); the definition it stands for is
// global: every vertex on or behind every triangle's plane. Checked here against that definition,
// and on the shapes that are convex at every edge yet not convex, which only its global step
// (one sphere, wrapped once) tells apart.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/primitives.h"
#include "scene/scene.h"
#include "scene/teapot.h"

using namespace penumbra;

namespace {

// The definition, by brute force: vertices x triangles.
bool convex_by_definition(const scene::Topology& t) {
    scene::Bounds b;
    for (const glm::vec3& p : t.positions) b.add(p);
    const float tolerance = 1e-5f * glm::length(b.max - b.min);
    for (size_t k = 0; k + 2 < t.triangles.size(); k += 3) {
        const glm::vec3 a = t.positions[t.triangles[k]];
        const glm::vec3 n = glm::cross(t.positions[t.triangles[k + 1]] - a, t.positions[t.triangles[k + 2]] - a);
        const float len = glm::length(n);
        if (!(len > 0.0f)) continue;
        for (const glm::vec3& p : t.positions)
            if (glm::dot(p - a, n) > tolerance * len) return false;
    }
    return true;
}

scene::Mesh sphere_with(float radius, int slices, int stacks, float (*shape)(const glm::vec3&)) {
    scene::Mesh m = scene::make_sphere(radius, slices, stacks);
    for (glm::vec3& p : m.positions) p *= shape(glm::normalize(p));
    scene::seal(m);
    return m;
}

// A shallow dimple, 2 % of the radius deep, round the +y pole.
float dimple(const glm::vec3& d) { return d.y > 0.95f ? 1.0f - 0.02f * (d.y - 0.95f) / 0.05f : 1.0f; }
// A low bump: still convex if gentle enough to keep every fold outward; the definition says.
float bump(const glm::vec3& d) { return 1.0f + 0.05f * d.y * d.y; }
// An egg: convex.
float egg(const glm::vec3& d) { return 1.0f / std::sqrt(1.0f - 0.3f * d.y); }

// A bipyramid over a pentagram: the equator visits a pentagon's corners in star order, so the
// surface wraps its convex hull twice round the two apexes. Every edge folds outward and
// V - E + F = 2, yet a chord of the star hides the corner it skips.
scene::Topology star_bipyramid() {
    scene::Topology t;
    t.positions = {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f)};
    for (int k = 0; k < 5; ++k) {
        const float a = 2.0f * 3.14159265f * static_cast<float>(2 * k) / 5.0f;
        t.positions.emplace_back(std::cos(a), 0.0f, -std::sin(a));
    }
    for (std::uint32_t k = 0; k < 5; ++k) {
        const std::uint32_t p = 2 + k, q = 2 + (k + 1) % 5;
        t.triangles.insert(t.triangles.end(), {0, p, q, 1, q, p});
    }
    scene::index_edges(t);
    return t;
}

// The same with the pentagon in order: a convex bipyramid, the control.
scene::Topology pentagon_bipyramid() {
    scene::Topology t = star_bipyramid();
    for (int k = 0; k < 5; ++k) {
        const float a = 2.0f * 3.14159265f * static_cast<float>(k) / 5.0f;
        t.positions[static_cast<size_t>(2 + k)] = glm::vec3(std::cos(a), 0.0f, -std::sin(a));
    }
    return t;
}

}  // namespace

TEST(MeshConvexity, AgreesWithTheDefinition) {
    scene::Mesh dented = scene::make_box(glm::vec3(1.0f));
    for (glm::vec3& p : dented.positions)
        if (p.x > 0.0f && p.y > 0.0f && p.z > 0.0f) p = glm::vec3(0.2f);
    scene::seal(dented);
    scene::Mesh pushed = scene::make_box(glm::vec3(1.0f));
    for (glm::vec3& p : pushed.positions)
        if (p.x > 0.0f && p.y > 0.0f && p.z > 0.0f) p = glm::vec3(1.5f);  // a corner pulled out: convex
    scene::seal(pushed);
    const std::vector<std::pair<std::string, scene::Mesh>> meshes = {
        {"quad", scene::make_quad(4.0f)},
        {"box", scene::make_box(glm::vec3(1.0f, 2.0f, 0.5f))},
        {"sphere 3x2", scene::make_sphere(1.0f, 3, 2)},
        {"sphere 16x8", scene::make_sphere(1.0f, 16, 8)},
        {"sphere 96x48", scene::make_sphere(2.5f, 96, 48)},
        {"egg", sphere_with(1.0f, 48, 24, egg)},
        {"dimpled sphere", sphere_with(1.0f, 96, 48, dimple)},
        {"bumped sphere", sphere_with(1.0f, 32, 16, bump)},
        {"bowl", scene::make_bowl(1.0f, 16, 8)},
        {"teapot", scene::make_teapot(4)},
        {"dented box", dented},
        {"pushed box", pushed},
    };
    int convex = 0;
    for (const auto& [name, mesh] : meshes) {
        ASSERT_TRUE(mesh.topology) << name;
        const bool expected = (mesh.closed || name == "quad") && convex_by_definition(*mesh.topology);
        EXPECT_EQ(mesh.convex, expected) << name;
        convex += expected ? 1 : 0;
    }
    // Both answers are asked: the list is not all one way.
    EXPECT_GE(convex, 5);
    EXPECT_GE(static_cast<int>(meshes.size()) - convex, 4);
}

TEST(MeshConvexity, EveryEdgeFoldingOutwardIsNotEnough) {
    const scene::Topology star = star_bipyramid(), pentagon = pentagon_bipyramid();
    ASSERT_TRUE(scene::is_closed(star));
    ASSERT_TRUE(scene::is_closed(pentagon));
    EXPECT_FALSE(convex_by_definition(star));
    EXPECT_FALSE(scene::is_convex(star, true)) << "wraps twice round its apexes";
    EXPECT_TRUE(convex_by_definition(pentagon));
    EXPECT_TRUE(scene::is_convex(pentagon, true));

    // Two boxes in one mesh: each convex, the pair not (one shadows the other).
    scene::Mesh two = scene::make_box(glm::vec3(1.0f));
    const scene::Mesh other = scene::make_box(glm::vec3(1.0f));
    const auto base = static_cast<std::uint32_t>(two.positions.size());
    for (size_t i = 0; i < other.positions.size(); ++i) {
        two.positions.push_back(other.positions[i] + glm::vec3(3.0f, 0.5f, 0.0f));
        two.normals.push_back(other.normals[i]);
    }
    two.uvs.clear();
    for (std::uint32_t i : other.indices) two.indices.push_back(base + i);
    scene::seal(two);
    EXPECT_TRUE(two.closed);
    EXPECT_FALSE(convex_by_definition(*two.topology));
    EXPECT_FALSE(two.convex);
}

TEST(MeshConvexity, ALargeConvexMeshIsStillAsked) {
    // 256x128: 33 thousand vertices by 65 thousand triangles, past what the definition could check
    // in a frame's setup.
    const scene::Mesh fine = scene::make_sphere(1.0f, 256, 128);
    EXPECT_TRUE(fine.closed);
    EXPECT_TRUE(fine.convex);
    // The control: the same with one vertex sunk by 1 % of the radius.
    scene::Mesh sunk = fine;
    sunk.positions[sunk.positions.size() / 2] *= 0.99f;
    scene::seal(sunk);
    EXPECT_TRUE(sunk.closed);
    EXPECT_FALSE(sunk.convex);
}
