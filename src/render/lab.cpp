#include "render/lab.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace penumbra::render {

Settings lab_settings(Settings s) {
    s.lab = true;
    if (s.bias_auto) {
        s.bias_auto = false;
        s.bias.reset();
    }
    s.pcf_kernel = shadow::PcfKernel::Full;
    if (s.cascades == 0) s.cascades = 1;
    // The course's map, the table in it: the mistakes' acne shows there (W09P2c's default).
    if (s.light_fit == LightFit::Shadows) s.light_fit = LightFit::Tight;
    return s;
}

namespace {

// The compiler's messages about the snippets (or, when none names their lines, its first error).
std::vector<SnippetProblem> compile_problems(const std::vector<std::string>& failures) {
    std::vector<SnippetProblem> out;
    for (const std::string& f : failures)
        for (SnippetProblem& p : snippet_log_problems(f))
            if (p.line > 0 && std::none_of(out.begin(), out.end(), [&](const SnippetProblem& q) {
                    return q.line == p.line && q.message == p.message;
                }))
                out.push_back(std::move(p));
    if (!out.empty()) return out;
    for (const std::string& f : failures) {
        // "LABEL: fragment shader failed to compile: LOG": the log's first line that says error.
        for (const SnippetProblem& p : snippet_log_problems(f)) {
            std::string lower = p.message;
            std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
            if (lower.find("error") != std::string::npos && lower.find("failed to") == std::string::npos)
                return {{0, p.message}};
        }
        return {{0, f.substr(0, 300)}};
    }
    return out;
}

// The share of pixels (%) whose red channels differ by more than kLabPixelStep.
double differing_pct(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    const size_t n = std::min(a.size(), b.size()) / 4;
    if (n == 0) return 0;
    size_t differ = 0;
    for (size_t i = 0; i < n; ++i) differ += std::abs(int(a[4 * i]) - int(b[4 * i])) > kLabPixelStep;
    return 100.0 * static_cast<double>(differ) / static_cast<double>(n);
}

std::vector<std::uint8_t> difference(const std::vector<std::uint8_t>& student, const std::vector<std::uint8_t>& ref) {
    std::vector<std::uint8_t> out(ref.size());
    for (size_t i = 0; i + 3 < out.size() && i + 3 < student.size(); i += 4) {
        const int d = int(student[i]) - int(ref[i]);
        const std::uint8_t grey = static_cast<std::uint8_t>(64 + ref[i] / 2);
        if (d < -kLabPixelStep) {
            out[i] = 255, out[i + 1] = 32, out[i + 2] = 32;  // the student's darker
        } else if (d > kLabPixelStep) {
            out[i] = 32, out[i + 1] = 220, out[i + 2] = 32;  // lighter
        } else {
            out[i] = out[i + 1] = out[i + 2] = grey;
        }
        out[i + 3] = 255;
    }
    return out;
}

}  // namespace

std::vector<SnippetProblem> set_snippets(Renderer& r, const scene::Scene& scene, const Settings& s,
                                         std::string_view text, const FrameInputs& in) {
    const SnippetScan scan = scan_snippets(text);
    if (!scan.problems.empty()) return scan.problems;
    const Settings ls = lab_settings(s);
    if (std::string why = lab_refusal(ls); !why.empty()) return {{0, why}};
    if (std::string why = r.check(scene, ls, in); !why.empty()) return {{0, why}};
    // The lab's programs of this frame and of its visibility view (lab_frame's).
    std::vector<Variant> variants;
    std::vector<std::string> keys;
    Settings visibility = ls;
    visibility.aov = Aov::Visibility;
    for (const Settings* t : {&ls, static_cast<const Settings*>(&visibility)})
        for (const Pass& p : r.plan(scene, *t, in).passes)
            for (const Draw& d : p.draws)
                if (std::find(d.variant.defines.begin(), d.variant.defines.end(), "LAB") != d.variant.defines.end() &&
                    std::find(keys.begin(), keys.end(), d.variant.key()) == keys.end()) {
                    keys.push_back(d.variant.key());
                    variants.push_back(d.variant);
                }
    std::vector<std::string> failed = check_variants(variants, std::string(text));
    if (!failed.empty()) return compile_problems(failed);
    r.set_snippets(std::string(text));
    return {};
}

