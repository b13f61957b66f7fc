// The exercise apps' options without a GL context: what the URL, the controls and the desktop keys
// set, read back through the same names (the pages restore a reload from query()).
#include <gtest/gtest.h>

#include "exercises.h"

using penumbra::examples::CourseApp;
using penumbra::examples::Exercise;
using penumbra::examples::exercise_list;

TEST(ExerciseOptions, DefaultsOfEachPage) {
    EXPECT_EQ(CourseApp(Exercise::W09P1).query(), "light=on&jump=on");
    EXPECT_EQ(CourseApp(Exercise::W09P2a).query(), "light=on&jump=on&projection=persp");
    EXPECT_EQ(CourseApp(Exercise::W09P2b).query(), "light=on&jump=on&fbo-view=light&map-size=1024");
    EXPECT_EQ(CourseApp(Exercise::W09P2c).query(),
              "light=on&jump=on&encoding=rgba&filter=hard&bias=auto&map-faces=auto&precision=highp&map-size=1024&aov=color&"
              "map-view=on");
    EXPECT_EQ(CourseApp(Exercise::Volumes).query(),
              "light=on&jump=on&volume-method=auto&show-volumes=off&eye=scene&aov=color");
}

TEST(ExerciseOptions, EveryChangeReadsBack) {
    const std::vector<std::pair<std::string, std::string>> changes = {
        {"light", "off"}, {"jump", "off"},   {"projection", "ortho"}, {"fbo-view", "camera"}, {"map-view", "off"},
        {"encoding", "r8"}, {"filter", "pcf4x4"}, {"bias", "0.003"},   {"map-size", "2048"},     {"aov", "visibility"},
        {"precision", "mediump"}, {"volume-method", "zfail"}, {"show-volumes", "on"}, {"eye", "in-shadow"}};
    for (const auto& x : exercise_list()) {
        const Exercise e = x.id;
        CourseApp a(e);
        for (const auto& [k, v] : changes) ASSERT_EQ(a.set_option(k, v), "") << k;
        CourseApp b(e);
        for (const auto& [k, v] : a.options()) ASSERT_EQ(b.set_option(k, v), "") << k << "=" << v;
        EXPECT_EQ(a.query(), b.query());
        EXPECT_EQ(a.settings(), b.settings());
        EXPECT_TRUE(b.eye_in_shadow()) << x.name << ": " << a.query();
    }
    CourseApp c(Exercise::W09P2c);
    ASSERT_EQ(c.set_option("bias", "0.003"), "");
    EXPECT_NE(c.query().find("bias=0.003&"), std::string::npos) << c.query();  // not 0.0030000000260770321
}

TEST(ExerciseOptions, BiasAutoAndPrecisionReadBack) {
    CourseApp a(Exercise::W09P2c);
    ASSERT_EQ(a.set_option("bias", "auto"), "");
    ASSERT_EQ(a.set_option("precision", "mediump"), "");
    EXPECT_NE(a.query().find("bias=auto&map-faces=auto&precision=mediump&"), std::string::npos) << a.query();
    EXPECT_TRUE(a.settings().bias_auto);
    EXPECT_EQ(a.settings().precision, penumbra::shadow::Precision::Mediump);
    CourseApp b(Exercise::W09P2c);
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
    CourseApp c(Exercise::W09P1);
    ASSERT_EQ(c.set_option("precision", "mediump"), "");
    EXPECT_NE(c.query().find("precision=mediump"), std::string::npos) << c.query();
    EXPECT_EQ(CourseApp(Exercise::W09P1).query().find("precision"), std::string::npos);
    EXPECT_NE(a.set_option("precision", "lowp"), "");
    EXPECT_NE(a.set_option("bias", "automatic"), "");
}

TEST(ExerciseOptions, SettingsOutsideThePageSurviveTheQuery) {
    CourseApp a(Exercise::W09P1);
    ASSERT_EQ(a.set_option("encoding", "r8"), "");  // not shown on W09P1, but kept
    EXPECT_NE(a.query().find("encoding=r8"), std::string::npos) << a.query();
}

TEST(ExerciseOptions, ThePcfKernelIsReachableByUrlOnTheShadowMapPage) {
    // No control on W09P2c: the course's full kernel is one URL parameter away, and kept there.
    CourseApp a(Exercise::W09P2c);
    EXPECT_EQ(a.settings().pcf_kernel, penumbra::shadow::PcfKernel::EarlyExit);
    EXPECT_EQ(a.query().find("pcf-kernel"), std::string::npos) << "the default is not written: " << a.query();
    ASSERT_EQ(a.set_option("pcf-kernel", "full"), "");
    EXPECT_EQ(a.settings().pcf_kernel, penumbra::shadow::PcfKernel::Full);
    EXPECT_NE(a.query().find("pcf-kernel=full"), std::string::npos) << a.query();
    EXPECT_NE(a.set_option("pcf-kernel", "fast"), "");
}

