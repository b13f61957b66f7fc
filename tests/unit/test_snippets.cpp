// The shader lab's snippets (plan/snippets.h, docs/snippets.md): what the scan lets into the
// renderer's shaders and what it refuses, the sheet's answer and its mistakes, the compiler's
// messages brought back to the student's lines; and the sheet's packing's error on the CPU.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "plan/snippets.h"
#include "shadow/encoding.h"

using namespace penumbra;
using render::scan_snippets;
using render::SnippetFn;

namespace {

// The first problem's line and whether its message holds `words`.
void expect_refused(const std::string& text, int line, const std::string& words) {
    const auto scan = scan_snippets(text);
    ASSERT_FALSE(scan.problems.empty()) << text;
    EXPECT_EQ(scan.problems[0].line, line) << scan.problems[0].message;
    EXPECT_NE(scan.problems[0].message.find(words), std::string::npos) << scan.problems[0].message;
    EXPECT_TRUE(scan.defines.empty());
}

}  // namespace

TEST(Snippets, TheSheetsAnswerAndTheSkeletonDefineAllFourFunctions) {
    for (auto e : {shadow::Encoding::R8, shadow::Encoding::RGBA}) {
        const auto scan = scan_snippets(render::sheet_answer(e));
        EXPECT_TRUE(scan.problems.empty()) << scan.problems[0].message;
        EXPECT_EQ(scan.defines.size(), 4u);
    }
    const auto skeleton = scan_snippets(render::snippet_skeleton());
    EXPECT_TRUE(skeleton.problems.empty());
    EXPECT_EQ(skeleton.defines.size(), 4u);
    // The two answers differ where the sheet does: the red channel against bit-shift packing.
    EXPECT_NE(render::sheet_answer(shadow::Encoding::R8).find("rgbaDepth.r"), std::string::npos);
    EXPECT_NE(render::sheet_answer(shadow::Encoding::RGBA).find("bitShift"), std::string::npos);
}

TEST(Snippets, EachMistakeIsOneFunctionThatPassesTheScan) {
    const auto rgba = render::snippet_mistakes(shadow::Encoding::RGBA);
    const auto r8 = render::snippet_mistakes(shadow::Encoding::R8);
    EXPECT_EQ(rgba.size(), 8u);
    EXPECT_EQ(r8.size(), 5u);  // no bit-shift packing to get wrong
    for (const auto& m : rgba) {
        const auto scan = scan_snippets(m.text);
        EXPECT_TRUE(scan.problems.empty()) << m.name;
        EXPECT_EQ(scan.defines.size(), 1u) << m.name;
        EXPECT_FALSE(m.hint.empty());
        // Each name once: a verdict names one.
        int same = 0;
        for (const auto& o : rgba) same += o.name == m.name;
        EXPECT_EQ(same, 1) << m.name;
    }
    std::vector<std::string> names;
    for (const auto& m : rgba) names.push_back(m.name);
    EXPECT_EQ(names, (std::vector<std::string>{"no-bias", "wrong-way", "bias-wrong-side", "8-bit-threshold", "red-only",
                                               "unpack-reversed", "detached", "no-texmapscale"}));
    names.clear();
    for (const auto& m : r8) names.push_back(m.name);
    EXPECT_EQ(names, (std::vector<std::string>{"no-bias", "wrong-way", "bias-wrong-side", "detached", "no-texmapscale"}));
}

TEST(Snippets, NamesTheFunctionsAFileDefinesInTheContractsOrder) {
    EXPECT_EQ(render::snippet_names({}), "");
    EXPECT_EQ(render::snippet_names({SnippetFn::ShadowTest, SnippetFn::PackDepth}), "packDepth shadowTest");
    EXPECT_EQ(render::snippet_names(scan_snippets(render::sheet_answer(shadow::Encoding::RGBA)).defines),
              "packDepth unpackDepth shadowTest offset_lookup");
    // What defines none: nothing, comments (a function in one too), a helper of its own.
    for (const char* none : {"", "// vec4 packDepth(float z) { return vec4(z); }\n", "/* float shadowTest */",
                             "float half(float x) { return 0.5 * x; }\n"}) {
        const auto scan = scan_snippets(none);
        EXPECT_TRUE(scan.problems.empty()) << none;
        EXPECT_EQ(render::snippet_names(scan.defines), "") << none;
    }
}

