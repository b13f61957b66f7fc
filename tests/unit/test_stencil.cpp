// The stencil as data of the plan: each module declares its uses, the plan gives them bits that
// never overlap (or refuses, naming the uses), and every pass's stencil state stays inside its
// use's bits. The outline effect's passes. No GL context.
#include <algorithm>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "full_caps.h"
#include "plan/frames/area_light.h"
#include "plan/techniques/reports.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"

using namespace penumbra;
using render::FramePlan;
using render::StencilUse;

namespace {

using penumbra::testing::full_caps;

const render::FrameInputs kIn = render::offscreen(64, 64);

StencilUse use(const char* name, int bits, bool counts) {
    StencilUse u;
    u.name = name;
    u.bits = bits;
    u.counts = counts;
    return u;
}

// Every stencil state of the plan's passes: the bits it may read, write, and compare with.
struct Touch {
    std::string pass;
    std::uint32_t read = 0, write = 0;
    int ref = 0;
};
std::vector<Touch> stencil_touches(const FramePlan& p) {
    std::vector<Touch> out;
    for (const auto& pass : p.passes)
        if (pass.state.stencil.enabled)
            out.push_back({pass.name, pass.state.stencil.read_mask, pass.state.stencil.write_mask, pass.state.stencil.ref});
    return out;
}

// The plan's pass of that name (std::runtime_error when it has none), and every pass's name in order.
const render::Pass& pass_named(const FramePlan& p, const char* name) {
    for (const auto& pass : p.passes)
        if (pass.name == name) return pass;
    throw std::runtime_error(std::string("no pass ") + name);
}
std::vector<std::string> pass_names(const FramePlan& p) {
    std::vector<std::string> names;
    for (const auto& pass : p.passes) names.push_back(pass.name);
    return names;
}

struct StencilPlan : ::testing::Test {
    scene::CourseScene course = scene::make_course_scene(4);
    gl::Caps caps = full_caps();
    render::Settings s;
    FramePlan make() { return render::plan(course.scene, s, caps, kIn); }
    std::string check() { return render::check(course.scene, s, caps, kIn); }
};

TEST(StencilAllocation, TheCounterTakesTheLowBitsAndTheRestGoesFromTheTop) {
    std::vector<StencilUse> uses = {use("a: counts", 2, true), use("b: marks", 1, false), use("c: marks", 2, false)};
    ASSERT_EQ(render::allocate_stencil(uses, 8), "");
    EXPECT_EQ(uses[0].shift, 0);
    EXPECT_EQ(uses[0].width, 5);  // every bit the others leave
    EXPECT_EQ(uses[0].mask(), 0x1Fu);
    EXPECT_EQ(uses[1].mask(), 0x80u);
    EXPECT_EQ(uses[2].mask(), 0x60u);
    EXPECT_EQ(uses[2].ref(1), 0x20);
    EXPECT_EQ(uses[2].ref(3), 0x60);
    EXPECT_EQ(uses[0].top_bit(), 0x10u);
    EXPECT_EQ(uses[0].mask() & uses[1].mask(), 0u);
    EXPECT_EQ((uses[0].mask() | uses[1].mask()) & uses[2].mask(), 0u);
    // A use alone that counts has the whole stencil: the states of a frame without effects.
    std::vector<StencilUse> alone = {use("a: counts", 2, true)};
    ASSERT_EQ(render::allocate_stencil(alone, 8), "");
    EXPECT_EQ(alone[0].mask(), 0xFFu);
    const gl::StencilState t = alone[0].test(gl::Compare::Equal, 1, gl::StencilOp::Incr);
    EXPECT_EQ(t, gl::stencil_test(gl::Compare::Equal, 1, gl::StencilOp::Incr));
    EXPECT_EQ(alone[0].count(true), gl::stencil_count(true));
}

TEST(StencilAllocation, RefusesTooManyBitsNamingBothUses) {
    std::vector<StencilUse> uses = {use("volumes: shadow count", 4, true), use("outline: the model's pixels", 1, false)};
    const std::string why = render::allocate_stencil(uses, 4);
    EXPECT_NE(why.find("volumes: shadow count"), std::string::npos) << why;
    EXPECT_NE(why.find("outline: the model's pixels"), std::string::npos) << why;
    EXPECT_NE(why.find("5 bits"), std::string::npos) << why;
    EXPECT_EQ(why.find('\n'), std::string::npos);
    std::vector<StencilUse> two = {use("x: counts", 1, true), use("y: counts", 1, true)};
    const std::string both = render::allocate_stencil(two, 8);
    EXPECT_NE(both.find("'x: counts' and 'y: counts'"), std::string::npos) << both;
}

TEST_F(StencilPlan, PlanarAndOutlineGetDisjointBitsAndEveryPassKeepsToItsOwn) {
    s.technique = render::Technique::Planar;
    s.effects = {render::Effect::Outline};
    ASSERT_EQ(check(), "");
    const FramePlan p = make();
    ASSERT_EQ(p.stencil.size(), 2u);
    const StencilUse* planar = p.stencil_use("planar: shadowed ground");
    const StencilUse* outline = p.stencil_use("outline: the model's pixels");
    ASSERT_NE(planar, nullptr);
    ASSERT_NE(outline, nullptr);
    EXPECT_EQ(planar->mask() & outline->mask(), 0u);
    EXPECT_EQ(planar->shift, 0);  // it counts (1 -> 2 by incr)
    EXPECT_EQ(outline->mask(), 0x80u);
    for (const Touch& t : stencil_touches(p)) {
        const StencilUse* own = t.pass.rfind("outline", 0) == 0 ? outline : planar;
        EXPECT_EQ(t.read & ~own->mask(), 0u) << t.pass;
        EXPECT_EQ(t.write & ~own->mask(), 0u) << t.pass;
        EXPECT_EQ(static_cast<std::uint32_t>(t.ref) & ~own->mask(), 0u) << t.pass;
    }
    // The outline's passes come after the technique's, on the camera's target, which has a stencil.
    ASSERT_GE(p.passes.size(), 2u);
    EXPECT_EQ(p.passes[p.passes.size() - 2].name, "outline-mark");
    EXPECT_EQ(p.passes.back().name, "outline-draw");
    EXPECT_EQ(p.passes.back().state.stencil.func, gl::Compare::NotEqual);
    EXPECT_EQ(p.passes.back().state.stencil.write_mask & outline->mask(), outline->mask());
    EXPECT_EQ(p.passes.back().state.stencil.pass, gl::StencilOp::Keep);
}

TEST_F(StencilPlan, VolumesAndOutlineGetDisjointBitsAndTheCountKeepsTheRest) {
    s.technique = render::Technique::Volumes;
    s.effects = {render::Effect::Outline};
    s.aov = render::Aov::Color;
    ASSERT_EQ(check(), "");
    const FramePlan p = make();
    const StencilUse* volumes = p.stencil_use("volumes: shadow count");
    const StencilUse* outline = p.stencil_use("outline: the model's pixels");
    ASSERT_NE(volumes, nullptr);
    ASSERT_NE(outline, nullptr);
    EXPECT_EQ(volumes->mask(), 0x7Fu);
    EXPECT_EQ(outline->mask(), 0x80u);
    for (const Touch& t : stencil_touches(p)) {
        const StencilUse* own = t.pass.rfind("outline", 0) == 0 ? outline : volumes;
        EXPECT_EQ(t.write & ~own->mask(), 0u) << t.pass;
        EXPECT_EQ(t.read & ~own->mask(), 0u) << t.pass;
    }
}

TEST_F(StencilPlan, WithoutEffectsTheStatesAreTheWholeStencilAsBefore) {
    s.technique = render::Technique::Volumes;
    const FramePlan p = make();
    ASSERT_EQ(p.stencil.size(), 1u);
    EXPECT_EQ(p.stencil[0].mask(), 0xFFu);
    for (const Touch& t : stencil_touches(p)) {
        EXPECT_EQ(t.write, 0xFFu) << t.pass;
        EXPECT_EQ(t.read, 0xFFu) << t.pass;
    }
    s.technique = render::Technique::ShadowMap;
    EXPECT_TRUE(make().stencil.empty());
    EXPECT_FALSE(make().passes.back().clear->stencil);
}

TEST_F(StencilPlan, TheCountViewsNegativeBitIsTheCountsTopBit) {
    s.technique = render::Technique::Volumes;
    s.aov = render::Aov::StencilCount;
    const FramePlan alone = make();
    bool seen = false;
    for (const auto& pass : alone.passes) {
        if (pass.name == "volumes-count-negative") {
            seen = true;
            EXPECT_EQ(pass.state.stencil.read_mask, 0x80u);
            EXPECT_EQ(pass.state.stencil.ref, 0x80);
        }
    }
    EXPECT_TRUE(seen);
}

TEST_F(StencilPlan, APlanNeedingMoreBitsThanTheTargetHasIsRefusedNamingBoth) {
    s.technique = render::Technique::Volumes;
    s.effects = {render::Effect::Outline};
    caps.stencil_bits = 4;
    const std::string why = check();
    EXPECT_NE(why.find("volumes: shadow count"), std::string::npos) << why;
    EXPECT_NE(why.find("outline: the model's pixels"), std::string::npos) << why;
    caps.stencil_bits = 5;
    EXPECT_EQ(check(), "");
    // Gooch's 16 planes count to 17: 5 bits, and the outline's one.
    s.technique = render::Technique::Gooch;
    s.gooch_planes = 16;
    s.light_radius = 0.3f;
    const std::string gooch = check();
    EXPECT_NE(gooch.find("gooch: planes lighting the ground"), std::string::npos) << gooch;
    EXPECT_NE(gooch.find("outline: the model's pixels"), std::string::npos) << gooch;
    caps.stencil_bits = 8;
    EXPECT_EQ(check(), "");
}

TEST_F(StencilPlan, OutlineWorksBesideEveryTechnique) {
    s.effects = {render::Effect::Outline};
    for (render::Technique t : render::kAllTechniques) {
        s.technique = t;
        ASSERT_EQ(check(), "") << render::to_string(t);
        const FramePlan p = make();
        ASSERT_TRUE(p.has_pass("outline-draw")) << render::to_string(t);
        EXPECT_EQ(p.passes.back().name, "outline-draw");
        // The camera pass clears the stencil the outline marks.
        for (const auto& pass : p.passes) {
            if (pass.name == "camera") {
                EXPECT_TRUE(pass.clear && pass.clear->stencil) << render::to_string(t);
            }
        }
        const auto& camera = p.resource("camera")->desc;
        EXPECT_EQ(camera.depth_buffer, caps.depth_stencil_format()) << render::to_string(t);
        // Only the teapot is outlined, not the table.
        const auto& draw = p.passes.back().draws;
        ASSERT_EQ(draw.size(), 1u);
        EXPECT_NE(draw[0].object, course.scene.ground_object);
    }
    // Soft shadows (light samples) too: the outline after the last camera pass.
    s.technique = render::Technique::ShadowMap;
    s.area_samples = 4;
    s.light_radius = 0.3f;
    const FramePlan area = make();
    ASSERT_TRUE((render::area_of(area) != nullptr));
    EXPECT_EQ(area.passes.back().name, "outline-draw");
    // Not on an AOV: a note instead.
    s.area_samples = 1;
    s.aov = render::Aov::Visibility;
    const FramePlan vis = make();
    EXPECT_FALSE(vis.has_pass("outline-draw"));
    EXPECT_TRUE(vis.stencil.empty());
    ASSERT_FALSE(vis.notes.empty());
}

TEST_F(StencilPlan, ThePrintedPlanListsTheUses) {
    s.technique = render::Technique::Planar;
    s.effects = {render::Effect::Outline};
    const FramePlan p = make();
    const std::string text = p.to_text();
    EXPECT_NE(text.find("stencil uses (8 bits):"), std::string::npos) << text;
    EXPECT_NE(text.find("planar: shadowed ground (planar): bits 0-6 (mask 7f)"), std::string::npos) << text;
    EXPECT_NE(text.find("outline: the model's pixels (outline): bit 7 (mask 80)"), std::string::npos) << text;
    const auto j = nlohmann::json::parse(p.to_json());
    ASSERT_EQ(j["stencil"].size(), 2u);
    EXPECT_EQ(j["stencil_bits"], 8);
    EXPECT_EQ(j["stencil"][1]["name"], "outline: the model's pixels");
    EXPECT_EQ(j["stencil"][1]["read_mask"], 128);
    EXPECT_EQ(j["stencil"][1]["ref_of_1"], 128);
    EXPECT_EQ(j["stencil"][0]["write_mask"], 127);
}

// The mirror's passes after the technique's and before the translucent pass and the outline, all
// inside the mirror's bit; the reflected draws are every object but the table, through the
// reflected camera, culling front faces, clipped by the table's plane turned towards the camera.
TEST_F(StencilPlan, TheMirrorsPassesKeepToItsBitAndReflectEveryObjectButTheTable) {
    s.technique = render::Technique::Planar;
    s.effects = {render::Effect::Outline, render::Effect::Mirror};
    ASSERT_EQ(check(), "");
    const FramePlan p = make();
    const StencilUse* mirror = p.stencil_use("mirror: the mirror's pixels");
    const StencilUse* outline = p.stencil_use("outline: the model's pixels");
    const StencilUse* planar = p.stencil_use("planar: shadowed ground");
    ASSERT_TRUE(mirror && outline && planar);
    EXPECT_EQ(mirror->mask() & (outline->mask() | planar->mask()), 0u);
    const std::vector<std::string> names = pass_names(p);
    const std::vector<std::string> want = {"mirror-mark", "mirror-far", "mirror-depth", "mirror-sky", "mirror-reflect",
                                           "mirror-restore", "outline-mark", "outline-draw"};
    ASSERT_GE(names.size(), want.size());
    EXPECT_EQ(std::vector<std::string>(names.end() - static_cast<long>(want.size()), names.end()), want);
    for (const auto& pass : p.passes) {
        if (pass.module != "mirror") continue;
        EXPECT_EQ(pass.state.stencil.read_mask, mirror->mask()) << pass.name;
        EXPECT_EQ(pass.state.stencil.write_mask, mirror->mask()) << pass.name;
        if (pass.name != "mirror-mark") {
            EXPECT_EQ(pass.state.stencil.func, gl::Compare::Equal) << pass.name;
        }
    }
    const auto find = [&](const char* name) -> const render::Pass& { return pass_named(p, name); };
    const render::Pass& reflect = find("mirror-reflect");
    EXPECT_EQ(reflect.state.blend, gl::Blend::Over);
    EXPECT_EQ(reflect.state.depth_func, gl::Compare::Equal);
    ASSERT_EQ(reflect.draws.size(), 1u);
    EXPECT_EQ(reflect.draws[0].object, course.teapot);
    EXPECT_EQ(reflect.draws[0].cull, gl::Cull::Front);
    EXPECT_NE(reflect.draws[0].variant.key().find("REFLECTED"), std::string::npos);
    // The camera above the table (y = 0, normal +y): the clip plane is the table's, the view-
    // projection the camera's times the reflection y -> -y.
    for (const auto& b : reflect.bindings)
        for (const auto& u : b.uniforms) {
            if (u.name == "u_clip_plane") {
                EXPECT_EQ(std::get<glm::vec4>(u.value), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
            }
            if (u.name == "u_view_proj") {
                const glm::mat4 flip = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f));
                const glm::mat4 want_vp = p.camera.view_proj * flip;
                const glm::mat4 got = std::get<glm::mat4>(u.value);
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j) EXPECT_NEAR(got[i][j], want_vp[i][j], 1e-5f);
            }
        }
    EXPECT_FALSE(find("mirror-depth").state.color_write);
    EXPECT_EQ(find("mirror-far").state.depth_func, gl::Compare::Always);
    EXPECT_TRUE(find("mirror-restore").state.depth_write);
    // Volumes: the reflection unshadowed, with a note; a scene with no ground is refused.
    s.technique = render::Technique::Volumes;
    const FramePlan v = make();
    EXPECT_TRUE(std::any_of(v.notes.begin(), v.notes.end(),
                            [](const std::string& n) { return n.find("without shadows") != std::string::npos; }));
    course.scene.ground_plane.reset();
    EXPECT_NE(check().find("no ground plane"), std::string::npos);
}

