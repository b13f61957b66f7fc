// The light's frustum fit (exercise W09P2a): every input point inside the clip volume, the fit
// tight on at least one side, sane matrices for degenerate inputs; plus the sheet's B matrix and
// the PCF kernels the shadow lookup uses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "shadow/light_frustum.h"
#include "shadow/pcf.h"

#include "../test_finite.h"

using namespace penumbra;
using namespace penumbra::shadow;

namespace {

constexpr float kEps = 1e-5f;

using test::finite;

// A table-top scene's corner points: a 10 x 10 ground quad and a box on it.
std::vector<glm::vec3> table_points() {
    std::vector<glm::vec3> pts;
    for (float x : {-5.0f, 5.0f})
        for (float z : {-5.0f, 5.0f}) pts.emplace_back(x, 0.0f, z);
    for (float x : {-1.0f, 1.5f})
        for (float y : {0.0f, 2.0f})
            for (float z : {-0.5f, 1.0f}) pts.emplace_back(x, y, z);
    return pts;
}

// A fixed-seed cloud. mt19937's sequence is fixed by the standard; the float conversion is ours
// (std::uniform_real_distribution differs between standard libraries).
std::vector<glm::vec3> cloud(std::uint32_t seed, int n, const glm::vec3& centre, float half) {
    std::mt19937 gen(seed);
    const auto unit = [&gen] { return static_cast<float>(gen() >> 8) * (1.0f / 16777216.0f); };
    std::vector<glm::vec3> pts;
    for (int i = 0; i < n; ++i)
        pts.push_back(centre + half * glm::vec3(2.0f * unit() - 1.0f, 2.0f * unit() - 1.0f, 2.0f * unit() - 1.0f));
    return pts;
}

glm::vec3 centre_of(const std::vector<glm::vec3>& pts) {
    scene::Bounds b;
    for (const auto& p : pts) b.add(p);
    return b.center();
}

scene::Light point_light(const glm::vec3& pos, scene::LightType type = scene::LightType::Point) {
    scene::Light l;
    l.type = type;
    l.position = pos;
    return l;
}

scene::Light directional(const glm::vec3& dir) {
    scene::Light l;
    l.type = scene::LightType::Directional;
    l.direction = glm::normalize(dir);
    return l;
}

// Every point inside -w <= x, y, z <= w with w > 0; returns the clip-space points after the divide.
std::vector<glm::vec3> check_contains(const LightFrustum& f, const std::vector<glm::vec3>& pts) {
    EXPECT_TRUE(finite(f.view));
    EXPECT_TRUE(finite(f.proj));
    std::vector<glm::vec3> ndc;
    for (const auto& p : pts) {
        const glm::vec4 c = f.view_proj() * glm::vec4(p, 1.0f);
        EXPECT_GT(c.w, 0.0f) << p.x << " " << p.y << " " << p.z;
        const float tol = kEps * std::max(1.0f, std::fabs(c.w));
        EXPECT_LE(std::fabs(c.x), c.w + tol) << p.x << " " << p.y << " " << p.z;
        EXPECT_LE(std::fabs(c.y), c.w + tol) << p.x << " " << p.y << " " << p.z;
        EXPECT_LE(std::fabs(c.z), c.w + tol) << p.x << " " << p.y << " " << p.z;
        ndc.push_back(glm::vec3(c) / c.w);
    }
    return ndc;
}

void check_perspective_fit(const scene::Light& light, const std::vector<glm::vec3>& pts, const glm::vec3& aim) {
    const LightFrustum f = fit_light_frustum(light, pts, aim);
    EXPECT_TRUE(f.perspective);
    EXPECT_GT(f.znear, 0.0f);
    EXPECT_GT(f.zfar, f.znear);
    float widest = 0.0f;
    for (const auto& n : check_contains(f, pts)) widest = std::max({widest, std::fabs(n.x), std::fabs(n.y)});
    EXPECT_GT(widest, 0.95f) << "the fit is not tight";
}

void check_ortho_fit(const scene::Light& light, const std::vector<glm::vec3>& pts) {
    const LightFrustum f = fit_light_frustum(light, pts, centre_of(pts));
    EXPECT_FALSE(f.perspective);
    EXPECT_GT(f.znear, 0.0f);  // the eye is outside the points' bounding sphere
    EXPECT_GT(f.zfar, f.znear);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (const auto& n : check_contains(f, pts)) {
        lo = glm::min(lo, glm::vec2(n));
        hi = glm::max(hi, glm::vec2(n));
    }
    // Tight on all four sides: within 2% of each edge.
    EXPECT_LT(lo.x, -0.98f);
    EXPECT_LT(lo.y, -0.98f);
    EXPECT_GT(hi.x, 0.98f);
    EXPECT_GT(hi.y, 0.98f);
}

}  // namespace

