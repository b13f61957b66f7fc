// The shader lab on a GL context (render/lab.h, docs/snippets.md): snippets files compiled into
// the renderer's own programs and checked against the sheet's answer on the course scene. What
// holds on any conformant context: a file that is the answer draws the answer's frame, each classic
// mistake is told apart from it and from the others, a file that writes none of the functions is no
// match, each function of a file is checked alone, a file that does not compile leaves the last good
// snippets.
// Frames of the same function from two programs may round differently (GLSL ES 1.00 4.6.1
// promises invariance only within a program): "matches" allows render::kLabMatchPct of the pixels.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "gl_fixture.h"
#include "plan/snippets.h"
#include "render/lab.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

std::string read(const std::string& name) {
    std::ifstream in(test::test_data_dir() + "/snippets/" + name);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_FALSE(s.str().empty()) << name;
    return s.str();
}

struct Lab : test::GlTest {
    scene::CourseScene course = scene::make_course_scene(6);
    render::Settings settings;
    render::FrameInputs in = render::offscreen(128, 96);
    void SetUp() override {
        GlTest::SetUp();
        scene::animate_course(course, 0.6, 0.6);
        settings.filter = shadow::Filter::PCF4x4;  // the sheet's 4x4 lookup: offset_lookup counts
    }
    render::LabVerdict check(const std::string& file) {
        return render::lab_check(*renderer, course.scene, settings, read(file), in);
    }
};

}  // namespace

TEST_F(Lab, TheSheetsAnswerWrittenOutDrawsTheAnswersFrame) {
    for (const char* file : {"answer.glsl", "unpack_only.glsl"}) {
        const render::LabVerdict v = check(file);
        ASSERT_TRUE(v.compiles) << file << ": " << (v.problems.empty() ? "" : v.problems[0].message);
        EXPECT_LE(v.differing_pct, render::kLabMatchPct) << file;
        EXPECT_EQ(v.mistake, "") << file;
        EXPECT_EQ(v.student.size(), 128u * 96u * 4u);
        EXPECT_NE(v.hint.find("Matches"), std::string::npos) << v.hint;
    }
    // The control: a file without the bias draws another frame.
    const render::LabVerdict no_bias = check("no_bias.glsl");
    EXPECT_GT(no_bias.differing_pct, 1.0);
}

TEST_F(Lab, EachClassicMistakeIsToldApartAndNamed) {
    const std::pair<const char*, const char*> cases[] = {{"no_bias.glsl", "no-bias"},
                                                         {"wrong_way.glsl", "wrong-way"},
                                                         {"bias_wrong_side.glsl", "bias-wrong-side"},
                                                         {"eight_bit_threshold.glsl", "8-bit-threshold"},
                                                         {"red_only.glsl", "red-only"},
                                                         {"unpack_reversed.glsl", "unpack-reversed"},
                                                         {"detached.glsl", "detached"},
                                                         {"no_texmapscale.glsl", "no-texmapscale"}};
    const auto mistakes = render::snippet_mistakes(settings.encoding);
    for (const auto& [file, name] : cases) {
        const render::LabVerdict v = check(file);
        ASSERT_TRUE(v.compiles) << file;
        EXPECT_GT(v.differing_pct, render::kLabMatchPct) << file;
        EXPECT_EQ(v.outcome, render::LabOutcome::Mistake) << file;
        EXPECT_EQ(v.mistake, name) << file << ": " << v.hint;
        // With its own hint.
        std::string hint;
        for (const auto& m : mistakes)
            if (m.name == name) hint = m.hint;
        EXPECT_FALSE(hint.empty()) << name;
        EXPECT_EQ(v.hint, hint) << file;
    }
    // The wrong-way comparison in its other form (the mistake's own text: wrong_way.glsl writes
    // `zLight - bias > depth ? 1.0 : 0.0`) is named too.
    const render::LabVerdict other = render::lab_check(
        *renderer, course.scene, settings,
        "float shadowTest(float zLight, float depth, float bias) {\n    return zLight > depth + bias ? 1.0 : 0.0;\n}\n", in);
    EXPECT_EQ(other.mistake, "wrong-way") << other.hint;
}

