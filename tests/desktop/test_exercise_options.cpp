// The exercise apps' options without a GL context: what the URL, the controls and the desktop keys
// set, read back through the same names (the pages restore a reload from query()).
#include <gtest/gtest.h>

#include <algorithm>

#include "exercises.h"
#include "platform/platform.h"
#include "scenes/course_scene.h"
#include "scenes/terrain_scene.h"

using penumbra::examples::CourseApp;
using penumbra::examples::Exercise;
using penumbra::examples::exercise_list;

TEST(ExerciseOptions, DefaultsOfEachPage) {
    EXPECT_EQ(CourseApp("w09p1").query(), "light=on&jump=on");
    EXPECT_EQ(CourseApp("w09p2a").query(), "light=on&jump=on&projection=persp");
    EXPECT_EQ(CourseApp("w09p2b").query(), "light=on&jump=on&fbo-view=light&rtt=fbo&map-size=1024");
    EXPECT_EQ(CourseApp("w09p2c").query(),
              "light=on&jump=on&budget-ms=0&max-error=0&encoding=rgba&filter=hard&bias=auto&map-faces=auto&precision=highp&map-size=1024&"
              "aov=color&map-view=on");
    EXPECT_EQ(CourseApp("volumes").query(),
              "light=on&jump=on&volume-method=auto&show-volumes=off&eye=scene&aov=color");
    // The soft exercise starts still (a frame can converge), with a light of radius 0.3 and PCSS.
    EXPECT_EQ(CourseApp("soft").query(),
              "light=off&jump=off&light-radius=0.3&filter=pcss&area-samples=1&area-per-frame=4&area-interleave=1&reference=off&"
              "pcss-search=16&pcss-taps=16&pcss-blockers=layered&technique=shadowmap&aov=color");
    // The stencil exercise starts with the outline on.
    EXPECT_EQ(CourseApp("stencil").query(),
              "light=on&jump=on&effects=outline&outline-width=3&outline-color=ff8c00&reflectivity=0.5&technique=shadowmap");
    // The cascades exercise starts with four cascades, tinted.
    EXPECT_EQ(CourseApp("cascades").query(),
              "cascades=4&cascade-split=0.95&cascade-snap=on&cascade-blend=0.1&map-size=1024&aov=cascades");
    // The bulb exercise with the cube's faces tinted, 512 texels a face, a bulb of 5 cm.
    EXPECT_EQ(CourseApp("bulb").query(), "cascades=cube&map-size=512&cube-layout=atlas&filter=hard&light-radius=0.05&aov=cascades");
}

TEST(ExerciseOptions, EveryChangeReadsBack) {
    const std::vector<std::pair<std::string, std::string>> changes = {
        {"light", "off"}, {"jump", "off"},   {"projection", "ortho"}, {"fbo-view", "camera"}, {"rtt", "copy"}, {"map-view", "off"},
        {"encoding", "r8"}, {"filter", "pcf4x4"}, {"bias", "0.003"},   {"map-size", "2048"},     {"aov", "visibility"},
        {"precision", "mediump"}, {"volume-method", "zfail"}, {"show-volumes", "on"}, {"eye", "in-shadow"},
        {"light-radius", "0.45"}, {"pcss-search", "32"}, {"pcss-taps", "8"}, {"pcss-blockers", "mean"}, {"area-samples", "64"},
        {"area-per-frame", "0"}, {"area-interleave", "2"}, {"reference", "on"}};
    for (const auto& x : exercise_list()) {
        const std::string_view e = x.name;
        CourseApp a(e);
        for (const auto& [k, v] : changes) ASSERT_EQ(a.set_option(k, v), "") << k;
        CourseApp b(e);
        for (const auto& [k, v] : a.options()) ASSERT_EQ(b.set_option(k, v), "") << k << "=" << v;
        EXPECT_EQ(a.query(), b.query());
        EXPECT_EQ(a.settings(), b.settings());
        EXPECT_TRUE(b.eye_in_shadow()) << x.name << ": " << a.query();
    }
    CourseApp c("w09p2c");
    ASSERT_EQ(c.set_option("bias", "0.003"), "");
    EXPECT_NE(c.query().find("bias=0.003&"), std::string::npos) << c.query();  // not 0.0030000000260770321
}

