#include "lab_command.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#ifdef PENUMBRA_HAVE_TRUTH
#include "bench.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#endif
#include "cli_options.h"
#include "gl/caps.h"
#include "measure.h"
#include "measure/image_io.h"
#include "render/lab.h"
#include "scene/printable.h"

namespace fs = std::filesystem;

namespace penumbra::tools {

std::string read_snippets(const std::string& option, const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec))
        throw CommandError{option + " " + scene::printable(path) + ": is a folder, not a snippets file", 2};
    std::ifstream in(path, std::ios::binary);
    if (!in) throw CommandError{option + " " + scene::printable(path) + ": cannot read it (" + std::strerror(errno) + ")", 2};
    std::string text(render::kMaxSnippetBytes + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<size_t>(in.gcount()));
    if (in.bad()) throw CommandError{option + " " + scene::printable(path) + ": cannot read it", 2};
    if (text.size() > render::kMaxSnippetBytes) {
        // Said by the scan with the file's whole size.
        const auto size = fs::file_size(path, ec);
        if (!ec) text.resize(static_cast<size_t>(std::min<std::uintmax_t>(size, 64u << 20)), ' ');
    }
    return text;
}

std::string snippet_problems_text(const std::string& path, const std::vector<render::SnippetProblem>& problems) {
    std::string out;
    for (const auto& p : problems)
        out += (out.empty() ? "" : "; ") + scene::printable(path) + (p.line > 0 ? ":" + std::to_string(p.line) : "") +
               ": " + p.message;
    return out;
}

#ifdef PENUMBRA_HAVE_TRUTH
CLI::App* add_grade_command(CLI::App& app, GradeOptions& o) {
    auto* cmd = app.add_subcommand(
        "grade", "score every snippets file (*.glsl) of a folder against the sheet's answer and the truth: a CSV and an HTML report");
    cmd->add_option("dir", o.dir, "the folder of snippets files (docs/snippets.md)")->required();
    cmd->add_option("--out", o.out, "FILE.csv; the report is FILE.html beside it, its images in FILE_files/")->required();
    cmd->add_option("--encoding", o.encoding, "the exercise: r8 (the depth in red) or rgba (bit-shift packing) (default rgba)");
    cmd->add_option("--filter", o.filter, "hard, pcf2x2 or pcf4x4 (default pcf4x4: the sheet's 4x4 lookup)");
    cmd->add_option("--size", o.size, "WxH of each frame (default 192x144)");
    return cmd;
}