// Where every front end checks (render/lab.h): a file that defines none of the four functions
// draws the sheet's answer's own frame, since what it leaves out is the answer's; it is "no
// function of the sheet written", never a match.
TEST_F(Lab, AFileWritingNoFunctionIsNeverAMatch) {
    for (const char* file : {"empty.glsl", "comment_only.glsl", "helper_only.glsl"}) {
        std::ifstream f(test::test_data_dir() + "/snippets/" + file);
        std::stringstream text;
        text << f.rdbuf();
        const render::LabVerdict v = render::lab_check(*renderer, course.scene, settings, text.str(), in);
        ASSERT_TRUE(v.compiles) << file;
        EXPECT_EQ(v.outcome, render::LabOutcome::NoFunction) << file;
        EXPECT_FALSE(v.matches()) << file;
        EXPECT_TRUE(v.defines.empty()) << file;
        EXPECT_EQ(v.mistake, "") << file;
        EXPECT_EQ(v.hint, std::string(render::kLabNoFunctionHint)) << file;
        EXPECT_EQ(render::lab_outcome_name(v.outcome), "no-function");
        // The control: its frame is the answer's to the pixel, so the frame alone would call it a
        // match; only the rule keeps it from being one.
        EXPECT_EQ(v.differing_pct, 0.0) << file;
    }
    // The rule is the text's, not the frame's: the answer's own frame, given as the student's,
    // reads as a match with the answer's text and as no function with an empty one.
    const render::LabReference ref = render::lab_reference(*renderer, course.scene, settings, in);
    render::LabVerdict with_answer, with_nothing;
    with_answer.compiles = with_nothing.compiles = true;
    render::lab_verdict(with_answer, ref, read("answer.glsl"), ref.answer);
    render::lab_verdict(with_nothing, ref, "// nothing yet\n", ref.answer);
    EXPECT_EQ(with_answer.outcome, render::LabOutcome::Matches);
    EXPECT_EQ(with_answer.defines.size(), 4u);
    EXPECT_EQ(with_nothing.outcome, render::LabOutcome::NoFunction);
    // The sheet's answer itself still matches to 0 pixels, and says so.
    const render::LabVerdict answer = check("answer.glsl");
    EXPECT_EQ(answer.outcome, render::LabOutcome::Matches);
    EXPECT_EQ(answer.differing_pct, 0.0);
    EXPECT_EQ(answer.hint, "Matches the sheet's answer: every pixel is the same.");
}

// A mistake whose frame equals another's cannot be named: on the lab's check frames (the page's:
// t = 0.6 s at 256x192; grade's size, 192x144, at 0.3, 0.6 and 1.2 s) in each encoding and filter,
// every mistake the frame shows differs from the answer and from every other mistake by more than
// the match's kLabMatchPct. The only one not shown is no-texmapscale under the hard filter (its one
// tap has the offset (0, 0)).
TEST_F(Lab, EveryMistakesFrameDiffersFromTheAnswersAndFromEveryOthers) {
    struct Frame {
        double t;
        int w, h;
    };
    const Frame frames[] = {{0.6, 256, 192}, {0.3, 192, 144}, {0.6, 192, 144}, {1.2, 192, 144}};
    const auto differ = [](const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
        size_t n = 0;
        for (size_t i = 0; i < a.size() && i < b.size(); i += 4) n += std::abs(int(a[i]) - int(b[i])) > render::kLabPixelStep;
        return 100.0 * double(n) / double(a.size() / 4);
    };
    double closest = 101;  // the two frames nearest each other, said at the end
    std::string closest_pair;
    for (auto e : {shadow::Encoding::RGBA, shadow::Encoding::R8})
        for (auto f : {shadow::Filter::Hard, shadow::Filter::PCF2x2, shadow::Filter::PCF4x4})
            for (const Frame& fr : frames) {
                render::Settings s = settings;
                s.encoding = e;
                s.filter = f;
                scene::animate_course(course, fr.t, fr.t);
                const render::LabReference ref =
                    render::lab_reference(*renderer, course.scene, s, render::offscreen(fr.w, fr.h));
                const std::string where = std::string(shadow::to_string(e)) + " " + std::string(shadow::to_string(f)) + " t=" +
                                          std::to_string(fr.t) + " " + std::to_string(fr.w) + "x" + std::to_string(fr.h);
                ASSERT_EQ(ref.frames.size(), ref.mistakes.size());
                EXPECT_EQ(ref.mistakes.size(), e == shadow::Encoding::RGBA ? 8u : 5u);
                for (size_t i = 0; i < ref.frames.size(); ++i) {
                    const double vs_answer = differ(ref.frames[i], ref.answer);
                    const bool unseen = f == shadow::Filter::Hard && ref.mistakes[i].name == "no-texmapscale";
                    if (unseen) {
                        EXPECT_LE(vs_answer, render::kLabMatchPct) << where;
                        continue;
                    }
                    EXPECT_GT(vs_answer, render::kLabMatchPct) << where << ": " << ref.mistakes[i].name;
                    if (vs_answer < closest) {
                        closest = vs_answer;
                        closest_pair = ref.mistakes[i].name + " and the answer (" + where + ")";
                    }
                    for (size_t j = i + 1; j < ref.frames.size(); ++j) {
                        if (f == shadow::Filter::Hard && ref.mistakes[j].name == "no-texmapscale") continue;
                        const double d = differ(ref.frames[i], ref.frames[j]);
                        EXPECT_GT(d, render::kLabMatchPct) << where << ": " << ref.mistakes[i].name << " and "
                                                           << ref.mistakes[j].name;
                        if (d < closest) {
                            closest = d;
                            closest_pair = ref.mistakes[i].name + " and " + ref.mistakes[j].name + " (" + where + ")";
                        }
                    }
                }
            }
    std::printf("the closest two frames: %s, %.3f %% of the pixels apart\n", closest_pair.c_str(), closest);
}