TEST(ExerciseOptions, BiasAutoAndPrecisionReadBack) {
    CourseApp a("w09p2c");
    ASSERT_EQ(a.set_option("bias", "auto"), "");
    ASSERT_EQ(a.set_option("precision", "mediump"), "");
    EXPECT_NE(a.query().find("bias=auto&map-faces=auto&precision=mediump&"), std::string::npos) << a.query();
    EXPECT_TRUE(a.settings().bias_auto);
    EXPECT_EQ(a.settings().precision, penumbra::shadow::Precision::Mediump);
    CourseApp b("w09p2c");
    for (const auto& [k, v] : a.options()) ASSERT_EQ(b.set_option(k, v), "") << k << "=" << v;
    EXPECT_EQ(a.settings(), b.settings());
    EXPECT_EQ(a.query(), b.query());
    // auto's constant part: the encoding's quantum for the precision (the slope term is per fragment).
    EXPECT_FLOAT_EQ(a.bias(), penumbra::shadow::auto_bias_constant(penumbra::shadow::Encoding::RGBA,
                                                                   penumbra::shadow::Precision::Mediump));
    // A fixed value leaves auto; the sheet's constant leaves it too.
    ASSERT_EQ(a.set_option("bias", "0.002"), "");
    EXPECT_FALSE(a.settings().bias_auto);
    EXPECT_NE(a.query().find("bias=0.002&"), std::string::npos) << a.query();
    ASSERT_EQ(a.set_option("bias", "auto"), "");
    ASSERT_EQ(a.set_option("bias", "sheet"), "");
    EXPECT_FALSE(a.settings().bias_auto);
    EXPECT_FALSE(a.settings().bias.has_value());
    // Other pages keep a changed precision in their URL too, though they show no control for it.
    CourseApp c("w09p1");
    ASSERT_EQ(c.set_option("precision", "mediump"), "");
    EXPECT_NE(c.query().find("precision=mediump"), std::string::npos) << c.query();
    EXPECT_EQ(CourseApp("w09p1").query().find("precision"), std::string::npos);
    EXPECT_NE(a.set_option("precision", "lowp"), "");
    EXPECT_NE(a.set_option("bias", "automatic"), "");
}

TEST(ExerciseOptions, SettingsOutsideThePageSurviveTheQuery) {
    CourseApp a("w09p1");
    ASSERT_EQ(a.set_option("encoding", "r8"), "");  // not shown on W09P1, but kept
    EXPECT_NE(a.query().find("encoding=r8"), std::string::npos) << a.query();
}

TEST(ExerciseOptions, ThePcfKernelIsReachableByUrlOnTheShadowMapPage) {
    // No control on W09P2c: the course's full kernel is one URL parameter away, and kept there.
    CourseApp a("w09p2c");
    EXPECT_EQ(a.settings().pcf_kernel, penumbra::shadow::PcfKernel::EarlyExit);
    EXPECT_EQ(a.query().find("pcf-kernel"), std::string::npos) << "the default is not written: " << a.query();
    ASSERT_EQ(a.set_option("pcf-kernel", "full"), "");
    EXPECT_EQ(a.settings().pcf_kernel, penumbra::shadow::PcfKernel::Full);
    EXPECT_NE(a.query().find("pcf-kernel=full"), std::string::npos) << a.query();
    EXPECT_NE(a.set_option("pcf-kernel", "fast"), "");
}

TEST(ExerciseOptions, BadValuesChangeNothing) {
    CourseApp a("w09p2c");
    const std::string before = a.query();
    EXPECT_NE(a.set_option("encoding", "r16"), "");
    EXPECT_NE(a.set_option("light", "maybe"), "");
    EXPECT_NE(a.set_option("projection", "fisheye"), "");
    EXPECT_NE(a.set_option("map-size", "-4"), "");
    EXPECT_NE(a.set_option("technique", "planar"), "");  // the exercise decides
    EXPECT_NE(a.set_option("scene", "x.gltf"), "");
    EXPECT_NE(a.set_option("nonsense", "1"), "");
    EXPECT_EQ(a.query(), before);
    EXPECT_EQ(a.set_option("encoding", "r16").rfind("encoding: ", 0), 0u) << "no leading -- in a URL's message";
}

// A URL's key without its value (`?encoding=`, `?light`) is named with what it takes, for the
// table's options, the page's toggles, the clock and the camera; nothing changes.
TEST(ExerciseOptions, AKeyWithoutItsValueIsNamed) {
    CourseApp a("w09p2c");
    const std::string before = a.query();
    for (const char* name : {"encoding", "filter", "bias", "map-size", "light", "jump", "time", "eye", "aov"}) {
        const std::string err = a.set_option(name, "");
        EXPECT_EQ(err.rfind(std::string(name) + ": needs a value: ", 0), 0u) << err;
    }
    EXPECT_EQ(a.query(), before);
    CourseApp flying("cascades");
    EXPECT_EQ(flying.set_option("camera", ""), "camera: needs a value: X,Y,Z,YAW,PITCH (metres, degrees)");
    // The control: a bad value is not called a missing one.
    EXPECT_EQ(a.set_option("encoding", "r16").find("needs a value"), std::string::npos);
}

