// The option table: every option round-trips through its printer and parser, bad values are named
// with what the option accepts, and the printed forms (to_args, accepted_values) come from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "plan/options.h"

using namespace penumbra::render;
using penumbra::shadow::Encoding;
using penumbra::shadow::Filter;

namespace {

Options parse_all(const std::vector<std::pair<std::string, std::string>>& pairs) {
    Options o;
    for (const auto& [k, v] : pairs) {
        const std::string err = parse_option(o, k, v);
        EXPECT_EQ(err, "") << k << "=" << v;
    }
    return o;
}

TEST(Options, EveryOptionRoundTrips) {
    Options o;
    o.job.scene = "tests/data/sphere_over_plane.gltf";
    o.job.time = 1.0 / 3.0;
    o.job.width = 640;
    o.job.height = 360;
    o.settings.encoding = Encoding::DepthTex;
    o.settings.filter = Filter::PCF2x2;
    o.settings.pcf_kernel = penumbra::shadow::PcfKernel::Full;
    o.settings.map_size = 2048;
    o.settings.bias = 0.0023f;
    o.settings.bias_auto = false;
    o.settings.precision = penumbra::shadow::Precision::Mediump;
    o.settings.aov = Aov::LightDepth;
    o.settings.technique = Technique::Planar;
    o.job.out = "some dir/frame.png";
    o.job.frames = 20;
    const auto pairs = to_pairs(o);
    // Every option is printed, in the table's order.
    ASSERT_EQ(pairs.size(), option_table().size());
    for (size_t i = 0; i < pairs.size(); ++i) EXPECT_EQ(pairs[i].first, option_table()[i].info.name);
    EXPECT_EQ(parse_all(pairs), o);
    // The defaults round-trip too, auto and the absent fixed bias.
    EXPECT_EQ(parse_all(to_pairs(Options{})), Options{});
}

TEST(Options, TheTechniquePartAndTheJobPartSplit) {
    std::vector<std::string> technique, job;
    for (const auto& o : option_table())
        (o.info.part == OptionPart::Technique ? technique : job).emplace_back(o.info.name);
    EXPECT_EQ(job, (std::vector<std::string>{"scene", "time", "size", "eye", "out", "frames", "budget-ms", "max-error"}));
    EXPECT_EQ(technique.size(), to_pairs(Settings{}).size());
    Settings s;
    EXPECT_EQ(parse_option(s, "encoding", "r8"), "");
    EXPECT_EQ(s.encoding, Encoding::R8);
    EXPECT_EQ(parse_option(s, "size", "64x64"), "--size: not a technique setting");
}

TEST(Options, EachValueOfEachChoiceRoundTrips) {
    for (const auto& opt : option_table()) {
        if (opt.info.type != OptionType::Choice) continue;
        ASSERT_FALSE(opt.info.choices.empty()) << opt.info.name;
        for (const Choice& c : opt.info.choices) {
            Options o;
            ASSERT_EQ(parse_option(o, opt.info.name, c.value), "") << opt.info.name;
            EXPECT_EQ(opt.print(o), c.value) << opt.info.name;
            EXPECT_FALSE(c.label.empty()) << opt.info.name << " " << c.value << ": a page shows a label";
        }
    }
}

TEST(Options, AutoBiasRoundTripsAndReplacesAFixedOne) {
    Settings s;
    ASSERT_EQ(parse_option(s, "bias", "0.01"), "");
    ASSERT_EQ(parse_option(s, "bias", "auto"), "");
    EXPECT_TRUE(s.bias_auto);
    EXPECT_FALSE(s.bias.has_value());
    Options o;
    o.settings = s;
    EXPECT_EQ(parse_all(to_pairs(o)), o);
    EXPECT_FLOAT_EQ(s.effective_bias(), penumbra::shadow::auto_bias_constant(s.encoding, s.precision));
    ASSERT_EQ(parse_option(s, "bias", "0.002"), "");
    EXPECT_FALSE(s.bias_auto);
    EXPECT_FLOAT_EQ(s.effective_bias(), 0.002f);
    // A float prints as the shortest text that reads back as it (a URL's 0.003).
    ASSERT_EQ(parse_option(s, "bias", "0.003"), "");
    const auto pairs = to_pairs(s);
    EXPECT_NE(std::find(pairs.begin(), pairs.end(), std::pair<std::string, std::string>{"bias", "0.003"}), pairs.end());
}

TEST(Options, DefaultsAreAutoBiasWithTheSheetsConstantsOneChoiceAway) {
    const Options o;
    EXPECT_EQ(o.job.scene, "teapot");
    EXPECT_EQ(o.settings.technique, Technique::ShadowMap);
    // The map matched to the pixels it serves (issue 56); --map-size N fixes it.
    EXPECT_EQ(o.settings.map_size, Settings::kAutoMapSize);
    // PCF 4x4 takes the early exit unless --pcf-kernel full asks for the course's kernel.
    EXPECT_EQ(o.settings.pcf_kernel, penumbra::shadow::PcfKernel::EarlyExit);
    EXPECT_TRUE(o.settings.bias_auto);
    EXPECT_FLOAT_EQ(o.settings.effective_bias(), auto_bias_constant(Encoding::RGBA, penumbra::shadow::Precision::Highp));
    Settings sheet = o.settings;
    ASSERT_EQ(parse_option(sheet, "bias", "sheet"), "");
    EXPECT_FALSE(sheet.bias_auto);
    EXPECT_FLOAT_EQ(sheet.effective_bias(), 0.0015f);  // rgba
    Settings r8 = sheet;
    r8.encoding = Encoding::R8;
    EXPECT_FLOAT_EQ(r8.effective_bias(), 0.005f);
    r8.bias = 0.01f;
    EXPECT_FLOAT_EQ(r8.effective_bias(), 0.01f);
}

TEST(Options, BadValuesAreNamedAndLeaveTheOptionsAlone) {
    const struct {
        const char* name;
        const char* value;
        const char* says;
    } bad[] = {
        {"encoding", "r16", "--encoding: unknown value 'r16' (r8, rgba, depthtex)"},
        {"filter", "pcf8x8", "--filter: unknown value 'pcf8x8' (hard, pcf2x2, pcf4x4, pcss)"},
        {"pcf-kernel", "fast", "--pcf-kernel: unknown value 'fast' (early-exit, full)"},
        {"size", "0x100", "--size: width and height must be at least 1, got '0x100'"},
        {"size", "100", "--size: expected WIDTHxHEIGHT, got '100'"},
        {"size", "10x10x10", "--size: expected WIDTHxHEIGHT, got '10x10x10'"},
        {"map-size", "-4", "--map-size: must lie in [1, 65536], got '-4'"},
        {"map-size", "65537", "--map-size: must lie in [1, 65536], got '65537'"},
        {"size", "16385x16", "--size: width and height must be at most 16384 (the maximum), got '16385x16'"},
        {"map-size", "1.5", "--map-size: not a whole number: '1.5' (or 'auto')"},
        {"map-size", "99999999999", "--map-size: not a whole number: '99999999999' (or 'auto')"},
        {"map-size", "Auto", "--map-size: not a whole number: 'Auto' (or 'auto')"},
        {"time", "nan", "--time: must be a finite number in [-1000000, 1000000], got 'nan'"},
        {"time", "-inf", "--time: must be a finite number in [-1000000, 1000000], got '-inf'"},
        {"time", "1e7", "--time: must lie in [-1000000, 1000000], got '1e7'"},
        {"time", "a\nb", "--time: not a number: 'a\\nb'"},  // one line: the newline shown as \n
        {"light-radius", "inf", "--light-radius: must be a finite number in [0, 1000000], got 'inf'"},
        {"time", "1s", "--time: not a number: '1s'"},
        {"precision", "lowp", "--precision: unknown value 'lowp' (highp, mediump)"},
        {"bias", "slope", "--bias: not a number: 'slope' (or 'auto', 'sheet')"},
        {"bias", "2", "--bias: must lie in [0, 1], got '2'"},
        {"frames", "0", "--frames: must lie in [1, 10000], got '0'"},
        {"frames", "10001", "--frames: must lie in [1, 10000], got '10001'"},
        {"aov", "normal", "--aov: unknown value 'normal' (color, visibility, light-depth, stencil-count, gbuffer-color, gbuffer-normal, "
         "gbuffer-position, gbuffer-depth, cascades)"},
        {"technique", "volume", "--technique: unknown value 'volume' (shadowmap, planar, volumes, gooch, none)"},
        {"volume-method", "zmid", "--volume-method: unknown value 'zmid' (auto, zpass, zfail)"},
        {"show-volumes", "yes", "--show-volumes: unknown value 'yes' (off, on)"},
        {"gooch-planes", "0", "--gooch-planes: must lie in [1, 16], got '0'"},
        {"gooch-planes", "17", "--gooch-planes: must lie in [1, 16], got '17'"},
        {"gooch-method", "disc", "--gooch-method: unknown value 'disc' (planes, texture)"},
        {"eye", "above", "--eye: unknown value 'above' (scene, in-shadow)"},
        {"colour", "red", "unknown option --colour"},
        {"scene", "", "--scene: needs a value: teapot (the course scene), FILE.gltf / FILE.glb, or pile:N / forest:N "
                      "(N pyramids; :spot or :sun for another light)"},
    };
    for (const auto& b : bad) {
        Options o;
        EXPECT_EQ(parse_option(o, b.name, b.value), b.says);
        EXPECT_EQ(o, Options{}) << b.name;
    }
}

TEST(Options, ArgsLabelTheResult) {
    Options o;
    o.settings.encoding = Encoding::R8;
    EXPECT_EQ(to_args(o),
              "--scene teapot --time 0 --size 512x512 --encoding r8 --filter hard --pcf-kernel early-exit "
              "--map-size auto --cascades auto --cascade-split 0.95 --cascade-snap on --cascade-blend 0.1 --cube-layout atlas --bias auto --map-faces auto --light-fit shadows --precision highp --volume-method auto "
              "--show-volumes off --light-radius scene --pcss-search 16 --pcss-taps 16 --pcss-blockers layered --area-samples 1 --area-per-frame 0 --area-interleave 1 "
              "--gooch-planes 8 --gooch-method planes --blend-shadows off --effects none --outline-color ff8c00 "
              "--outline-width 3 --reflectivity 0.5 --post none --shading forward --lights 0 --aov color --technique shadowmap --eye scene --frames 1");
    EXPECT_EQ(to_args(o.settings),
              "--encoding r8 --filter hard --pcf-kernel early-exit --map-size auto --cascades auto --cascade-split 0.95 --cascade-snap on --cascade-blend 0.1 --cube-layout atlas --bias auto --map-faces auto "
              "--light-fit shadows --precision highp --volume-method auto --show-volumes off --light-radius scene "
              "--pcss-search 16 --pcss-taps 16 --pcss-blockers layered --area-samples 1 --area-per-frame 0 --area-interleave 1 --gooch-planes 8 --gooch-method planes "
              "--blend-shadows off "
              "--effects none --outline-color ff8c00 --outline-width 3 --reflectivity 0.5 --post none --shading forward --lights 0 --aov color --technique shadowmap");
}

TEST(Options, AcceptedValuesAndListsComeFromTheTable) {
    EXPECT_EQ(accepted_values(option_info("encoding")), "r8, rgba, depthtex");
    EXPECT_EQ(accepted_values(option_info("map-size")), "a whole number in [1, 65536], or auto");
    EXPECT_EQ(accepted_values(option_info("pcss-taps")).find(", or"), std::string::npos);  // an integer with no words
    EXPECT_EQ(accepted_values(option_info("size")), "WIDTHxHEIGHT, each <= 16384");
    EXPECT_EQ(accepted_values(option_info("bias")), "a number in [0, 1], or auto, sheet");
    std::vector<std::string> out;
    EXPECT_EQ(parse_list(option_info("filter"), "hard,pcf4x4", out), "");
    EXPECT_EQ(out, (std::vector<std::string>{"hard", "pcf4x4"}));
    EXPECT_EQ(parse_list(option_info("map-size"), "256,x", out), "--map-size: not a whole number: 'x' (or 'auto')");
    EXPECT_EQ(out.size(), 2u) << "nothing added on a problem";
    EXPECT_NE(parse_list(option_info("encoding"), "", out), "");
}

TEST(Options, TheSharedNumberParsers) {
    int i = 0;
    double d = 0.0;
    int w = 0, h = 0;
    EXPECT_TRUE(parse_int("12", i));
    EXPECT_FALSE(parse_int(" 3", i));
    EXPECT_FALSE(parse_int("12x", i));
    EXPECT_TRUE(parse_number(".5", d));
    EXPECT_TRUE(parse_number("1e-3", d));
    EXPECT_FALSE(parse_number("inf", d));
    EXPECT_TRUE(parse_size("640x360", w, h));
    EXPECT_EQ(w, 640);
    EXPECT_FALSE(parse_size("640x", w, h));
    EXPECT_EQ(shortest_float(0.003f), "0.003");
}

// read_number: strtod's decimals and words, nothing else of it (the browser reads the same texts
// with JavaScript's Number(): web.url checks them there).
TEST(Options, ReadNumberTakesDecimalsAndTheWordsOnly) {
    double d = 0.0;
    for (const char* ok : {"0", "5.", ".5", "+2", "-0.25", "1e-3", "1E+3", "007", "123456789012345678901234"}) {
        EXPECT_TRUE(read_number(ok, d)) << ok;
        EXPECT_EQ(d, std::strtod(ok, nullptr)) << ok;
    }
    for (const char* word : {"inf", "-Infinity", "NAN"}) {
        EXPECT_TRUE(read_number(word, d)) << word;
        EXPECT_FALSE(std::isfinite(d)) << word;
    }
    EXPECT_TRUE(read_number("1e999", d));
    EXPECT_FALSE(std::isfinite(d));
    for (const char* bad : {"", " 1", "1 ", "0x10", "1e", "e5", ".", "-", "1..2", "--1", "1.2.3", "infx", "1,5"})
        EXPECT_FALSE(read_number(bad, d)) << "'" << bad << "'";
    // What format_number prints (17 digits: past a double's 2^53 mantissa) reads back exactly.
    for (const double x : {0.1, 1.0 / 3.0, 6.02214076e23, 2.2250738585072014e-308, 4.9406564584124654e-324}) {
        EXPECT_TRUE(read_number(format_number(x), d)) << format_number(x);
        EXPECT_EQ(d, x) << format_number(x);
    }
}

}  // namespace

namespace {
// --out none writes nothing, as its help says: stored as no file.
TEST(Options, OutNoneWritesNothing) {
    penumbra::render::Options o;
    o.job.out = "x.png";
    EXPECT_EQ(penumbra::render::parse_option(o, "out", "none"), "");
    EXPECT_EQ(o.job.out, "");
}
}  // namespace