TEST(Snippets, OneFunctionAloneRenamesTheOthersOutOfTheContract) {
    const std::string text =
        "// shadowTest and unpackDepth, and a helper that calls unpackDepth\n"
        "float unpackDepth(const in vec4 rgbaDepth) { return rgbaDepth.r; }\n"
        "float twice(vec4 t) { return 2.0 * unpackDepth(t); /* unpackDepth */ }\n"
        "float shadowTest(float zLight, float depth, float bias) { return zLight > depth + 1.0e-3 ? 0.0 : 1.0; }\n";
    const std::string only = render::snippet_only(text, SnippetFn::ShadowTest);
    const auto scan = scan_snippets(only);
    ASSERT_TRUE(scan.problems.empty()) << scan.problems[0].message << "\n" << only;
    EXPECT_EQ(scan.defines, std::vector<SnippetFn>{SnippetFn::ShadowTest});
    // Calls renamed with the function, comments and numbers as they were.
    EXPECT_NE(only.find("float unpackDepth_notChecked(const in vec4"), std::string::npos) << only;
    EXPECT_NE(only.find("2.0 * unpackDepth_notChecked(t); /* unpackDepth */"), std::string::npos) << only;
    EXPECT_NE(only.find("// shadowTest and unpackDepth,"), std::string::npos) << only;
    EXPECT_NE(only.find("1.0e-3"), std::string::npos) << only;
    // So the block takes the sheet's answer's unpackDepth.
    EXPECT_NE(render::snippet_block(only, shadow::Encoding::RGBA).find("dot(rgbaDepth, bitShift)"), std::string::npos);
    // The other way round: the test renamed, unpackDepth kept.
    const auto other = scan_snippets(render::snippet_only(text, SnippetFn::UnpackDepth));
    ASSERT_TRUE(other.problems.empty());
    EXPECT_EQ(other.defines, std::vector<SnippetFn>{SnippetFn::UnpackDepth});
    // The control: the file itself defines both.
    EXPECT_EQ(scan_snippets(text).defines.size(), 2u);
}

TEST(Snippets, FindsWhichFunctionsAFileDefinesWhateverItsQualifiersAndNames) {
    const auto scan = scan_snippets(
        "// a comment naming packDepth(float z)\n"
        "float helper(float x) { return x * 2.0; }\n"
        "highp float unpackDepth(const in highp vec4 texel) { return helper(texel.r); }\n"
        "float unpackDepth(vec4 t);\n"  // a prototype defines nothing
        "vec4 offset_lookup(sampler2D m, vec3 c, vec2 o) { return texture2D(m, c.xy + o * texmapscale); }\n");
    ASSERT_TRUE(scan.problems.empty()) << scan.problems[0].message;
    ASSERT_EQ(scan.defines.size(), 2u);
    EXPECT_EQ(scan.defines[0], SnippetFn::UnpackDepth);
    EXPECT_EQ(scan.defines[1], SnippetFn::OffsetLookup);
}

TEST(Snippets, RefusesAContractFunctionWithAnotherSignature) {
    expect_refused("float unpackDepth(vec3 rgb) { return rgb.r; }\n", 1, "float unpackDepth(const in vec4 rgbaDepth)");
    expect_refused("\nvec4 shadowTest(float z, float d, float b) { return vec4(1.0); }\n", 2, "shadowTest must be");
    expect_refused("float shadowTest(float z, float d) { return 1.0; }\n", 1, "shadowTest must be");
}

TEST(Snippets, RefusesWhatWouldReachIntoTheRenderersShader) {
    expect_refused("void main() { }\n", 1, "main");
    expect_refused("\n\nuniform sampler2D mine;\n", 3, "uniform");
    expect_refused("varying vec2 v;\n", 1, "varying");
    expect_refused("#define bias 0.0\n", 1, "preprocessor");
    expect_refused("float f() { return 1.0; }\n#extension GL_OES_standard_derivatives : enable\n", 2, "preprocessor");
    expect_refused("float shadowTest(float z, float d, float b) { return z > u_bias ? 0.0 : 1.0; }\n", 1, "u_bias");
    expect_refused("vec4 packDepth(float z) { gl_FragColor = vec4(z); return vec4(z); }\n", 1, "gl_FragColor");
    expect_refused("float shadowTest(float z, float d, float b) { discard; }\n", 1, "discard");
    expect_refused("void set(out float x) { x = 1.0; }\n", 1, "out parameter");
    expect_refused("vec2 texmapscale;\n", 1, "texmapscale");
    // A function returning a struct would be no function the loop checks see.
    expect_refused("struct S { float x; };\nS f() { S s; for (int i = 0; i < 4; i += 0) s.x = 1.0; return s; }\n", 1, "struct");
}