// The eye is a job option the exercises take (like time): shown on the volumes page, kept in the
// URL of the others once moved into the shadow, refused when misspelt.
TEST(ExerciseOptions, TheEyeMovesIntoTheShadowAndIsKept) {
    CourseApp a("volumes");
    EXPECT_FALSE(a.eye_in_shadow());
    ASSERT_EQ(a.set_option("eye", "in-shadow"), "");
    EXPECT_TRUE(a.eye_in_shadow());
    EXPECT_NE(a.query().find("eye=in-shadow"), std::string::npos) << a.query();
    ASSERT_EQ(a.set_option("eye", "scene"), "");
    EXPECT_NE(a.query().find("eye=scene"), std::string::npos) << a.query();
    EXPECT_EQ(a.set_option("eye", "inside").rfind("eye: ", 0), 0u) << a.set_option("eye", "inside");
    EXPECT_FALSE(a.eye_in_shadow());
    CourseApp b("w09p1");
    EXPECT_EQ(b.query().find("eye"), std::string::npos) << "the default is not written: " << b.query();
    ASSERT_EQ(b.set_option("eye", "in-shadow"), "");
    EXPECT_NE(b.query().find("eye=in-shadow"), std::string::npos) << b.query();
    EXPECT_NE(b.set_option("out", "x.png"), "");  // the other job options stay the exercise's
    EXPECT_NE(b.set_option("frames", "3"), "");
}

TEST(ExerciseOptions, VolumeKeys) {
    CourseApp a("w09p1");
    EXPECT_EQ(a.on_key('5', false).rfind("Shadow volumes", 0), 0u);
    EXPECT_EQ(a.exercise().name, "volumes");
    EXPECT_EQ(a.on_key('Z', false), "volume-method = zpass");
    EXPECT_EQ(a.on_key('Z', false), "volume-method = zfail");
    EXPECT_EQ(a.on_key('Z', false), "volume-method = auto");
    EXPECT_EQ(a.on_key('Z', true), "volume-method = zfail");
    EXPECT_EQ(a.settings().volume_method, penumbra::render::VolumeMethod::ZFail);
    EXPECT_EQ(a.on_key('G', false), "show-volumes = on");
    EXPECT_TRUE(a.settings().show_volumes);
    EXPECT_EQ(a.on_key('I', false), "eye = in-shadow");
    EXPECT_TRUE(a.eye_in_shadow());
    EXPECT_EQ(a.on_key('I', false), "eye = scene");
    // The volumes page's view offers the stencil count too.
    EXPECT_EQ(a.on_key('A', false), "aov = visibility");
    EXPECT_EQ(a.on_key('A', false), "aov = stencil-count");
    EXPECT_EQ(a.on_key('A', false), "aov = color");
    const std::string help = CourseApp::key_help();
    for (const char* k : {"  5  ", "  Z  ", "  G  ", "  I  "}) EXPECT_NE(help.find(k), std::string::npos) << k << help;
}

// The soft exercise: its own defaults (set when chosen, put back when another is), the technique
// as a control of its own, the methods excluding each other, the reference, and its keys.
TEST(ExerciseOptions, SoftShadows) {
    using penumbra::render::Technique;
    using penumbra::shadow::Filter;
    CourseApp a("soft");
    EXPECT_FALSE(a.toggles().light);
    EXPECT_FALSE(a.toggles().jump);
    EXPECT_EQ(a.settings().light_radius, 0.3f);
    EXPECT_EQ(a.settings().filter, Filter::PCSS);
    EXPECT_EQ(a.settings().area_per_frame, 4);
    // Light samples take the hard filter; a filter takes one sample.
    ASSERT_EQ(a.set_option("area-samples", "64"), "");
    EXPECT_EQ(a.settings().filter, Filter::Hard);
    ASSERT_EQ(a.set_option("filter", "pcss"), "");
    EXPECT_EQ(a.settings().area_samples, 1);
    ASSERT_EQ(a.set_option("area-samples", "1"), "");
    EXPECT_EQ(a.settings().filter, Filter::PCSS) << "one sample leaves the filter alone";
    // The technique is the soft page's to choose (every technique of the option table).
    ASSERT_EQ(a.set_option("technique", "volumes"), "");
    EXPECT_EQ(a.frame_settings().technique, Technique::Volumes);
    EXPECT_NE(CourseApp("w09p2c").set_option("technique", "volumes"), "") << "W09P2c's is shadow mapping";
    // The reference: Heckbert-Herf with 256 samples, converging, whatever the method.
    ASSERT_EQ(a.set_option("reference", "on"), "");
    EXPECT_EQ(a.frame_settings().area_samples, penumbra::examples::kReferenceSamples);
    EXPECT_EQ(a.frame_settings().filter, Filter::Hard);
    EXPECT_GT(a.frame_settings().area_per_frame, 0);
    EXPECT_EQ(a.settings().filter, Filter::PCSS) << "the method chosen is kept for the flip back";
    EXPECT_NE(a.on_key('P', false).find("--area-samples 256"), std::string::npos) << a.on_key('P', false);
    // Keys: the radius, the filter (with PCSS), the light samples, converging, the reference.
    CourseApp k("w09p1");
    EXPECT_EQ(k.on_key('6', false).rfind("Soft shadows", 0), 0u);
    EXPECT_EQ(k.exercise().name, "soft");
    EXPECT_EQ(k.query(), CourseApp("soft").query()) << "the soft exercise's defaults when chosen by a key";
    EXPECT_EQ(k.on_key('=', false), "light-radius = 0.35");
    EXPECT_EQ(k.on_key('-', false), "light-radius = 0.3");
    for (int i = 0; i < 8; ++i) k.on_key('-', false);
    EXPECT_EQ(k.settings().light_radius, 0.0f) << "not below 0";
    EXPECT_EQ(k.on_key('F', false), "filter = hard");
    EXPECT_EQ(k.on_key('F', false), "filter = pcf4x4");
    EXPECT_EQ(k.on_key('F', false), "filter = pcss");
    EXPECT_EQ(k.on_key('N', false), "area-samples = 4");
    EXPECT_EQ(k.settings().filter, Filter::Hard);
    EXPECT_EQ(k.on_key('N', true), "area-samples = 1");
    EXPECT_EQ(k.on_key('N', true), "area-samples = 256");
    EXPECT_EQ(k.on_key('C', false), "area-per-frame = 0");
    EXPECT_EQ(k.on_key('X', false), "reference = on");
    EXPECT_EQ(k.on_key('T', false), "technique = planar");
    EXPECT_EQ(k.on_key('A', false), "aov = visibility");
    EXPECT_EQ(k.on_key('A', false), "aov = color");
    // Back to W09P2c: what the soft exercise started with goes back to the defaults.
    k.on_key('4', false);
    EXPECT_TRUE(k.toggles().light);
    EXPECT_TRUE(k.toggles().jump);
    EXPECT_FALSE(k.settings().light_radius.has_value());
    EXPECT_EQ(k.settings().filter, Filter::Hard);
    EXPECT_EQ(k.settings().area_per_frame, 0);
    EXPECT_EQ(k.frame_settings().technique, Technique::ShadowMap);
    const std::string help = CourseApp::key_help();
    for (const char* key : {"  6  ", "  N  ", "  C  ", "  X  ", "  T  ", "  - =  "})
        EXPECT_NE(help.find(key), std::string::npos) << key << help;
}

