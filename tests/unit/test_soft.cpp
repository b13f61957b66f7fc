// Soft shadows without a context: the light's samples (a lattice spiral on its disc), the plan of
// Heckbert-Herf's accumulation (passes per sample, the sum kept while still, notes when it cannot
// apply) and PCSS's shader variant and radii.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

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

// Mean and mean squared radius of points k in [from, to) of n: near a uniform disc's 0 and 1/2.
void expect_spread(int from, int to, int n) {
    glm::vec2 mean(0.0f);
    float r2 = 0.0f;
    for (int k = from; k < to; ++k) {
        const glm::vec2 p = shadow::area_sample_point(k, n);
        EXPECT_LE(glm::length(p), 1.0f + 1e-6f);
        mean += p;
        r2 += glm::dot(p, p);
    }
    const int m = to - from;
    mean /= static_cast<float>(m);
    r2 /= static_cast<float>(m);
    EXPECT_LT(glm::length(mean), m >= 64 ? 0.05f : m >= 16 ? 0.1f : 0.3f) << from << ".." << to << " of " << n;
    EXPECT_NEAR(r2, 0.5f, m >= 16 ? 0.06f : 0.2f) << from << ".." << to << " of " << n;
}

// The mean |share of the points on one side of a line - share of the disc's area there| over
// 4096 lines across the unit disc (directions and offsets from a fixed generator): what a
// Heckbert-Herf pixel inside a straight edge's penumbra gets wrong, on average.
template <class Point>
double half_plane_error(int n, Point point) {
    std::vector<glm::vec2> pts;
    for (int k = 0; k < n; ++k) pts.push_back(point(k));
    std::uint32_t state = 12345u;
    const auto uniform = [&] {
        state = state * 1664525u + 1013904223u;
        return static_cast<double>(state >> 8) / 16777216.0;
    };
    double sum = 0.0;
    const int lines = 4096;
    for (int i = 0; i < lines; ++i) {
        const double th = 2.0 * 3.14159265358979 * uniform(), d = 2.0 * uniform() - 1.0;
        const glm::vec2 dir(static_cast<float>(std::cos(th)), static_cast<float>(std::sin(th)));
        int above = 0;
        for (const glm::vec2& q : pts) above += static_cast<double>(glm::dot(q, dir)) > d ? 1 : 0;
        const double area = (std::acos(d) - d * std::sqrt(1.0 - d * d)) / 3.14159265358979;
        sum += std::fabs(static_cast<double>(above) / n - area);
    }
    return sum / lines;
}

float halton(int i, int base) {
    float inv = 1.0f / static_cast<float>(base), f = inv, r = 0.0f;
    for (; i > 0; i /= base) {
        r += f * static_cast<float>(i % base);
        f *= inv;
    }
    return r;
}

TEST(AreaLight, SamplesCoverTheDiscEvenlyInEveryPrefix) {
    // Whole sets, n not a power of two among them; then the prefixes a progressive render stops
    // at, and the blocks of n / K^2 an interleaved pixel class counts.
    for (int n : {4, 16, 24, 64, 100, 256}) expect_spread(0, n, n);
    for (int m : {4, 16, 64}) expect_spread(0, m, 256);
    for (int j = 0; j < 16; ++j) expect_spread(16 * j, 16 * (j + 1), 256);
    for (int j = 0; j < 4; ++j) expect_spread(16 * j, 16 * (j + 1), 64);
    // Every spiral index once: k -> i is a permutation of [0, n).
    for (int n : {7, 64, 100}) {
        std::vector<glm::vec2> seen;
        for (int k = 0; k < n; ++k) seen.push_back(shadow::area_sample_point(k, n));
        for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b)
                EXPECT_GT(glm::length(seen[static_cast<size_t>(a)] - seen[static_cast<size_t>(b)]), 1e-4f);
    }
    EXPECT_EQ(shadow::area_sample_point(0, 1), glm::vec2(0.0f)) << "one sample: the centre";
}

