// Issue 37: model only what the scene requires. A caster that shadows no receiver in view is left
// out of the map (the table under the teapot), and the map's window is cut to where the drawn
// casters' shadows can fall. The rule is conservative: checked here against brute-force segments.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan/plan.h"
#include "plan/techniques/reports.h"
#include "scene/primitives.h"
#include "scene/teapot.h"
#include "scenes/course_scene.h"
#include "shadow/casting.h"
#include "shadow/light_frustum.h"

using namespace penumbra;
using shadow::may_shadow;

namespace {

scene::Bounds box(const glm::vec3& lo, const glm::vec3& hi) { return scene::Bounds::around(lo, hi); }

// Whether the open segment (a, b] minus its start meets the box's interior or boundary: slabs.
bool segment_meets(const glm::vec3& a, const glm::vec3& b, const scene::Bounds& bx) {
    float t0 = 1e-6f, t1 = 1.0f;
    const glm::vec3 d = b - a;
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(d[i]) < 1e-12f) {
            if (a[i] < bx.min[i] || a[i] > bx.max[i]) return false;
            continue;
        }
        float u = (bx.min[i] - a[i]) / d[i], v = (bx.max[i] - a[i]) / d[i];
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

TEST(Casting, AFlatGroundUnderAnObjectLitFromAboveShadowsNothingOfIt) {
    const scene::Bounds ground = box({-2, 0, -2}, {2, 0, 2});
    const std::vector<glm::vec3> pot = scene::corners(box({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}));
    const glm::vec4 above(1, 3, 1, 1), below(1, -3, 1, 1);
    EXPECT_FALSE(may_shadow(ground, pot, above)) << "standing on the ground plane is not being hidden by it";
    EXPECT_TRUE(may_shadow(ground, pot, below)) << "control: lit from under the ground, the ground hides it";
    EXPECT_TRUE(may_shadow(box({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}), scene::corners(ground), above));
    // A directional light: (direction towards the light, 0).
    EXPECT_FALSE(may_shadow(ground, pot, glm::vec4(0.3f, 1.0f, 0.2f, 0.0f)));
    EXPECT_TRUE(may_shadow(ground, pot, glm::vec4(0.3f, -1.0f, 0.2f, 0.0f)));
    // A light level with the ground: its rays along the plane may graze it.
    EXPECT_TRUE(may_shadow(ground, pot, glm::vec4(5, 0, 0, 1)));
    // A box beyond every receiver point, seen from a point light: out of reach.
    EXPECT_FALSE(may_shadow(box({10, 10, 10}, {11, 11, 11}), pot, glm::vec4(0, 0.5f, 0, 1)));
}

TEST(Casting, EveryCasterLeftOutHidesNoPointFromTheLight) {
    // Random boxes, receiver point sets and lights; wherever may_shadow says false, no segment from
    // a point of the receiver's hull towards the light meets the box. Some must be true and some
    // false, or the test proves nothing.
    std::mt19937 rng(37);
    std::uniform_real_distribution<float> u(-4.0f, 4.0f), s(0.1f, 2.0f), t(0.0f, 1.0f);
    int left_out = 0, kept = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const glm::vec3 c(u(rng), u(rng), u(rng));
        const scene::Bounds caster = box(c, c + glm::vec3(s(rng), s(rng) * (trial % 5 == 0 ? 0.0f : 1.0f), s(rng)));
        std::vector<glm::vec3> pts;
        const glm::vec3 r(u(rng), u(rng), u(rng));
        for (int k = 0; k < 4; ++k) pts.push_back(r + glm::vec3(s(rng), s(rng), s(rng)));
        const bool directional = trial % 3 == 0;
        const glm::vec4 light = directional ? glm::vec4(glm::normalize(glm::vec3(u(rng), u(rng), u(rng))), 0.0f)
                                            : glm::vec4(u(rng) * 2.0f, u(rng) * 2.0f, u(rng) * 2.0f, 1.0f);
        if (may_shadow(caster, pts, light)) {
            ++kept;
            continue;
        }
        ++left_out;
        for (int k = 0; k < 200; ++k) {
            // A point of the hull: a random convex combination.
            float w[4], sum = 0.0f;
            for (float& x : w) sum += (x = t(rng) + 1e-3f);
            glm::vec3 p(0.0f);
            for (int j = 0; j < 4; ++j) p += pts[static_cast<size_t>(j)] * (w[j] / sum);
            const glm::vec3 end = directional ? p + 100.0f * glm::vec3(light) : glm::vec3(light);
            ASSERT_FALSE(segment_meets(p, end, caster)) << "trial " << trial << ": left out, yet it hides a point";
        }
    }
    EXPECT_GT(left_out, 300);
    EXPECT_GT(kept, 300);
}