// The course scene's portal (the stencil exercise's effects=portal) is made for the first frame
// that asks for it, not with the scene. desktop.stencil-portal and web.stencil draw it.
TEST(ExerciseOptions, ThePortalIsMadeForTheFirstFrameThatAsksForIt) {
    CourseApp a("stencil");
    EXPECT_FALSE(a.scene().portal) << "made with the scene: every page would build it for nothing";
    a.course_scene_for(a.frame_settings());
    EXPECT_FALSE(a.scene().portal) << "the exercise's default, effects=outline, asks for no portal";
    ASSERT_EQ(a.set_option("effects", "outline,mirror,portal"), "");
    const penumbra::scene::Scene& s = a.course_scene_for(a.frame_settings());
    ASSERT_TRUE(s.portal);
    ASSERT_NE(s.portal->beyond, nullptr);
    // The portal of the CLI's course scene (penumbra render --effects portal).
    const penumbra::scene::CourseScene cli = penumbra::scene::make_course_scene();
    ASSERT_TRUE(cli.scene.portal);
    EXPECT_EQ(s.portal->beyond->meshes.size(), cli.scene.portal->beyond->meshes.size());
    EXPECT_EQ(s.portal->beyond->objects.size(), cli.scene.portal->beyond->objects.size());
    EXPECT_TRUE(s.portal->world == cli.scene.portal->world);
    const penumbra::scene::Scene* made = s.portal->beyond.get();
    ASSERT_EQ(a.set_option("effects", "none"), "");
    a.course_scene_for(a.frame_settings());
    ASSERT_EQ(a.set_option("effects", "portal"), "");
    EXPECT_EQ(a.course_scene_for(a.frame_settings()).portal->beyond.get(), made) << "made once";
}

