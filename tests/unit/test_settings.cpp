// The one Settings parser and printer: every option round-trips, and bad values are named.
#include <gtest/gtest.h>

#include "render/settings.h"

using namespace penumbra::render;
using penumbra::shadow::Encoding;
using penumbra::shadow::Filter;

namespace {

Settings parse_all(const std::vector<std::pair<std::string, std::string>>& pairs) {
    Settings s;
    for (const auto& [k, v] : pairs) {
        const std::string err = parse_option(s, k, v);
        EXPECT_EQ(err, "") << k << "=" << v;
    }
    return s;
}

TEST(Settings, EveryOptionRoundTrips) {
    Settings s;
    s.scene = "tests/data/sphere_over_plane.gltf";
    s.time = 1.0 / 3.0;
    s.width = 640;
    s.height = 360;
    s.encoding = Encoding::DepthTex;
    s.filter = Filter::PCF2x2;
    s.map_size = 2048;
    s.bias = 0.0023f;
    s.precision = penumbra::shadow::Precision::Mediump;
    s.aov = Aov::LightDepth;
    s.technique = Technique::Planar;
    s.out = "some dir/frame.png";
    s.frames = 20;
    const auto pairs = to_pairs(s);
    // Every option is printed, in the documented order.
    ASSERT_EQ(pairs.size(), option_names().size());
    for (size_t i = 0; i < pairs.size(); ++i) EXPECT_EQ(pairs[i].first, option_names()[i]);
    EXPECT_EQ(parse_all(pairs), s);
    // The defaults round-trip too, the absent bias as "default".
    EXPECT_EQ(parse_all(to_pairs(Settings{})), Settings{});
}

TEST(Settings, EachValueOfEachEnumRoundTrips) {
    for (auto e : {Encoding::R8, Encoding::RGBA, Encoding::DepthTex})
        for (auto f : {Filter::Hard, Filter::PCF2x2, Filter::PCF4x4})
            for (auto a : {Aov::Color, Aov::Visibility, Aov::LightDepth})
                for (auto t : {Technique::ShadowMap, Technique::Planar, Technique::None}) {
                    Settings s;
                    s.encoding = e;
                    s.filter = f;
                    s.aov = a;
                    s.technique = t;
                    EXPECT_EQ(parse_all(to_pairs(s)), s) << to_args(s);
                }
}

TEST(Settings, AutoBiasRoundTripsAndReplacesAFixedOne) {
    Settings s;
    ASSERT_EQ(parse_option(s, "bias", "0.01"), "");
    ASSERT_EQ(parse_option(s, "bias", "auto"), "");
    EXPECT_TRUE(s.bias_auto);
    EXPECT_FALSE(s.bias.has_value());
    EXPECT_EQ(parse_all(to_pairs(s)), s);
    EXPECT_FLOAT_EQ(s.effective_bias(), penumbra::shadow::auto_bias_constant(s.encoding, s.precision));
    ASSERT_EQ(parse_option(s, "bias", "0.002"), "");
    EXPECT_FALSE(s.bias_auto);
    EXPECT_FLOAT_EQ(s.effective_bias(), 0.002f);
}

TEST(Settings, DefaultsAreTheSheets) {
    const Settings s;
    EXPECT_EQ(s.scene, "teapot");
    EXPECT_EQ(s.technique, Technique::ShadowMap);
    EXPECT_EQ(s.map_size, 1024);
    EXPECT_FLOAT_EQ(s.effective_bias(), 0.0015f);  // rgba
    Settings r8 = s;
    r8.encoding = Encoding::R8;
    EXPECT_FLOAT_EQ(r8.effective_bias(), 0.005f);
    r8.bias = 0.01f;
    EXPECT_FLOAT_EQ(r8.effective_bias(), 0.01f);
}

TEST(Settings, BadValuesAreNamedAndLeaveTheSettingsAlone) {
    const struct {
        const char* name;
        const char* value;
        const char* says;
    } bad[] = {
        {"encoding", "r16", "--encoding: unknown value 'r16' (r8, rgba, depthtex)"},
        {"filter", "pcf8x8", "--filter: unknown value 'pcf8x8' (hard, pcf2x2, pcf4x4)"},
        {"size", "0x100", "--size: width and height must be at least 1, got '0x100'"},
        {"size", "100", "--size: expected WIDTHxHEIGHT, got '100'"},
        {"size", "10x10x10", "--size: expected WIDTHxHEIGHT, got '10x10x10'"},
        {"map-size", "-4", "--map-size: must be at least 1, got '-4'"},
        {"map-size", "1.5", "--map-size: not a whole number: '1.5'"},
        {"time", "nan", "--time: not a number: 'nan'"},
        {"time", "1s", "--time: not a number: '1s'"},
        {"precision", "lowp", "--precision: unknown value 'lowp' (highp, mediump)"},
        {"bias", "slope", "--bias: not a number: 'slope' (or 'default', 'auto')"},
        {"bias", "2", "--bias: must lie in [0, 1] (a depth offset), got '2'"},
        {"frames", "0", "--frames: must be at least 1, got '0'"},
        {"aov", "normal", "--aov: unknown value 'normal' (color, visibility, light-depth)"},
        {"technique", "volume", "--technique: unknown value 'volume' (shadowmap, planar, none)"},
        {"colour", "red", "unknown option --colour"},
        {"scene", "", "--scene: needs 'teapot' or a .gltf/.glb file"},
    };
    for (const auto& b : bad) {
        Settings s;
        EXPECT_EQ(parse_option(s, b.name, b.value), b.says);
        EXPECT_EQ(s, Settings{}) << b.name;
    }
}

TEST(Settings, ArgsLabelTheResult) {
    Settings s;
    s.encoding = Encoding::R8;
    EXPECT_EQ(to_args(s),
              "--scene teapot --time 0 --size 512x512 --encoding r8 --filter hard --map-size 1024 --bias default "
              "--precision highp --aov color --technique shadowmap --frames 1");
}

}  // namespace