glm::vec2 halton_disc(int k) {
    const float a = 2.0f * halton(k + 1, 2) - 1.0f, b = 2.0f * halton(k + 1, 3) - 1.0f;
    if (a == 0.0f && b == 0.0f) return glm::vec2(0.0f);
    const float q = 0.785398163f;  // Shirley's concentric map
    return std::fabs(a) > std::fabs(b) ? a * glm::vec2(std::cos(q * b / a), std::sin(q * b / a))
                                       : b * glm::vec2(std::cos(2.0f * q - q * a / b), std::sin(2.0f * q - q * a / b));
}

TEST(AreaLight, SamplesSplitTheDiscUnderALineAsItsAreaDoes) {
    // The control is the first 64 Halton (2, 3) points on Shirley's concentric map, which this
    // renderer used before. Measured with these lines: the lattice's 64 points err by 1.01 % of the
    // disc, Halton's by 1.57 %; their four blocks of 16 (an interleaved pixel class's share,
    // --area-interleave 2) by 3.07 % and 3.51 %; 256 points by 0.35 % and 0.52 %. (Modelled apart,
    // over 8000 random lines, a golden-angle spiral's 64 err by 1.00 % but its blocks by 4.7 %.)
    const double whole = half_plane_error(64, [](int k) { return shadow::area_sample_point(k, 64); });
    const double control = half_plane_error(64, halton_disc);
    double blocks = 0.0, control_blocks = 0.0;
    for (int j = 0; j < 4; ++j) {
        blocks += half_plane_error(16, [=](int k) { return shadow::area_sample_point(16 * j + k, 64); }) / 4.0;
        control_blocks += half_plane_error(16, [=](int k) { return halton_disc(16 * j + k); }) / 4.0;
    }
    const double whole256 = half_plane_error(256, [](int k) { return shadow::area_sample_point(k, 256); });
    std::printf("mean error of a line's split: 64 points %.3f %% (Halton %.3f %%), "
                "blocks of 16 %.3f %% (Halton %.3f %%), 256 points %.3f %%\n",
                100.0 * whole, 100.0 * control, 100.0 * blocks, 100.0 * control_blocks, 100.0 * whole256);
    EXPECT_LT(whole, 0.012);
    EXPECT_GT(control, 0.014) << "the control no longer differs: the test cannot tell a poor set";
    EXPECT_LT(blocks, control_blocks) << "an interleaved pixel class's share splits worse than Halton's did";
    EXPECT_LT(whole256, 0.004) << "Halton's 256: 0.52 %";
}