TEST(Snippets, RefusesTextThatIsNotPrintableAsciiOrTooLong) {
    expect_refused("float f() { return 1.0; }\nfloat caf\xc3\xa9() { return 1.0; }\n", 2, "0xC3");
    // In a comment (a student's own language) any byte but NUL is taken, and written as '?'.
    const std::string danish = "// skyggetest: \xc3\xb8 og \xc3\xa5\nfloat f() { return 1.0; } /* \xc3\xa6 */\n";
    EXPECT_TRUE(scan_snippets(danish).problems.empty());
    const std::string block = render::snippet_block(danish, shadow::Encoding::RGBA);
    EXPECT_NE(block.find("// skyggetest: ?? og ??\nfloat f() { return 1.0; } /* ?? */\n"), std::string::npos);
    expect_refused(std::string("float f() {\0 return 1.0; }", 26), 1, "0x00");
    expect_refused(std::string("// a\0 comment\n", 15), 1, "0x00");
    expect_refused("/* never closed\n", 1, "never closed");
    expect_refused("float f() { return 1.0; \n", 1, "never closed");
    expect_refused(std::string(render::kMaxSnippetBytes + 1, ' '), 0, "may hold");
    // Exactly the limit is taken.
    EXPECT_TRUE(scan_snippets(std::string(render::kMaxSnippetBytes, ' ')).problems.empty());
}

TEST(Snippets, LoopsMustBeShortWithLiteralBoundsAndAConstantIndex) {
    // Taken: a short loop, counting down, float steps, one nested loop.
    EXPECT_TRUE(scan_snippets("float f(vec4 t) { float s = 0.0; for (int i = 0; i < 4; ++i) s += t[i]; return s; }\n")
                    .problems.empty());
    EXPECT_TRUE(scan_snippets("float f() { float s = 0.0; for (float x = -1.5; x <= 1.5; x += 1.0) {\n"
                              "  for (int i = 3; i >= 0; i--) { s += x; } } return s; }\n")
                    .problems.empty());
    expect_refused("float f() { float s = 0.0; while (s < 1.0) s += 0.1; return s; }\n", 1, "while");
    expect_refused("float f() { float s = 0.0; do { s += 1.0; } while (s < 2.0); return s; }\n", 1, "do loop");
    expect_refused("float f(float n) { float s = 0.0;\nfor (int i = 0; i < int(n); ++i) s += 1.0; return s; }\n", 2,
                   "literal numbers");
    expect_refused("float f() { float s = 0.0; for (int i = 0; i < 17; ++i) s += 1.0; return s; }\n", 1, "more than 16");
    expect_refused("float f() { float s = 0.0; for (int i = 0; i < 4; i += 0) s += 1.0; return s; }\n", 1, "never ends");
    expect_refused("float f() { float s = 0.0; for (int i = 0; i < 4; ++i) { i = 0; } return s; }\n", 1,
                   "assigns the loop index");
    expect_refused("float f() { float s = 0.0; for (int i = 0; i < 2; ++i) for (int j = 0; j < 2; ++j)\n"
                   "for (int k = 0; k < 2; ++k) s += 1.0; return s; }\n",
                   2, "nested more than 2");
}

TEST(Snippets, RefusesRecursionAndWorkThatMultipliesPastTheBound) {
    expect_refused("float g(float x);\nfloat f(float x) { return g(x); }\nfloat g(float x) { return f(x); }\n"
                   "float shadowTest(float z, float d, float b) { return f(z); }\n",
                   2, "calls itself");
    // 1 + 16 iterations + 16 x (1 + 16) = 289 steps for b, then 16 x 289 in shadowTest.
    expect_refused("float a(float x) { for (int i = 0; i < 16; ++i) x += 1.0; return x; }\n"
                   "float b(float x) { for (int i = 0; i < 16; ++i) x += a(x); return x; }\n"
                   "float shadowTest(float z, float d, float b2) { for (int i = 0; i < 16; ++i) d += b(d); return 1.0; }\n",
                   3, "4641 steps");
    // The control: the same calls without the outer loop are within it (1 + 289).
    EXPECT_TRUE(scan_snippets("float a(float x) { for (int i = 0; i < 16; ++i) x += 1.0; return x; }\n"
                              "float b(float x) { for (int i = 0; i < 8; ++i) x += a(x); return x; }\n"
                              "float shadowTest(float z, float d, float b2) { return b(d); }\n")
                    .problems.empty());
}