TEST(LightFrustum, PointLightContainsTableScene) {
    const auto pts = table_points();
    const glm::vec3 aim = centre_of(pts);
    for (const glm::vec3 pos : {glm::vec3(3, 8, 2), glm::vec3(-6, 4, 7), glm::vec3(0.5f, 12, -9), glm::vec3(20, 1, 0)})
        check_perspective_fit(point_light(pos), pts, aim);
}

TEST(LightFrustum, PointLightStraightOverhead) {
    const auto pts = table_points();
    // (0,10,0) aiming at the origin: the view axis is -y, parallel to the default up.
    check_perspective_fit(point_light({0, 10, 0}), pts, glm::vec3(0.0f));
    // And straight below, looking up.
    check_perspective_fit(point_light({0, -10, 0}), pts, glm::vec3(0.0f));
}

TEST(LightFrustum, PointLightGrazing) {
    const auto pts = table_points();
    const float e = glm::radians(2.0f);
    check_perspective_fit(point_light(20.0f * glm::vec3(std::cos(e), std::sin(e), 0.0f)), pts, glm::vec3(0.0f));
}

TEST(LightFrustum, SpotLightIsFittedLikeAPointLight) {
    const auto pts = table_points();
    const glm::vec3 pos(4, 6, -3);
    scene::Light spot = point_light(pos, scene::LightType::Spot);
    spot.direction = glm::normalize(-pos);
    spot.spot_outer_cone = 1.2f;  // wider than the points need: the fit must not widen to it
    check_perspective_fit(spot, pts, glm::vec3(0.0f));
    const LightFrustum a = fit_light_frustum(spot, pts, glm::vec3(0.0f));
    const LightFrustum b = fit_light_frustum(point_light(pos), pts, glm::vec3(0.0f));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_FLOAT_EQ(a.proj[c][r], b.proj[c][r]);
}

TEST(LightFrustum, PerspectiveDepthRangeHugsThePoints) {
    const auto pts = table_points();
    const LightFrustum f = fit_light_frustum(point_light({3, 8, 2}), pts, centre_of(pts));
    float zmin = 1e9f, zmax = 0.0f;
    for (const auto& p : pts) {
        const float d = -(f.view * glm::vec4(p, 1.0f)).z;
        zmin = std::min(zmin, d);
        zmax = std::max(zmax, d);
    }
    EXPECT_NEAR(f.znear, 0.98f * zmin, 1e-4f);
    EXPECT_NEAR(f.zfar, 1.02f * zmax, 1e-4f);
}

TEST(LightFrustum, RandomCloudsPointAndSpot) {
    std::mt19937 gen(1234);
    const auto unit = [&gen] { return static_cast<float>(gen() >> 8) * (1.0f / 16777216.0f); };
    for (int trial = 0; trial < 40; ++trial) {
        const glm::vec3 centre(8.0f * unit() - 4.0f, 8.0f * unit() - 4.0f, 8.0f * unit() - 4.0f);
        const auto pts = cloud(100u + static_cast<std::uint32_t>(trial), 60, centre, 0.5f + 3.0f * unit());
        // A light 12..30 away in a random direction (the cloud's radius is at most ~6.1).
        const glm::vec3 d = glm::normalize(glm::vec3(2.0f * unit() - 1.0f, 2.0f * unit() - 1.0f, 2.0f * unit() - 1.0f));
        const glm::vec3 pos = centre + (12.0f + 18.0f * unit()) * d;
        SCOPED_TRACE(trial);
        check_perspective_fit(point_light(pos, trial % 2 ? scene::LightType::Spot : scene::LightType::Point), pts,
                              centre_of(pts));
    }
}

