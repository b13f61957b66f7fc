// Cascaded shadow maps without a GL context: the splits, the slices' spheres, each cascade's
// window (the slice inside it, snapped to whole texels, casters towards the light included), the
// automatic count, and the plan's atlas, passes and lookups.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan/techniques/reports.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"
#include "scene/primitives.h"
#include "shadow/cascades.h"

using namespace penumbra;

namespace {

const glm::mat4 kProj = glm::perspective(glm::radians(58.0f), 16.0f / 9.0f, 0.5f, 1500.0f);

// A kilometre of flat ground, a few boxes, a sun 32 degrees up; the camera 2 m above the ground
// looking along it.
scene::Scene field() {
    scene::Scene s;
    s.meshes = {scene::make_quad(1000.0f), scene::make_box(glm::vec3(1.0f))};
    s.materials.resize(1);
    scene::Object ground;
    ground.name = "ground";
    ground.mesh = 0;
    s.objects.push_back(ground);
    for (int i = 0; i < 6; ++i) {
        scene::Object box;
        box.name = "box" + std::to_string(i);
        box.mesh = 1;
        const float z = -8.0f * std::pow(2.5f, static_cast<float>(i));
        box.world = glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, 2.0f, z)) * glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 4.0f, 2.0f));
        s.objects.push_back(box);
    }
    s.light.type = scene::LightType::Directional;
    s.light.direction = glm::normalize(glm::vec3(-0.8f, -0.53f, 0.25f));
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, 1.0f, -40.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(58.0f);
    s.camera.aspect = 16.0f / 9.0f;
    s.camera.znear = 0.5f;
    s.camera.zfar = 1500.0f;
    return s;
}

shadow::CascadeFit fit(const scene::Scene& s, const glm::mat4& view, shadow::CascadeOptions o = {}) {
    const render::ShadowBounds b = render::shadow_bounds(s);
    std::string why;
    shadow::CascadeFit f = shadow::fit_cascades(s.light, b.receivers, b.casters, view, kProj, o, &why);
    EXPECT_EQ(why, "");
    return f;
}

// The orthographic window's left and bottom edges in the light's eye space.
glm::vec2 window_origin(const shadow::LightFrustum& f) {
    const float w = 2.0f / f.proj[0][0], h = 2.0f / f.proj[1][1];
    return {-(f.proj[3][0] + 1.0f) * w / 2.0f, -(f.proj[3][1] + 1.0f) * h / 2.0f};
}

TEST(CascadeSplits, BlendLogarithmicAndUniform) {
    const auto u = shadow::cascade_splits(1.0f, 1000.0f, 4, 0.0f);
    const auto l = shadow::cascade_splits(1.0f, 1000.0f, 4, 1.0f);
    const auto m = shadow::cascade_splits(1.0f, 1000.0f, 4, 0.5f);
    ASSERT_EQ(u.size(), 5u);
    EXPECT_FLOAT_EQ(u[2], 500.5f);
    EXPECT_NEAR(l[1], std::pow(1000.0f, 0.25f), 1e-4f);
    EXPECT_NEAR(l[2], std::sqrt(1000.0f), 1e-3f);
    for (size_t i = 0; i < 5; ++i) EXPECT_NEAR(m[i], 0.5f * (u[i] + l[i]), 1e-3f);
    for (const auto* s : {&u, &l, &m}) {
        EXPECT_EQ(s->front(), 1.0f);
        EXPECT_EQ(s->back(), 1000.0f);
        for (size_t i = 1; i < s->size(); ++i) EXPECT_LT((*s)[i - 1], (*s)[i]);
    }
}

TEST(CascadeSpheres, HoldTheSliceAndDependOnlyOnTheProjection) {
    const glm::mat4 inv = glm::inverse(kProj);
    for (auto [a, b] : {std::pair{0.5f, 4.0f}, {4.0f, 30.0f}, {30.0f, 200.0f}, {0.5f, 1000.0f}}) {
        float c = 0.0f, r = 0.0f;
        shadow::slice_sphere(kProj, a, b, c, r);
        float far_corner = 0.0f;
        for (float z : {a, b})
            for (float x : {-1.0f, 1.0f})
                for (float y : {-1.0f, 1.0f}) {
                    // The view ray through NDC (x, y), scaled to view depth z.
                    glm::vec4 p = inv * glm::vec4(x, y, 1.0f, 1.0f);
                    glm::vec3 ray = glm::vec3(p) / p.w;
                    ray *= z / -ray.z;
                    const float d = glm::length(ray - glm::vec3(0.0f, 0.0f, -c));
                    far_corner = std::max(far_corner, d);
                    EXPECT_LE(d, r * 1.0001f) << a << ".." << b;
                }
        EXPECT_NEAR(far_corner, r, 1e-3f * r) << "the sphere is no larger than the corners need";
    }
}