TEST(ExerciseOptions, StencilOutline) {
    using penumbra::render::Effect;
    using penumbra::render::Technique;
    CourseApp a("stencil");
    ASSERT_EQ(a.settings().effects, std::vector<Effect>{Effect::Outline});
    // The select's four values, any width the slider's box takes, the colours listed, four techniques.
    ASSERT_EQ(a.set_option("effects", "none"), "");
    EXPECT_TRUE(a.settings().effects.empty());
    ASSERT_EQ(a.set_option("effects", "outline,mirror"), "");
    EXPECT_EQ(a.settings().effects, (std::vector<Effect>{Effect::Outline, Effect::Mirror}));
    ASSERT_EQ(a.set_option("effects", "portal"), "");
    EXPECT_EQ(a.settings().effects, std::vector<Effect>{Effect::Portal});
    ASSERT_EQ(a.set_option("effects", "outline,mirror"), "");
    ASSERT_EQ(a.set_option("reflectivity", "0.8"), "");
    EXPECT_EQ(a.settings().reflectivity, 0.8f);
    ASSERT_EQ(a.set_option("effects", "outline"), "");
    ASSERT_EQ(a.set_option("outline-width", "7.5"), "");
    EXPECT_EQ(a.settings().outline_width, 7.5f);
    ASSERT_EQ(a.set_option("outline-color", "00FFFF"), "");
    EXPECT_NE(a.query().find("outline-color=00ffff"), std::string::npos) << a.query();
    EXPECT_NE(a.set_option("outline-color", "123456"), "") << "not one of the colours offered";
    EXPECT_NE(a.query().find("outline-color=00ffff"), std::string::npos) << "a refused value changes nothing";
    ASSERT_EQ(a.set_option("technique", "volumes"), "");
    EXPECT_EQ(a.frame_settings().technique, Technique::Volumes);
    EXPECT_NE(a.set_option("technique", "gooch"), "") << "not offered here";
    EXPECT_NE(a.on_key('P', false).find("--effects outline"), std::string::npos) << a.on_key('P', false);
    // Keys: the outline on/off, the width's steps, the colours; chosen by its number key, and the
    // outline goes back off when another exercise is chosen.
    CourseApp k("w09p1");
    EXPECT_EQ(k.on_key('7', false).rfind("Stencil effects", 0), 0u);
    EXPECT_EQ(k.query(), CourseApp("stencil").query());
    EXPECT_EQ(k.on_key('Y', false), "effects = none");
    EXPECT_EQ(k.on_key('Y', false), "effects = mirror");
    EXPECT_EQ(k.on_key('Y', false), "effects = outline,mirror");
    EXPECT_EQ(k.on_key('Y', false), "effects = portal");
    EXPECT_EQ(k.on_key('Y', false), "effects = outline,mirror,portal");
    EXPECT_EQ(k.on_key('Y', false), "effects = outline");
    EXPECT_EQ(k.on_key('Q', false), "reflectivity = 0.75");
    EXPECT_EQ(k.on_key('Q', true), "reflectivity = 0.5");
    EXPECT_EQ(k.on_key('W', false), "outline-width = 5");
    EXPECT_EQ(k.on_key('W', true), "outline-width = 3");
    EXPECT_EQ(k.on_key('D', false), "outline-color = ffff00");
    EXPECT_EQ(k.on_key('T', false), "technique = planar");
    k.on_key('1', false);
    EXPECT_TRUE(k.settings().effects.empty());
    const std::string help = CourseApp::key_help();
    for (const char* key : {"  7  ", "  Y  ", "  W  ", "  D  "}) EXPECT_NE(help.find(key), std::string::npos) << key << help;
}

TEST(ExerciseOptions, MultipassPost) {
    using penumbra::render::PostKind;
    CourseApp a("multipass");
    ASSERT_EQ(a.settings().post.size(), 1u);
    EXPECT_EQ(a.settings().post[0].kind, PostKind::ShadowBlur);
    EXPECT_NE(a.query().find("post=shadow-blur:6"), std::string::npos) << a.query();
    ASSERT_EQ(a.set_option("post", "blur:4"), "");
    EXPECT_EQ(a.frame_settings().post.at(0).kind, PostKind::Blur);
    EXPECT_NE(a.set_option("post", "blur:99"), "") << "the option's range";
    EXPECT_NE(a.on_key('P', false).find("--post blur:4"), std::string::npos) << a.on_key('P', false);
    // The 0 key steps through the select's values; chosen by its number key; no other exercise
    // draws the post passes, and choosing one puts the default back.
    CourseApp k("w09p1");
    EXPECT_EQ(k.on_key('8', false).rfind("Multipass", 0), 0u);
    EXPECT_EQ(k.query(), CourseApp("multipass").query());
    EXPECT_EQ(k.on_key('0', false), "post = none");
    EXPECT_EQ(k.on_key('0', false), "post = blur:4");
    EXPECT_EQ(k.on_key('0', false), "post = bloom:0.6");
    EXPECT_EQ(k.on_key('0', true), "post = blur:4");
    EXPECT_EQ(k.on_key('A', false), "aov = visibility");
    k.on_key('1', false);
    EXPECT_TRUE(k.frame_settings().post.empty());
    EXPECT_EQ(k.query().find("post="), std::string::npos) << k.query();
    const std::string help = CourseApp::key_help();
    for (const char* key : {"  8  ", "  0  "}) EXPECT_NE(help.find(key), std::string::npos) << key << help;
}

TEST(ExerciseOptions, TimeFreezesAndIsKept) {
    CourseApp a("w09p1");
    ASSERT_EQ(a.set_option("time", "0.6"), "");
    EXPECT_TRUE(a.paused());
    EXPECT_DOUBLE_EQ(a.light_time(), 0.6);
    a.advance(1.0);
    EXPECT_DOUBLE_EQ(a.jump_time(), 0.6);
    EXPECT_NE(a.query().find("time=0.6"), std::string::npos) << a.query();
}