TEST(LightFrustum, DirectionalContainsAndIsTight) {
    const auto pts = table_points();
    const float e = glm::radians(2.0f);
    for (const glm::vec3 dir : {glm::vec3(0, -1, 0), glm::vec3(-0.3f, -1, -0.2f), glm::vec3(0, 1, 0),
                                glm::vec3(-std::cos(e), -std::sin(e), 0), glm::vec3(1, 0, 0), glm::vec3(0.01f, -1, 0)}) {
        SCOPED_TRACE(dir.x);
        check_ortho_fit(directional(dir), pts);
    }
}

TEST(LightFrustum, DirectionalRandomClouds) {
    std::mt19937 gen(99);
    const auto unit = [&gen] { return static_cast<float>(gen() >> 8) * (1.0f / 16777216.0f); };
    for (int trial = 0; trial < 40; ++trial) {
        const glm::vec3 centre(40.0f * unit() - 20.0f, 40.0f * unit() - 20.0f, 40.0f * unit() - 20.0f);
        const auto pts = cloud(500u + static_cast<std::uint32_t>(trial), 50, centre, 0.1f + 10.0f * unit());
        const glm::vec3 d(2.0f * unit() - 1.0f, 2.0f * unit() - 1.0f, 2.0f * unit() - 1.0f);
        SCOPED_TRACE(trial);
        check_ortho_fit(directional(d), pts);
    }
}

TEST(LightFrustum, DegenerateInputsGiveValidMatrices) {
    const std::vector<std::vector<glm::vec3>> cases = {
        {}, {glm::vec3(1, 2, 3)}, {glm::vec3(1, 2, 3), glm::vec3(1, 2, 3), glm::vec3(1, 2, 3)}, {glm::vec3(0, 0, 0)},
        {glm::vec3(0, 5, 0)}};  // the last one sits on the point light
    const scene::Light lights[] = {point_light({0, 5, 0}), point_light({0, 5, 0}, scene::LightType::Spot),
                                   directional({0, -1, 0}), directional({0.3f, -1, 0.1f})};
    for (const auto& pts : cases) {
        for (const auto& light : lights) {
            for (const glm::vec3 aim : {glm::vec3(0.0f), glm::vec3(0, 5, 0)}) {  // aim at the light itself too
                const LightFrustum f = fit_light_frustum(light, pts, aim);
                EXPECT_TRUE(finite(f.view));
                EXPECT_TRUE(finite(f.proj));
                EXPECT_TRUE(finite(f.view_proj()));
                EXPECT_TRUE(std::isfinite(f.znear) && std::isfinite(f.zfar));
                EXPECT_GT(f.zfar, f.znear);
                if (f.perspective) {
                    EXPECT_GT(f.znear, 0.0f);
                }
                EXPECT_NE(glm::determinant(f.proj), 0.0f);
            }
        }
    }
    // A single point or all-equal points off the light are still inside the fitted volume.
    check_contains(fit_light_frustum(point_light({0, 5, 0}), cases[2], glm::vec3(0.0f)), cases[2]);
    check_contains(fit_light_frustum(directional({0.3f, -1, 0.1f}), cases[2], glm::vec3(0.0f)), cases[2]);
    check_contains(fit_light_frustum(directional({0, -1, 0}), cases[1], glm::vec3(0.0f)), cases[1]);
}

