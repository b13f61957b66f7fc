// Meshes made in code (quad, sphere, box) and the procedural marble texture: the invariants the
// renderer relies on (valid indices, unit normals, outward counter-clockwise winding, no
// degenerate triangles), and the marble's determinism and contrast.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <set>

#include <glm/glm.hpp>

#include "scene/marble.h"
#include "scene/primitives.h"

using namespace penumbra::scene;

namespace {

// Structural checks shared by every mesh; `outward(centroid, face_normal)` says whether a
// triangle faces the right way.
template <class Outward>
void check_mesh(const Mesh& m, Outward outward) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_TRUE(m.uvs.empty() || m.uvs.size() == m.positions.size());
    ASSERT_EQ(m.indices.size() % 3, 0u);
    ASSERT_FALSE(m.indices.empty());
    for (const auto& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    std::set<std::uint32_t> used;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        for (size_t k = 0; k < 3; ++k) {
            ASSERT_LT(m.indices[t + k], m.positions.size());
            used.insert(m.indices[t + k]);
        }
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        const glm::vec3 fn = glm::cross(b - a, c - a);
        EXPECT_GT(glm::length(fn), 1e-6f) << "degenerate triangle " << t / 3;
        EXPECT_TRUE(outward((a + b + c) / 3.0f, fn)) << "triangle " << t / 3 << " winds inwards";
        // The vertex normals agree with the face (within the faceting of a smooth mesh).
        for (size_t k = 0; k < 3; ++k) EXPECT_GT(glm::dot(m.normals[m.indices[t + k]], fn), 0.0f);
    }
    EXPECT_EQ(used.size(), m.positions.size()) << "unused vertices";
}

}  // namespace

TEST(Primitives, Quad) {
    const Mesh q = make_quad(4.0f, 3.0f);
    EXPECT_EQ(q.name, "quad");
    EXPECT_EQ(q.positions.size(), 4u);
    EXPECT_EQ(q.indices.size(), 6u);
    check_mesh(q, [](const glm::vec3&, const glm::vec3& fn) { return fn.y > 0.0f && std::fabs(fn.x) + std::fabs(fn.z) < 1e-6f; });
    glm::vec2 uvmin(1e9f), uvmax(-1e9f);
    for (size_t i = 0; i < q.positions.size(); ++i) {
        EXPECT_EQ(q.positions[i].y, 0.0f);
        EXPECT_EQ(std::fabs(q.positions[i].x), 2.0f);
        EXPECT_EQ(std::fabs(q.positions[i].z), 2.0f);
        EXPECT_EQ(q.normals[i], glm::vec3(0, 1, 0));
        uvmin = glm::min(uvmin, q.uvs[i]);
        uvmax = glm::max(uvmax, q.uvs[i]);
    }
    EXPECT_EQ(uvmin, glm::vec2(0.0f));
    EXPECT_EQ(uvmax, glm::vec2(3.0f));
}

TEST(Primitives, Sphere) {
    const int slices = 16, stacks = 8;
    const float r = 1.5f;
    const Mesh s = make_sphere(r, slices, stacks);
    EXPECT_EQ(s.name, "sphere");
    // One vertex per slice at each pole, slices + 1 (seam duplicated) on each interior ring.
    EXPECT_EQ(s.positions.size(), static_cast<size_t>(2 * slices + (stacks - 1) * (slices + 1)));
    // Triangles at the poles, two per quad elsewhere.
    EXPECT_EQ(s.indices.size(), static_cast<size_t>(3 * (2 * slices + 2 * slices * (stacks - 2))));
    EXPECT_EQ(s.uvs.size(), s.positions.size());
    check_mesh(s, [](const glm::vec3& c, const glm::vec3& fn) { return glm::dot(fn, c) > 0.0f; });
    for (size_t i = 0; i < s.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(s.positions[i]), r, 1e-5f);
        EXPECT_GT(glm::dot(s.normals[i], s.positions[i]), 0.999f * r);
        EXPECT_GE(s.uvs[i].x, 0.0f);
        EXPECT_LE(s.uvs[i].x, 1.0f);
        EXPECT_GE(s.uvs[i].y, 0.0f);
        EXPECT_LE(s.uvs[i].y, 1.0f);
    }
}

