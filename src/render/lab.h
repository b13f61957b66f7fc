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

// One lab verdict on the frame of `scene` (at its time), `s` (lab_settings(s) with
// Aov::Visibility) and `in` (its size: in.output).
struct LabVerdict {
    bool compiles = false;
    std::vector<SnippetProblem> problems;  // why it does not compile (or is refused)
    int width = 0, height = 0;
    double differing_pct = 0;  // pixels whose visibility differs from the sheet's answer's, % of all
    std::string mistake;       // the classic mistake whose frame the student's matches ("" none)
    std::string hint;          // its hint, or a word on the match
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
// compiles, problems, width and height are the caller's; this fills the rest.
void lab_verdict(LabVerdict& v, const LabReference& ref, std::vector<std::uint8_t> student);

}  // namespace penumbra::render
