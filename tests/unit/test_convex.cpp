// The small convex geometry behind the tight light frustum (src/shadow/convex.h): half-spaces of
// a clip volume, a box clipped by half-spaces, and the 2D hull, rectangle clip and area that
// measure the shadow map's texel use.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "shadow/convex.h"

using namespace penumbra;
using namespace penumbra::shadow;

namespace {

scene::Bounds box(const glm::vec3& lo, const glm::vec3& hi) { return scene::Bounds::around(lo, hi); }

bool has_point(const std::vector<glm::vec3>& pts, const glm::vec3& p, float tol = 1e-4f) {
    return std::any_of(pts.begin(), pts.end(), [&](const glm::vec3& q) { return glm::length(q - p) < tol; });
}

bool has_point(const std::vector<glm::vec2>& pts, const glm::vec2& p, float tol = 1e-5f) {
    return std::any_of(pts.begin(), pts.end(), [&](const glm::vec2& q) { return glm::length(q - p) < tol; });
}

}  // namespace

TEST(Convex, HullDropsInnerAndCollinearPoints) {
    const std::vector<glm::vec2> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.5f}, {0.5f, 0}, {0, 0.25f}, {1, 1}, {0.2f, 0.7f}};
    const auto h = convex_hull(pts);
    ASSERT_EQ(h.size(), 4u);
    for (const glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) EXPECT_TRUE(has_point(h, c));
    // Counter-clockwise: the signed area is positive.
    double twice = 0.0;
    for (size_t i = 0; i < h.size(); ++i) twice += h[i].x * h[(i + 1) % h.size()].y - h[(i + 1) % h.size()].x * h[i].y;
    EXPECT_GT(twice, 0.0);
    EXPECT_FLOAT_EQ(polygon_area(h), 1.0f);
}

TEST(Convex, HullOfFewOrCollinearPointsHasNoArea) {
    EXPECT_TRUE(convex_hull({}).empty());
    EXPECT_EQ(convex_hull({{1, 2}}).size(), 1u);
    EXPECT_EQ(convex_hull({{1, 2}, {1, 2}, {1, 2}}).size(), 1u);
    EXPECT_FLOAT_EQ(polygon_area(convex_hull({{0, 0}, {1, 1}, {2, 2}, {3, 3}})), 0.0f);
}

TEST(Convex, HullOfRandomPointsHoldsThemAll) {
    std::mt19937 gen(5);
    const auto unit = [&gen] { return static_cast<float>(gen() >> 8) * (1.0f / 16777216.0f); };
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<glm::vec2> pts;
        for (int i = 0; i < 50; ++i) pts.emplace_back(4.0f * unit() - 2.0f, 4.0f * unit() - 2.0f);
        const auto h = convex_hull(pts);
        ASSERT_GE(h.size(), 3u);
        for (const auto& p : pts)
            for (size_t i = 0; i < h.size(); ++i) {
                const glm::vec2 a = h[i], b = h[(i + 1) % h.size()];
                EXPECT_GE((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x), -1e-5f);
            }
    }
}

TEST(Convex, ClipToRect) {
    // A square larger than the rectangle: the rectangle.
    const std::vector<glm::vec2> big = {{-3, -3}, {3, -3}, {3, 3}, {-3, 3}};
    EXPECT_FLOAT_EQ(polygon_area(clip_to_rect(big, glm::vec2(-1), glm::vec2(1))), 4.0f);
    // A triangle half outside: (0,0), (2,0), (0,2) clipped to [-1,1]^2 keeps 1 - 0.5 * 0 ... the
    // unit square minus nothing, since x + y <= 2 holds on all of [0,1]^2.
    const std::vector<glm::vec2> tri = {{0, 0}, {2, 0}, {0, 2}};
    EXPECT_FLOAT_EQ(polygon_area(clip_to_rect(tri, glm::vec2(-1), glm::vec2(1))), 1.0f);
    // The triangle (0,0), (4,0), (0,4): [0,1]^2 again.
    const std::vector<glm::vec2> tri2 = {{0, 0}, {4, 0}, {0, 4}};
    const auto c = clip_to_rect(tri2, glm::vec2(-1), glm::vec2(1));
    EXPECT_FLOAT_EQ(polygon_area(c), 1.0f);
    EXPECT_TRUE(has_point(c, {1, 1}));
    // A triangle cut by one edge: (0,-1), (2,-1), (0,1) keeps x <= 1: 2 - 0.5.
    const std::vector<glm::vec2> tri3 = {{0, -1}, {2, -1}, {0, 1}};
    EXPECT_NEAR(polygon_area(clip_to_rect(tri3, glm::vec2(-1), glm::vec2(1))), 1.5f, 1e-6f);
    // Outside: nothing.
    const std::vector<glm::vec2> far = {{2, 2}, {3, 2}, {3, 3}};
    EXPECT_TRUE(clip_to_rect(far, glm::vec2(-1), glm::vec2(1)).empty());
    EXPECT_FLOAT_EQ(polygon_area({}), 0.0f);
}

