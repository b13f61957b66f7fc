// The tight fit of the light's frustum (issue 9): the frustum around what the camera sees
// shadowed holds every visible receiver point and every caster that shadows one, draws no caster
// outside its window, stays finite in degenerate cases, and uses more of the map on the course.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "plan/plan.h"
#include "scenes/course_scene.h"
#include "shadow/light_frustum.h"
#include "../test_finite.h"

using namespace penumbra;
using namespace penumbra::shadow;

// ---- the tight fit (issue 9): the light's frustum around what the camera sees shadowed ----------

namespace {

using test::finite;

scene::Bounds box(const glm::vec3& lo, const glm::vec3& hi) { return scene::Bounds::around(lo, hi); }

// Inside -w <= x, y, z <= w with w > 0, with a relative tolerance for float rounding.
bool in_clip_volume(const glm::mat4& vp, const glm::vec3& p, float tol = 1e-4f) {
    const glm::vec4 c = vp * glm::vec4(p, 1.0f);
    if (!(c.w > 0.0f)) return false;
    const float lim = c.w * (1.0f + tol) + 1e-6f;
    return std::fabs(c.x) <= lim && std::fabs(c.y) <= lim && std::fabs(c.z) <= lim;
}

// Where the segment a -> b crosses the box (slabs): false when it misses; t0 <= t1 in [0, 1].
bool segment_box(const glm::vec3& a, const glm::vec3& b, const scene::Bounds& bx, float& t0, float& t1) {
    t0 = 0.0f;
    t1 = 1.0f;
    const glm::vec3 d = b - a;
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(d[i]) < 1e-12f) {
            if (a[i] < bx.min[i] || a[i] > bx.max[i]) return false;
            continue;
        }
        float u = (bx.min[i] - a[i]) / d[i];
        float v = (bx.max[i] - a[i]) / d[i];
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
        if (t0 > t1) return false;
    }
    return true;
}

bool lit_by_cone(const scene::Light& l, const glm::vec3& p) {
    if (l.type != scene::LightType::Spot) return true;
    return glm::dot(glm::normalize(p - l.position), glm::normalize(l.direction)) >= std::cos(l.spot_outer_cone);
}

// A random scene: a ground (receiver and caster, as the course's table) and boxes standing on or
// floating above it (casters, most also receivers), a camera looking at it, a light above.
struct RandomScene {
    std::vector<scene::Bounds> receivers, casters;
    glm::mat4 camera{1.0f};
    scene::Light light;
};

RandomScene random_scene(std::mt19937& gen, scene::LightType type) {
    const auto unit = [&gen] { return static_cast<float>(gen() >> 8) * (1.0f / 16777216.0f); };
    const auto in = [&](float lo, float hi) { return lo + (hi - lo) * unit(); };
    RandomScene s;
    const scene::Bounds ground = box({-6, -0.2f, -6}, {6, 0, 6});
    s.receivers.push_back(ground);
    s.casters.push_back(ground);
    const int n = 2 + static_cast<int>(gen() % 5);
    for (int i = 0; i < n; ++i) {
        const glm::vec3 c(in(-4, 4), in(0.2f, 2.5f), in(-4, 4));
        const glm::vec3 h(in(0.1f, 1.0f), in(0.1f, 1.0f), in(0.1f, 1.0f));
        const scene::Bounds b = box(c - h, c + h);
        s.casters.push_back(b);
        if (gen() % 4) s.receivers.push_back(b);
    }
    const float az = in(0.0f, 6.2832f);
    const glm::vec3 eye(in(5, 11) * std::cos(az), in(1, 7), in(5, 11) * std::sin(az));
    const glm::vec3 at(in(-2, 2), in(0, 1), in(-2, 2));
    s.camera = glm::perspective(glm::radians(in(35, 70)), in(1.0f, 1.8f), 0.1f, in(9, 40)) * glm::lookAt(eye, at, {0, 1, 0});
    s.light.type = type;
    s.light.position = glm::vec3(in(-6, 6), in(5, 12), in(-6, 6));
    if (type == scene::LightType::Directional) {
        s.light.direction = glm::normalize(glm::vec3(in(-1, 1), -in(0.4f, 1.0f), in(-1, 1)));
    } else {
        s.light.direction = glm::normalize(glm::vec3(in(-2, 2), 0, in(-2, 2)) - s.light.position);
        s.light.spot_outer_cone = in(0.3f, 1.0f);
    }
    return s;
}