TEST(Snippets, TheBlockTakesTheAnswerForWhatTheFileLeavesOutAndNumbersTheFilesLines) {
    const std::string text = "float shadowTest(float zLight, float depth, float bias) { return 1.0; }\n";
    const std::string block = render::snippet_block(text, shadow::Encoding::RGBA);
    // The answer's packDepth, unpackDepth and offset_lookup before the file, not its shadowTest.
    const size_t line = block.find("#line 1 7\n");
    ASSERT_NE(line, std::string::npos);
    EXPECT_LT(block.find("vec4 packDepth("), line);
    EXPECT_LT(block.find("float unpackDepth("), line);
    EXPECT_LT(block.find("vec4 offset_lookup("), line);
    EXPECT_EQ(block.find("float shadowTest("), line + 10);
    EXPECT_NE(block.find("#line 1 0\n"), std::string::npos);
    // R8's answer reads red alone.
    EXPECT_NE(render::snippet_block("", shadow::Encoding::R8).find("return rgbaDepth.r;"), std::string::npos);
}

TEST(Snippets, CompilerMessagesComeBackAtTheStudentsLines) {
    // Mesa, ANGLE / SwiftShader, NVIDIA; a message about the renderer's own source has no line.
    const auto p = render::snippet_log_problems(
        "7:4(5): error: syntax error, unexpected RETURN\n"
        "ERROR: 7:12: 'x' : undeclared identifier\n"
        "7(3) : error C1008: undefined variable \"y\"\n"
        "0:210(2): error: `return' with wrong type\n"
        "17:2(1): error: not ours\n");
    ASSERT_EQ(p.size(), 5u);
    EXPECT_EQ(p[0].line, 4);
    EXPECT_EQ(p[0].message, "error: syntax error, unexpected RETURN");
    EXPECT_EQ(p[1].line, 12);
    EXPECT_EQ(p[1].message, "'x' : undeclared identifier");
    EXPECT_EQ(p[2].line, 3);
    EXPECT_EQ(p[2].message, "error C1008: undefined variable \"y\"");
    EXPECT_EQ(p[3].line, 0);
    EXPECT_EQ(p[4].line, 0);
}

// The sheet's bit-shift packing (the lab's reference) against the renderer's: its channels are
// multiples of 1/256 that the store rounds to bytes of 1/255, so a depth reads back up to 0.00195
// nearer, more than the sheet's bias 0.0015 for depths 0.504..0.621: acne there, on any context
// whose store rounds as GLES 2.0 2.1.2 asks. The renderer's packing reads back within 2^-24.
TEST(Snippets, TheSheetsPackingReadsSomeDepthsNearerThanItsBias) {
    double nearest = 0.0, lo = 1.0, hi = 0.0;
    double exact = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const double z = (i + 0.5) / n;
        const double e = shadow::sheet_unpack_rgba(shadow::sheet_pack_rgba(z, shadow::UnormRounding::Round)) - z;
        nearest = std::min(nearest, e);
        if (e < -0.0015) lo = std::min(lo, z), hi = std::max(hi, z);
        exact = std::max(exact, std::abs(double(shadow::unpack_rgba(shadow::pack_rgba(float(z)))) - double(float(z))));
    }
    EXPECT_NEAR(nearest, -0.00195, 0.00002);
    EXPECT_NEAR(lo, 0.504, 0.001);
    EXPECT_NEAR(hi, 0.621, 0.001);
    EXPECT_LE(exact, 1.0 / 16777216.0);
    // Under 0.5 the rounding reads depths farther, never nearer than the bias.
    for (int i = 0; i < n / 2; ++i) {
        const double z = (i + 0.5) / n;
        EXPECT_GT(shadow::sheet_unpack_rgba(shadow::sheet_pack_rgba(z, shadow::UnormRounding::Round)) - z, -0.0015) << z;
    }
}

TEST(Snippets, ALogsLineNumberPastSevenDigitsIsNoLine) {
    // fuzz.snippets found an int overflow here: "7:" and a run of digits.
    const auto p = render::snippet_log_problems("7:33333333333333333333: error: x\n7:9999999: error: y\n");
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0].line, 0);
    EXPECT_EQ(p[1].line, 9999999);
}
