// The shader lab on a GL context (render/lab.h, docs/snippets.md): snippets files compiled into
// the renderer's own programs and checked against the sheet's answer on the course scene. What
// holds on any conformant context: a file that is the answer draws the answer's frame, each classic
// mistake is told apart from it, a file that does not compile leaves the last good snippets.
// Frames of the same function from two programs may round differently (GLSL ES 1.00 4.6.1
// promises invariance only within a program): "matches" allows render::kLabMatchPct of the pixels.
#include <gtest/gtest.h>

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
                                                         {"eight_bit_threshold.glsl", "8-bit-threshold"},
                                                         {"red_only.glsl", "red-only"},
                                                         {"detached.glsl", "detached"},
                                                         {"no_texmapscale.glsl", "no-texmapscale"}};
    for (const auto& [file, name] : cases) {
        const render::LabVerdict v = check(file);
        ASSERT_TRUE(v.compiles) << file;
        EXPECT_GT(v.differing_pct, render::kLabMatchPct) << file;
        EXPECT_EQ(v.mistake, name) << file << ": " << v.hint;
    }
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