TEST(ExerciseOptions, BadValuesChangeNothing) {
    CourseApp a(Exercise::W09P2c);
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

// The eye is a job option the exercises take (like time): shown on the volumes page, kept in the
// URL of the others once moved into the shadow, refused when misspelt.
TEST(ExerciseOptions, TheEyeMovesIntoTheShadowAndIsKept) {
    CourseApp a(Exercise::Volumes);
    EXPECT_FALSE(a.eye_in_shadow());
    ASSERT_EQ(a.set_option("eye", "in-shadow"), "");
    EXPECT_TRUE(a.eye_in_shadow());
    EXPECT_NE(a.query().find("eye=in-shadow"), std::string::npos) << a.query();
    ASSERT_EQ(a.set_option("eye", "scene"), "");
    EXPECT_NE(a.query().find("eye=scene"), std::string::npos) << a.query();
    EXPECT_EQ(a.set_option("eye", "inside").rfind("eye: ", 0), 0u) << a.set_option("eye", "inside");
    EXPECT_FALSE(a.eye_in_shadow());
    CourseApp b(Exercise::W09P1);
    EXPECT_EQ(b.query().find("eye"), std::string::npos) << "the default is not written: " << b.query();
    ASSERT_EQ(b.set_option("eye", "in-shadow"), "");
    EXPECT_NE(b.query().find("eye=in-shadow"), std::string::npos) << b.query();
    EXPECT_NE(b.set_option("out", "x.png"), "");  // the other job options stay the exercise's
    EXPECT_NE(b.set_option("frames", "3"), "");
}

TEST(ExerciseOptions, VolumeKeys) {
    CourseApp a(Exercise::W09P1);
    EXPECT_EQ(a.on_key('5', false).rfind("Shadow volumes", 0), 0u);
    EXPECT_EQ(a.exercise(), Exercise::Volumes);
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

TEST(ExerciseOptions, TimeFreezesAndIsKept) {
    CourseApp a(Exercise::W09P1);
    ASSERT_EQ(a.set_option("time", "0.6"), "");
    EXPECT_TRUE(a.paused());
    EXPECT_DOUBLE_EQ(a.light_time(), 0.6);
    a.advance(1.0);
    EXPECT_DOUBLE_EQ(a.jump_time(), 0.6);
    EXPECT_NE(a.query().find("time=0.6"), std::string::npos) << a.query();
}

TEST(ExerciseOptions, ClocksFollowTheToggles) {
    CourseApp a(Exercise::W09P1);
    ASSERT_EQ(a.set_option("light", "off"), "");
    a.advance(0.1);
    EXPECT_DOUBLE_EQ(a.light_time(), 0.0);
    EXPECT_DOUBLE_EQ(a.jump_time(), 0.1);
    a.advance(5.0);  // a long pause (a hidden tab) moves at most a quarter second
    EXPECT_DOUBLE_EQ(a.jump_time(), 0.35);
}

TEST(ExerciseOptions, Keys) {
    CourseApp a(Exercise::W09P1);
    EXPECT_EQ(a.on_key('L', false), "light = off");
    EXPECT_EQ(a.on_key('4', false).rfind("W09P2c", 0), 0u);
    EXPECT_EQ(a.exercise(), Exercise::W09P2c);
    a.on_key('M', false);
    EXPECT_EQ(a.settings().map_size, 2048);
    a.on_key('M', true);
    a.on_key('M', true);
    EXPECT_EQ(a.settings().map_size, 512);
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
    ASSERT_EQ(exercise_list().size(), 5u);
    for (const auto& x : exercise_list()) {
        Exercise parsed{};
        ASSERT_TRUE(examples::parse_exercise(x.name, parsed));
        EXPECT_EQ(parsed, x.id);
        EXPECT_FALSE(x.title.empty());
        if (x.name.rfind("w09p", 0) == 0) {
            EXPECT_EQ(x.title.substr(0, 5), "W09P" + std::string(1, x.name[4])) << x.title;
        }
        for (const auto& c : x.controls) {
            const render::OptionInfo* info = nullptr;
            if (const auto* t = render::find_option(examples::toggle_table(), c.option)) info = &t->info;
            else if (const auto* r = render::find_option(render::option_table(), c.option)) info = &r->info;
            ASSERT_NE(info, nullptr) << x.name << ": " << c.option;
            // A page sets no job option but the eye (the exercises place it: CourseApp::set_option).
            if (c.option != "eye") {
                EXPECT_EQ(info->part, render::OptionPart::Technique) << c.option << ": a page sets no job option";
            }
            for (std::string_view v : c.values) EXPECT_EQ(render::check_value(*info, v), "") << c.option << "=" << v;
            CourseApp a(x.id);
            EXPECT_NE(a.query().find(std::string(c.option) + "="), std::string::npos) << x.name << ": " << c.option;
        }
    }
    for (const auto& k : examples::key_bindings()) {
        const bool known = render::find_option(examples::toggle_table(), k.option) ||
                           render::find_option(render::option_table(), k.option);
        EXPECT_TRUE(known) << k.option;
    }
}
