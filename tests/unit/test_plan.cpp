// Planning frames without a GL context: which passes, resources, states, bindings and variants a
// frame of each technique has, when a resource is reused, and that the printed plan (text and
// JSON) holds all of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan/techniques/reports.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"
#include "shadow/pcf.h"

using namespace penumbra;
using render::FramePlan;

namespace {

using penumbra::testing::full_caps;

const render::FrameInputs kIn = render::offscreen(64, 64);

std::vector<std::string> pass_names(const FramePlan& p) {
    std::vector<std::string> n;
    for (const auto& pass : p.passes) n.push_back(pass.name);
    return n;
}

bool has_define(const render::Draw& d, const std::string& name) {
    for (const auto& def : d.variant.defines)
        if (def.substr(0, def.find(' ')) == name) return true;
    return false;
}

struct PlanTest : ::testing::Test {
    scene::CourseScene course = scene::make_course_scene(4);
    gl::Caps caps = full_caps();
    render::Settings s;
    FramePlan make(const FramePlan* previous = nullptr) { return render::plan(course.scene, s, caps, kIn, previous); }
};

TEST_F(PlanTest, TheShadowMapIsAPassIntoAResourceTheCameraPassReads) {
    s.map_size = 1024;  // fixed: what auto chooses is test_resolution.cpp's
    const FramePlan p = make();
    EXPECT_EQ(pass_names(p), (std::vector<std::string>{"shadow-map", "camera"}));
    const int map = p.resource_index("shadow-map");
    const int camera = p.resource_index("camera");
    ASSERT_GE(map, 0);
    ASSERT_GE(camera, 0);
    const auto& sm = p.passes[0];
    EXPECT_EQ(sm.target.resource, map);
    EXPECT_EQ(sm.target.width, 1024);
    EXPECT_EQ(sm.state.cull, gl::Cull::None) << "open meshes cast from both sides";
    EXPECT_TRUE(sm.state.color_write);
    EXPECT_EQ(sm.object_uniforms, render::ObjectUniforms::Mvp);
    // The teapot casts; the table (a flat quad under the teapot, lit from above) shadows nothing
    // the camera sees, so the shadows fit leaves it out; the course's tight fit draws it.
    ASSERT_EQ(sm.draws.size(), 1u);
    EXPECT_EQ(sm.draws[0].object, course.teapot);
    s.light_fit = render::LightFit::Tight;
    EXPECT_EQ(make().passes[0].draws.size(), 2u);
    s.light_fit = render::LightFit::Shadows;
    EXPECT_EQ(p.resources[static_cast<size_t>(map)].desc.sampling, gl::Sampling::Nearest);
    const auto& cam = p.passes[1];
    EXPECT_EQ(cam.target.resource, camera);
    EXPECT_EQ(cam.reads(), std::vector<int>{map});
    ASSERT_TRUE(cam.clear);
    EXPECT_FALSE(cam.clear->stencil) << "no stencil without planar shadows";
    for (const auto& d : cam.draws) {
        EXPECT_TRUE(has_define(d, "SHADOW_MAP")) << d.label;
        EXPECT_TRUE(has_define(d, "PCF_TAPS")) << d.label;
    }
    // The lookup's uniforms hold the map's size and the bias.
    const auto lookup = std::find_if(cam.bindings.begin(), cam.bindings.end(),
                                     [](const render::Binding& b) { return b.name == "shadow lookup"; });
    ASSERT_NE(lookup, cam.bindings.end());
    for (const auto& u : lookup->uniforms) {
        if (u.name == "u_texmapscale") {
            EXPECT_EQ(std::get<glm::vec2>(u.value), glm::vec2(1.0f / 1024.0f));
        }
        if (u.name == "u_bias") {
            EXPECT_FLOAT_EQ(std::get<float>(u.value), shadow::auto_bias_constant(s.encoding, s.precision));
        }
    }
    ASSERT_TRUE(render::light_frustum_of(p));
    EXPECT_TRUE(render::light_frustum_of(p)->perspective);
}

TEST_F(PlanTest, ADepthTextureMapHasNoColour) {
    s.encoding = shadow::Encoding::DepthTex;
    const FramePlan p = make();
    const auto& d = p.resource("shadow-map")->desc;
    EXPECT_FALSE(d.color);
    EXPECT_TRUE(d.depth_texture);
    EXPECT_FALSE(p.passes[0].state.color_write);
    EXPECT_FALSE(p.passes[0].clear->color);
    caps.depth_texture = false;
    EXPECT_NE(render::check(course.scene, s, caps, kIn).find("OES_depth_texture"), std::string::npos);
}

// A packed map reads its depth from the colour; its depth buffer only keeps the nearest caster,
// in 16 bits even where the context has 24 (the camera's buffer keeps them).
TEST_F(PlanTest, APackedMapKeepsTheNearestCasterInSixteenBitsOfDepth) {
    ASSERT_TRUE(caps.depth24);
    for (const auto e : {shadow::Encoding::RGBA, shadow::Encoding::R8}) {
        s.encoding = e;
        const FramePlan p = make();
        ASSERT_TRUE(p.resource("shadow-map")->desc.depth_buffer);
        EXPECT_EQ(*p.resource("shadow-map")->desc.depth_buffer, gl::RenderbufferFormat::Depth16);
        ASSERT_TRUE(p.resource("camera")->desc.depth_buffer);
        EXPECT_EQ(*p.resource("camera")->desc.depth_buffer, gl::RenderbufferFormat::Depth24);
    }
}

TEST_F(PlanTest, ObjectsThatReceiveNoShadowLookNothingUp) {
    course.scene.objects[static_cast<size_t>(course.teapot)].receives_shadow = false;
    const FramePlan p = make();
    for (const auto& d : p.passes.back().draws)
        EXPECT_EQ(has_define(d, "SHADOW_MAP"), d.object != course.teapot) << d.label;
}

TEST_F(PlanTest, NoCastersNoShadowPass) {
    for (auto& o : course.scene.objects) o.casts_shadow = false;
    const FramePlan p = make();
    EXPECT_EQ(pass_names(p), std::vector<std::string>{"camera"});
    EXPECT_EQ(p.resource("shadow-map"), nullptr);
    ASSERT_FALSE(p.notes.empty());
    EXPECT_NE(p.passes[0].detail.find("no shadows"), std::string::npos);
}

TEST_F(PlanTest, AnUnchangedMapIsReusedAndAMovedOneIsNot) {
    const FramePlan first = make();
    EXPECT_FALSE(first.passes[0].skipped);
    const FramePlan second = make(&first);
    EXPECT_TRUE(second.resource("shadow-map")->reused);
    EXPECT_TRUE(second.passes[0].skipped);
    EXPECT_FALSE(second.drawn("shadow-map"));
    // The camera's side of the settings does not touch the map.
    s.filter = shadow::Filter::PCF4x4;
    s.pcf_kernel = shadow::PcfKernel::Full;
    s.bias = 0.01f;
    EXPECT_TRUE(make(&second).passes[0].skipped);
    // The light, a caster, the encoding or the map size do.
    scene::animate_course(course, 1.0, 0.0);
    const FramePlan moved = make(&second);
    EXPECT_FALSE(moved.passes[0].skipped);
    s.encoding = shadow::Encoding::R8;
    EXPECT_FALSE(make(&moved).passes[0].skipped);
    s.encoding = shadow::Encoding::RGBA;
    s.map_size = 512;
    EXPECT_FALSE(make(&moved).passes[0].skipped);
}

TEST_F(PlanTest, TheMapIsFittedToWhatTheCameraSees) {
    s.light_fit = render::LightFit::Tight;
    const FramePlan p = make();
    ASSERT_TRUE(render::texel_use_of(p));
    EXPECT_GT(*render::texel_use_of(p), 0.5f) << "the tight fit covers most of the map with the table in view";
    EXPECT_NE(p.passes[0].detail.find("texel use"), std::string::npos) << p.passes[0].detail;
    EXPECT_NE(p.to_text().find("texel use"), std::string::npos);
    const auto j = nlohmann::json::parse(p.to_json());
    EXPECT_FLOAT_EQ(static_cast<float>(j["light_frustum"]["texel_use"].get<double>()), *render::texel_use_of(p));
    // The fit follows the camera: another view, another map.
    render::FrameInputs in = kIn;
    in.view = glm::lookAt(glm::vec3(3.0f, 2.0f, 3.0f), glm::vec3(0.5f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const FramePlan other = render::plan(course.scene, s, caps, in, &p);
    EXPECT_FALSE(other.passes[0].skipped);
    EXPECT_NE(render::light_frustum_of(other)->view_proj(), render::light_frustum_of(p)->view_proj());
    // A caster far out of the light's window is not drawn into the map.
    auto& teapot = course.scene.objects[static_cast<size_t>(course.teapot)];
    teapot.world = glm::translate(glm::mat4(1.0f), glm::vec3(40.0f, 0.0f, 0.0f)) * teapot.world;
    const FramePlan away = make();
    ASSERT_EQ(away.passes[0].draws.size(), 1u);
    EXPECT_EQ(away.passes[0].draws[0].object, course.table);
    EXPECT_NE(away.passes[0].detail.find("1 of 2 caster(s)"), std::string::npos) << away.passes[0].detail;
    // With the automatic bias the lookup gets the middle of the (asymmetric) window.
    s.bias_auto = true;
    const FramePlan biased = make();
    const auto& b = biased.passes[1].bindings;
    const auto lookup = std::find_if(b.begin(), b.end(), [](const render::Binding& x) { return x.name == "shadow lookup"; });
    ASSERT_NE(lookup, b.end());
    EXPECT_TRUE(std::any_of(lookup->uniforms.begin(), lookup->uniforms.end(),
                            [](const render::Uniform& u) { return u.name == "u_bias_center"; }));
}

TEST_F(PlanTest, PlanarShadowsTakeTheGroundOutOfTheCameraPass) {
    s.technique = render::Technique::Planar;
    const FramePlan p = make();
    EXPECT_EQ(pass_names(p), (std::vector<std::string>{"camera", "planar-ground", "planar-stencil", "planar-shadow"}));
    EXPECT_TRUE(p.passes[0].clear->stencil);
    ASSERT_TRUE(p.resource("camera")->desc.depth_buffer);
    EXPECT_EQ(*p.resource("camera")->desc.depth_buffer, gl::RenderbufferFormat::Depth24Stencil8);
    for (const auto& d : p.passes[0].draws) EXPECT_NE(d.object, course.scene.ground_object);
    const auto& mark = p.passes[1].state.stencil;
    EXPECT_TRUE(mark.enabled);
    EXPECT_EQ(mark.pass, gl::StencilOp::Replace);
    const auto& project = p.passes[2];
    EXPECT_FALSE(project.state.color_write);
    EXPECT_EQ(project.state.stencil.func, gl::Compare::Equal);
    EXPECT_EQ(project.state.stencil.ref, mark.ref);
    EXPECT_EQ(p.passes[3].state.stencil.ref, mark.ref + 1);
    EXPECT_TRUE(has_define(p.passes[3].draws[0], "IN_SHADOW"));
    // WebGL 1 spells the depth-stencil buffer its own way.
    caps.api = platform::Api::WebGL1;
    EXPECT_EQ(*make().resource("camera")->desc.depth_buffer, gl::RenderbufferFormat::DepthStencil);
    scene::Scene flat = course.scene;
    flat.ground_plane.reset();
    EXPECT_NE(render::check(flat, s, caps, kIn).find("ground plane"), std::string::npos);
}

TEST_F(PlanTest, TheLightDepthViewReplacesTheCameraPass) {
    s.aov = render::Aov::LightDepth;
    const FramePlan p = make();
    EXPECT_EQ(pass_names(p), (std::vector<std::string>{"shadow-map", "light-depth view"}));
    EXPECT_TRUE(p.passes[1].draws[0].fullscreen);
    EXPECT_EQ(p.passes[1].reads(), std::vector<int>{p.resource_index("shadow-map")});
    s.technique = render::Technique::None;
    EXPECT_NE(render::check(course.scene, s, caps, kIn), "");
}

TEST_F(PlanTest, MapSizesAreClampedWithANote) {
    caps.max_texture_size = 512;
    s.map_size = 4096;
    FramePlan p = make();
    EXPECT_EQ(p.resource("shadow-map")->desc.width, 512);
    ASSERT_FALSE(p.notes.empty());
    EXPECT_NE(p.notes[0].find("clamped to 512"), std::string::npos);
    s.map_size = 4;
    p = make();
    EXPECT_EQ(p.resource("shadow-map")->desc.width, 16);
}

TEST_F(PlanTest, InputsOverrideTheViewTheLightAndTheOutput) {
    render::FrameInputs in;
    in.output = render::Output::window_region(10, 20, 30, 40);
    in.view = glm::mat4(2.0f);
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    in.light = sun;
    const FramePlan p = render::plan(course.scene, s, caps, in);
    EXPECT_EQ(p.resource("camera"), nullptr) << "a window needs no offscreen target";
    const auto& t = p.passes.back().target;
    EXPECT_EQ(t.resource, -1);
    EXPECT_EQ(t.x, 10);
    EXPECT_TRUE(t.clip);
    EXPECT_EQ(p.camera.view, glm::mat4(2.0f));
    EXPECT_FALSE(render::light_frustum_of(p)->perspective) << "the input's directional light";
    EXPECT_EQ(course.scene.light.type, scene::LightType::Point) << "the scene is not edited";
}

TEST_F(PlanTest, ThePlanPrintsAsJsonWithEveryPassAndResource) {
    for (auto t : render::kAllTechniques) {
        s.technique = t;
        const FramePlan p = make();
        const auto j = nlohmann::json::parse(p.to_json());
        ASSERT_EQ(j["passes"].size(), p.passes.size()) << render::to_string(t);
        ASSERT_EQ(j["resources"].size(), p.resources.size());
        for (size_t i = 0; i < p.passes.size(); ++i) {
            const auto& jp = j["passes"][i];
            EXPECT_EQ(jp["name"], p.passes[i].name);
            EXPECT_EQ(jp["draws"].size(), p.passes[i].draws.size());
            EXPECT_TRUE(jp["state"].contains("depth_test"));
            EXPECT_EQ(jp["state"]["text"], gl::to_string(p.passes[i].state));
        }
        EXPECT_EQ(j["settings"]["technique"], std::string(render::to_string(t)));
        std::size_t bytes = 0;
        for (const auto& r : j["resources"]) bytes += r["bytes"].get<std::size_t>();
        EXPECT_EQ(j["bytes"].get<std::size_t>(), bytes);
        // One line per pass for -v, and the long form names every pass and resource.
        const std::string lines = p.describe();
        EXPECT_EQ(static_cast<size_t>(std::count(lines.begin(), lines.end(), '\n')), p.passes.size());
        const std::string text = p.to_text();
        for (const auto& pass : p.passes) EXPECT_NE(text.find(pass.name), std::string::npos);
        for (const auto& r : p.resources) EXPECT_NE(text.find(r.desc.name + ": "), std::string::npos);
    }
    s.technique = render::Technique::ShadowMap;
    const auto j = nlohmann::json::parse(make().to_json());
    EXPECT_EQ(j["passes"][0]["target"]["resource"], "shadow-map");
    EXPECT_EQ(j["passes"][1]["reads"][0], "shadow-map");
    EXPECT_FLOAT_EQ(static_cast<float>(j["passes"][1]["bindings"][1]["uniforms"]["u_bias"].get<double>()),
                    shadow::auto_bias_constant(s.encoding, s.precision));
}

TEST(PcfKernel, TheShaderAndTheCpuMirrorShareTheTaps) {
    for (auto f : shadow::kAllFilters) {
        if (f == shadow::Filter::PCSS) {  // its taps are loops in shadow.glsl, sized per fragment
            EXPECT_TRUE(render::pcf_kernel_defines(f).empty());
            continue;
        }
        const auto taps = shadow::pcf_offsets(f);
        const auto defines = render::pcf_kernel_defines(f);
        ASSERT_EQ(defines.size(), 2u);
        EXPECT_EQ(defines[0], "PCF_TAPS " + std::to_string(taps.size()));
        size_t calls = 0;
        for (size_t at = defines[1].find("F(vec2"); at != std::string::npos; at = defines[1].find("F(vec2", at + 1)) ++calls;
        EXPECT_EQ(calls, taps.size()) << defines[1];
        for (const auto& t : taps) {
            char tap[48];
            std::snprintf(tap, sizeof tap, "vec2(%.1f, %.1f)", static_cast<double>(t.x), static_cast<double>(t.y));
            EXPECT_NE(defines[1].find(tap), std::string::npos) << tap;
        }
    }
    // The mirror: a step in the stored depth halfway across the 4x4 kernel lights half the taps
    // (its corners disagree, so the early exit reads them all too).
    const auto step = [](glm::vec2 uv) { return uv.x < 0.5f ? 0.2f : 1.0f; };
    const glm::vec2 texel(1.0f / 64.0f);
    for (auto k : shadow::kAllPcfKernels) {
        EXPECT_FLOAT_EQ(shadow::pcf_visibility(shadow::Filter::PCF4x4, k, glm::vec2(0.5f), 0.6f, 0.001f, texel, step), 0.5f);
        EXPECT_FLOAT_EQ(shadow::pcf_visibility(shadow::Filter::Hard, k, glm::vec2(0.25f), 0.6f, 0.001f, texel, step), 0.0f);
    }
    EXPECT_FLOAT_EQ(shadow::kernel_reach_texels(shadow::Filter::PCF4x4), 2.5f);
}

// The taps named in one generated sum, as "vec2(x, y)" strings.
std::vector<std::string> taps_in(const std::string& define) {
    std::vector<std::string> out;
    for (size_t at = define.find("vec2("); at != std::string::npos; at = define.find("vec2(", at + 1))
        out.push_back(define.substr(at, define.find(')', at) + 1 - at));
    return out;
}

std::string tap_text(glm::vec2 t) {
    char tap[48];
    std::snprintf(tap, sizeof tap, "vec2(%.1f, %.1f)", static_cast<double>(t.x), static_cast<double>(t.y));
    return tap;
}

TEST(PcfKernel, TheEarlyExitSplitsTheSameTapsIntoCornersAndRest) {
    // PCF 4x4: the 16 taps, the 4 at (+-1.5, +-1.5) in PCF_CORNERS and the other 12 in PCF_REST.
    const auto taps = shadow::pcf_offsets(shadow::Filter::PCF4x4);
    const auto d = render::pcf_kernel_defines(shadow::Filter::PCF4x4, shadow::PcfKernel::EarlyExit);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d[0], "PCF_TAPS 16");
    EXPECT_EQ(d[1], "PCF_EARLY_EXIT");
    ASSERT_EQ(d[2].rfind("PCF_CORNERS(F, uv, z, bias) (", 0), 0u) << d[2];
    ASSERT_EQ(d[3].rfind("PCF_REST(F, uv, z, bias) (", 0), 0u) << d[3];
    EXPECT_EQ(taps_in(d[2]), (std::vector<std::string>{"vec2(-1.5, -1.5)", "vec2(1.5, -1.5)", "vec2(-1.5, 1.5)",
                                                       "vec2(1.5, 1.5)"}));
    auto all = taps_in(d[2]);
    const auto rest = taps_in(d[3]);
    EXPECT_EQ(rest.size(), 12u);
    all.insert(all.end(), rest.begin(), rest.end());
    std::vector<std::string> expected;
    for (const auto& t : taps) expected.push_back(tap_text(t));
    std::sort(all.begin(), all.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(all, expected) << "every tap once, in one of the two sums";
    // Hard and PCF 2x2 have no taps besides their corners: the same defines either way.
    for (auto f : {shadow::Filter::Hard, shadow::Filter::PCF2x2}) {
        EXPECT_FALSE(shadow::pcf_early_exit_applies(f));
        EXPECT_EQ(render::pcf_kernel_defines(f, shadow::PcfKernel::EarlyExit),
                  render::pcf_kernel_defines(f, shadow::PcfKernel::Full));
        for (const auto& t : shadow::pcf_offsets(f)) EXPECT_TRUE(shadow::pcf_is_corner(f, t));
    }
    EXPECT_TRUE(shadow::pcf_early_exit_applies(shadow::Filter::PCF4x4));
}

// Every one of the 2^16 lit/shadowed patterns of the 4x4 kernel's taps, through the CPU mirror:
// the early exit equals the full kernel wherever the corners disagree or all 16 taps agree, and
// differs exactly where the corners agree and an inner tap does not (it returns the corners'
// 0 or 1 where the full kernel has a fraction strictly between).
TEST(PcfKernel, TheEarlyExitDiffersOnlyWhereTheCornersAgreeAndAnInnerTapDoesNot) {
    const auto taps = shadow::pcf_offsets(shadow::Filter::PCF4x4);
    ASSERT_EQ(taps.size(), 16u);
    const glm::vec2 uv(0.5f), texel(1.0f / 64.0f);
    const float z = 0.5f, bias = 0.001f;
    unsigned corner_bits = 0;
    for (size_t i = 0; i < taps.size(); ++i)
        if (shadow::pcf_is_corner(shadow::Filter::PCF4x4, taps[i])) corner_bits |= 1u << i;
    ASSERT_EQ(corner_bits, (1u << 0) | (1u << 3) | (1u << 12) | (1u << 15));
    int differ = 0, corners_agree_inner_not = 0;
    for (unsigned lit = 0; lit < (1u << 16); ++lit) {
        // Bit i set: tap i sees a far caster (lit); clear: a near one (shadowed).
        const auto depth = [&](glm::vec2 at) {
            const glm::vec2 o = (at - uv) / texel;
            for (size_t i = 0; i < taps.size(); ++i)
                if (taps[i] == o) return (lit >> i) & 1u ? 1.0f : 0.1f;
            ADD_FAILURE() << "a tap off the kernel: " << o.x << ", " << o.y;
            return 1.0f;
        };
        const float full = shadow::pcf_visibility(shadow::Filter::PCF4x4, shadow::PcfKernel::Full, uv, z, bias, texel, depth);
        const float early =
            shadow::pcf_visibility(shadow::Filter::PCF4x4, shadow::PcfKernel::EarlyExit, uv, z, bias, texel, depth);
        const unsigned corners = lit & corner_bits;
        const bool agree = corners == 0 || corners == corner_bits;
        const bool all_agree = lit == 0 || lit == 0xffffu;
        EXPECT_FLOAT_EQ(full, static_cast<float>(std::bitset<16>(lit).count()) / 16.0f);
        if (!agree || all_agree) {
            EXPECT_EQ(early, full) << std::hex << lit;
        } else {
            ++corners_agree_inner_not;
            EXPECT_EQ(early, corners ? 1.0f : 0.0f) << std::hex << lit;
            EXPECT_GT(full, 0.0f);
            EXPECT_LT(full, 1.0f);
            // At most the 12 inner taps' worth: full lies in [4/16, 15/16] or [1/16, 12/16].
            EXPECT_LE(std::fabs(early - full), 12.0f / 16.0f);
        }
        differ += early != full;
    }
    // Corners all lit or all shadowed, the 12 inner taps anything but all the same: 2 (2^12 - 1).
    EXPECT_EQ(corners_agree_inner_not, 2 * 4095);
    EXPECT_EQ(differ, 2 * 4095);
}

// The auto bias's slope per vertex (lit.vert) only where it is the same over each triangle: the
// table (faceted), not the teapot (smooth normals); one map in the forward pass, not PCSS, the
// cascades or the cube, whose lookups choose their map or reach per fragment.
TEST_F(PlanTest, TheBiasSlopeIsPerVertexOnFacetedReceiversWithOneMap) {
    const auto per_vertex = [&](const FramePlan& p, int object) {
        for (const auto& d : p.passes.back().draws)
            if (d.object == object) return has_define(d, "BIAS_PER_VERTEX");
        ADD_FAILURE() << "object " << object << " not drawn";
        return false;
    };
    FramePlan p = make();
    EXPECT_TRUE(per_vertex(p, course.table));
    EXPECT_FALSE(per_vertex(p, course.teapot));
    s.bias_auto = false;
    s.bias = 0.0015f;
    EXPECT_FALSE(per_vertex(make(), course.table)) << "a constant bias has no slope";
    s.bias_auto = true;
    s.filter = shadow::Filter::PCSS;
    EXPECT_FALSE(per_vertex(make(), course.table));
    s.filter = shadow::Filter::PCF4x4;
    EXPECT_TRUE(per_vertex(make(), course.table));
    s.cascades = render::Settings::kCube;
    EXPECT_FALSE(per_vertex(make(), course.table));
}

TEST_F(PlanTest, PcfKernelChoosesTheLookupsVariant) {
    s.filter = shadow::Filter::PCF4x4;
    const FramePlan early = make();
    for (const auto& d : early.passes.back().draws) {
        if (!has_define(d, "SHADOW_MAP")) continue;
        EXPECT_TRUE(has_define(d, "PCF_EARLY_EXIT")) << d.label;
        EXPECT_TRUE(has_define(d, "PCF_CORNERS(F,")) << d.label;
        EXPECT_FALSE(has_define(d, "PCF_SUM(F,")) << d.label;
    }
    EXPECT_NE(early.passes.back().detail.find("pcf4x4 early-exit"), std::string::npos) << early.passes.back().detail;
    s.pcf_kernel = shadow::PcfKernel::Full;
    const FramePlan full = make();
    for (const auto& d : full.passes.back().draws) {
        if (!has_define(d, "SHADOW_MAP")) continue;
        EXPECT_FALSE(has_define(d, "PCF_EARLY_EXIT")) << d.label;
        EXPECT_TRUE(has_define(d, "PCF_SUM(F,")) << d.label;
    }
    EXPECT_NE(full.passes.back().detail.find("pcf4x4 full"), std::string::npos) << full.passes.back().detail;
    // PCF 2x2 has only corners: its variant is the same under either kernel.
    s.filter = shadow::Filter::PCF2x2;
    const FramePlan two_full = make();
    s.pcf_kernel = shadow::PcfKernel::EarlyExit;
    const FramePlan two_early = make();
    ASSERT_EQ(two_full.passes.back().draws.size(), two_early.passes.back().draws.size());
    for (size_t i = 0; i < two_full.passes.back().draws.size(); ++i)
        EXPECT_EQ(two_full.passes.back().draws[i].variant, two_early.passes.back().draws[i].variant);
    // Every variant either kernel asks for is among those the shader tests compile.
    const auto all = render::all_variants();
    for (const FramePlan* p : {&early, &full})
        for (const auto& d : p->passes.back().draws)
            EXPECT_NE(std::find(all.begin(), all.end(), d.variant), all.end()) << d.variant.key();
}

}  // namespace

TEST_F(PlanTest, StateChangesAreCountedFromThePlan) {
    // First frame: the map pass and the camera pass run; the next frame reuses the map and runs
    // only the camera pass, so it makes fewer GL calls of every kind.
    const FramePlan first = make();
    const render::StateCounts a = first.state_counts();
    EXPECT_EQ(a.passes, 2);
    EXPECT_EQ(a.draws, static_cast<int>(first.passes[0].draws.size() + first.passes[1].draws.size()));
    EXPECT_GE(a.program_switches, 2);  // the depth program, then the lit one(s)
    EXPECT_EQ(a.texture_binds_skipped, 0);
    const render::StateCounts b = make(&first).state_counts();
    EXPECT_EQ(b.passes, 1);
    EXPECT_LT(b.draws, a.draws);
    EXPECT_LT(b.texture_binds, a.texture_binds + 1);
    // Planar shadows draw the table again in a later pass: its marble is still bound there.
    s.technique = render::Technique::Planar;
    const render::StateCounts p = make().state_counts();
    EXPECT_EQ(p.texture_binds_skipped, 1);
    const auto j = nlohmann::json::parse(make().to_json());
    EXPECT_EQ(j["state_changes"]["texture_binds_skipped"], 1);
    EXPECT_EQ(j["state_changes"]["passes"], p.passes);
}