TEST(CascadeFit, EachVisibleReceiverPointIsInsideItsCascadesWindow) {
    const scene::Scene s = field();
    const shadow::CascadeFit f = fit(s, s.camera.view);
    ASSERT_EQ(f.cascades.size(), 4u);
    EXPECT_EQ(f.atlas_width, 2048);
    EXPECT_EQ(f.atlas_height, 2048);
    ASSERT_FALSE(f.visible.empty());
    // Points on the ground in view, at many depths: each inside the cascade that serves it.
    int checked = 0;
    for (float z = -1.0f; z > -900.0f; z *= 1.3f)
        for (float x : {-0.4f, 0.0f, 0.4f}) {
            const glm::vec3 p(x * -z, 0.0f, z);
            const float depth = -(s.camera.view * glm::vec4(p, 1.0f)).z;
            for (const shadow::Cascade& c : f.cascades) {
                if (depth < c.fit_begin || depth > c.end) continue;
                const glm::vec4 q = c.frustum.view_proj() * glm::vec4(p, 1.0f);
                EXPECT_LE(std::fabs(q.x), 1.0f) << "depth " << depth;
                EXPECT_LE(std::fabs(q.y), 1.0f) << "depth " << depth;
                EXPECT_LE(std::fabs(q.z), 1.0f) << "depth " << depth;
                ++checked;
            }
        }
    EXPECT_GT(checked, 20);
    // Finer texels near the camera.
    for (size_t i = 1; i < f.cascades.size(); ++i) EXPECT_LT(f.cascades[i - 1].texel, f.cascades[i].texel);
}

TEST(CascadeFit, ASmallCameraMoveShiftsEachWindowByWholeTexels) {
    const scene::Scene s = field();
    for (bool snap : {true, false}) {
        shadow::CascadeOptions o;
        o.snap = snap;
        const shadow::CascadeFit a = fit(s, s.camera.view, o);
        int fractional = 0;
        for (int step = 1; step <= 20; ++step) {
            const glm::mat4 moved = glm::translate(glm::mat4(1.0f), glm::vec3(-0.0037f * static_cast<float>(step), 0.0f, 0.0f)) * s.camera.view;
            const shadow::CascadeFit b = fit(s, moved, o);
            ASSERT_EQ(b.cascades.size(), a.cascades.size());
            for (size_t i = 0; i < a.cascades.size(); ++i) {
                ASSERT_FLOAT_EQ(a.cascades[i].texel, b.cascades[i].texel) << "the texel size stays";
                const glm::vec2 d = (window_origin(b.cascades[i].frustum) - window_origin(a.cascades[i].frustum)) /
                                    a.cascades[i].texel;
                const glm::vec2 frac = glm::abs(d - glm::round(d));
                if (frac.x > 0.01f || frac.y > 0.01f) ++fractional;
            }
        }
        if (snap) EXPECT_EQ(fractional, 0) << "snapped windows move by whole texels only";
        else EXPECT_GT(fractional, 40) << "free windows slide by fractions of a texel";
    }
}

TEST(CascadeFit, ACasterOutsideTheSliceButTowardsTheLightIsDrawn) {
    scene::Scene s = field();
    // A box high above the ground between the sun and the first slice, outside the camera's view
    // (behind and above it).
    scene::Object high;
    high.name = "high";
    high.mesh = 1;
    high.world = glm::translate(glm::mat4(1.0f), glm::vec3(8.0f * 4.0f, 2.0f + 5.3f * 4.0f, -5.0f - 2.5f * 4.0f));
    s.objects.push_back(high);
    const shadow::CascadeFit f = fit(s, s.camera.view);
    const render::ShadowBounds b = render::shadow_bounds(s);
    const int index = static_cast<int>(b.casters.size()) - 1;
    const auto& first = f.cascades.front();
    EXPECT_NE(std::find(first.casters.begin(), first.casters.end(), index), first.casters.end());
    const glm::vec4 q = first.frustum.view_proj() * glm::vec4(b.casters.back().center(), 1.0f);
    EXPECT_GE(q.z, -1.0f) << "its depth is inside the map's range";
}