namespace {

// The course frames every file is scored on: the light and the teapot at three places.
constexpr double kGradeTimes[] = {0.3, 0.6, 1.2};

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string html(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

std::string pct(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

struct Row {
    std::string file;
    std::string functions;  // the contract's functions it defines, space-separated
    bool compiles = false;
    std::string error;
    std::string verdict = "error";  // render::lab_outcome_name
    double differing = 0, truth = 0;
    std::string mistake, hint;
    std::string thumb, diff;  // image files, relative to the report
    // Where the file defines several functions: each one's verdict alone (the file with only that
    // function, the others the sheet's answer's: render::snippet_only): its name and its verdict.
    std::vector<std::pair<std::string, std::string>> each;
};

// One function's verdict alone, in words.
std::string function_verdict(const render::LabVerdict& v) {
    switch (v.outcome) {
        case render::LabOutcome::Matches: return "matches the sheet's answer";
        case render::LabOutcome::Mistake: return "the classic mistake " + v.mistake;
        case render::LabOutcome::Differs:
            return "differs from the sheet's answer (" + pct(v.differing_pct) + " % of the pixels) and matches none "
                   "of the classic mistakes";
        case render::LabOutcome::NoFunction:
        case render::LabOutcome::Error: break;
    }
    return v.hint;
}

}  // namespace

int run_grade(const GradeOptions& o) {
    render::Options opts;
    auto& s = opts.settings;
    if (o.encoding == "r8") s.encoding = shadow::Encoding::R8;
    else if (o.encoding == "rgba") s.encoding = shadow::Encoding::RGBA;
    else throw CommandError{"--encoding: unknown value '" + scene::printable(o.encoding) + "' (r8, rgba)", 2};
    if (o.filter == "hard") s.filter = shadow::Filter::Hard;
    else if (o.filter == "pcf2x2") s.filter = shadow::Filter::PCF2x2;
    else if (o.filter == "pcf4x4") s.filter = shadow::Filter::PCF4x4;
    else throw CommandError{"--filter: unknown value '" + scene::printable(o.filter) + "' (hard, pcf2x2, pcf4x4)", 2};
    int w = 0, h = 0;
    if (!render::parse_size(o.size, w, h) || w < 16 || h < 16 || w > 1024 || h > 1024)
        throw CommandError{"--size: '" + scene::printable(o.size) + "' is not WxH with each side 16..1024", 2};
    std::error_code ec;
    if (!fs::is_directory(o.dir, ec)) throw CommandError{"grade " + scene::printable(o.dir) + ": not a folder", 2};
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(o.dir, ec))
        if (e.path().extension() == ".glsl" && !fs::is_directory(e.path())) files.push_back(e.path());
    if (ec) throw CommandError{"grade " + scene::printable(o.dir) + ": cannot list it (" + ec.message() + ")", 2};
    if (files.empty()) throw CommandError{"grade " + scene::printable(o.dir) + ": no snippets files (*.glsl) in it", 2};
    std::sort(files.begin(), files.end());
    check_output_file("--out", o.out, ".csv");
    const fs::path out(o.out);
    const fs::path report = fs::path(out).replace_extension(".html");
    const fs::path images = out.parent_path() / (out.stem().string() + "_files");
    prepare_output_dir("--out", images.string());

    scene::SceneSource src = open_scene("teapot");
    auto ctx = bench::make_context();
    render::Renderer r(gl::probe_caps(*ctx));
    const render::FrameInputs in = render::offscreen(w, h);
    const render::Settings ls = render::lab_settings(s);
    if (const std::string why = render::lab_refusal(ls); !why.empty()) throw CommandError{why, 2};

    // The sheet's answer, the mistakes and the truth on each frame, once for every file.
    std::fprintf(stderr, "grade: the sheet's answer, %zu classic mistakes and the ray-traced truth on %zu frames\n",
                 render::snippet_mistakes(s.encoding).size(), std::size(kGradeTimes));
    render::LabReference ref;
    std::vector<std::uint8_t> truth_lit, truth_valid;
    for (double t : kGradeTimes) {
        const scene::Scene sc = src.at(t);
        ref.append(render::lab_reference(r, sc, ls, in));
        measure::TruthOptions to;
        to.width = w;
        to.height = h;
        to.view_proj = bench::renderer_view_proj(sc, w, h);
        const measure::TruthImage ti = measure::RayTracer(sc).render(to);
        truth_lit.insert(truth_lit.end(), ti.lit.begin(), ti.lit.end());
        const auto valid = ti.valid_mask();
        truth_valid.insert(truth_valid.end(), valid.begin(), valid.end());
    }

    // The visibility's red channel, and its mean absolute error against the truth (%).
    const auto vs_truth = [&](const std::vector<std::uint8_t>& rgba) {
        std::vector<std::uint8_t> red(rgba.size() / 4);
        for (size_t i = 0; i < red.size(); ++i) red[i] = rgba[4 * i];
        return measure::score(red, truth_lit, truth_valid).mae_pct;
    };
    const double answer_truth = vs_truth(ref.answer);

    std::vector<Row> rows;
    for (size_t k = 0; k < files.size(); ++k) {
        Row row;
        row.file = files[k].filename().string();
        std::fprintf(stderr, "grade: %zu/%zu %s\n", k + 1, files.size(), scene::printable(row.file).c_str());
        std::string text;
        try {
            text = read_snippets("grade", files[k].string());
        } catch (const CommandError& e) {
            row.error = e.message;
            rows.push_back(row);
            continue;
        }
        row.functions = render::snippet_names(render::scan_snippets(text).defines);
        const auto problems = render::set_snippets(r, src.at(kGradeTimes[0]), ls, text, in);
        if (!problems.empty()) {
            row.error = snippet_problems_text(row.file, problems);
            rows.push_back(row);
            continue;
        }
        row.compiles = true;
        std::vector<std::uint8_t> student;
        std::vector<std::uint8_t> middle;  // the frame at kGradeTimes[1], for the report
        for (size_t i = 0; i < std::size(kGradeTimes); ++i) {
            auto img = render::lab_frame(r, src.at(kGradeTimes[i]), ls, in, text);
            if (i == 1) middle = img;
            student.insert(student.end(), img.begin(), img.end());
        }
        render::LabVerdict v;
        v.compiles = true;
        render::lab_verdict(v, ref, text, student);
        row.verdict = render::lab_outcome_name(v.outcome);
        row.differing = v.differing_pct;
        row.mistake = v.mistake;
        row.hint = v.hint;
        row.truth = vs_truth(student);
        // The middle frame and its difference from the answer's, for the report.
        const size_t frame = static_cast<size_t>(w) * static_cast<size_t>(h) * 4;
        const std::vector<std::uint8_t> diff(v.difference.begin() + static_cast<std::ptrdiff_t>(frame),
                                             v.difference.begin() + static_cast<std::ptrdiff_t>(2 * frame));
        const std::string base = std::to_string(k + 1);
        row.thumb = (fs::path(images.filename()) / (base + "_frame.png")).generic_string();
        row.diff = (fs::path(images.filename()) / (base + "_difference.png")).generic_string();
        bench::write_or_throw((images / (base + "_frame.png")).string(), measure::from_rgba(middle, w, h, 1));
        bench::write_or_throw((images / (base + "_difference.png")).string(), measure::from_rgba(diff, w, h, 3));
        // Each function alone, where there are several: one compile and three frames each.
        if (v.defines.size() > 1)
            for (render::SnippetFn f : v.defines) {
                const std::string name(render::snippet_name(f));
                const std::string only = render::snippet_only(text, f);
                if (const auto p = render::set_snippets(r, src.at(kGradeTimes[0]), ls, only, in); !p.empty()) {
                    row.each.emplace_back(name, "not checked alone: " + p[0].message);
                    continue;
                }
                std::vector<std::uint8_t> frames;
                for (double t : kGradeTimes) {
                    const auto img = render::lab_frame(r, src.at(t), ls, in, only);
                    frames.insert(frames.end(), img.begin(), img.end());
                }
                render::LabVerdict fv;
                fv.compiles = true;
                render::lab_verdict(fv, ref, only, frames);
                row.each.emplace_back(name, function_verdict(fv));
            }
        rows.push_back(row);
    }

    // The report, then the CSV: each written whole or not at all.
    std::string page = "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>penumbra grade: " + html(o.dir) +
                       "</title>\n<style>body{font-family:sans-serif;margin:1.5em}td,th{border-bottom:1px solid #ccc;"
                       "padding:.4em;vertical-align:top;text-align:left}.no,.verdict-no-function{color:#b00}img{image-rendering:pixelated;border:1px solid #999}"
                       "</style></head><body>\n<h1>Snippets of " + html(o.dir) + "</h1>\n<p>Each file compiled into "
                       "the renderer's shaders (docs/snippets.md) and drawn on the course scene at t = 0.3, 0.6 and 1.2 s, " +
                       std::to_string(w) + "x" + std::to_string(h) + ", encoding " + html(o.encoding) + ", filter " +
                       html(o.filter) + ". <b>Differing</b>: pixels whose visibility differs from the sheet's answer's; "
                       "<b>vs truth</b>: mean absolute error of the visibility against the ray-traced hard shadow (the sheet's answer: " +
                       pct(answer_truth) + " %; docs/snippets.md says why it is not 0). "
                       "The images are the frame at t = 0.6 s and its difference from the answer's (red: darker, green: "
                       "lighter). A file that defines none of the sheet's functions draws the answer's own frame: it is no "
                       "match. Where a file defines several, each is also checked alone (the others the sheet's answer's)."
                       "</p>\n<table><tr><th>file</th><th>functions</th><th>compiles</th><th>differing %</th><th>vs truth %</th>"
                       "<th>frame</th><th>difference</th><th>verdict, hint or error</th></tr>\n";
    std::string csv = "file,functions,compiles,error,verdict,differing_pixels_pct,error_vs_truth_pct,mistake,hint\n";
    for (const Row& row : rows) {
        csv += csv_field(row.file) + "," + csv_field(row.functions) + "," + (row.compiles ? "yes" : "no") + "," +
               csv_field(row.error) + "," + row.verdict + "," + (row.compiles ? pct(row.differing) : "") + "," +
               (row.compiles ? pct(row.truth) : "") + "," + csv_field(row.mistake) + "," + csv_field(row.hint) + "\n";
        page += "<tr><td>" + html(row.file) + "</td><td>" + html(row.functions) + "</td><td" +
                (row.compiles ? ">yes" : " class=\"no\">no") + "</td><td>" + (row.compiles ? pct(row.differing) : "") +
                "</td><td>" + (row.compiles ? pct(row.truth) : "") + "</td>";
        if (row.compiles) {
            page += "<td><img src=\"" + html(row.thumb) + "\" alt=\"frame\"></td><td><img src=\"" + html(row.diff) +
                    "\" alt=\"difference\"></td><td class=\"verdict-" + row.verdict + "\">" +
                    (row.mistake.empty() ? "" : "<b>" + html(row.mistake) + "</b>: ") + html(row.hint);
            if (!row.each.empty()) {
                page += "<ul>";
                for (const auto& [fn, verdict] : row.each)
                    page += "<li><code>" + html(fn) + "</code> alone: " + html(verdict) + "</li>";
                page += "</ul>";
            }
            page += "</td></tr>\n";
        } else
            page += "<td></td><td></td><td class=\"no\">" + html(row.error) + "</td></tr>\n";
    }
    page += "</table>\n</body></html>\n";
    bench::write_text(report, page);
    bench::write_text(out, csv);
    std::printf("graded %zu file(s): %s and %s\n", rows.size(), scene::printable(out.string()).c_str(),
                scene::printable(report.string()).c_str());
    return 0;
}

#endif  // PENUMBRA_HAVE_TRUTH

}  // namespace penumbra::tools
