// The shader lab's snippets (docs/snippets.md): GLSL ES 1.00 text holding any of the sheet's
// functions (W09P2c and its PCF), checked here without a GL context, then compiled into the
// renderer's own depth and camera programs (the LAB variants: Settings::lab) in place of its exact
// packing and lookup. The functions a file leaves out are the sheet's answer's, so each one can be
// checked alone, and a file that writes what the sheet teaches renders the sheet's answer's frame.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "shadow/encoding.h"

namespace penumbra::render {

// The four functions of the contract, with the sheet's names and signatures.
enum class SnippetFn { PackDepth, UnpackDepth, ShadowTest, OffsetLookup };
inline constexpr SnippetFn kAllSnippetFns[] = {SnippetFn::PackDepth, SnippetFn::UnpackDepth, SnippetFn::ShadowTest,
                                               SnippetFn::OffsetLookup};
// "packDepth", "unpackDepth", "shadowTest", "offset_lookup".
std::string_view snippet_name(SnippetFn f);
// The function's signature as the contract writes it, e.g. "float unpackDepth(const in vec4 rgbaDepth)".
std::string_view snippet_signature(SnippetFn f);

// One problem of a snippets file: the line of the student's text it is at (1-based; 0: the whole
// file) and one sentence.
struct SnippetProblem {
    int line = 0;
    std::string message;
};

// The most text a snippets file may hold.
inline constexpr std::size_t kMaxSnippetBytes = 64 * 1024;
// The most iterations of one loop, and the deepest loop nesting.
inline constexpr int kMaxLoopIterations = 16;
inline constexpr int kMaxLoopDepth = 2;
// The most steps one call of a contract function may take, counted without compiling: 1, plus 1
// per loop iteration and per call of a built-in (texture2D, dot, a constructor), plus each call of
// a function of the file times its own steps, each times the iterations of the loops around it
// (the sheet's answer: 2 to 4 each). A file within it runs at most 16 x 3 x 256 steps per pixel.
inline constexpr int kMaxSnippetCost = 256;

// What a snippets file is, found without compiling it: the contract's functions it defines, and
// the problems that keep it out of the renderer's shaders (too long; a byte outside printable
// ASCII; a preprocessor directive; `main`; a uniform, attribute or varying of its own; a name the
// renderer keeps: u_*, a_*, v_*, g_*, gl_* other than the built-in functions, penumbra*; a `while`
// or `do` loop; a `for` loop whose bounds are not literal numbers or that runs more than
// kMaxLoopIterations times or assigns its index; loops nested deeper than kMaxLoopDepth; an out
// or inout parameter; discard; a struct; recursion; a contract function costing more than kMaxSnippetCost;
// a contract function with another signature). Never throws.
struct SnippetScan {
    std::vector<SnippetFn> defines;        // in kAllSnippetFns order
    std::vector<SnippetProblem> problems;  // empty: it may be compiled
    bool defines_fn(SnippetFn f) const;
};
SnippetScan scan_snippets(std::string_view text);
// The functions, space-separated in kAllSnippetFns order ("packDepth unpackDepth"; "" for none):
// `penumbra grade`'s functions column.
std::string snippet_names(const std::vector<SnippetFn>& fns);

// `text` with only `f` of the contract's functions: every other contract function it defines is
// renamed out of the contract (its name and each call of it, outside comments, get the suffix
// "_notChecked"), so snippet_block takes the sheet's answer for them. A call of one of them from
// `f` still calls the student's own, renamed. `text` must have passed scan_snippets; the result
// passes it too unless the file already names something `NAME_notChecked`.
std::string snippet_only(std::string_view text, SnippetFn f);

// The sheet's answer (02561 W09, "Drawing depth" and "Shadow mapping in the fragment shader") as a
// snippets file: for Encoding::R8 the depth in the red channel, read back from red; for RGBA the
// bit-shift packing and its unpackDepth. Both with the test `zLight > depth + bias` (the caller
// passes the sheet's bias: 0.005 for R8, 0.0015 for RGBA) and the 4x4 lookup's offset_lookup.
// A starter skeleton: the four signatures with bodies that compile and draw no shadow.
std::string sheet_answer(shadow::Encoding e);
std::string sheet_answer_fn(SnippetFn f, shadow::Encoding e);  // one function of it
std::string snippet_skeleton();

// The GLSL inserted into a LAB variant where pack.glsl marks it: the sheet's answer's functions
// that `text` does not define, then `text` itself under `#line 1 kSnippetSourceString`, so a
// compiler's messages about it name the student's lines. `text` must have passed scan_snippets.
inline constexpr int kSnippetSourceString = 7;
std::string snippet_block(std::string_view text, shadow::Encoding e);

// A GL info log's messages about the snippet's source string (kSnippetSourceString), each with
// the student's line, in the formats of Mesa ("7:3(12): error: ..."), ANGLE and SwiftShader
// ("ERROR: 7:3: ..."), and NVIDIA ("7(3) : error ..."). Messages naming no line of it come back
// with line 0.
std::vector<SnippetProblem> snippet_log_problems(std::string_view log);

// The classic mistakes the sheet warns of, each as the sheet's answer with that one mistake: the
// page and `penumbra grade` render them beside a student's frame and give the hint of the one the
// student's frame matches.
struct SnippetMistake {
    std::string name;  // "no-bias", "wrong-way", "bias-wrong-side", "8-bit-threshold", "red-only",
                       // "unpack-reversed", "detached", "no-texmapscale"
    std::string hint;  // one or two sentences for the student
    std::string text;  // the snippets file that makes it
};
// Those that apply to the encoding (R8 has no bit-shift to get wrong).
std::vector<SnippetMistake> snippet_mistakes(shadow::Encoding e);

}  // namespace penumbra::render