float max_abs_entry(const glm::mat4& m) {
    float v = 0.0f;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) v = std::max(v, std::fabs(m[c][r]));
    return v;
}

}  // namespace

TEST(TightLightFrustum, HoldsEveryVisibleReceiverPointAndEveryCasterThatShadowsOne) {
    std::mt19937 gen(2024);
    const auto unit = [&gen] { return static_cast<float>(gen() >> 8) * (1.0f / 16777216.0f); };
    int tight = 0, points = 0, crossings = 0;
    for (int trial = 0; trial < 120; ++trial) {
        const scene::LightType type = trial % 3 == 0 ? scene::LightType::Point
                                      : trial % 3 == 1 ? scene::LightType::Spot
                                                       : scene::LightType::Directional;
        const RandomScene s = random_scene(gen, type);
        const TightFit fit = fit_light_frustum_tight(s.light, s.receivers, s.casters, s.camera);
        SCOPED_TRACE(trial);
        ASSERT_TRUE(finite(fit.frustum.view_proj()));
        if (!fit.tight) continue;  // the fallback (no receiver in view): checked below
        ++tight;
        const glm::mat4 vp = fit.frustum.view_proj();
        EXPECT_GT(fit.texel_use, 0.0f);
        EXPECT_LE(fit.texel_use, 1.0f);
        for (const scene::Bounds& r : s.receivers)
            for (int i = 0; i < 300; ++i) {
                const glm::vec3 p = r.min + (r.max - r.min) * glm::vec3(unit(), unit(), unit());
                if (!in_clip_volume(s.camera, p, 0.0f) || !lit_by_cone(s.light, p)) continue;
                ++points;
                ASSERT_TRUE(in_clip_volume(vp, p)) << "visible receiver point " << p.x << " " << p.y << " " << p.z;
                // The way to the light: every caster it crosses is drawn, and the part crossed is
                // inside the light's volume.
                const glm::vec3 from = type == scene::LightType::Directional ? p - 100.0f * s.light.direction : s.light.position;
                for (size_t k = 0; k < s.casters.size(); ++k) {
                    float t0 = 0.0f, t1 = 0.0f;
                    if (!segment_box(from, p, s.casters[k], t0, t1) || t1 - t0 < 1e-4f) continue;
                    ++crossings;
                    EXPECT_NE(std::find(fit.casters.begin(), fit.casters.end(), static_cast<int>(k)), fit.casters.end())
                        << "caster " << k << " shadows a visible point but is not drawn";
                    for (const float t : {t0, 0.5f * (t0 + t1), t1}) {
                        const glm::vec3 q = from + t * (p - from);
                        EXPECT_TRUE(in_clip_volume(vp, q)) << "caster " << k << " at " << q.x << " " << q.y << " " << q.z;
                    }
                }
            }
    }
    std::printf("tight fits %d of 120, %d visible receiver points, %d caster crossings checked\n", tight, points, crossings);
    EXPECT_GT(tight, 90);
    EXPECT_GT(points, 10000);
    EXPECT_GT(crossings, 1000);
}