TEST(ExerciseOptions, ClocksFollowTheToggles) {
    CourseApp a("w09p1");
    ASSERT_EQ(a.set_option("light", "off"), "");
    a.advance(0.1);
    EXPECT_DOUBLE_EQ(a.light_time(), 0.0);
    EXPECT_DOUBLE_EQ(a.jump_time(), 0.1);
    a.advance(5.0);  // a long pause (a hidden tab) moves at most a quarter second
    EXPECT_DOUBLE_EQ(a.jump_time(), 0.35);
}

TEST(ExerciseOptions, RenderToTextureByCopy) {
    CourseApp a("w09p2b");
    EXPECT_EQ(a.value_of("rtt"), "fbo");
    EXPECT_EQ(a.on_key('.', false), "rtt = copy");
    EXPECT_TRUE(a.toggles().rtt_copy);
    EXPECT_NE(a.query().find("rtt=copy"), std::string::npos) << a.query();
    EXPECT_NE(a.set_option("rtt", "blit"), "");
    EXPECT_TRUE(a.toggles().rtt_copy);  // a bad value changes nothing
    EXPECT_EQ(a.set_option("rtt", "fbo"), "");
    EXPECT_FALSE(a.toggles().rtt_copy);
    EXPECT_EQ(a.frame_note(), "");  // no frame drawn
}

TEST(ExerciseOptions, Keys) {
    CourseApp a("w09p1");
    EXPECT_EQ(a.on_key('L', false), "light = off");
    EXPECT_EQ(a.on_key('4', false).rfind("W09P2c", 0), 0u);
    EXPECT_EQ(a.exercise().name, "w09p2c");
    a.on_key('M', false);
    EXPECT_EQ(a.settings().map_size, 2048);
    a.on_key('M', true);
    a.on_key('M', true);
    EXPECT_EQ(a.settings().map_size, 512);
    // auto, the last of the sizes offered: M from 4096 reaches it, and from it wraps to 256.
    EXPECT_EQ(a.set_option("map-size", "4096"), "");
    a.on_key('M', false);
    EXPECT_EQ(a.settings().map_size, penumbra::render::Settings::kAutoMapSize);
    a.on_key('M', false);
    EXPECT_EQ(a.settings().map_size, 256);
    EXPECT_EQ(a.set_option("map-size", "512"), "");
    a.on_key('F', false);
    EXPECT_EQ(a.settings().filter, penumbra::shadow::Filter::PCF4x4);
    a.on_key('E', false);  // rgba -> (no context: no depth texture) -> r8
    EXPECT_EQ(a.settings().encoding, penumbra::shadow::Encoding::R8);
    a.on_key(']', false);
    EXPECT_NEAR(a.bias(), 0.0075f, 1e-6f);
    a.on_key('B', false);
    EXPECT_FALSE(a.settings().bias.has_value());
    EXPECT_EQ(a.on_key('U', false).rfind("bias = auto", 0), 0u);
    EXPECT_TRUE(a.settings().bias_auto);
    EXPECT_NE(a.query().find("bias=auto"), std::string::npos) << a.query();
    a.on_key(']', false);  // from auto, a step from the sheet's constant (r8: 0.005)
    EXPECT_FALSE(a.settings().bias_auto);
    EXPECT_NEAR(a.bias(), 0.0075f, 1e-6f);
    a.on_key('U', false);
    a.on_key('B', false);
    EXPECT_FALSE(a.settings().bias_auto);
    EXPECT_FALSE(a.settings().bias.has_value());
    EXPECT_EQ(a.on_key('R', false), "precision = mediump");
    EXPECT_EQ(a.settings().precision, penumbra::shadow::Precision::Mediump);
    EXPECT_NE(a.query().find("precision=mediump"), std::string::npos) << a.query();
    EXPECT_EQ(a.on_key('R', false), "precision = highp");
    EXPECT_EQ(a.settings().precision, penumbra::shadow::Precision::Highp);
    const std::string help = CourseApp::key_help();
    EXPECT_NE(help.find("  U  "), std::string::npos) << help;
    EXPECT_NE(help.find("  R  "), std::string::npos) << help;
    EXPECT_EQ(a.on_key('Q', false), "");
    // Keys step through what the exercise's control offers: W09P2c shows colour and visibility.
    EXPECT_EQ(a.on_key('A', false), "aov = visibility");
    EXPECT_EQ(a.on_key('A', false), "aov = color");
    // W09P2b offers textures up to 2048: from 2048, M wraps to 256.
    a.on_key('3', false);
    ASSERT_EQ(a.set_option("map-size", "2048"), "");
    EXPECT_EQ(a.on_key('M', false), "map-size = 256");
}

