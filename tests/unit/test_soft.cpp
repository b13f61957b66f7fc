// Soft shadows without a context: the light's samples (Halton points on its disc), the plan of
// Heckbert-Herf's accumulation (passes per sample, the sum kept while still, notes when it cannot
// apply) and PCSS's shader variant and radii.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "plan/frames/area_light.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"
#include "shadow/area_light.h"
#include "shadow/pcf.h"

using namespace penumbra;

namespace {

gl::Caps caps() {
    gl::Caps c;
    c.depth_texture = c.packed_depth_stencil = c.depth24 = c.element_index_uint = true;
    c.max_texture_size = c.max_renderbuffer_size = c.max_viewport_width = c.max_viewport_height = 4096;
    return c;
}

int count_passes(const render::FramePlan& p, const std::string& name) {
    return static_cast<int>(std::count_if(p.passes.begin(), p.passes.end(), [&](const render::Pass& x) { return x.name == name; }));
}

TEST(AreaLight, SamplesCoverTheDiscEvenlyInEveryPrefix) {
    // Every point inside the unit disc; the first 4, 16 and 64 points' mean near the centre and
    // their spread near a uniform disc's (mean squared radius 1/2).
    for (int n : {4, 16, 64, 256}) {
        glm::vec2 mean(0.0f);
        float r2 = 0.0f;
        for (int k = 0; k < n; ++k) {
            const glm::vec2 p = shadow::area_sample_point(k);
            EXPECT_LE(glm::length(p), 1.0f + 1e-6f);
            mean += p;
            r2 += glm::dot(p, p);
        }
        mean /= static_cast<float>(n);
        r2 /= static_cast<float>(n);
        EXPECT_LT(glm::length(mean), n >= 64 ? 0.05f : n >= 16 ? 0.1f : 0.3f) << n;
        EXPECT_NEAR(r2, 0.5f, n >= 16 ? 0.06f : 0.2f) << n;
    }
    EXPECT_FLOAT_EQ(shadow::radical_inverse(1, 2), 0.5f);
    EXPECT_FLOAT_EQ(shadow::radical_inverse(3, 2), 0.75f);
    EXPECT_FLOAT_EQ(shadow::radical_inverse(1, 3), 1.0f / 3.0f);
}

TEST(AreaLight, ALightIsMovedOverItsDiscAcrossTheAxis) {
    scene::Light l;
    l.position = glm::vec3(1.0f, 5.0f, 2.0f);
    l.radius = 0.5f;
    const glm::vec3 axis(0.0f, -1.0f, 0.0f);
    for (int k = 0; k < 32; ++k) {
        const scene::Light s = shadow::area_light_sample(l, k, axis);
        const glm::vec3 d = s.position - l.position;
        EXPECT_NEAR(d.y, 0.0f, 1e-6f) << "on the disc across the axis";
        EXPECT_LE(glm::length(d), 0.5f + 1e-5f);
    }
    l.radius = 0.0f;
    EXPECT_EQ(shadow::area_light_sample(l, 7, axis).position, l.position);
    // A sun: its direction tilted by at most its angular radius.
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    sun.radius = 0.05f;
    for (int k = 0; k < 32; ++k) {
        const float c = glm::dot(shadow::area_light_sample(sun, k, axis).direction, sun.direction);
        EXPECT_GE(c, std::cos(0.05f) - 1e-6f);
    }
}

TEST(AreaPlan, EachSampleDrawsTheTechniqueAndAddsOneCount) {
    scene::CourseScene course = scene::make_course_scene(4);
    render::Settings s;
    s.light_radius = 0.3f;
    s.area_samples = 6;
    const render::FrameInputs in = render::offscreen(64, 64);
    const render::FramePlan p = render::plan(course.scene, s, caps(), in);
    ASSERT_TRUE(render::area_of(p));
    EXPECT_EQ(render::area_of(p)->total, 6);
    EXPECT_EQ(render::area_of(p)->done, 6);
    EXPECT_EQ(count_passes(p, "shadow-map"), 6);
    EXPECT_EQ(count_passes(p, "area-camera"), 6);
    EXPECT_EQ(count_passes(p, "area-add"), 6);
    EXPECT_EQ(count_passes(p, "camera"), 1);
    EXPECT_EQ(p.passes.back().name, "camera");
    // Additive counts into the sum; only the first clears it.
    int clears = 0;
    for (const render::Pass& x : p.passes)
        if (x.name == "area-add") {
            EXPECT_EQ(x.state.blend, gl::Blend::Add);
            clears += x.clear ? 1 : 0;
        }
    EXPECT_EQ(clears, 1);
    // The lights differ per sample: six different shadow-map matrices.
    EXPECT_NE(p.to_text().find("light samples (Heckbert-Herf): 6 of 6"), std::string::npos) << p.to_text();

    // A still frame reuses the sum; progressive frames add their share.
    const render::FramePlan again = render::plan(course.scene, s, caps(), in, &p);
    EXPECT_EQ(render::area_of(again)->added, 0);
    EXPECT_EQ(count_passes(again, "area-add"), 0);
    EXPECT_TRUE(again.resource("area-light")->reused);
    s.area_per_frame = 4;
    s.area_samples = 10;
    const render::FramePlan a = render::plan(course.scene, s, caps(), in);
    const render::FramePlan b = render::plan(course.scene, s, caps(), in, &a);
    const render::FramePlan c = render::plan(course.scene, s, caps(), in, &b);
    EXPECT_EQ(render::area_of(a)->done, 4);
    EXPECT_EQ(render::area_of(b)->done, 8);
    EXPECT_EQ(render::area_of(c)->done, 10);
    EXPECT_EQ(render::area_of(c)->added, 2);
    EXPECT_FALSE(b.passes[static_cast<size_t>(0)].clear && b.passes[0].name == "area-add");
    // Moving the camera starts again.
    scene::Scene moved = course.scene;
    moved.camera.view = glm::translate(moved.camera.view, glm::vec3(0.1f, 0.0f, 0.0f));
    EXPECT_EQ(render::area_of(render::plan(moved, s, caps(), in, &c))->done, 4);
}

TEST(AreaPlan, WithoutARadiusOrWithAViewOfOneSampleItSaysWhy) {
    scene::CourseScene course = scene::make_course_scene(4);
    render::Settings s;
    s.area_samples = 16;  // the course light's radius is 0
    const render::FramePlan p = render::plan(course.scene, s, caps(), render::offscreen(64, 64));
    EXPECT_FALSE(render::area_of(p));
    ASSERT_FALSE(p.notes.empty());
    EXPECT_NE(p.notes.back().find("the light has no radius"), std::string::npos) << p.notes.back();
    s.light_radius = 0.3f;
    s.aov = render::Aov::LightDepth;
    const render::FramePlan q = render::plan(course.scene, s, caps(), render::offscreen(64, 64));
    EXPECT_FALSE(render::area_of(q));
    EXPECT_NE(q.notes.back().find("one hard sample"), std::string::npos) << q.notes.back();
}

TEST(Pcss, TheVariantAndTheLookupsUniforms) {
    scene::CourseScene course = scene::make_course_scene(4);
    render::Settings s;
    ASSERT_EQ(render::parse_option(s, "filter", "pcss"), "");
    ASSERT_EQ(render::parse_option(s, "pcss-taps", "32"), "");
    ASSERT_EQ(render::parse_option(s, "light-radius", "0.2"), "");
    EXPECT_NE(render::parse_option(s, "pcss-taps", "65"), "");
    const render::FramePlan p = render::plan(course.scene, s, caps(), render::offscreen(64, 64));
    const render::Pass& cam = p.passes.back();
    const auto& defines = cam.draws.front().variant.defines;
    const auto has = [&](const std::string& d) { return std::find(defines.begin(), defines.end(), d) != defines.end(); };
    EXPECT_TRUE(has("FILTER_PCSS"));
    EXPECT_TRUE(has("PCSS_SEARCH_TAPS 16"));
    EXPECT_TRUE(has("PCSS_FILTER_TAPS 32"));
    EXPECT_TRUE(has("LIGHT_PERSPECTIVE")) << "the course's point light: a perspective map";
    bool size = false;
    for (const auto& b : cam.bindings)
        for (const auto& u : b.uniforms)
            if (u.name == "u_pcss") size = std::get<glm::vec2>(u.value).x == 0.2f;
    EXPECT_TRUE(size) << "the light's radius reaches the shader";
    // The layered blocker estimate by default, and the part of the light above the horizon.
    EXPECT_TRUE(has("PCSS_LAYERED"));
    EXPECT_TRUE(has("LIGHT_HORIZON"));
    ASSERT_EQ(render::parse_option(s, "pcss-blockers", "mean"), "");
    EXPECT_NE(render::parse_option(s, "pcss-blockers", "median"), "");
    const render::FramePlan m = render::plan(course.scene, s, caps(), render::offscreen(64, 64));
    const auto& md = m.passes.back().draws.front().variant.defines;
    EXPECT_EQ(std::find(md.begin(), md.end(), "PCSS_LAYERED"), md.end());
    EXPECT_NE(m.passes.back().detail.find("mean blockers"), std::string::npos) << m.passes.back().detail;
    // A point light (radius 0): neither, so PCSS is the hard lookup.
    ASSERT_EQ(render::parse_option(s, "light-radius", "0"), "");
    const render::FramePlan point = render::plan(course.scene, s, caps(), render::offscreen(64, 64));
    const auto& pd = point.passes.back().draws.front().variant.defines;
    EXPECT_EQ(std::find(pd.begin(), pd.end(), "LIGHT_HORIZON"), pd.end());
}

TEST(Pcss, TheConeInWindowDepthIsTheConeOfTheRadii) {
    // A blocker at eye depth e exactly the penumbra's radius from the ray is on the cone's edge:
    // its window depth is the deepest the cone allows there.
    const float n = 0.5f, f = 20.0f, zr = 8.0f;
    for (const bool persp : {true, false}) {
        const float size = persp ? 0.6f : 0.05f;
        const shadow::PcssConeDepth cone = shadow::pcss_cone_depth(size, persp, zr, n, f);
        for (const float e : {1.0f, 3.0f, 6.0f, 7.9f}) {
            const float rho = shadow::pcss_radii(size, persp, zr, e, n).penumbra;
            const float window = persp ? f / (f - n) * (1.0f - n / e) : (e - n) / (f - n);
            EXPECT_NEAR(cone.deepest(rho), window, 1e-5f) << (persp ? "perspective" : "orthographic") << " e " << e;
        }
        EXPECT_NEAR(cone.deepest(0.0f), persp ? f / (f - n) * (1.0f - n / zr) : (zr - n) / (f - n), 1e-6f) << "the receiver";
    }
}

TEST(Pcss, StackedCastersTheLayerOverTheReceiverSizesThePenumbra) {
    // A receiver at eye depth 8 under a light of radius 0.6 (perspective, planes 0.5 and 20). Its
    // search finds two layers: a caster at eye depth 4 straight over it (rho 0.01, inside the cone
    // there, whose radius is 0.6 * 4 / 32 = 0.075), and a low caster beside it at eye depth 7.5, 0.05
    // from the ray: outside the cone at that depth (radius 0.6 * 0.5 / 60 = 0.005), so it hides
    // none of the light from this receiver. Exact answer: the penumbra of the caster at 4.
    const float n = 0.5f, f = 20.0f, zr = 8.0f, size = 0.6f;
    const auto window = [&](float e) { return f / (f - n) * (1.0f - n / e); };
    const shadow::PcssConeDepth cone = shadow::pcss_cone_depth(size, true, zr, n, f);
    std::vector<shadow::PcssBlocker> taps;
    for (int i = 0; i < 3; ++i) taps.push_back({window(4.0f), 0.01f});
    for (int i = 0; i < 5; ++i) taps.push_back({window(7.5f), 0.05f});
    EXPECT_FLOAT_EQ(shadow::pcss_blocker_depth(taps, cone, true), window(4.0f));
    const float mean = shadow::pcss_blocker_depth(taps, cone, false);
    EXPECT_FLOAT_EQ(mean, (3.0f * window(4.0f) + 5.0f * window(7.5f)) / 8.0f);
    // The mean lies between the layers: its penumbra is too narrow for the caster over the receiver.
    const auto eye = [&](float w) { return n / (1.0f - w * (f - n) / f); };
    EXPECT_LT(shadow::pcss_radii(size, true, zr, eye(mean), n).penumbra, 0.5f * shadow::pcss_radii(size, true, zr, 4.0f, n).penumbra);
    // The low caster alone (nothing inside the cone): the mean of all, as Fernando's; none: lit.
    const std::vector<shadow::PcssBlocker> low(taps.begin() + 3, taps.end());
    EXPECT_FLOAT_EQ(shadow::pcss_blocker_depth(low, cone, true), window(7.5f));
    EXPECT_EQ(shadow::pcss_blocker_depth({}, cone, true), -1.0f);
}

TEST(Pcss, RadiiFollowFromSimilarTriangles) {
    // A receiver at depth 5 from the light, blockers at 4, a light of radius 0.5, the near plane at 1.
    const shadow::PcssRadii r = shadow::pcss_radii(0.5f, true, 5.0f, 4.0f, 1.0f);
    EXPECT_FLOAT_EQ(r.penumbra, 0.5f * 1.0f / (5.0f * 4.0f));  // world half-width R (zr - d)/d = 0.125, over zr
    EXPECT_FLOAT_EQ(r.search, 0.5f * 4.0f / 5.0f);
    EXPECT_GT(r.search, r.penumbra);
    const shadow::PcssRadii o = shadow::pcss_radii(0.1f, false, 5.0f, 4.0f, 1.0f);  // a sun: tan(theta) = 0.1
    EXPECT_FLOAT_EQ(o.penumbra, 0.1f);
    EXPECT_FLOAT_EQ(shadow::pcss_radii(0.5f, true, 5.0f, 5.0f, 1.0f).penumbra, 0.0f) << "contact: no penumbra";
    EXPECT_EQ(shadow::vogel_disc(16).size(), 16u);
    for (const glm::vec2& t : shadow::vogel_disc(16)) EXPECT_LE(glm::length(t), 1.0f);
}

}  // namespace