// grade's report checks each function of a file alone (render::snippet_only): the others are the
// sheet's answer's. two_functions.glsl's unpackDepth is right and its shadowTest has no bias.
TEST_F(Lab, EachFunctionOfAFileIsCheckedAlone) {
    const std::string text = read("two_functions.glsl");
    const render::LabVerdict whole = render::lab_check(*renderer, course.scene, settings, text, in);
    EXPECT_EQ(whole.mistake, "no-bias");
    ASSERT_EQ(whole.defines.size(), 2u);
    const render::LabVerdict unpack =
        render::lab_check(*renderer, course.scene, settings, render::snippet_only(text, render::SnippetFn::UnpackDepth), in);
    ASSERT_TRUE(unpack.compiles) << (unpack.problems.empty() ? "" : unpack.problems[0].message);
    EXPECT_EQ(unpack.outcome, render::LabOutcome::Matches);
    EXPECT_EQ(unpack.defines, std::vector<render::SnippetFn>{render::SnippetFn::UnpackDepth});
    const render::LabVerdict test_alone =
        render::lab_check(*renderer, course.scene, settings, render::snippet_only(text, render::SnippetFn::ShadowTest), in);
    ASSERT_TRUE(test_alone.compiles);
    EXPECT_EQ(test_alone.mistake, "no-bias");
    // The control: red_only.glsl's unpackDepth alone is its mistake, not a match.
    const render::LabVerdict red = render::lab_check(
        *renderer, course.scene, settings, render::snippet_only(read("red_only.glsl"), render::SnippetFn::UnpackDepth), in);
    EXPECT_EQ(red.mistake, "red-only");
}

TEST_F(Lab, ACompileErrorKeepsTheLastGoodSnippets) {
    const std::string good = read("no_bias.glsl");
    ASSERT_TRUE(render::set_snippets(*renderer, course.scene, settings, good, in).empty());
    EXPECT_EQ(renderer->shaders().snippets(), good);
    const auto problems = render::set_snippets(*renderer, course.scene, settings, read("broken.glsl"), in);
    ASSERT_FALSE(problems.empty());
    // The info log's form is the implementation's, and so is where its parser recovers: where it
    // names the file's lines, they are the broken function's (lines 2-6). Mesa names the missing
    // semicolon's line (4) or the token after it (5); NVIDIA 580 also the function's first line
    // (2: "function "shadowTest" has no return statement", its recovery having eaten the return).
    // A line not mapped back through `#line 1 7` would be the preamble's, hundreds further on.
    for (const auto& p : problems)
        if (p.line > 0) {
            EXPECT_TRUE(p.line >= 2 && p.line <= 6) << p.line << ": " << p.message;
        }
    EXPECT_EQ(renderer->shaders().snippets(), good);
    // A refused file never reaches the compiler, nor does a setting the lab cannot run.
    EXPECT_EQ(render::set_snippets(*renderer, course.scene, settings, read("hostile_main.glsl"), in)[0].line, 3);
    render::Settings volumes = settings;
    volumes.technique = render::Technique::Volumes;
    const auto refused = render::set_snippets(*renderer, course.scene, volumes, good, in);
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_NE(refused[0].message.find("shadow map"), std::string::npos);
    EXPECT_EQ(renderer->shaders().snippets(), good);
}

TEST_F(Lab, TheLabsPlanHasTheLabVariantsAndTheSheetsBias) {
    const render::Settings s = render::lab_settings(settings);
    EXPECT_FALSE(s.bias_auto);
    EXPECT_FLOAT_EQ(s.effective_bias(), 0.0015f);
    EXPECT_EQ(s.pcf_kernel, shadow::PcfKernel::Full);
    const render::FramePlan plan = renderer->plan(course.scene, s, in);
    int lab = 0;
    for (const auto& p : plan.passes)
        for (const auto& d : p.draws)
            for (const auto& def : d.variant.defines) lab += def == "LAB";
    EXPECT_GT(lab, 0);
    EXPECT_NE(plan.describe().find("the shader lab's"), std::string::npos);
    // Without the lab, none.
    EXPECT_EQ(renderer->plan(course.scene, settings, in).describe().find("LAB"), std::string::npos);
}