TEST(Convex, ClipVolumeHalfSpacesOfAPerspective) {
    const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.5f, 0.5f, 20.0f) *
                         glm::lookAt(glm::vec3(1, 2, 5), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    const auto hs = clip_volume_half_spaces(vp);
    std::mt19937 gen(9);
    const auto unit = [&gen] { return static_cast<float>(gen() >> 8) * (1.0f / 16777216.0f); };
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 p(20.0f * unit() - 10.0f, 20.0f * unit() - 10.0f, 20.0f * unit() - 10.0f);
        const glm::vec4 c = vp * glm::vec4(p, 1.0f);
        const bool inside = c.w > 0.0f && std::fabs(c.x) <= c.w && std::fabs(c.y) <= c.w && std::fabs(c.z) <= c.w;
        const bool all = std::all_of(hs.begin(), hs.end(), [&](const HalfSpace& h) { return signed_distance(h, p) >= 0.0f; });
        EXPECT_EQ(inside, all) << p.x << " " << p.y << " " << p.z;
    }
    for (const HalfSpace& h : hs) EXPECT_NEAR(glm::length(glm::vec3(h)), 1.0f, 1e-5f);
}

TEST(Convex, ClipBoxWithoutHalfSpacesIsTheBox) {
    const scene::Bounds b = box({-1, 0, 2}, {3, 1, 4});
    const auto pts = clip_box(b, {});
    for (const auto& c : scene::corners(b)) EXPECT_TRUE(has_point(pts, c));
    for (const auto& p : pts) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, b.min - 1e-5f)));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(p, b.max + 1e-5f)));
    }
    EXPECT_TRUE(clip_box(scene::Bounds{}, {}).empty());
}

TEST(Convex, ClipBoxByOnePlane) {
    const scene::Bounds b = box(glm::vec3(-1), glm::vec3(1));
    // x + y >= 0.5: the corner (1, 1, z) stays, the cut passes through (1, -0.5, z) and (-0.5, 1, z).
    const HalfSpace h = glm::vec4(1, 1, 0, -0.5f) / std::sqrt(2.0f);
    const auto pts = clip_box(b, {h});
    ASSERT_FALSE(pts.empty());
    for (const auto& p : pts) EXPECT_GE(signed_distance(h, p), -1e-5f);
    for (const float z : {-1.0f, 1.0f}) {
        EXPECT_TRUE(has_point(pts, {1, 1, z}));
        EXPECT_TRUE(has_point(pts, {1, -0.5f, z}));
        EXPECT_TRUE(has_point(pts, {-0.5f, 1, z}));
        EXPECT_FALSE(has_point(pts, {-1, -1, z}));
    }
    // A half-space the box lies beyond: nothing.
    EXPECT_TRUE(clip_box(b, {glm::vec4(1, 0, 0, -2)}).empty());
    // A degenerate half-space that holds nothing, and one that holds everything.
    EXPECT_TRUE(clip_box(b, {glm::vec4(0, 0, 0, -1)}).empty());
    EXPECT_EQ(clip_box(b, {glm::vec4(0, 0, 0, 1)}).size(), clip_box(b, {}).size());
}