TEST(TightLightFrustum, CastersOutsideTheWindowAreNotDrawn) {
    // A ground seen by a camera looking down at its middle; a point light above. One caster between
    // the light and the ground in view, one far off to the side, one beyond the ground (farther
    // from the light than any visible receiver point), one behind the light.
    scene::Light light;
    light.position = {0, 8, 0};
    const std::vector<scene::Bounds> receivers = {box({-20, -0.1f, -20}, {20, 0, 20})};
    const std::vector<scene::Bounds> casters = {box({-0.5f, 1, -0.5f}, {0.5f, 2, 0.5f}), box({15, 1, 15}, {16, 2, 16}),
                                                box({-1, -5, -1}, {1, -3, 1}), box({-1, 9, -1}, {1, 10, 1}), receivers[0]};
    const glm::mat4 camera = glm::perspective(glm::radians(40.0f), 1.0f, 0.1f, 50.0f) *
                             glm::lookAt(glm::vec3(0, 6, 6), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    const TightFit fit = fit_light_frustum_tight(light, receivers, casters, camera);
    ASSERT_TRUE(fit.tight);
    EXPECT_EQ(fit.casters, (std::vector<int>{0, 4}));
    // The near plane comes to the caster in view, not to the one behind the light.
    EXPECT_LT(fit.frustum.znear, 6.0f);
    EXPECT_GT(fit.frustum.znear, 5.0f);
    // The old fit holds the whole 40 x 40 ground; the tight one what the camera sees of it.
    const LightFrustum old = fit_light_frustum(light, scene::corners(receivers[0]), receivers[0].center());
    EXPECT_GT(fit.texel_use, 2.0f * texel_use(old, fit.visible));
}

TEST(TightLightFrustum, DegenerateCasesGiveFiniteMatrices) {
    scene::Light point;
    point.position = {0, 5, 0};
    scene::Light spot = point;
    spot.type = scene::LightType::Spot;
    spot.direction = {0, -1, 0};
    spot.spot_outer_cone = 0.5f;
    scene::Light wide_spot = spot;
    wide_spot.spot_outer_cone = 2.0f;  // beyond a hemisphere: no cone planes
    scene::Light narrow_spot = spot;
    narrow_spot.spot_outer_cone = 0.0f;
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1, 0.2f));
    scene::Light sun_down = sun;
    sun_down.direction = {0, -1, 0};
    scene::Light no_dir = point;
    no_dir.type = scene::LightType::Spot;
    no_dir.direction = glm::vec3(0.0f);

    const glm::mat4 proj = glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 30.0f);
    const glm::mat4 looking = proj * glm::lookAt(glm::vec3(0, 3, 6), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 away = proj * glm::lookAt(glm::vec3(0, 3, 6), glm::vec3(0, 3, 12), glm::vec3(0, 1, 0));
    const glm::mat4 down = proj * glm::lookAt(glm::vec3(0, 3, 0), glm::vec3(0), glm::vec3(0, 0, -1));

    const scene::Bounds table = box({-2, 0, -2}, {2, 0, 2});  // flat
    const scene::Bounds pot = box({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f});
    const scene::Bounds around_light = box({-1, 4, -1}, {1, 6, 1});
    const scene::Bounds dot = box({0.2f, 0.5f, 0.1f}, {0.2f, 0.5f, 0.1f});  // a single point
    const std::vector<std::vector<scene::Bounds>> receiver_sets = {{}, {table}, {table, pot}, {dot}, {around_light, table}};
    const std::vector<std::vector<scene::Bounds>> caster_sets = {{}, {pot}, {table, pot}, {around_light}, {dot}};
    int fallbacks = 0;
    for (const scene::Light& l : {point, spot, wide_spot, narrow_spot, sun, sun_down, no_dir})
        for (const glm::mat4& cam : {looking, away, down, glm::mat4(1.0f), glm::mat4(0.0f)})
            for (const auto& rs : receiver_sets)
                for (const auto& cs : caster_sets) {
                    const TightFit fit = fit_light_frustum_tight(l, rs, cs, cam);
                    const LightFrustum& f = fit.frustum;
                    ASSERT_TRUE(finite(f.view));
                    ASSERT_TRUE(finite(f.proj));
                    ASSERT_TRUE(std::isfinite(f.znear) && std::isfinite(f.zfar));
                    ASSERT_GT(f.zfar, f.znear);
                    if (f.perspective) {
                        ASSERT_GT(f.znear, 0.0f);
                    }
                    ASSERT_NE(glm::determinant(f.proj), 0.0f);
                    ASSERT_TRUE(fit.texel_use >= 0.0f && fit.texel_use <= 1.0f);
                    ASSERT_LT(max_abs_entry(f.proj), 1e9f);
                    for (int k : fit.casters) ASSERT_TRUE(k >= 0 && k < static_cast<int>(cs.size()));
                    if (!fit.tight) {
                        ++fallbacks;
                        ASSERT_EQ(fit.casters.size(), cs.size()) << "the fallback draws every caster";
                    }
                }
    EXPECT_GT(fallbacks, 0);

    // The camera looking away sees no receiver: the fallback, no texel in use.
    const TightFit a = fit_light_frustum_tight(point, {table, pot}, {table, pot}, away);
    EXPECT_FALSE(a.tight);
    EXPECT_TRUE(a.visible.empty());
    EXPECT_EQ(a.texel_use, 0.0f);
    // The light inside a caster's bounds: the fallback, the old fit over everything.
    const TightFit in = fit_light_frustum_tight(point, {table}, {around_light, pot}, looking);
    EXPECT_FALSE(in.tight);
    scene::Bounds all;
    for (const auto& b : {table, around_light, pot}) all.add(b);
    const LightFrustum old = fit_light_frustum(point, scene::corners(all), all.center());
    EXPECT_EQ(in.frustum.view_proj(), old.view_proj());
    EXPECT_GT(in.texel_use, 0.0f);
    // A directional light and a spot light over the table in view: tight.
    EXPECT_TRUE(fit_light_frustum_tight(sun, {table}, {pot}, looking).tight);
    const TightFit sp = fit_light_frustum_tight(spot, {table}, {pot}, looking);
    EXPECT_TRUE(sp.tight);
    // The spot's cone (0.5 rad from 5 up) lights a disc of radius 5 tan 0.5 = 2.73 on the table:
    // every visible point lies in the pyramid around it.
    for (const glm::vec3& p : sp.visible) EXPECT_LE(std::max(std::fabs(p.x), std::fabs(p.z)), 5.0f * std::tan(0.5f) + 1e-3f);
}