TEST(AreaLight, ALightIsMovedOverItsDiscAcrossTheAxis) {
    scene::Light l;
    l.position = glm::vec3(1.0f, 5.0f, 2.0f);
    l.radius = 0.5f;
    const glm::vec3 axis(0.0f, -1.0f, 0.0f);
    for (int k = 0; k < 32; ++k) {
        const scene::Light s = shadow::area_light_sample(l, k, 32, axis);
        const glm::vec3 d = s.position - l.position;
        EXPECT_NEAR(d.y, 0.0f, 1e-6f) << "on the disc across the axis";
        EXPECT_LE(glm::length(d), 0.5f + 1e-5f);
    }
    l.radius = 0.0f;
    EXPECT_EQ(shadow::area_light_sample(l, 7, 32, axis).position, l.position);
    // A sun: its direction tilted by at most its angular radius.
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    sun.radius = 0.05f;
    for (int k = 0; k < 32; ++k) {
        const float c = glm::dot(shadow::area_light_sample(sun, k, 32, axis).direction, sun.direction);
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

TEST(LightHorizon, FromTheTrianglesOwnNormalWhereTheContextHasDerivatives) {
    // Both soft methods' horizon: PCSS's part of the light above it, each Heckbert-Herf sample's
    // n.l > 0. With OES_standard_derivatives it is the triangle's plane (GEOMETRIC_HORIZON);
    // without, the interpolated normal's, as before.
    scene::CourseScene course = scene::make_course_scene(4);
    // The frame's lit draws' defines, with a light of radius 0.2 (or `radius`).
    const auto lit_defines = [&](const char* option, const char* value, bool derivatives, const char* radius = "0.2") {
        render::Settings s;
        EXPECT_EQ(render::parse_option(s, option, value), "");
        EXPECT_EQ(render::parse_option(s, "light-radius", radius), "");
        gl::Caps c = caps();
        c.standard_derivatives = derivatives;
        const render::FramePlan p = render::plan(course.scene, s, c, render::offscreen(64, 64));
        std::vector<std::vector<std::string>> out;
        for (const auto& pass : p.passes)
            for (const auto& d : pass.draws)
                if (d.variant.fragment == "lit.frag") out.push_back(d.variant.defines);
        return out;
    };
    const auto count = [](const std::vector<std::vector<std::string>>& all, const char* define) {
        return std::count_if(all.begin(), all.end(), [&](const std::vector<std::string>& d) {
            return std::find(d.begin(), d.end(), define) != d.end();
        });
    };
    for (const auto& [option, value] : {std::pair{"filter", "pcss"}, std::pair{"area-samples", "4"}}) {
        const std::string args = std::string(option) + "=" + value;
        const auto with = lit_defines(option, value, true);
        const auto without = lit_defines(option, value, false);
        ASSERT_GT(count(with, "LIGHT_HORIZON"), 0) << args;
        EXPECT_EQ(count(with, "GEOMETRIC_HORIZON"), count(with, "LIGHT_HORIZON")) << args;
        EXPECT_EQ(count(without, "LIGHT_HORIZON"), count(with, "LIGHT_HORIZON")) << args;
        EXPECT_EQ(count(without, "GEOMETRIC_HORIZON"), 0) << args;
    }
    // PCSS shares its filtered visibility over the pixel quad through the same derivatives; a
    // Heckbert-Herf sample has no filter to share.
    EXPECT_EQ(count(lit_defines("filter", "pcss", true), "PCSS_QUAD"), count(lit_defines("filter", "pcss", true), "LIGHT_HORIZON"));
    EXPECT_EQ(count(lit_defines("filter", "pcss", false), "PCSS_QUAD"), 0);
    EXPECT_EQ(count(lit_defines("area-samples", "4", true), "PCSS_QUAD"), 0);
    // No horizon (a point light): nothing asks for derivatives.
    EXPECT_EQ(count(lit_defines("filter", "pcss", true, "0"), "GEOMETRIC_HORIZON"), 0);
    EXPECT_EQ(count(lit_defines("filter", "pcss", true, "0"), "PCSS_QUAD"), 0);
    // The lighting pass of deferred shading reads the surface back: its quads may straddle two
    // triangles, so it keeps the interpolated normal.
    render::LitFeatures f;
    f.horizon = f.derivatives = true;
    f.gbuffer = render::Gbuffer::Read;
    const auto rd = render::lit_variant(f).defines;
    EXPECT_EQ(std::find(rd.begin(), rd.end(), "GEOMETRIC_HORIZON"), rd.end());
    f.gbuffer = render::Gbuffer::None;
    const auto fd = render::lit_variant(f).defines;
    EXPECT_NE(std::find(fd.begin(), fd.end(), "GEOMETRIC_HORIZON"), fd.end());
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
    // The low caster alone (nothing inside the cone): its depth; none: lit.
    std::vector<shadow::PcssBlocker> low(taps.begin() + 3, taps.end());
    EXPECT_FLOAT_EQ(shadow::pcss_blocker_depth(low, cone, true), window(7.5f));
    EXPECT_EQ(shadow::pcss_blocker_depth({}, cone, true), -1.0f);
    // Beside it a caster nearer the light, also outside the cone (at eye depth 6, 0.1 from the
    // ray where the cone's radius is 0.6 * 2 / 48 = 0.025): nothing inside, so the nearest sizes
    // the widest penumbra, where the search may have missed a thin caster between its taps. The
    // mean of all would be the narrower penumbra between them (the control).
    low.push_back({window(6.0f), 0.1f});
    ASSERT_GT(window(6.0f), cone.deepest(0.1f));
    EXPECT_FLOAT_EQ(shadow::pcss_blocker_depth(low, cone, true), window(6.0f));
    EXPECT_GT(shadow::pcss_blocker_depth(low, cone, false), window(6.0f) + 0.001f);
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

// --area-interleave K: sample passes counting one light sample at one of the K x K pixel classes.
namespace interleave {

bool has_define(const render::Pass& pass, const std::string& prefix) {
    for (const render::Draw& d : pass.draws)
        for (const std::string& x : d.variant.defines)
            if (x.rfind(prefix, 0) == 0) return true;
    return false;
}

bool has_uniform(const render::Pass& pass, const std::string& name) {
    for (const auto& b : pass.bindings)
        for (const auto& u : b.uniforms)
            if (u.name == name) return true;
    return false;
}

float area_weight(const render::Pass& cam) {
    for (const auto& b : cam.bindings)
        for (const auto& u : b.uniforms)
            if (u.name == "u_area_weights") return std::get<glm::vec4>(u.value).x;
    return -1.0f;
}

// The class each of a plan's area-add passes counts at, from its u_class (x + K y).
std::vector<int> classes_of(const render::FramePlan& p) {
    std::vector<int> out;
    for (const render::Pass& x : p.passes)
        if (x.name == "area-add")
            for (const auto& b : x.bindings)
                for (const auto& u : b.uniforms)
                    if (u.name == "u_class") {
                        const glm::vec4 c = std::get<glm::vec4>(u.value);
                        out.push_back(static_cast<int>(c.x + c.z * c.y));
                    }
    return out;
}

}  // namespace interleave

TEST(AreaPlan, InterleaveOneIsThePlanWithoutIt) {
    scene::CourseScene course = scene::make_course_scene(4);
    render::Settings s;
    s.light_radius = 0.3f;
    s.area_samples = 6;
    s.area_per_frame = 4;
    render::Settings one = s;
    ASSERT_EQ(render::parse_option(one, "area-interleave", "1"), "");
    EXPECT_NE(render::parse_option(one, "area-interleave", "3"), "") << "K is 1, 2 or 4";
    const render::FrameInputs in = render::offscreen(64, 64);
    const render::FramePlan a = render::plan(course.scene, s, caps(), in);
    const render::FramePlan b = render::plan(course.scene, one, caps(), in);
    EXPECT_EQ(a.to_json(), b.to_json());
    EXPECT_EQ(render::to_args(s), render::to_args(one)) << "the default is not printed";
    // The report as before: no interleave in it (the settings' line lists --area-interleave 1).
    EXPECT_EQ(render::AreaStats::json(*render::area_of(a)).find("interleave"), std::string::npos);
    EXPECT_NE(a.to_text().find("light samples (Heckbert-Herf): 4 of 6 in the sum, 4 drawn this frame"), std::string::npos);
    for (const render::Pass& x : a.passes) {
        EXPECT_FALSE(interleave::has_define(x, "AREA_INTERLEAVE")) << x.name;
        EXPECT_FALSE(interleave::has_uniform(x, "u_class")) << x.name;
    }
    EXPECT_EQ(render::area_of(a)->total, 6);
    EXPECT_EQ(render::area_of(a)->done, 4);
    EXPECT_FLOAT_EQ(interleave::area_weight(a.passes.back()), 255.0f / 4.0f);
}

TEST(AreaPlan, InterleavedStepsGiveEveryClassEverySampleOnce) {
    for (int k : {2, 4})
        for (int n : {3, 8, 16, 37, 64}) {
            const int classes = k * k;
            std::vector<int> seen(static_cast<size_t>(n * classes), 0);
            for (int s = 0; s < n * classes; ++s) {
                const render::AreaStep st = render::area_step(s, n, k);
                ASSERT_GE(st.pixel_class, 0);
                ASSERT_LT(st.pixel_class, classes);
                EXPECT_EQ(st.sample, s % n);
                ++seen[static_cast<size_t>(st.sample * classes + st.pixel_class)];
            }
            for (int x : seen) EXPECT_EQ(x, 1) << "K " << k << " N " << n;
            // The classes' counts after any number of passes, against counting them one by one.
            std::vector<int> count(static_cast<size_t>(classes), 0);
            for (int done = 0; done <= n * classes; ++done) {
                for (int j = 0; j < classes; ++j)
                    ASSERT_EQ(render::area_class_samples(j, done, n, k), count[static_cast<size_t>(j)])
                        << "K " << k << " N " << n << " after " << done;
                if (done < n * classes) ++count[static_cast<size_t>(render::area_step(done, n, k).pixel_class)];
            }
            if (n % classes == 0) {  // a round: each class a block of N / K^2 consecutive samples
                for (int j = 0; j < classes; ++j) EXPECT_EQ(render::area_class_samples(j, n, n, k), n / classes);
            }
        }
}

TEST(AreaPlan, InterleavedFramesAddRoundsAndTheLastIsUnfiltered) {
    scene::CourseScene course = scene::make_course_scene(4);
    render::Settings s;
    s.light_radius = 0.3f;
    s.area_samples = 8;
    s.area_interleave = 2;
    const render::FrameInputs in = render::offscreen(64, 64);
    std::vector<render::FramePlan> frames;
    std::vector<int> per_class(4, 0);
    for (int f = 0; f < 5; ++f) {
        frames.push_back(render::plan(course.scene, s, caps(), in, frames.empty() ? nullptr : &frames.back()));
        const render::FramePlan& p = frames.back();
        const render::AreaStats& a = *render::area_of(p);
        EXPECT_EQ(a.total, 32);
        EXPECT_EQ(a.samples, 8);
        EXPECT_EQ(a.interleave, 2);
        EXPECT_EQ(a.done, std::min(32, 8 * (f + 1))) << "one round of the 8 samples per frame";
        EXPECT_EQ(a.added, f < 4 ? 8 : 0);
        EXPECT_EQ(count_passes(p, "area-add"), a.added);
        EXPECT_EQ(count_passes(p, "area-camera"), a.added);
        for (int j : interleave::classes_of(p)) ++per_class[static_cast<size_t>(j)];
        for (int j = 0; j < 4; ++j) EXPECT_EQ(per_class[static_cast<size_t>(j)], 2 * std::min(f + 1, 4)) << j;
        EXPECT_EQ(a.pixel_min, 2 * std::min(f + 1, 4));
        EXPECT_EQ(a.pixel_max, a.pixel_min);
        const render::Pass& cam = p.passes.back();
        EXPECT_EQ(cam.name, "camera");
        // Filtered over the tile until the last round; then each pixel's own 8, as without it.
        EXPECT_EQ(interleave::has_define(cam, "AREA_INTERLEAVE 2"), a.done < 32) << f;
        EXPECT_FLOAT_EQ(interleave::area_weight(cam), 255.0f / static_cast<float>(a.done < 32 ? a.done : 8)) << f;
        const std::string text = p.to_text();
        EXPECT_NE(text.find("interleaved 2x2"), std::string::npos) << text;
        EXPECT_NE(p.to_json().find("\"interleave\":2"), std::string::npos);
    }
    // The complete frame's camera pass is the one without interleaving.
    render::Settings plain = s;
    plain.area_interleave = 1;
    const render::FramePlan q = render::plan(course.scene, plain, caps(), in);
    const auto variants = [](const render::Pass& cam) {
        std::vector<std::string> v;
        for (const render::Draw& d : cam.draws) v.push_back(d.variant.key());
        return v;
    };
    EXPECT_EQ(variants(frames[3].passes.back()), variants(q.passes.back()));
    // Progressive: --area-per-frame passes per frame, across the rounds.
    s.area_per_frame = 5;
    s.area_interleave = 4;
    s.area_samples = 16;
    const render::FramePlan a = render::plan(course.scene, s, caps(), in);
    const render::FramePlan b = render::plan(course.scene, s, caps(), in, &a);
    EXPECT_EQ(render::area_of(a)->total, 256);
    EXPECT_EQ(render::area_of(b)->done, 10);
    EXPECT_EQ(render::area_of(b)->pixel_min, 0);
    EXPECT_EQ(render::area_of(b)->pixel_max, 1);
    EXPECT_EQ(interleave::classes_of(b), (std::vector<int>{5, 6, 7, 8, 9})) << "sample k at class k (N = K^2)";
}