TEST(Casting, FlatAndClosedConvexMeshesCannotShadowThemselves) {
    EXPECT_TRUE(scene::make_quad(4.0f).convex);
    EXPECT_TRUE(scene::make_box(glm::vec3(1.0f, 2.0f, 0.5f)).convex);
    EXPECT_TRUE(scene::make_sphere(1.0f, 16, 8).convex);
    EXPECT_FALSE(scene::make_bowl(1.0f, 16, 8).convex) << "open: its rim shadows its inside";
    EXPECT_FALSE(scene::make_teapot(4).convex);
    // A closed but concave mesh: a box with one corner pushed inwards.
    scene::Mesh dented = scene::make_box(glm::vec3(1.0f));
    for (glm::vec3& p : dented.positions)
        if (p.x > 0.0f && p.y > 0.0f && p.z > 0.0f) p = glm::vec3(0.2f);
    scene::seal(dented);
    EXPECT_TRUE(dented.closed);
    EXPECT_FALSE(dented.convex);
}

TEST(Casting, FacetedMeshesHaveTheirTrianglesNormals) {
    EXPECT_TRUE(scene::make_quad(4.0f).faceted);
    EXPECT_TRUE(scene::make_box(glm::vec3(1.0f, 2.0f, 0.5f)).faceted);
    EXPECT_FALSE(scene::make_sphere(1.0f, 16, 8).faceted) << "smooth normals";
    EXPECT_FALSE(scene::make_teapot(4).faceted);
    // The control: one corner's normal turned by 0.01 radians.
    scene::Mesh tilted = scene::make_quad(4.0f);
    tilted.normals[0] = glm::normalize(tilted.normals[0] + glm::vec3(0.01f, 0.0f, 0.0f));
    scene::seal(tilted);
    EXPECT_FALSE(tilted.faceted);
    // Either way round (a normal against the winding): still the triangle's own line.
    scene::Mesh flipped = scene::make_quad(4.0f);
    for (glm::vec3& n : flipped.normals) n = -n;
    scene::seal(flipped);
    EXPECT_TRUE(flipped.faceted);
}

TEST(Casting, TheShadowsFitLeavesTheTableOutAndCutsTheWindowToTheTeapot) {
    scene::CourseScene course = scene::make_course_scene(4);
    scene::animate_course(course, 0.6, 0.6);
    const render::ShadowBounds b = render::shadow_bounds(course.scene);
    const glm::mat4 vp = render::camera_view(course.scene, render::FrameInputs{}).view_proj;
    const shadow::TightFit tight = shadow::fit_light_frustum_tight(course.scene.light, b.receivers, b.casters, vp);
    const shadow::TightFit shadows =
        shadow::fit_light_frustum_shadows(course.scene.light, b.receivers, b.casters, vp, b.casting);
    ASSERT_TRUE(shadows.tight);
    EXPECT_EQ(tight.casters.size(), 2u);
    ASSERT_EQ(shadows.casters.size(), 1u);
    EXPECT_EQ(b.casting.caster_objects[static_cast<size_t>(shadows.casters[0])], course.teapot);
    EXPECT_EQ(shadows.culled, 1);
    EXPECT_TRUE(shadows.cut);
    // The cut window is smaller: the teapot's part of the map is larger.
    const auto area = [](const shadow::LightFrustum& f) {
        const glm::mat4 inv = glm::inverse(f.proj);
        const glm::vec4 a = inv * glm::vec4(-1, -1, -1, 1), c = inv * glm::vec4(1, 1, -1, 1);
        return std::fabs((c.x / c.w - a.x / a.w) * (c.y / c.w - a.y / a.w)) / (f.znear * f.znear);
    };
    EXPECT_LT(area(shadows.frustum), 0.5f * area(tight.frustum));
    // Every corner of the teapot's box that lies in the tight window is inside the cut one.
    for (const glm::vec3& p : scene::corners(b.casters[static_cast<size_t>(shadows.casters[0])])) {
        const glm::vec4 q = shadows.frustum.view_proj() * glm::vec4(p, 1.0f);
        EXPECT_LE(std::fabs(q.x), q.w * 1.0001f);
        EXPECT_LE(std::fabs(q.y), q.w * 1.0001f);
    }
    // Soft shadows keep the window (their penumbrae reach beyond the casters) but not the table.
    shadow::CastingInfo soft = b.casting;
    soft.fit_window = false;
    const shadow::TightFit kept = shadow::fit_light_frustum_shadows(course.scene.light, b.receivers, b.casters, vp, soft);
    EXPECT_FALSE(kept.cut);
    EXPECT_EQ(kept.casters.size(), 1u);
    EXPECT_EQ(kept.frustum.view_proj(), tight.frustum.view_proj());
}