std::vector<std::uint8_t> lab_frame(Renderer& r, const scene::Scene& scene, const Settings& s, const FrameInputs& in,
                                    const std::string& text) {
    Settings ls = lab_settings(s);
    ls.aov = Aov::Visibility;
    r.set_snippets(text);
    r.render(scene, ls, in);
    return r.read_image(in.output.name);
}

void LabReference::append(const LabReference& o) {
    answer.insert(answer.end(), o.answer.begin(), o.answer.end());
    if (mistakes.empty()) {
        mistakes = o.mistakes;
        frames.resize(mistakes.size());
    }
    for (size_t i = 0; i < frames.size() && i < o.frames.size(); ++i)
        frames[i].insert(frames[i].end(), o.frames[i].begin(), o.frames[i].end());
}

LabReference lab_reference(Renderer& r, const scene::Scene& scene, const Settings& s, const FrameInputs& in) {
    const std::string kept = r.shaders().snippets();
    LabReference ref;
    ref.answer = lab_frame(r, scene, s, in, "");
    ref.mistakes = snippet_mistakes(s.encoding);
    for (const SnippetMistake& m : ref.mistakes) ref.frames.push_back(lab_frame(r, scene, s, in, m.text));
    r.set_snippets(kept);
    return ref;
}

std::string_view lab_outcome_name(LabOutcome o) {
    switch (o) {
        case LabOutcome::Error: return "error";
        case LabOutcome::NoFunction: return "no-function";
        case LabOutcome::Matches: return "matches";
        case LabOutcome::Mistake: return "mistake";
        case LabOutcome::Differs: return "differs";
    }
    return "";
}

std::string lab_no_function(std::string_view text) {
    const SnippetScan scan = scan_snippets(text);
    return scan.problems.empty() && scan.defines.empty() ? std::string(kLabNoFunctionHint) : std::string();
}

void lab_verdict(LabVerdict& v, const LabReference& ref, std::string_view text, std::vector<std::uint8_t> student) {
    v.defines = scan_snippets(text).defines;
    v.student = std::move(student);
    v.reference = ref.answer;
    v.differing_pct = differing_pct(v.student, v.reference);
    v.difference = difference(v.student, v.reference);
    v.mistake.clear();
    v.hint.clear();
    // Before any comparison: a file that writes none of the functions draws the answer's frame
    // (its frames were drawn, so the scan took it: no function defined is lab_no_function's case).
    if (v.defines.empty()) {
        v.outcome = LabOutcome::NoFunction;
        v.hint = std::string(kLabNoFunctionHint);
        return;
    }
    if (v.differing_pct <= kLabMatchPct) {
        v.outcome = LabOutcome::Matches;
        v.hint = v.differing_pct == 0 ? "Matches the sheet's answer: every pixel is the same."
                                      : "Matches the sheet's answer (the few pixels that differ are rounding).";
        return;
    }
    v.outcome = LabOutcome::Differs;
    double best = 101;
    for (size_t i = 0; i < ref.mistakes.size() && i < ref.frames.size(); ++i) {
        // A mistake that these frames do not show (the offsets under the hard filter) tells nothing.
        if (differing_pct(ref.frames[i], ref.answer) <= kLabMatchPct) continue;
        const double d = differing_pct(v.student, ref.frames[i]);
        if (d <= kLabMatchPct && d < best) {
            best = d;
            v.mistake = ref.mistakes[i].name;
            v.hint = ref.mistakes[i].hint;
            v.outcome = LabOutcome::Mistake;
        }
    }
    if (v.mistake.empty())
        v.hint = "Differs from the sheet's answer and matches none of the classic mistakes: the difference view "
                 "shows where (red: darker than the answer, green: lighter).";
}

LabVerdict lab_check(Renderer& r, const scene::Scene& scene, const Settings& s, std::string_view text,
                     const FrameInputs& in) {
    LabVerdict v;
    v.width = in.output.width;
    v.height = in.output.height;
    v.problems = set_snippets(r, scene, s, text, in);
    if (!v.problems.empty()) {
        v.defines = scan_snippets(text).defines;  // none where the scan refused it
        return v;
    }
    v.compiles = true;
    const LabReference ref = lab_reference(r, scene, s, in);
    lab_verdict(v, ref, text, lab_frame(r, scene, s, in, std::string(text)));
    return v;
}

}  // namespace penumbra::render
