// penumbra bench --soft's outputs: soft.csv, soft.md, the Pareto and convergence plots, and the
// truth-noise CSV and table (the sweep that fills them: soft_bench.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "measure/score_columns.h"
#include "soft_bench.h"

namespace penumbra::tools::bench {

std::string noise_csv(const SoftRun& w) {
    std::ostringstream o;
    o << "scene,time,width,height,light_radius,samples,compared_with,valid_pixels,penumbra_pixels,mean_abs_pct,"
         "mean_abs_penumbra_pct,max_abs,seconds\n";
    for (const NoiseRow& r : w.noise_rows)
        o << "course@" << fixed(kNoiseTime, 2) << "," << kNoiseTime << "," << w.noise_width << "," << w.noise_height << ","
          << fixed(r.radius, 4) << "," << r.n << "," << 4 * r.n << "," << r.valid << "," << r.penumbra << "," << fixed(r.mean_abs_pct, 4)
          << "," << fixed(r.mean_abs_penumbra_pct, 4) << "," << fixed(r.max_abs, 4) << "," << fixed(r.seconds, 2) << "\n";
    return o.str();
}

std::string noise_table(const SoftRun& w) {
    std::ostringstream o;
    o << "| light radius | N | compared with | mean abs % (valid pixels) | mean abs % (penumbra of the 4N truth) | max abs | valid px | penumbra px | "
         "trace s (N) |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const NoiseRow& r : w.noise_rows)
        o << "| " << fixed(r.radius, 3) << " | " << r.n << " | " << 4 * r.n << " | " << fixed(r.mean_abs_pct, 4) << " | " << fixed(r.mean_abs_penumbra_pct, 3) << " | "
          << fixed(r.max_abs, 3) << " | " << r.valid << " | " << r.penumbra << " | " << fixed(r.seconds, 1) << " |\n";
    return o.str();
}

// ---- the report ----------------------------------------------------------------------------------

std::string soft_csv(const SoftRun& w) {
    std::ostringstream o;
    o << "section,scene,light,radius_fraction,light_radius,method,family,samples," << measure::score_csv_header()
      << ",ms_per_frame,frames,settings\n";
    for (const SoftRow& r : w.rows)
        o << r.section << "," << r.scene << "," << r.light << "," << r.fraction << "," << fixed(r.radius, 5) << "," << r.method << ","
          << r.family << "," << r.samples << "," << measure::score_csv_cells(r.score) << "," << (r.ms >= 0.0 ? fixed(r.ms, 3) : "")
          << "," << r.frames << ",\"" << r.settings << "\"\n";
    return o.str();
}

namespace {

struct MeanOf {
    double soft = 0.0, penumbra = 0.0, ms = 0.0;
    int n = 0;
};

// Per method (in the methods' order), the mean over the sweep's rows that `pick` selects.
template <typename Pick>
std::vector<std::pair<std::string, MeanOf>> means(const SoftRun& w, Pick pick) {
    std::vector<std::pair<std::string, MeanOf>> out;
    for (const Method& m : w.methods) {
        MeanOf a;
        for (const SoftRow& r : w.rows)
            if (r.section == kSweepSection && r.method == m.name && pick(r)) {
                a.soft += r.score.mae_soft_pct;
                a.penumbra += r.score.mae_penumbra_pct;
                a.ms += r.ms;
                ++a.n;
            }
        if (a.n == 0) continue;
        a.soft /= a.n;
        a.penumbra /= a.n;
        a.ms /= a.n;
        out.emplace_back(m.name, a);
    }
    return out;
}

const SoftRow* find_row(const SoftRun& w, const std::string& section, const std::string& scene, double fraction,
                        const std::string& method) {
    for (const SoftRow& r : w.rows)
        if (r.section == section && r.scene == scene && r.fraction == fraction && r.method == method) return &r;
    return nullptr;
}

int family_color(const std::string& family) {
    return family == "pcss" ? 1 : family == "heckbert-herf" ? 2 : family == "gooch" ? 3 : family == "screen blur" ? 4 : 0;
}

}  // namespace

Plot pareto_plot(const SoftRun& w, std::vector<std::string>* front_names) {
    Plot p;
    p.title = "Soft shadows: error against the area-light truth, and time";
    p.subtitle = "mean over " + std::to_string(w.scenes.size()) + " scene frame(s) x " + std::to_string(w.fractions.size()) +
                 " light radii at " + std::to_string(w.width) + "x" + std::to_string(w.height) +
                 "; time: median ms/frame, light moving" + (w.gl_renderer.empty() ? "" : "; " + w.gl_renderer);
    p.xlabel = "ms per frame, light moving (log scale)";
    p.ylabel = "mean |visibility - area-light truth| %";
    p.colors = {"#666666", "#d95f02", "#1b9e77", "#7570b3", "#e7298a"};
    p.color_title = "method (colour)";
    p.marker_title = "variant (shape)";
    p.color_legend = {{"shadow map (hard, PCF)", 0}, {"PCSS", 1}, {"Heckbert-Herf", 2}};
    if (w.gooch) p.color_legend.push_back({"Gooch", 3});
    p.color_legend.push_back({"shadow blur (screen space)", 4});
    p.marker_legend = {{"hard / 4 samples / 8 taps / blur 4 px", Marker::Circle}, {"pcf4x4 / 16 / blur 8 px", Marker::Triangle},
                       {"32 taps / 64 samples / blur 16 px", Marker::Square}, {"256 samples", Marker::Diamond}};
    p.notes = {"rgba shadow map 1024 for all", "hover (SVG) for the figures"};
    std::vector<measure::Point2> pts;
    std::vector<std::string> names;
    for (const auto& [name, a] : means(w, [](const SoftRow&) { return true; })) {
        // By value: clang 14 (C++17) does not let a lambda capture a structured binding.
        const Method& m = *std::find_if(w.methods.begin(), w.methods.end(), [n = name](const Method& x) { return x.name == n; });
        PlotPoint pt;
        pt.x = a.ms;
        pt.y = a.soft;
        pt.color = family_color(m.family);
        const bool big = m.samples == 64 || m.s.pcss_taps == 32;
        pt.marker = m.samples == 256                                                  ? Marker::Diamond
                    : (big && (m.family == "pcss" || m.family == "heckbert-herf")) || name == "shadow-blur 16"
                        ? Marker::Square
                    : name == "pcf4x4" || m.samples == 16 || name == "pcss 16/16" || name == "shadow-blur 8"
                        ? Marker::Triangle
                                                                                      : Marker::Circle;
        pt.radius = 5.0;
        pt.label = name;
        pt.tooltip = name + ": vs area light " + fixed(a.soft, 3) + " %, in the penumbra " + fixed(a.penumbra, 2) + " %, " +
                     fixed(a.ms, 2) + " ms/frame (mean of " + std::to_string(a.n) + " scene x radius)";
        p.points.push_back(pt);
        pts.push_back({a.ms, a.soft});
        names.push_back(name);
    }
    p.front = measure::pareto_front(pts, 0.01);
    if (front_names)
        for (size_t i : p.front) front_names->push_back(names[i]);
    return p;
}

Plot convergence_plot(const SoftRun& w) {
    Plot p;
    p.title = "Heckbert-Herf: error against the number of light samples N";
    std::string scene;
    for (const SoftRow& r : w.rows)
        if (r.section == kConvergenceSection) scene = r.scene;
    p.subtitle = scene + " at " + std::to_string(w.width) + "x" + std::to_string(w.height) + ", rgba hard shadow map 1024, one colour per light radius";
    p.xlabel = "light samples N (log scale)";
    p.ylabel = "mean |visibility - area-light truth| %";
    p.colors = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a"};
    p.color_title = "light radius (colour)";
    p.marker_title = "";
    for (size_t i = 0; i < w.fractions.size(); ++i) p.color_legend.push_back({fixed(w.fractions[i], 2) + " of the scene", static_cast<int>(i % 4)});
    for (const SoftRow& r : w.rows) {
        if (r.section != kConvergenceSection) continue;
        const size_t fi = static_cast<size_t>(std::find(w.fractions.begin(), w.fractions.end(), r.fraction) - w.fractions.begin());
        PlotPoint pt;
        pt.x = r.samples;
        pt.y = r.score.mae_soft_pct;
        pt.color = static_cast<int>(fi % 4);
        pt.radius = 4.5;
        pt.tooltip = "N = " + std::to_string(r.samples) + ", radius " + fixed(r.fraction, 2) + ": " + fixed(r.score.mae_soft_pct, 3) +
                     " % (in the penumbra " + fixed(r.score.mae_penumbra_pct, 2) + " %)";
        p.points.push_back(pt);
    }
    return p;
}

std::string soft_markdown(const SoftRun& w, double elapsed, const std::vector<std::string>& front) {
    std::ostringstream o;
    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
    o << "# penumbra bench --soft: soft shadows against the area-light truth\n\n"
      << "Generated by `" << w.command_line << "` on " << date << " in " << duration_str(elapsed) << ": " << w.context << ", "
      << w.gl_renderer << ", " << std::thread::hardware_concurrency() << " hardware threads; 1-minute load average " << w.load_before
      << " before, " << w.load_after << " after. Explained in `docs/soft.md`.\n\n"
      << "Frames of " << w.width << "x" << w.height << ". Truth: the Embree ray tracer's area light, " << w.truth_samples
      << " stratified samples per pixel on a disc facing the point (radius in world units at a point or spot light; "
         "an angular radius for a directional light). Light radius: a fraction of the scene's size, x the diagonal of the "
         "scene's bounds for point and spot lights, atan(fraction) radians for a directional light; the renderer gets the "
         "same radius (`--light-radius`). Every method draws an rgba shadow map of 1024. *vs area light*: mean |rendered "
         "visibility - area-light truth| over the valid pixels, %; *in penumbra*: the same over the valid pixels whose truth "
         "is strictly between 0 and 1; *ms*: the median ms/frame of "
      << w.frames << " frames (Heckbert-Herf with N samples: max(2, " << 8 * w.frames << "/N) frames, at most " << w.frames
      << ") after one untimed, the light (and the teapot) moving so every map is redrawn, each frame finished with `glFinish`"
      << (w.o.rounds > 1 ? "; the median of " + std::to_string(w.o.rounds) + " rounds" : "") << ".\n\n";
    if (w.o.quick) o << "**Quick mode: small frames and few of them; the timings mean nothing.**\n\n";

    // The mean over the scenes, one column group per radius.
    o << "## Mean over the scenes, per light radius\n\n| method |";
    for (double f : w.fractions) o << " r " << fixed(f, 2) << ": vs area light % | in penumbra % | ms |";
    o << " all: vs area light % | ms | Pareto |\n|---|";
    for (size_t i = 0; i < w.fractions.size(); ++i) o << "---:|---:|---:|";
    o << "---:|---:|:-:|\n";
    std::vector<std::vector<std::pair<std::string, MeanOf>>> by_radius;
    for (double f : w.fractions) by_radius.push_back(means(w, [f](const SoftRow& r) { return r.fraction == f; }));
    const auto all = means(w, [](const SoftRow&) { return true; });
    for (const auto& [name, a] : all) {
        o << "| " << name << " |";
        for (const auto& br : by_radius) {
            const auto it = std::find_if(br.begin(), br.end(), [&, &nm = name](const auto& x) { return x.first == nm; });
            if (it == br.end()) o << " - | - | - |";
            else o << " " << fixed(it->second.soft, 2) << " | " << fixed(it->second.penumbra, 1) << " | " << fixed(it->second.ms, 1) << " |";
        }
        o << " " << fixed(a.soft, 2) << " | " << fixed(a.ms, 1) << " | "
          << (std::find(front.begin(), front.end(), name) != front.end() ? "yes" : "") << " |\n";
    }

    // Per scene and radius.
    o << "\n## Per scene and light radius\n";
    for (const SceneSpec& spec : w.scenes) {
        const SoftRow* any = nullptr;
        for (const SoftRow& r : w.rows)
            if (r.scene == spec.label && r.section == kSweepSection) any = &r;
        if (!any) continue;
        o << "\n### " << spec.label << " (" << any->light << " light)\n\n| method |";
        for (double f : w.fractions) {
            const SoftRow* r0 = nullptr;
            for (const SoftRow& r : w.rows)
                if (r.scene == spec.label && r.fraction == f) r0 = &r;
            o << " r " << fixed(f, 2) << " (" << (r0 ? fixed(r0->radius, 3) : "?") << (any->light == "directional" ? " rad" : "")
              << "): vs area light % | in penumbra % | ms |";
        }
        o << "\n|---|";
        for (size_t i = 0; i < w.fractions.size(); ++i) o << "---:|---:|---:|";
        o << "\n";
        for (const Method& m : w.methods) {
            o << "| " << m.name << " |";
            for (double f : w.fractions) {
                const SoftRow* r = find_row(w, kSweepSection, spec.label, f, m.name);
                if (!r) o << " - | - | - |";
                else o << " " << fixed(r->score.mae_soft_pct, 2) << " | " << fixed(r->score.mae_penumbra_pct, 1) << " | " << fixed(r->ms, 1) << " |";
            }
            o << "\n";
        }
        o << "\nPenumbra pixels (truth strictly between 0 and 1) of the valid ones:";
        for (double f : w.fractions)
            if (const SoftRow* r = find_row(w, kSweepSection, spec.label, f, "hard"))
                o << " r " << fixed(f, 2) << ": " << r->score.penumbra << " of " << r->score.valid << ";";
        o << "\n";
    }

    // The issue's goals, checked per scene and radius.
    o << "\n## The issue's goals, per scene and radius\n\n"
         "HH 64 <= 1 % vs the area light; PCSS <= 2.5 % at <= 2x the time of pcf4x4 (same run), and better than pcf4x4 at "
         "radius >= 0.05.\n\n| scene | radius | pcf4x4 % | pcf4x4 ms | hh 64 % | hh 64 <= 1 % |";
    const std::vector<std::string> pcss = [&] {
        std::vector<std::string> v;
        for (const Method& m : w.methods)
            if (m.family == "pcss") v.push_back(m.name);
        return v;
    }();
    for (const auto& p : pcss) o << " " << p << " % | ms | goal |";
    o << "\n|---|---:|---:|---:|---:|:-:|";
    for (size_t i = 0; i < pcss.size(); ++i) o << "---:|---:|:-:|";
    o << "\n";
    int hh_ok = 0, hh_n = 0;
    std::map<std::string, std::pair<int, int>> pcss_ok;
    for (const SceneSpec& spec : w.scenes)
        for (double f : w.fractions) {
            const SoftRow* pcf = find_row(w, kSweepSection, spec.label, f, "pcf4x4");
            const SoftRow* hh = find_row(w, kSweepSection, spec.label, f, "hh 64");
            if (!pcf) continue;
            o << "| " << spec.label << " | " << fixed(f, 2) << " | " << fixed(pcf->score.mae_soft_pct, 2) << " | " << fixed(pcf->ms, 1) << " | ";
            if (hh) {
                const bool ok = hh->score.mae_soft_pct <= 1.0;
                hh_ok += ok;
                ++hh_n;
                o << fixed(hh->score.mae_soft_pct, 2) << " | " << (ok ? "yes" : "**no**") << " |";
            } else {
                o << "- | - |";
            }
            for (const auto& p : pcss) {
                const SoftRow* r = find_row(w, kSweepSection, spec.label, f, p);
                if (!r) {
                    o << " - | - | - |";
                    continue;
                }
                const bool err_ok = r->score.mae_soft_pct <= 2.5;
                const bool time_ok = r->ms <= 2.0 * pcf->ms;
                const bool beats = f < 0.05 - 1e-9 || r->score.mae_soft_pct < pcf->score.mae_soft_pct;
                const bool ok = err_ok && time_ok && beats;
                auto& [good, n] = pcss_ok[p];
                good += ok;
                ++n;
                std::string why;
                if (!err_ok) why += " error";
                if (!time_ok) why += " time";
                if (!beats) why += " not better than pcf";
                o << " " << fixed(r->score.mae_soft_pct, 2) << " | " << fixed(r->ms, 1) << " | " << (ok ? "yes" : "**no:" + why + "**") << " |";
            }
            o << "\n";
        }
    o << "\nHH 64 meets its goal in " << hh_ok << " of " << hh_n << " cases;";
    for (const auto& p : pcss) o << " " << p << " in " << pcss_ok[p].first << " of " << pcss_ok[p].second << ";";
    o << "\n";

    // Heckbert-Herf's convergence.
    bool any_conv = false;
    std::string conv_scene;
    for (const SoftRow& r : w.rows)
        if (r.section == kConvergenceSection) any_conv = true, conv_scene = r.scene;
    if (any_conv) {
        o << "\n## Heckbert-Herf's convergence on " << conv_scene << "\n\nvs area light % (in penumbra %) against the number of "
             "light samples N (Halton points on the light, the hard rgba shadow map 1024 from each); ms from the sweep where it "
             "ran that N.\n\n| N |";
        for (double f : w.fractions) o << " r " << fixed(f, 2) << " |";
        o << " ms (r " << fixed(w.fractions.back(), 2) << ") |\n|---:|";
        for (size_t i = 0; i < w.fractions.size(); ++i) o << "---:|";
        o << "---:|\n";
        for (int n : w.convergence_n) {
            o << "| " << n << " |";
            for (double f : w.fractions) {
                const SoftRow* r = find_row(w, kConvergenceSection, conv_scene, f, "hh " + std::to_string(n));
                o << " " << (r ? fixed(r->score.mae_soft_pct, 3) + " (" + fixed(r->score.mae_penumbra_pct, 1) + ")" : "-") << " |";
            }
            const SoftRow* t = find_row(w, kSweepSection, conv_scene, w.fractions.back(), n == 1 ? "hard" : "hh " + std::to_string(n));
            o << " " << (t ? fixed(t->ms, 1) : "-") << " |\n";
        }
    }
    if (!w.noise_rows.empty())
        o << "\n## The truth's own noise\n\nmean |soft(N) - soft(4N)| on course@" << fixed(kNoiseTime, 2) << " at " << w.noise_width
          << "x" << w.noise_height << " (light radius in world units):\n\n"
          << noise_table(w);
    if (!w.notes.empty()) {
        o << "\n## Notes\n\n";
        for (const auto& n : w.notes) o << "- " << n << "\n";
    }
    return o.str();
}

}  // namespace penumbra::tools::bench