// bench_hard's case: a plank dips 3 cm below the ground, so the ground may shadow the plank's tip
// and is drawn; but its shadow can fall only on the plank, so the window stays cut to the plank
// and the post, not widened to the whole ground.
TEST(Casting, TheWindowIsCutToTheReceiversEachCasterCanShadow) {
    scene::Light light;
    light.type = scene::LightType::Point;
    light.position = {-6.5f, 2.3f, 1.1f};
    const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 50.0f) *
                         glm::lookAt(glm::vec3(0.3f, 3.2f, 6.0f), glm::vec3(0.4f, 0.3f, -0.2f), glm::vec3(0, 1, 0));
    const scene::Bounds ground = box({-6, 0, -6}, {6, 0, 6}), post = box({-2.0f, 0, 0.5f}, {-1.9f, 1, 0.6f});
    const auto fit = [&](const std::vector<scene::Bounds>& boxes) {
        shadow::CastingInfo info;
        for (size_t k = 0; k < boxes.size(); ++k) {
            info.receiver_objects.push_back(static_cast<int>(k));
            info.caster_objects.push_back(static_cast<int>(k));
            info.caster_convex.push_back(1);
        }
        return shadow::fit_light_frustum_shadows(light, boxes, boxes, vp, info);
    };
    const auto area = [](const shadow::LightFrustum& f) {
        const glm::mat4 inv = glm::inverse(f.proj);
        const glm::vec4 a = inv * glm::vec4(-1, -1, -1, 1), c = inv * glm::vec4(1, 1, -1, 1);
        return std::fabs((c.x / c.w - a.x / a.w) * (c.y / c.w - a.y / a.w)) / (f.znear * f.znear);
    };
    const shadow::TightFit above = fit({ground, box({1.2f, 0.0f, 0.2f}, {1.6f, 1.2f, 0.6f}), post});
    const shadow::TightFit dips = fit({ground, box({1.2f, -0.03f, 0.2f}, {1.6f, 1.2f, 0.6f}), post});
    ASSERT_TRUE(above.tight && dips.tight && above.cut && dips.cut);
    EXPECT_EQ(above.culled, 1) << "standing on the ground, nothing is shadowed by it";
    EXPECT_EQ(dips.culled, 0) << "the ground may shadow the plank's tip below it: drawn";
    EXPECT_LT(area(dips.frustum), 1.05f * area(above.frustum));
    // The plank's tip, just under the ground, is inside the window.
    for (const glm::vec3& p : {glm::vec3(1.2f, -0.02f, 0.2f), glm::vec3(1.6f, -0.02f, 0.6f)}) {
        const glm::vec4 q = dips.frustum.view_proj() * glm::vec4(p, 1.0f);
        EXPECT_LE(std::fabs(q.x), q.w);
        EXPECT_LE(std::fabs(q.y), q.w);
    }
    // The control: a slab under the whole ground, which the ground may shadow everywhere; the
    // window is then the ground's, several times larger.
    const shadow::TightFit basement =
        fit({ground, box({1.2f, -0.03f, 0.2f}, {1.6f, 1.2f, 0.6f}), post, box({-6, -1, -6}, {6, -0.5f, 6})});
    EXPECT_GT(area(basement.frustum), 3.0f * area(dips.frustum));
}

TEST(Casting, ShadowVolumesLeaveOutTheCastersThatShadowNothing) {
    scene::CourseScene course = scene::make_course_scene(4);
    scene::animate_course(course, 0.6, 0.6);
    render::Settings s;
    s.technique = render::Technique::Volumes;
    const gl::Caps caps = penumbra::testing::full_caps();
    const auto drawn = [&](const render::FramePlan& p, int object) {
        int n = 0;
        for (const render::Pass& pass : p.passes)
            if (pass.name.rfind("volumes-z", 0) == 0)
                for (const render::Draw& d : pass.draws) n += d.label == course.scene.objects[static_cast<size_t>(object)].name;
        return n;
    };
    const render::FramePlan shadows = render::plan(course.scene, s, caps);
    ASSERT_TRUE(render::volumes_of(shadows));
    EXPECT_EQ(render::volumes_of(shadows)->culled, 1);
    EXPECT_EQ(drawn(shadows, course.table), 0);
    EXPECT_GT(drawn(shadows, course.teapot), 0);
    EXPECT_NE(shadows.to_text().find("shadow volumes left out: 1 caster(s)"), std::string::npos);
    // The control: the tight fit extrudes the table's volume too, and its fill is larger.
    s.light_fit = render::LightFit::Tight;
    const render::FramePlan tight = render::plan(course.scene, s, caps);
    EXPECT_EQ(render::volumes_of(tight)->culled, 0);
    EXPECT_GT(drawn(tight, course.table), 0);
    EXPECT_GT(render::volumes_of(tight)->fill, render::volumes_of(shadows)->fill);
}