TEST(Primitives, SphereClampsTooFewSegments) {
    const Mesh s = make_sphere(1.0f, 1, 1);
    check_mesh(s, [](const glm::vec3& c, const glm::vec3& fn) { return glm::dot(fn, c) > 0.0f; });
}

TEST(Primitives, Box) {
    const glm::vec3 h(1.0f, 0.5f, 2.0f);
    const Mesh b = make_box(h);
    EXPECT_EQ(b.name, "box");
    EXPECT_EQ(b.positions.size(), 24u);
    EXPECT_EQ(b.indices.size(), 36u);
    check_mesh(b, [](const glm::vec3& c, const glm::vec3& fn) { return glm::dot(fn, c) > 0.0f; });
    for (size_t i = 0; i < b.positions.size(); ++i) {
        EXPECT_EQ(glm::abs(b.positions[i]), h);
        // Flat shading: the normal is the axis of the face the vertex is on.
        EXPECT_NEAR(glm::dot(b.normals[i], b.positions[i]), glm::dot(glm::abs(b.normals[i]), h), 1e-6f);
    }
}

namespace {

float luminance(const Image& img, size_t px) {
    return 0.2126f * img.rgba[px * 4] + 0.7152f * img.rgba[px * 4 + 1] + 0.0722f * img.rgba[px * 4 + 2];
}

}  // namespace

TEST(Marble, SizeAlphaAndDeterminism) {
    const Image a = make_marble(128, 7);
    EXPECT_EQ(a.width, 128);
    EXPECT_EQ(a.height, 128);
    ASSERT_EQ(a.rgba.size(), 128u * 128u * 4u);
    for (size_t i = 3; i < a.rgba.size(); i += 4) ASSERT_EQ(a.rgba[i], 255);
    EXPECT_EQ(make_marble(128, 7).rgba, a.rgba);
    EXPECT_NE(make_marble(128, 8).rgba, a.rgba);
    EXPECT_EQ(make_marble(0, 7).rgba.size(), 0u);
}

TEST(Marble, HasRealContrast) {
    // Mostly white with darker veins: the luminance spread is well above noise. Measured at
    // 256 px: a standard deviation of 22.5 to 25.5 (of 255) for seeds 1..8, mean about 217. The
    // faint cloudiness alone would give about 4, a flat image 0; 12 sits well between.
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const Image img = make_marble(256, seed);
        const size_t n = 256u * 256u;
        double sum = 0.0, sum2 = 0.0, lo = 255.0, hi = 0.0;
        for (size_t i = 0; i < n; ++i) {
            const double l = luminance(img, i);
            sum += l;
            sum2 += l * l;
            lo = std::min(lo, l);
            hi = std::max(hi, l);
        }
        const double mean = sum / static_cast<double>(n);
        const double sd = std::sqrt(sum2 / static_cast<double>(n) - mean * mean);
        EXPECT_GT(sd, 12.0) << seed;
        EXPECT_GT(mean, 170.0) << "marble should be whitish";
        EXPECT_GT(hi - lo, 80.0);
    }
}

TEST(Marble, Tiles) {
    // The last column continues into the first (and the last row into the first) about as
    // smoothly as neighbouring columns do inside the image.
    const int n = 256;
    const Image img = make_marble(n, 3);
    const auto diff = [&](int x0, int y0, int x1, int y1) {
        return std::abs(int(img.rgba[(size_t(y0) * n + x0) * 4]) - int(img.rgba[(size_t(y1) * n + x1) * 4]));
    };
    double seam_x = 0, inner_x = 0, seam_y = 0, inner_y = 0;
    for (int i = 0; i < n; ++i) {
        seam_x += diff(n - 1, i, 0, i);
        inner_x += diff(n / 2 - 1, i, n / 2, i);
        seam_y += diff(i, n - 1, i, 0);
        inner_y += diff(i, n / 2 - 1, i, n / 2);
    }
    EXPECT_LT(seam_x, 2.0 * inner_x + 2.0 * n);
    EXPECT_LT(seam_y, 2.0 * inner_y + 2.0 * n);
}