TEST(Convex, ClipBoxHoldsAFrustumInsideIt) {
    // A small camera frustum entirely inside a big box: the result is the frustum, corners included,
    // which only the half-spaces' own polygons give.
    const glm::mat4 vp = glm::perspective(glm::radians(50.0f), 1.0f, 0.5f, 3.0f) *
                         glm::lookAt(glm::vec3(0, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    const auto hs = clip_volume_half_spaces(vp);
    const auto pts = clip_box(box(glm::vec3(-10), glm::vec3(10)), {hs.begin(), hs.end()});
    const glm::mat4 inv = glm::inverse(vp);
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 c = inv * glm::vec4((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f);
        EXPECT_TRUE(has_point(pts, glm::vec3(c) / c.w, 1e-3f)) << i;
    }
    for (const auto& p : pts)
        for (const HalfSpace& h : hs) EXPECT_GE(signed_distance(h, p), -1e-3f);
}

TEST(Convex, ClipFlatBoxGivesItsPolygon) {
    // A table top at y = 0 (no thickness) under a camera that sees part of it.
    const scene::Bounds table = box({-2, 0, -2}, {2, 0, 2});
    const glm::mat4 vp = glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 30.0f) *
                         glm::lookAt(glm::vec3(0, 1, 3), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    const auto hs = clip_volume_half_spaces(vp);
    const auto pts = clip_box(table, {hs.begin(), hs.end()});
    ASSERT_GE(pts.size(), 3u);
    for (const auto& p : pts) {
        EXPECT_NEAR(p.y, 0.0f, 1e-5f);
        for (const HalfSpace& h : hs) EXPECT_GE(signed_distance(h, p), -1e-4f);
    }
    // The point the camera looks at is inside the hull of the result (seen from above: x-z).
    std::vector<glm::vec2> xz;
    for (const auto& p : pts) xz.emplace_back(p.x, p.z);
    const auto h = convex_hull(xz);
    for (size_t i = 0; i < h.size(); ++i) {
        const glm::vec2 a = h[i], b = h[(i + 1) % h.size()];
        EXPECT_GE((b.x - a.x) * (0.0f - a.y) - (b.y - a.y) * (0.0f - a.x), 0.0f);
    }
    EXPECT_GT(polygon_area(h), 0.5f);
}

TEST(Convex, ABoxInViewWholeGivesItsCornersOnceOrItsFaces) {
    const glm::mat4 vp = glm::perspective(glm::radians(50.0f), 1.0f, 0.5f, 30.0f) *
                         glm::lookAt(glm::vec3(0, 2, 8), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    const auto hs = clip_volume_half_spaces(vp);
    const std::vector<HalfSpace> planes(hs.begin(), hs.end());
    const scene::Bounds inside = box({-1, 0, -1}, {1, 1.5f, 0.5f});
    bool whole = false;
    const auto corners = clip_box_by(inside, clip_planes(planes), &whole);
    EXPECT_TRUE(whole);
    EXPECT_EQ(corners, scene::corners(inside));
    // Without `whole`: the six faces' 24 corners in box_face_corners' order, the same set.
    std::vector<glm::vec3> faces;
    box_face_corners(inside, [&](const glm::vec3& p) { faces.push_back(p); });
    EXPECT_EQ(clip_box(inside, planes), faces);
    for (const glm::vec3& p : faces) EXPECT_TRUE(has_point(corners, p));
    // Control: a box the view cuts is not whole, and is clipped.
    const scene::Bounds cut = box({-40, 0, -1}, {1, 1, 0.5f});
    EXPECT_FALSE(clip_box_by(cut, clip_planes(planes), &whole).empty());
    EXPECT_FALSE(whole);
}

// clip_box_by as it was before it skipped the planes that hold the whole box: every face clipped
// by every plane, and a square on every plane clipped by the box and the others.
std::vector<glm::vec3> clip_by_every_plane(const scene::Bounds& b, const std::vector<HalfSpace>& hs) {
    const float radius = 0.5f * glm::length(b.max - b.min);
    const float scale = std::max({radius, std::fabs(b.min.x), std::fabs(b.min.y), std::fabs(b.min.z), std::fabs(b.max.x),
                                  std::fabs(b.max.y), std::fabs(b.max.z)});
    const float eps = 1e-5f * scale;
    const std::vector<HalfSpace> box_hs = {{1, 0, 0, -b.min.x}, {-1, 0, 0, b.max.x}, {0, 1, 0, -b.min.y},
                                           {0, -1, 0, b.max.y}, {0, 0, 1, -b.min.z}, {0, 0, -1, b.max.z}};
    std::vector<glm::vec3> out;
    const auto clip_all = [&](std::vector<glm::vec3> poly, size_t skip, bool with_box) {
        if (with_box)
            for (const HalfSpace& h : box_hs)
                if (!poly.empty()) poly = clip_polygon(poly, h, eps);
        for (size_t j = 0; j < hs.size() && !poly.empty(); ++j)
            if (j != skip) poly = clip_polygon(poly, hs[j], eps);
        out.insert(out.end(), poly.begin(), poly.end());
    };
    std::vector<glm::vec3> faces;
    box_face_corners(b, [&](const glm::vec3& p) { faces.push_back(p); });
    for (size_t f = 0; f < faces.size(); f += 4) clip_all({faces.begin() + f, faces.begin() + f + 4}, hs.size(), false);
    const float half = 1.01f * radius + 1e-4f * scale + 1e-30f;
    for (size_t i = 0; i < hs.size(); ++i) {
        const glm::vec3 n(hs[i]);
        const glm::vec3 foot = b.center() - signed_distance(hs[i], b.center()) * n;
        const glm::vec3 t1 = glm::normalize(glm::cross(n, std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
        const glm::vec3 t2 = glm::cross(n, t1);
        clip_all({foot - half * t1 - half * t2, foot + half * t1 - half * t2, foot + half * t1 + half * t2, foot - half * t1 + half * t2},
                 i, true);
    }
    return out;
}

TEST(Convex, PlanesThatHoldTheWholeBoxChangeNothingOfItsClip) {
    // A receiver clipped by one tile of a map (resolution.cpp) lies inside most of the camera's
    // and the tile's planes; clip_box_by clips by the others only. The same points, in the same
    // order, as clipping by every plane, over random boxes and planes, many of them beside the box.
    std::mt19937 gen(56);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int clipped = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const glm::vec3 c(4.0f * u(gen), 4.0f * u(gen), 4.0f * u(gen));
        const glm::vec3 e(1.0f + u(gen), 1.0f + u(gen), 0.5f + 0.5f * u(gen));
        const scene::Bounds b = box(c - e, c + e);
        std::vector<HalfSpace> hs;
        const int planes = 1 + trial % 12;
        for (int k = 0; k < planes; ++k) {
            const glm::vec3 n = glm::normalize(glm::vec3(u(gen), u(gen), u(gen)) + glm::vec3(0.0f, 0.0f, 1e-3f));
            // Through a point near the box: some cut it, some hold all of it.
            const glm::vec3 at = c + 3.0f * glm::vec3(u(gen), u(gen), u(gen)) - 2.5f * n;
            hs.emplace_back(n, -glm::dot(n, at));
        }
        const std::vector<glm::vec3> expected = clip_by_every_plane(b, clip_planes(hs).unit);
        ASSERT_EQ(clip_box_by(b, clip_planes(hs)), expected) << "trial " << trial;
        clipped += !expected.empty() && expected.size() != 24;
    }
    // The control that the trials reach the case: most boxes are cut by some plane.
    EXPECT_GT(clipped, 100);
}

TEST(Convex, ASectionOfTheClippedBoxIsItsPolygonOnThePlane) {
    const scene::Bounds b = box(glm::vec3(-1.0f), glm::vec3(1.0f));
    // By x = 0 with nothing else: the square [-1, 1]^2 on it, in order (area 4 from its y, z).
    const auto square = clip_box_section(b, clip_planes({}), HalfSpace(1, 0, 0, 0));
    ASSERT_GE(square.size(), 4u);
    float area = 0.0f;
    for (size_t i = 0; i < square.size(); ++i) {
        const glm::vec3& p = square[i];
        const glm::vec3& q = square[(i + 1) % square.size()];
        EXPECT_NEAR(p.x, 0.0f, 1e-5f);
        area += p.y * q.z - q.y * p.z;
    }
    EXPECT_NEAR(std::fabs(area) / 2.0f, 4.0f, 1e-4f);
    // The planes given cut it too: z <= 0 leaves half.
    const auto half = clip_box_section(b, clip_planes({HalfSpace(0, 0, -1, 0)}), HalfSpace(1, 0, 0, 0));
    for (const glm::vec3& p : half) EXPECT_LE(p.z, 1e-5f);
    EXPECT_TRUE(has_point(half, {0, 1, -1}));
    EXPECT_TRUE(has_point(half, {0, -1, 0}));
    // A plane beside the box, or planes that hold nothing: no section.
    EXPECT_TRUE(clip_box_section(b, clip_planes({}), HalfSpace(1, 0, 0, -5)).empty());
    EXPECT_TRUE(clip_box_section(b, clip_planes({HalfSpace(0, 0, 0, -1)}), HalfSpace(1, 0, 0, 0)).empty());
}

TEST(Convex, ManyPointsHaveTheHullOfTheirHulls) {
    // Past 1024 points convex_hull drops the points deep inside first; the hull must not change.
    // Its reference: the hull of the parts' hulls, each part too small to be filtered.
    std::mt19937 gen(55);
    std::normal_distribution<float> n(0.0f, 1.0f);
    for (const int count : {2000, 20000}) {
        std::vector<glm::vec2> pts;
        for (int i = 0; i < count; ++i) pts.emplace_back(n(gen) * 3.0f, n(gen) + 0.1f * static_cast<float>(i % 7));
        std::vector<glm::vec2> parts;
        for (size_t at = 0; at < pts.size(); at += 1000) {
            const std::vector<glm::vec2> part(pts.begin() + static_cast<std::ptrdiff_t>(at),
                                              pts.begin() + static_cast<std::ptrdiff_t>(std::min(at + 1000, pts.size())));
            const std::vector<glm::vec2> h = convex_hull(part);
            parts.insert(parts.end(), h.begin(), h.end());
        }
        ASSERT_LE(parts.size(), 1024u);
        const std::vector<glm::vec2> hull = convex_hull(pts);
        EXPECT_EQ(hull, convex_hull(parts)) << count << " points";
        EXPECT_GE(hull.size(), 8u);
    }
}