// The list of exercises is the one place the pages, the desktop and the keys read: every control
// names an option of a table, and every value a control offers is one that option accepts.
TEST(ExerciseList, EveryControlNamesAnOptionAndOffersValidValues) {
    using namespace penumbra;
    ASSERT_EQ(exercise_list().size(), 10u);
    for (const auto& x : exercise_list()) {
        const examples::Exercise* parsed = examples::find_exercise(x.name);
        ASSERT_NE(parsed, nullptr);
        EXPECT_EQ(parsed, &x);
        EXPECT_FALSE(x.title.empty());
        if (x.name.rfind("w09p", 0) == 0) {
            EXPECT_EQ(x.title.substr(0, 5), "W09P" + std::string(1, x.name[4])) << x.title;
        }
        for (const auto& c : x.controls) {
            const render::OptionInfo* info = nullptr;
            if (const auto* t = render::find_option(examples::toggle_table(), c.option)) info = &t->info;
            else if (const auto* r = render::find_option(render::option_table(), c.option)) info = &r->info;
            ASSERT_NE(info, nullptr) << x.name << ": " << c.option;
            // A page sets no job option but the eye (the exercises place it: CourseApp::set_option)
            // and the time budget or the error target.
            if (c.option != "eye" && c.option != "budget-ms" && c.option != "max-error") {
                EXPECT_EQ(info->part, render::OptionPart::Technique) << c.option << ": a page sets no job option";
            }
            for (std::string_view v : c.values) EXPECT_EQ(render::check_value(*info, v), "") << c.option << "=" << v;
            CourseApp a(x.name);
            EXPECT_NE(a.query().find(std::string(c.option) + "="), std::string::npos) << x.name << ": " << c.option;
            if (c.kind == examples::ControlKind::Slider) {
                EXPECT_LT(c.min, c.max) << c.option;
                EXPECT_GE(c.min, info->min) << c.option;
                EXPECT_LE(c.max, info->max) << c.option;
            }
        }
        // The page starts with its defaults: its address names those it shows a control for (the
        // others are its address's defaults, as W09P2c's light-fit), its settings hold the rest.
        CourseApp a(x.name);
        const auto held = render::to_pairs(a.settings());
        for (const auto& [name, value] : x.defaults) {
            const bool in_query = a.query().find(std::string(name) + "=" + std::string(value)) != std::string::npos;
            const bool in_settings =
                std::find(held.begin(), held.end(), std::pair<std::string, std::string>(name, value)) != held.end();
            EXPECT_TRUE(in_query || in_settings) << x.name << ": " << name;
        }
    }
    for (const auto& k : examples::key_bindings()) {
        const bool known = render::find_option(examples::toggle_table(), k.option) ||
                           render::find_option(render::option_table(), k.option);
        EXPECT_TRUE(known) << k.option;
    }
}

// A control's list is what the page can show: a map size off it becomes the nearest size listed
// (on a log scale), with a note naming the option, the value given and the value used; a choice
// off it is refused (the select would go blank); the note clears with the next good change.
TEST(ExerciseValues, AMapSizeOffTheListTakesTheNearestListedWithANote) {
    CourseApp a("w09p2c");
    EXPECT_EQ(a.set_option("map-size", "1500"), "");
    EXPECT_EQ(a.settings().map_size, 2048) << "1500 is nearer 2048 than 1024 on a log scale";
    EXPECT_NE(a.note().find("map-size=1500"), std::string::npos) << a.note();
    EXPECT_NE(a.note().find("(256, 512, 1024, 2048, 4096, auto); using 2048"), std::string::npos) << a.note();
    EXPECT_EQ(a.set_option("map-size", "60000"), "");
    EXPECT_EQ(a.settings().map_size, 4096) << "the page's largest size";
    EXPECT_NE(a.note().find("using 4096"), std::string::npos) << a.note();
    // Beyond what the option takes at all: refused with its range, nothing changed.
    EXPECT_NE(a.set_option("map-size", "100000").find("[1, 65536]"), std::string::npos);
    EXPECT_EQ(a.settings().map_size, 4096);
    EXPECT_EQ(a.set_option("map-size", "512"), "");
    EXPECT_EQ(a.note(), "");
    EXPECT_EQ(a.settings().map_size, 512);
    // auto (issue 56) is offered: kept as it is, no note.
    EXPECT_EQ(a.set_option("map-size", "auto"), "");
    EXPECT_EQ(a.note(), "");
    EXPECT_EQ(a.settings().map_size, penumbra::render::Settings::kAutoMapSize);
    EXPECT_NE(a.query().find("map-size=auto"), std::string::npos) << a.query();
    // W09P2b's texture sizes stop at 2048, and auto is not among them: the size it stands for.
    CourseApp b("w09p2b");
    EXPECT_EQ(b.set_option("map-size", "auto"), "");
    EXPECT_EQ(b.settings().map_size, 1024) << b.note();
    EXPECT_EQ(b.set_option("map-size", "8192"), "");
    EXPECT_EQ(b.settings().map_size, 2048);
    EXPECT_EQ(b.query().find("8192"), std::string::npos) << b.query();
}

