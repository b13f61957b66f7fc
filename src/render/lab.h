// The shader lab's check (docs/snippets.md): a snippets file's frame beside the sheet's answer's
// on the same frame, and the classic mistake it matches. Shared by `penumbra render --snippets`,
// `penumbra grade`, the pages' lab panel and the desktop app.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "plan/settings.h"
#include "render/renderer.h"
#include "plan/snippets.h"
#include "scene/scene.h"

namespace penumbra::render {

// `s` as the lab runs it (what it cannot run, lab_refusal in plan/settings.h names): Settings::lab
// on, the bias constant (the sheet's for the encoding unless one was given: --bias auto is
// dropped), every tap of the PCF kernel (the sheet's 4x4, no early exit), one map where the
// cascades were auto, the course's tight fit (the table in the map) where the shadows fit was on.
Settings lab_settings(Settings s);

// Where the lab's frames compare: pixels whose visibility differs by more than one step of 8 bits
// (a PCF fraction differs by 1/16 at least), and the share of such pixels up to which a frame
// still "matches" another. Two programs that compute the same function may still round
// differently: GLSL ES 1.00 section 4.6.1 promises invariance only to outputs declared invariant
// and within one program, so a student's equivalent code may move a few edge pixels.
inline constexpr int kLabPixelStep = 1;
inline constexpr double kLabMatchPct = 0.1;

// The snippets compiled on the renderer's context into the lab's programs for `scene` and `s`
// (lab_settings(s)): the static scan's problems, else the compiler's at the student's lines.
// Empty: the renderer now draws Settings::lab frames with them. On a problem the renderer keeps
// the snippets it had (the last good frame stays).
std::vector<SnippetProblem> set_snippets(Renderer& r, const scene::Scene& scene, const Settings& s,
                                         std::string_view text, const FrameInputs& in = {});

// What a verdict says, decided in lab_verdict alone so that grade's CSV and report, the page's
// panel and the desktop app say the same:
// - Error: refused by the scan, or not compiled (LabVerdict::problems say why);
// - NoFunction: the file defines none of the four functions (empty, comments only, or only helpers of
//   its own). It is never a match: the functions a file leaves out are the sheet's answer's, so its
//   frame is the answer's own whatever it holds;
// - Matches: the sheet's answer's frame, up to kLabMatchPct of the pixels;
// - Mistake: a classic mistake's frame (LabVerdict::mistake names it);
// - Differs: neither.
enum class LabOutcome { Error, NoFunction, Matches, Mistake, Differs };
// "error", "no-function", "matches", "mistake", "differs": grade's verdict column, the page's JSON.
std::string_view lab_outcome_name(LabOutcome o);
// The verdict's sentence for a file that defines none of the functions; lab_no_function(text) is
// it for such a text (that passes the scan), "" for any other: the desktop app says it on loading.
inline constexpr std::string_view kLabNoFunctionHint =
    "No function of the sheet written: the file defines none of packDepth, unpackDepth, shadowTest and "
    "offset_lookup, so the frame is the sheet's answer's own. Write at least one of them.";
std::string lab_no_function(std::string_view text);

// One lab verdict on the frame of `scene` (at its time), `s` (lab_settings(s) with
// Aov::Visibility) and `in` (its size: in.output).
struct LabVerdict {
    bool compiles = false;
    std::vector<SnippetProblem> problems;  // why it does not compile (or is refused)
    std::vector<SnippetFn> defines;        // the contract's functions the file defines
    LabOutcome outcome = LabOutcome::Error;
    int width = 0, height = 0;
    double differing_pct = 0;  // pixels whose visibility differs from the sheet's answer's, % of all
    std::string mistake;       // the classic mistake whose frame the student's matches ("" none)
    std::string hint;          // its hint, or a word on the match (kLabNoFunctionHint for NoFunction)
    bool matches() const { return outcome == LabOutcome::Matches; }
    // Visibility images, RGBA8 top row first: the student's, the sheet's answer's, and the
    // difference (red: the student's darker, green: lighter, grey: the same).
    std::vector<std::uint8_t> student, reference, difference;
};
// Renders `text`'s frame, the sheet's answer's and each classic mistake's on `r` (visibility AOV)
// and compares them. Leaves the renderer with the student's snippets when they compile, else
// with the ones it had.
LabVerdict lab_check(Renderer& r, const scene::Scene& scene, const Settings& s, std::string_view text,
                     const FrameInputs& in = {});

// lab_check in parts, for a verdict over several frames (`penumbra grade`): the visibility frame
// (RGBA8, top row first) of snippets `text` that set_snippets took; the sheet's answer's and each
// classic mistake's (frames of several times may be appended one after the other, the same for
// all); the verdict on a student's frames against them.
std::vector<std::uint8_t> lab_frame(Renderer& r, const scene::Scene& scene, const Settings& s, const FrameInputs& in,
                                    const std::string& text);
struct LabReference {
    std::vector<std::uint8_t> answer;
    std::vector<SnippetMistake> mistakes;
    std::vector<std::vector<std::uint8_t>> frames;  // one per mistake
    void append(const LabReference& o);
};
LabReference lab_reference(Renderer& r, const scene::Scene& scene, const Settings& s, const FrameInputs& in);
// compiles, problems, width and height are the caller's; this fills the rest from `text` (the
// snippets the student's frames were drawn with: which functions it defines) and those frames.
void lab_verdict(LabVerdict& v, const LabReference& ref, std::string_view text, std::vector<std::uint8_t> student);

}  // namespace penumbra::render