// The portal's passes after the mirror's and before the outline's, in its own bit; the other
// scene's shadow map a resource of its own ("portal shadow-map") beside this scene's, whose light
// frustum stays the plan's; its objects drawn clipped at the opening. Gooch's five bits and the
// three effects' three are more than seven: refused, naming the uses. A scene without a portal
// (a glTF scene) is refused with the reason.
TEST_F(StencilPlan, ThePortalKeepsToItsBitAndDrawsTheOtherSceneWithItsOwnMap) {
    s.effects = {render::Effect::Outline, render::Effect::Mirror};
    const FramePlan before = make();
    s.effects.push_back(render::Effect::Portal);
    ASSERT_EQ(check(), "");
    const FramePlan p = make();
    const StencilUse* portal = p.stencil_use("portal: the opening's pixels");
    const StencilUse* mirror = p.stencil_use("mirror: the mirror's pixels");
    const StencilUse* outline = p.stencil_use("outline: the model's pixels");
    ASSERT_TRUE(portal && mirror && outline);
    EXPECT_EQ(portal->mask() & (mirror->mask() | outline->mask()), 0u);
    const std::vector<std::string> names = pass_names(p);
    const std::vector<std::string> want = {"mirror-restore", "portal-frame", "portal-mark", "portal-far",
                                           "portal shadow-map", "portal-scene", "portal-restore", "outline-mark",
                                           "outline-draw"};
    ASSERT_GE(names.size(), want.size());
    EXPECT_EQ(std::vector<std::string>(names.end() - static_cast<long>(want.size()), names.end()), want);
    const auto find = [&](const char* name) -> const render::Pass& { return pass_named(p, name); };
    for (const char* name : {"portal-far", "portal-scene", "portal-restore"})
        EXPECT_EQ(find(name).state.stencil.read_mask, portal->mask()) << name;
    EXPECT_EQ(find("portal-mark").state.stencil.write_mask, portal->mask());
    EXPECT_FALSE(find("portal-mark").state.depth_write);
    const render::Pass& other = find("portal-scene");
    ASSERT_EQ(other.draws.size(), course.scene.portal->beyond->objects.size());
    for (const auto& d : other.draws) {
        EXPECT_TRUE(d.beyond);
        EXPECT_NE(std::find(d.variant.defines.begin(), d.variant.defines.end(), "CLIPPED"), d.variant.defines.end());
    }
    ASSERT_EQ(other.reads().size(), 1u);
    EXPECT_EQ(p.resources[static_cast<size_t>(other.reads()[0])].desc.name, "portal shadow-map");
    ASSERT_TRUE(render::light_frustum_of(p) && render::light_frustum_of(before));
    EXPECT_EQ(render::light_frustum_of(p)->view_proj(), render::light_frustum_of(before)->view_proj()) << "this scene's light stays the plan's";
    // Gooch's 16 planes count in 5 bits: with three effects' bits that is one more than 7.
    s.technique = render::Technique::Gooch;
    s.gooch_planes = 16;
    s.light_radius = 0.3f;
    caps.stencil_bits = 7;
    const std::string refused = check();
    EXPECT_NE(refused.find("portal: the opening's pixels"), std::string::npos) << refused;
    EXPECT_NE(refused.find("gooch: planes lighting the ground"), std::string::npos) << refused;
    s.effects.pop_back();
    EXPECT_EQ(check(), "") << "without the portal the uses fit";
    s.effects.push_back(render::Effect::Portal);
    caps.stencil_bits = 8;
    s.technique = render::Technique::ShadowMap;
    course.scene.portal.reset();
    EXPECT_NE(check().find("the scene has no portal"), std::string::npos) << check();
}