// The course scene (W09): the tight fit, from the camera the plan uses, holds every vertex of the
// teapot and the table the camera can see, and covers more of the map than the old fit.
TEST(TightLightFrustumCourse, TexelUseRisesAndEveryVisibleVertexIsHeld) {
    auto course = scene::make_course_scene(6);
    std::string figures;
    for (double t : {0.0, 0.7, 1.5, 3.0, 4.5, 6.0, 11.3}) {
        scene::animate_course(course, t, t);
        const scene::Scene& s = course.scene;
        const glm::mat4 camera = render::camera_view(s, render::offscreen(512, 512)).view_proj;
        std::vector<scene::Bounds> receivers, casters;
        for (const auto& o : s.objects) {
            if (o.receives_shadow) receivers.push_back(scene::object_bounds(s, o));
            if (o.casts_shadow) casters.push_back(scene::object_bounds(s, o));
        }
        const TightFit fit = fit_light_frustum_tight(s.light, receivers, casters, camera);
        ASSERT_TRUE(fit.tight) << "t=" << t;
        EXPECT_EQ(fit.casters.size(), casters.size()) << "the teapot and the table shadow what the camera sees";
        const scene::Bounds all = render::shadowed_bounds(s);
        const LightFrustum old = fit_light_frustum(s.light, scene::corners(all), all.center());
        const float before = texel_use(old, fit.visible);
        EXPECT_GT(fit.texel_use, before) << "t=" << t;
        EXPECT_EQ(render::fit_light_view(s, s.light, camera).view_proj(), fit.frustum.view_proj());
        char line[96];
        std::snprintf(line, sizeof line, "t=%.1f: texel use %.1f%% -> %.1f%%\n", t, 100.0 * before, 100.0 * fit.texel_use);
        figures += line;
        size_t checked = 0;
        const glm::mat4 vp = fit.frustum.view_proj();
        for (const auto& o : s.objects)
            for (const auto& p : s.meshes[static_cast<size_t>(o.mesh)].positions) {
                const glm::vec3 w = glm::vec3(o.world * glm::vec4(p, 1.0f));
                if (!in_clip_volume(camera, w, 0.0f)) continue;
                ASSERT_TRUE(in_clip_volume(vp, w)) << "t=" << t;
                ++checked;
            }
        EXPECT_GT(checked, 500u);
    }
    std::printf("course scene, old fit -> tight fit:\n%s", figures.c_str());
    ::testing::Test::RecordProperty("texel_use", figures);
}