TEST(CascadeFit, NeedsADirectionalLightAndAPerspectiveCamera) {
    scene::Scene s = field();
    const render::ShadowBounds b = render::shadow_bounds(s);
    std::string why;
    s.light.type = scene::LightType::Point;
    EXPECT_TRUE(shadow::fit_cascades(s.light, b.receivers, b.casters, s.camera.view, kProj, {}, &why).cascades.empty());
    EXPECT_EQ(why, "cascades need a directional light");
    s.light.type = scene::LightType::Directional;
    const glm::mat4 ortho = glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 0.5f, 100.0f);
    EXPECT_TRUE(shadow::fit_cascades(s.light, b.receivers, b.casters, s.camera.view, ortho, {}, &why).cascades.empty());
    EXPECT_EQ(why, "cascades need a perspective camera");
}

TEST(CascadeFit, AutoCountFollowsTheDepthRange) {
    scene::Scene s = field();
    const render::ShadowBounds b = render::shadow_bounds(s);
    std::string why;
    // The ground seen from ~3.5 m to the far edge ~500 m away: a ratio over 8^2, 3 cascades.
    EXPECT_EQ(shadow::auto_cascade_count(s.light, b.receivers, s.camera.view, kProj, why), 3) << why;
    EXPECT_NE(why.find("3 cascades"), std::string::npos) << why;
    // Looking down at the ground from 3 m: depths 3 to ~5, one map.
    const glm::mat4 down = glm::lookAt(glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(0.0f, 0.0f, -0.01f), glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::mat4 narrow = glm::perspective(glm::radians(40.0f), 1.0f, 0.5f, 1500.0f);
    EXPECT_EQ(shadow::auto_cascade_count(s.light, b.receivers, down, narrow, why), 1) << why;
    s.light.type = scene::LightType::Spot;
    EXPECT_EQ(shadow::auto_cascade_count(s.light, b.receivers, s.camera.view, kProj, why), 1);
    EXPECT_EQ(why, "one map: the light is not directional");
}

TEST(CascadeSpheres, ASlicesProjectionKeepsTheImageAndClipsToTheSlice) {
    const glm::mat4 slice = shadow::slice_projection(kProj, 10.0f, 100.0f);
    const auto ndc = [](const glm::mat4& m, const glm::vec3& v) {
        const glm::vec4 c = m * glm::vec4(v, 1.0f);
        return glm::vec3(c) / c.w;
    };
    // View space looks down -z: the slice's near plane at depth 10, its far plane at 100.
    EXPECT_NEAR(ndc(slice, {0.0f, 0.0f, -10.0f}).z, -1.0f, 1e-5f);
    EXPECT_NEAR(ndc(slice, {0.0f, 0.0f, -100.0f}).z, 1.0f, 1e-4f);
    for (const glm::vec3 v : {glm::vec3(3.0f, -2.0f, -7.0f), glm::vec3(-40.0f, 12.0f, -60.0f), glm::vec3(5.0f, 5.0f, -300.0f)}) {
        EXPECT_NEAR(ndc(slice, v).x, ndc(kProj, v).x, 1e-5f);
        EXPECT_NEAR(ndc(slice, v).y, ndc(kProj, v).y, 1e-5f);
    }
    // The control: the whole frustum's projection puts depth 10 well inside, not on its near plane.
    EXPECT_GT(ndc(kProj, {0.0f, 0.0f, -10.0f}).z, -0.99f);
}

TEST(CascadeAtlas, TwoSideBySideThreeAndFourInTwoRows) {
    int c = 0, r = 0;
    shadow::atlas_layout(2, c, r);
    EXPECT_EQ(c * 10 + r, 21);
    shadow::atlas_layout(3, c, r);
    EXPECT_EQ(c * 10 + r, 22);
    shadow::atlas_layout(4, c, r);
    EXPECT_EQ(c * 10 + r, 22);
}

struct CascadePlan : ::testing::Test {
    scene::Scene s = field();
    gl::Caps caps = penumbra::testing::full_caps();
    render::Settings settings;
    render::FramePlan make(const render::FramePlan* previous = nullptr) {
        return render::plan(s, settings, caps, render::offscreen(128, 72), previous);
    }
};

TEST_F(CascadePlan, OnePassPerCascadeIntoItsTileAndOneLookup) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "3"), "");
    settings.map_size = 512;
    const render::FramePlan p = make();
    ASSERT_EQ(render::cascades_of(p).size(), 3u);
    EXPECT_EQ(render::cascades_why_of(p), "--cascades 3");
    const render::PlannedResource* map = p.resource("shadow-map");
    ASSERT_TRUE(map);
    EXPECT_EQ(map->desc.width, 1024);
    EXPECT_EQ(map->desc.height, 1024);
    // Every tile is drawn this frame: one clear of the whole atlas first (not a scissored clear
    // per tile), then a pass into each tile, its draws kept inside it.
    const render::Pass& clear = p.passes[0];
    EXPECT_EQ(clear.name, "shadow-map clear");
    EXPECT_EQ(clear.target.resource, p.resource_index("shadow-map"));
    EXPECT_EQ(clear.target.width, 1024);
    EXPECT_EQ(clear.target.height, 1024);
    EXPECT_FALSE(clear.target.clip);
    ASSERT_TRUE(clear.clear);
    EXPECT_TRUE(clear.clear->depth);
    EXPECT_TRUE(clear.draws.empty());
    const int tiles[3][2] = {{0, 0}, {512, 0}, {0, 512}};
    for (int i = 0; i < 3; ++i) {
        const render::Pass& pass = p.passes[static_cast<size_t>(i) + 1];
        EXPECT_EQ(pass.name, "shadow-map cascade " + std::to_string(i));
        EXPECT_EQ(pass.target.resource, p.resource_index("shadow-map"));
        EXPECT_EQ(pass.target.width, 512);
        EXPECT_EQ(pass.target.x, tiles[i][0]);
        EXPECT_EQ(pass.target.y, tiles[i][1]);
        EXPECT_TRUE(pass.target.clip) << "each pass's draws stay in its tile";
        EXPECT_FALSE(pass.clear) << "the atlas was cleared whole";
        EXPECT_EQ(pass.view_proj, render::cascades_of(p)[static_cast<size_t>(i)].frustum.view_proj());
    }
    const render::Pass& cam = p.passes.back();
    ASSERT_EQ(cam.name, "camera");
    bool cascaded = false;
    for (const auto& d : cam.draws)
        for (const auto& def : d.variant.defines) cascaded = cascaded || def == "CASCADES 3";
    EXPECT_TRUE(cascaded);
    bool matrix = false;
    for (const auto& b : cam.bindings)
        for (const auto& u : b.uniforms) matrix = matrix || u.name == "u_cascade_scale[2]";
    EXPECT_TRUE(matrix);
    EXPECT_NE(p.to_text().find("cascade 2: view depth"), std::string::npos);
    EXPECT_NE(p.to_json().find("\"cascades\":{\"why\":\"--cascades 3\",\"list\":[{"), std::string::npos);
}