TEST(EffectOptions, ParseCheckAndPrint) {
    render::Options o;
    EXPECT_EQ(render::parse_option(o, "effects", "outline"), "");
    EXPECT_TRUE(o.settings.has(render::Effect::Outline));
    EXPECT_EQ(render::parse_option(o, "effects", "none"), "");
    EXPECT_TRUE(o.settings.effects.empty());
    EXPECT_NE(render::parse_option(o, "effects", "window"), "");
    EXPECT_EQ(render::parse_option(o, "effects", "mirror,outline"), "");
    ASSERT_EQ(o.settings.effects.size(), 2u);
    EXPECT_EQ(o.settings.effects[0], render::Effect::Outline);  // kAllEffects' order
    for (const char* bad : {"-0.1", "1.01", "shiny", "nan"})
        EXPECT_NE(render::parse_option(o, "reflectivity", bad), "") << bad;
    EXPECT_EQ(render::parse_option(o, "reflectivity", "0.75"), "");
    EXPECT_FLOAT_EQ(o.settings.reflectivity, 0.75f);
    EXPECT_NE(render::parse_option(o, "effects", "outline,outline").find("twice"), std::string::npos);
    EXPECT_NE(render::parse_option(o, "effects", "outline,none"), "");
    EXPECT_NE(render::parse_option(o, "effects", ""), "");
    EXPECT_EQ(render::parse_option(o, "outline-color", "ff0080"), "");
    EXPECT_FLOAT_EQ(o.settings.outline_color.r, 1.0f);
    EXPECT_FLOAT_EQ(o.settings.outline_color.g, 0.0f);
    EXPECT_FLOAT_EQ(o.settings.outline_color.b, 128.0f / 255.0f);
    for (const char* bad : {"#ff0080", "ff008", "ff00800", "gg0000", "1,0,0", ""})
        EXPECT_NE(render::parse_option(o, "outline-color", bad), "") << bad;
    EXPECT_EQ(render::parse_option(o, "outline-width", "0.5"), "");
    EXPECT_EQ(render::parse_option(o, "outline-width", "32"), "");
    for (const char* bad : {"0.4", "33", "0", "-1", "wide", "nan"})
        EXPECT_NE(render::parse_option(o, "outline-width", bad), "") << bad;
    EXPECT_EQ(render::parse_option(o, "outline-width", "2.5"), "");
    EXPECT_EQ(render::parse_option(o, "effects", "outline"), "");
    // What to_pairs prints reads back as the same settings.
    render::Options back;
    for (const auto& [k, v] : render::to_pairs(o)) ASSERT_EQ(render::parse_option(back, k, v), "") << k << " " << v;
    EXPECT_EQ(back, o);
    const auto pairs = render::to_pairs(o);
    EXPECT_NE(std::find(pairs.begin(), pairs.end(), std::pair<std::string, std::string>{"reflectivity", "0.75"}), pairs.end());
    EXPECT_NE(std::find(pairs.begin(), pairs.end(), std::pair<std::string, std::string>{"outline-color", "ff0080"}), pairs.end());
    EXPECT_NE(std::find(pairs.begin(), pairs.end(), std::pair<std::string, std::string>{"outline-width", "2.5"}), pairs.end());
}

}  // namespace