TEST(LightFrustum, LightInsideTheBoundsFallsBackToAWideFrustum) {
    // The light sits in the middle of the cloud: some points are behind it. The fit documents
    // a fallback: a frustum of at most 150 degrees and a near plane of at most 1% of far.
    const auto pts = cloud(7, 40, glm::vec3(0.0f), 5.0f);
    const LightFrustum f = fit_light_frustum(point_light({0.0f, 0.0f, 0.0f}), pts, glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_TRUE(finite(f.view));
    EXPECT_TRUE(finite(f.proj));
    EXPECT_GT(f.znear, 0.0f);
    EXPECT_LE(f.znear, 0.01f * f.zfar * 1.0001f);
    const float min_cot = 1.0f / std::tan(glm::radians(75.0f));
    EXPECT_GE(f.proj[0][0], min_cot * 0.999f);
    EXPECT_GE(f.proj[1][1], min_cot * 0.999f);
    // The points in front of the light and inside the cap are still covered.
    for (const auto& p : pts) {
        const glm::vec3 e = glm::vec3(f.view * glm::vec4(p, 1.0f));
        if (-e.z < f.znear || std::fabs(e.x) > -e.z * 3.7f || std::fabs(e.y) > -e.z * 3.7f) continue;
        const glm::vec4 c = f.proj * glm::vec4(e, 1.0f);
        EXPECT_GT(c.w, 0.0f);
        EXPECT_LE(std::fabs(c.x), c.w * (1.0f + kEps));
        EXPECT_LE(std::fabs(c.y), c.w * (1.0f + kEps));
        EXPECT_LE(std::fabs(c.z), c.w * (1.0f + kEps));
    }
}

TEST(LightFrustum, ClipToTextureIsTheSheetsB) {
    const glm::mat4 b = clip_to_texture();
    const glm::vec4 lo = b * glm::vec4(-1, -1, -1, 1);
    const glm::vec4 hi = b * glm::vec4(1, 1, 1, 1);
    const glm::vec4 mid = b * glm::vec4(0, 0, 0, 1);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(lo[i], 0.0f);
        EXPECT_FLOAT_EQ(hi[i], 1.0f);
        EXPECT_FLOAT_EQ(mid[i], 0.5f);
    }
    EXPECT_FLOAT_EQ(lo.w, 1.0f);
    // Homogeneous: B (w x) = w (B x), so the divide can come after the lookup matrix.
    const glm::vec4 h = b * glm::vec4(-2, 2, 0, 2);
    EXPECT_FLOAT_EQ(h.x / h.w, 0.0f);
    EXPECT_FLOAT_EQ(h.y / h.w, 1.0f);
    EXPECT_FLOAT_EQ(h.z / h.w, 0.5f);
}

TEST(Pcf, KernelSizes) {
    EXPECT_EQ(pcf_offsets(Filter::Hard).size(), 1u);
    EXPECT_EQ(pcf_offsets(Filter::PCF2x2).size(), 4u);
    EXPECT_EQ(pcf_offsets(Filter::PCF4x4).size(), 16u);
    EXPECT_EQ(pcf_offsets(Filter::Hard)[0], glm::vec2(0.0f));
}

TEST(Pcf, KernelsAreSymmetricHalfTexelGrids) {
    for (const Filter f : {Filter::PCF2x2, Filter::PCF4x4}) {
        const auto offs = pcf_offsets(f);
        glm::vec2 sum(0.0f);
        for (const auto& o : offs) {
            sum += o;
            for (int i = 0; i < 2; ++i) {
                const float a = std::fabs(o[i]);
                EXPECT_TRUE(a == 0.5f || (f == Filter::PCF4x4 && a == 1.5f)) << o[i];
            }
        }
        EXPECT_EQ(sum, glm::vec2(0.0f));
        // No tap repeated.
        for (size_t i = 0; i < offs.size(); ++i)
            for (size_t j = i + 1; j < offs.size(); ++j) EXPECT_NE(offs[i], offs[j]);
    }
}

// The course scene itself: at several times, every vertex of every caster and receiver lies
// inside the frustum fitted around the objects' bounds.
#include "scenes/course_scene.h"

TEST(LightFrustumCourse, ContainsEveryCasterAndReceiverVertex) {
    using namespace penumbra;
    auto course = scene::make_course_scene(6);
    for (double t : {0.0, 0.37, 1.5, 2.9, 6.0, 11.3}) {
        scene::animate_course(course, t, t);
        const scene::Scene& s = course.scene;
        scene::Bounds b;
        for (const auto& o : s.objects) b.add(scene::object_bounds(s, o));
        const auto f = shadow::fit_light_frustum(s.light, scene::corners(b), b.center());
        const glm::mat4 vp = f.view_proj();
        size_t checked = 0;
        for (const auto& o : s.objects)
            for (const auto& p : s.meshes[static_cast<size_t>(o.mesh)].positions) {
                const glm::vec4 c = vp * o.world * glm::vec4(p, 1.0f);
                ASSERT_GT(c.w, 0.0f);
                for (int i = 0; i < 3; ++i) {
                    ASSERT_LE(c[i], c.w * (1.0f + 1e-5f)) << "t=" << t << " axis " << i;
                    ASSERT_GE(c[i], -c.w * (1.0f + 1e-5f)) << "t=" << t << " axis " << i;
                }
                ++checked;
            }
        EXPECT_GT(checked, 1000u);
    }
}