// The cascade passes that run (are not skipped), and those that draw `object`.
int cascades_run(const render::FramePlan& p, int object = -1, int* drawing = nullptr) {
    int ran = 0;
    if (drawing) *drawing = 0;
    for (const render::Pass& pass : p.passes) {
        if (pass.name.rfind("shadow-map cascade ", 0) != 0) continue;
        ran += !pass.skipped;
        if (drawing)
            *drawing += std::any_of(pass.draws.begin(), pass.draws.end(), [&](const render::Draw& d) { return d.object == object; });
    }
    return ran;
}

TEST_F(CascadePlan, AStillCascadeIsSkippedAndAMovedCasterRedrawsOnlyTheCascadesThatDrawIt) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "4"), "");
    const render::FramePlan first = make();
    ASSERT_EQ(render::cascades_of(first).size(), 4u);
    EXPECT_EQ(cascades_run(first), 4);
    const render::FramePlan second = make(&first);
    EXPECT_EQ(cascades_run(second), 0);
    // The farthest box moves a little: only the cascades that draw it run again.
    s.objects[6].world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -0.5f)) * s.objects[6].world;
    const render::FramePlan third = make(&second);
    int drawing = 0;
    const int ran = cascades_run(third, 6, &drawing);
    EXPECT_EQ(ran, drawing);
    EXPECT_GE(ran, 1);
    EXPECT_LT(ran, 4);
    // Some tiles are kept: each pass that runs clears its own tile, and nothing clears the atlas.
    EXPECT_FALSE(third.has_pass("shadow-map clear"));
    for (const render::Pass& pass : third.passes)
        if (pass.name.rfind("shadow-map cascade ", 0) == 0 && !pass.skipped) {
            EXPECT_TRUE(pass.clear && pass.target.clip) << pass.name;
        }
    // The camera turns: the windows move and every cascade runs.
    s.camera.view = glm::rotate(glm::mat4(1.0f), glm::radians(2.0f), glm::vec3(0.0f, 1.0f, 0.0f)) * s.camera.view;
    const render::FramePlan fourth = make(&third);
    EXPECT_EQ(cascades_run(fourth), 4);
    const render::FramePlan fifth = make(&fourth);
    EXPECT_EQ(cascades_run(fifth), 0);
    // Another packing is another content: every cascade runs.
    ASSERT_EQ(render::parse_option(settings, "encoding", "r8"), "");
    EXPECT_EQ(cascades_run(make(&fifth)), 4);
}