TEST(ExerciseValues, AChoiceOffTheListIsRefusedAndChangesNothing) {
    CourseApp a("w09p2c");
    const std::string err = a.set_option("filter", "pcf2x2");
    EXPECT_NE(err.find("filter=pcf2x2"), std::string::npos) << err;
    EXPECT_NE(err.find("pcf4x4, hard"), std::string::npos) << err;
    EXPECT_EQ(a.value_of("filter"), "hard");
    EXPECT_NE(a.set_option("aov", "stencil-count"), "");
    EXPECT_EQ(a.value_of("aov"), "color");
    // The same values where the page offers them.
    CourseApp v("volumes");
    EXPECT_EQ(v.set_option("aov", "stencil-count"), "");
    CourseApp s("soft");
    EXPECT_EQ(s.set_option("filter", "pcss"), "");
    // An option the page has no control for takes any value the option does (a link's setting).
    EXPECT_EQ(a.set_option("pcf-kernel", "full"), "");
    EXPECT_EQ(a.note(), "");
}

TEST(ExerciseValues, TheNoteBelongsToTheChangeThatCausedIt) {
    CourseApp a("w09p2c");
    ASSERT_EQ(a.set_option("map-size", "3000"), "");
    EXPECT_NE(a.note(), "");
    ASSERT_EQ(a.set_option("encoding", "r8"), "");
    EXPECT_EQ(a.note(), "");
    ASSERT_EQ(a.set_option("map-size", "3000"), "");
    EXPECT_NE(a.note(), "");
    EXPECT_NE(a.set_option("encoding", "r16"), "");
    EXPECT_EQ(a.note(), "") << "a refusal says its problem itself";
}

// Switched off in mid-air, the teapot comes down and rests on the table (it used to hang there).
TEST(ExerciseValues, TheJumpSwitchedOffLandsTheTeapot) {
    CourseApp a("w09p1");
    a.advance(0.2);
    a.advance(0.2);
    a.advance(0.2);  // 0.6 s: mid-bounce
    ASSERT_GT(penumbra::scene::course_teapot_lift(a.jump_time()), 0.1f);
    ASSERT_EQ(a.set_option("jump", "off"), "");
    for (int i = 0; i < 60; ++i) a.advance(1.0 / 60.0);
    EXPECT_NEAR(a.jump_time(), 1.5, 1e-9) << "lands at the bounce's end";
    EXPECT_LT(penumbra::scene::course_teapot_lift(a.jump_time()), 1e-5f);
    a.advance(0.2);
    EXPECT_NEAR(a.jump_time(), 1.5, 1e-9) << "and stays";
    ASSERT_EQ(a.set_option("jump", "on"), "");
    a.advance(0.2);
    EXPECT_NEAR(a.jump_time(), 1.7, 1e-9) << "and jumps again from there";
}

// The pages' app defers the marble's noise past the first frame (examples/course_web.cpp): until
// complete_scene() the table is untextured, in the 1 x 1 placeholder's colour (so the first frame's
// table and teapot share a program); after it, the table has the very marble an app made at once,
// byte for byte, and the same material, so the pages' later frames are the CLI's. The control: an
// app made at once is complete from the start and has nothing to make.
TEST(ExerciseOptions, ADeferredMarbleIsTheSameMarbleOnceMade) {
    const auto table = [](const CourseApp& app) -> const penumbra::scene::Material& {
        const auto& s = app.scene();
        const auto it = std::find_if(s.materials.begin(), s.materials.end(), [](const auto& m) { return m.name == "marble"; });
        EXPECT_NE(it, s.materials.end());
        return *it;
    };
    const auto marble = [&](const CourseApp& app) -> const penumbra::scene::Image& {
        return app.scene().images.at(static_cast<size_t>(table(app).base_color_texture));
    };
    CourseApp at_once("w09p1");
    EXPECT_TRUE(at_once.scene_complete());
    EXPECT_FALSE(at_once.complete_scene());
    EXPECT_EQ(marble(at_once).width, 512);
    EXPECT_EQ(table(at_once).base_color, glm::vec4(1.0f));

    CourseApp deferred("w09p1", true);
    EXPECT_FALSE(deferred.scene_complete());
    EXPECT_EQ(table(deferred).base_color_texture, -1);
    const auto& placeholder = deferred.scene().images.at(static_cast<size_t>(table(at_once).base_color_texture));
    ASSERT_EQ(placeholder.rgba.size(), 4u);
    for (int c = 0; c < 4; ++c)
        EXPECT_EQ(table(deferred).base_color[c], static_cast<float>(placeholder.rgba[static_cast<size_t>(c)]) / 255.0f);
    EXPECT_NE(table(deferred).base_color, glm::vec4(1.0f)) << "the placeholder is the marble's mean grey, not white";
    EXPECT_TRUE(deferred.complete_scene());
    EXPECT_TRUE(deferred.scene_complete());
    EXPECT_FALSE(deferred.complete_scene());
    EXPECT_EQ(table(deferred).base_color_texture, table(at_once).base_color_texture);
    EXPECT_EQ(table(deferred).base_color, table(at_once).base_color);
    EXPECT_EQ(marble(deferred).width, marble(at_once).width);
    EXPECT_EQ(marble(deferred).height, marble(at_once).height);
    EXPECT_TRUE(marble(deferred).rgba == marble(at_once).rgba);
}