TEST_F(CascadePlan, AutoExplainsItsChoiceAndAPointLightGetsOneMap) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "auto"), "");
    render::FramePlan p = make();
    EXPECT_EQ(render::cascades_of(p).size(), 3u);
    EXPECT_EQ(render::cascades_why_of(p).rfind("auto: 3 cascades: the receivers in view span view depths", 0), 0u) << render::cascades_why_of(p);
    s.light.type = scene::LightType::Point;
    s.light.position = glm::vec3(0.0f, 50.0f, 0.0f);
    p = make();
    EXPECT_TRUE(render::cascades_of(p).empty());
    EXPECT_FALSE((render::cube_of(p) != nullptr));
    EXPECT_EQ(render::cascades_why_of(p), "auto: one map: the point light is outside the scene's bounds");
    ASSERT_EQ(render::parse_option(settings, "cascades", "4"), "");
    p = make();
    EXPECT_TRUE(render::cascades_of(p).empty());
    ASSERT_FALSE(p.notes.empty());
    EXPECT_EQ(p.notes.back(), "--cascades 4: one map instead, cascades need a directional light");
    EXPECT_TRUE(p.has_pass("shadow-map"));
}

TEST_F(CascadePlan, TheAtlasIsCutToTheContextsMaximum) {
    ASSERT_EQ(render::parse_option(settings, "cascades", "4"), "");
    settings.map_size = 16384;
    caps.max_texture_size = caps.max_renderbuffer_size = caps.max_viewport_width = caps.max_viewport_height = 8192;
    const render::FramePlan p = make();
    ASSERT_EQ(render::cascades_of(p).size(), 4u);
    EXPECT_EQ(p.resource("shadow-map")->desc.width, 8192);
    bool noted = false;
    for (const auto& n : p.notes) noted = noted || n.find("each map cut to 4096") != std::string::npos;
    EXPECT_TRUE(noted);
}

TEST_F(CascadePlan, AutoMatchesTheCascadesToTheirSlicesWithinTheAtlassBound) {
    // Each cascade is matched to the receivers in view within its slice; the nearest slice's
    // ground, a few pixels from the camera, asks for far more texels than a tile can have, so the
    // tiles get the largest the atlas allows: 64 MiB at 6 bytes a texel, 2048 for 2 tiles and
    // 1024 for 4, each within the context's largest target.
    ASSERT_EQ(render::parse_option(settings, "map-size", "auto"), "");
    ASSERT_EQ(render::parse_option(settings, "cascades", "2"), "");
    render::FramePlan p = make();
    ASSERT_EQ(render::cascades_of(p).size(), 2u);
    const render::MapSizeReport* m = p.find<render::MapSizeReport>();
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->size, 2048);
    EXPECT_EQ(p.resource("shadow-map")->desc.width, 4096);
    EXPECT_GT(m->wanted, 2048);
    // The nearest slice asks the most: matched against the whole view instead, the farthest
    // cascade's window would hold the near ground too, at a far finer density on screen.
    EXPECT_NE(m->why.find("(cascade 0, the most of the 2)"), std::string::npos) << m->why;
    ASSERT_EQ(render::parse_option(settings, "cascades", "4"), "");
    p = make();
    ASSERT_EQ(render::cascades_of(p).size(), 4u);
    EXPECT_EQ(p.find<render::MapSizeReport>()->size, 1024);
    EXPECT_NE(p.find<render::MapSizeReport>()->why.find("(cascade 0, the most of the 4)"), std::string::npos);
    // A context whose largest target is 2048: two tiles side by side of 1024 each.
    ASSERT_EQ(render::parse_option(settings, "cascades", "2"), "");
    caps.max_texture_size = caps.max_renderbuffer_size = caps.max_viewport_width = caps.max_viewport_height = 2048;
    p = make();
    EXPECT_EQ(p.find<render::MapSizeReport>()->size, 1024);
    EXPECT_EQ(p.resource("shadow-map")->desc.width, 2048);
    // The control: a fixed size is kept, and no match is made.
    settings.map_size = 512;
    p = make();
    EXPECT_EQ(p.resource("shadow-map")->desc.width, 1024);
    EXPECT_EQ(p.find<render::MapSizeReport>(), nullptr);
}

TEST_F(CascadePlan, TheCascadesAovNeedsTheShadowMap) {
    settings.aov = render::Aov::Cascades;
    EXPECT_EQ(render::check(s, settings, caps), "");
    settings.technique = render::Technique::Planar;
    EXPECT_EQ(render::check(s, settings, caps), "--aov cascades: needs --technique shadowmap");
}

}  // namespace
