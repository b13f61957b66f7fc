// penumbra bench's outputs: results.csv (one row per scene frame and technique), results.md (the
// tables of means; the sections' tables are bench_sections.cpp's), tradeoff.svg/.png and
// tradeoff_mae.svg/.png (error against time with the Pareto front); --from-csv reads the rows back.
#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "bench.h"
#include "cli_options.h"
#include "measure/metrics.h"
#include "measure/score_columns.h"
#include "plot.h"
#include "plan/settings.h"

namespace fs = std::filesystem;

namespace penumbra::tools::bench {

void write_text(const std::filesystem::path& path, const std::string& text) { write_output(path.string(), text); }

namespace {


// Means over a set of rows (one technique and map size over several scenes): each score column's
// mean (measure::mean_score), the times' means, the largest memory.
struct Mean {
    measure::Score score;
    double moving = 0, still = 0, shadow = 0, camera = 0;
    std::size_t bytes = 0;
    int n = 0;
    double silhouette_edges = -1.0, fill_per_pixel = 0.0;  // shadow volumes' (< 0: none)
};

Mean mean_of(const std::vector<const Row*>& rows) {
    Mean m;
    std::vector<const measure::Score*> scores;
    for (const Row* r : rows) {
        scores.push_back(&r->score);
        m.moving += r->ms_moving;
        m.still += r->ms_still;
        m.shadow += r->ms_shadow;
        m.camera += r->ms_camera;
        m.bytes = std::max(m.bytes, r->bytes);
        ++m.n;
    }
    m.score = measure::mean_score(scores);
    if (m.n) {
        const double n = m.n;
        m.moving /= n, m.still /= n, m.shadow /= n, m.camera /= n;
    }
    if (!rows.empty() && std::all_of(rows.begin(), rows.end(), [](const Row* r) { return r->silhouette_edges >= 0; })) {
        m.silhouette_edges = 0.0;
        for (const Row* r : rows) m.silhouette_edges += r->silhouette_edges, m.fill_per_pixel += r->fill_per_pixel;
        m.silhouette_edges /= m.n, m.fill_per_pixel /= m.n;
    }
    return m;
}

std::vector<Key> keys_in_order(const std::vector<const Row*>& rows) {
    std::vector<Key> keys;
    std::set<Key> seen;
    for (const Row* r : rows)
        if (seen.insert({r->technique, r->map}).second) keys.push_back({r->technique, r->map});
    return keys;
}

std::map<Key, Mean> means_by_key(const std::vector<const Row*>& rows) {
    std::map<Key, std::vector<const Row*>> groups;
    for (const Row* r : rows) groups[{r->technique, r->map}].push_back(r);
    std::map<Key, Mean> out;
    for (const auto& [k, v] : groups) out[k] = mean_of(v);
    return out;
}

std::vector<const Row*> select(const Sweep& w, bool (*pred)(const Row&)) {
    std::vector<const Row*> out;
    for (const Row& r : w.rows)
        if (pred(r)) out.push_back(&r);
    return out;
}

bool ends_with(const std::string& technique, const std::string& suffix) {
    return technique.size() > suffix.size() && technique.compare(technique.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A run at the settings before issue 9 (bench.cpp, before_rows).
bool is_before(const std::string& technique) { return ends_with(technique, kBeforeSuffix); }

// y: the error % (false shadow + false lit), or with `mae` the mean absolute visibility error.
tools::Plot make_plot(const Sweep& w, const std::vector<const Row*>& rows, const std::string& title, bool mae,
                      std::vector<Key>* front_keys) {
    const auto keys = keys_in_order(rows);
    const auto means = means_by_key(rows);
    tools::Plot p;
    p.title = title;
    p.subtitle = "mean over " + std::to_string(w.scenes.size()) + " scene frames at " + std::to_string(w.width) + "x" +
                 std::to_string(w.height) + "; time: median ms/frame with the light moving (map redrawn)" +
                 (w.gl_renderer.empty() ? "" : "; " + w.gl_renderer);
    p.xlabel = "ms per frame, light moving (log scale)";
    p.ylabel = mae ? "mean absolute visibility error %" : "error % (false shadow + false lit)";
    p.colors = {"#d95f02", "#7570b3", "#1b9e77", "#666666", "#e7298a", "#e6ab02", "#17becf"};
    p.color_title = "encoding, technique (colour)";
    p.marker_title = "filter, method (shape)";
    p.color_legend = {{"r8", 0}, {"rgba", 1}, {"depthtex", 2}, {"no shadow map", 3}};
    const bool volumes = std::any_of(keys.begin(), keys.end(), [](const Key& k) { return is_volumes(k.technique); });
    if (volumes) p.color_legend.push_back({"shadow volumes", 6});
    const auto known = [](const std::string& enc) {
        return enc == "r8" || enc == "rgba" || enc == "depthtex" || enc == "none" || enc == "planar" || enc == "volumes";
    };
    for (const Key& k : keys)
        if (!known(k.technique.substr(0, k.technique.find(' ')))) {
            p.color_legend.push_back({"other (e.g. three.js)", 4});
            break;
        }
    const bool before_rows = std::any_of(keys.begin(), keys.end(), [](const Key& k) { return is_before(k.technique); });
    const std::string auto_suffix = kAutoSuffix;
    const bool auto_rows = std::any_of(keys.begin(), keys.end(), [&](const Key& k) { return ends_with(k.technique, auto_suffix); });
    if (before_rows) p.color_legend.push_back({"rgba before issue 9", 5});
    p.marker_legend = {{"hard", Marker::Circle}, {"pcf2x2", Marker::Square}, {"pcf4x4", Marker::Triangle},
                       {"planar", Marker::Diamond}, {"none", Marker::Cross}};
    if (volumes)
        p.marker_legend.insert(p.marker_legend.end(), {{"volumes auto", Marker::Star}, {"volumes zpass", Marker::TriangleDown},
                                                       {"volumes zfail", Marker::Hexagon}});
    p.notes = {"marker size: map 256 ... 4096", volumes ? "front: shadow maps and volumes;" : "front: shadow maps only;",
               "planar and none are references", "hover (SVG) for the exact", "settings of each point"};
    if (before_rows)
        p.notes.insert(p.notes.end(), {"dashed blue ring: the defaults", "(map auto) and the settings", "before issue 9 (map 1024)"});
    // The front is over the shadow-map techniques and the shadow volumes: planar shadows need a
    // flat ground and cast no shadow on anything else, and none is no answer; both are drawn as references.
    std::vector<measure::Point2> pts;
    std::vector<Key> order;
    for (const Key& k : keys) {
        const Mean& m = means.at(k);
        tools::PlotPoint pt;
        pt.x = m.moving;
        pt.y = mae ? m.score.mae_pct : m.score.error_pct;
        const bool before = is_before(k.technique);
        const std::string t = before ? k.technique.substr(0, k.technique.size() - std::string(kBeforeSuffix).size()) : k.technique;
        const std::string enc = t.substr(0, t.find(' '));
        const std::string fil = t.find(' ') == std::string::npos ? "" : t.substr(t.find(' ') + 1);
        const bool vol = is_volumes(k.technique);
        pt.color = before ? 5 : enc == "r8" ? 0 : enc == "rgba" ? 1 : enc == "depthtex" ? 2 : vol ? 6 : known(enc) ? 3 : 4;
        // Where the defaults sit (the map matched to the screen, issue 56; a fixed 1024 where the
        // sweep has no auto rows), and where they sat before issue 9 (map 1024).
        const bool matched = ends_with(t, auto_suffix);
        const std::string filter = matched ? fil.substr(0, fil.size() - auto_suffix.size()) : fil;
        const bool default_map = before ? k.map == 1024 : auto_rows ? matched : k.map == 1024;
        if (before_rows && default_map && enc == "rgba" && (filter == "hard" || filter == "pcf4x4"))
            pt.callout = before ? "before: " + t + " 1024" : "default: " + enc + " " + filter + (matched ? ", map auto (" + std::to_string(k.map) + ")" : " 1024");
        pt.marker = vol ? (fil == "zpass" ? Marker::TriangleDown : fil == "zfail" ? Marker::Hexagon : Marker::Star)
                    : fil == "hard" ? Marker::Circle : fil == "pcf2x2" ? Marker::Square : fil == "pcf4x4" ? Marker::Triangle
                    : enc == "planar" ? Marker::Diamond : Marker::Cross;
        pt.radius = k.map ? 3.0 + 1.1 * std::log2(static_cast<double>(k.map) / 256.0) : vol ? 6.0 : 5.0;
        pt.label = key_label(k);
        pt.tooltip = key_label(k) + ": error " + fixed(m.score.error_pct, 2) + " % (false shadow " + fixed(m.score.false_shadow_pct, 2) +
                     ", false lit " + fixed(m.score.false_lit_pct, 2) + "), mean abs error " + fixed(m.score.mae_pct, 2) + " %, " +
                     fixed(m.moving, 2) + " ms/frame moving, " + fixed(m.still, 2) + " still, " +
                     (m.silhouette_edges >= 0.0 ? fixed(m.silhouette_edges, 0) + " silhouette edges, fill " +
                                                      fixed(m.fill_per_pixel, 2) + " per pixel"
                                                : bytes_str(m.bytes));
        p.points.push_back(pt);
        pts.push_back({k.map || vol ? m.moving : NAN, pt.y});
        order.push_back(k);
    }
    p.front = measure::pareto_front(pts, 0.01);  // the tables' precision
    if (front_keys)
        for (size_t i : p.front) front_keys->push_back(order[i]);
    return p;
}

// The defaults set against the settings before issue 9 (the "(before)" rows), over all scenes:
// error, time, the shadow overhead (the frame's time over the time of the frame without shadows,
// same run) and the texel use. Empty where the sweep ran no "(before)" rows.
std::string defaults_against_before(const std::vector<const Row*>& all) {
    const auto means = means_by_key(all);
    const auto none = means.find({"none", 0});
    std::map<Key, double> texel;  // mean texel use per key
    {
        std::map<Key, std::vector<double>> v;
        for (const Row* r : all)
            if (r->texel_use_pct >= 0.0) v[{r->technique, r->map}].push_back(r->texel_use_pct);
        for (const auto& [k, xs] : v) texel[k] = std::accumulate(xs.begin(), xs.end(), 0.0) / static_cast<double>(xs.size());
    }
    std::ostringstream o;
    bool any = false;
    for (const auto& [k, m] : means) {
        if (!is_before(k.technique)) continue;
        const std::string now_name = k.technique.substr(0, k.technique.size() - std::string(kBeforeSuffix).size());
        const auto now = means.find({now_name, k.map});
        if (now == means.end()) continue;
        if (!any) {
            o << "\n## The defaults against the settings before issue 9 (all scenes)\n\n"
                 "*now*: the defaults (`--bias auto --map-faces auto --light-fit tight --pcf-kernel early-exit`); *before*: "
                 "`--bias sheet --map-faces both --light-fit scene --pcf-kernel full`. Shadow overhead: ms/frame over the "
                 "ms/frame of `none` (no shadows) in the same run, the light moving (the map redrawn) and still (the map reused). "
                 "Texel use: the share of the map covered by the receivers in view.\n\n"
                 "| technique | map | error % now | before | mean abs error % now | before | ms/frame moving now | before | "
                 "overhead moving now | before | overhead still now | texel use % now | before |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
            any = true;
        }
        const Mean& n = now->second;
        const auto ratio = [&](double a, double b) { return b > 0.0 ? fixed(a / b, 2) + "x" : std::string("-"); };
        const auto use = [&](const Key& key) { const auto it = texel.find(key); return it == texel.end() ? std::string("-") : fixed(it->second, 1); };
        o << "| " << now_name << " | " << k.map << " | " << fixed(n.score.error_pct, 2) << " | " << fixed(m.score.error_pct, 2) << " | "
          << fixed(n.score.mae_pct, 2) << " | " << fixed(m.score.mae_pct, 2) << " | " << fixed(n.moving, 2) << " | " << fixed(m.moving, 2)
          << " | " << (none == means.end() ? "-" : ratio(n.moving, none->second.moving)) << " | "
          << (none == means.end() ? "-" : ratio(m.moving, none->second.moving)) << " | "
          << (none == means.end() ? "-" : ratio(n.still, none->second.still)) << " | " << use({now_name, k.map}) << " | " << use(k) << " |\n";
    }
    return o.str();
}

// The shadow map the volumes are set against: rgba hard at map 1024, or at the middle map size
// swept when 1024 was not.
int comparison_map(const Sweep& w) {
    if (std::find(w.o.maps.begin(), w.o.maps.end(), 1024) != w.o.maps.end() || w.o.maps.empty()) return 1024;
    return w.o.maps[w.o.maps.size() / 2];
}

// Shadow volumes (each counting method) against rgba hard per scene frame: error, time, and what
// the volumes cost: silhouette edges, volume triangles, stencil fill. Empty without volume rows.
std::string volumes_against_map(const Sweep& w, const std::vector<const Row*>& all) {
    if (std::none_of(all.begin(), all.end(), [](const Row* r) { return is_volumes(r->technique); })) return "";
    const int map = comparison_map(w);
    std::ostringstream o;
    o << "\n## Shadow volumes against the shadow map (rgba hard, map " << map << ")\n\n"
      << "Per scene frame. Volumes: *auto* counts depth-pass unless the near plane may lie inside a caster's volume, then "
         "depth-fail, per caster; *zpass* and *zfail* count every caster one way. Silhouette edges and volume triangles "
         "(sides and caps) are the frame's; fill: the stencil fragments the volumes rasterise (every layer, before the depth "
         "test), per pixel of the image. Casters: counted depth-pass / depth-fail.\n\n"
      << "| scene frame | technique | error % | false shadow % | false lit % | ms/frame moving | ms/frame still | silhouette edges "
         "| volume triangles | fill per pixel | casters pass / fail |\n"
      << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
    std::vector<std::string> scenes;
    for (const Row* r : all)
        if (std::find(scenes.begin(), scenes.end(), r->scene) == scenes.end()) scenes.push_back(r->scene);
    const std::string map_name = "rgba hard";
    const auto line = [&](const std::string& scene, const std::string& technique, const Mean& m, const Row* one) {
        o << "| " << scene << " | " << technique << " | " << fixed(m.score.error_pct, 2) << " | " << fixed(m.score.false_shadow_pct, 2)
          << " | " << fixed(m.score.false_lit_pct, 2) << " | " << fixed(m.moving, 2) << " | " << fixed(m.still, 2) << " | ";
        if (m.silhouette_edges >= 0.0)
            o << fixed(m.silhouette_edges, 0) << " | " << (one ? std::to_string(one->volume_triangles) : "-") << " | "
              << fixed(m.fill_per_pixel, 2) << " | "
              << (one ? std::to_string(one->zpass_casters) + " / " + std::to_string(one->zfail_casters) : "-") << " |\n";
        else
            o << "- | - | - | - |\n";
    };
    std::vector<const Row*> chosen;
    for (const auto& scene : scenes) {
        for (const Row* r : all)
            if (r->scene == scene && ((r->technique == map_name && r->map == map) || is_volumes(r->technique))) {
                line(scene, key_label({r->technique, r->map}), mean_of({r}), r);
                chosen.push_back(r);
            }
    }
    const auto means = means_by_key(chosen);
    for (const Key& k : keys_in_order(chosen)) line("**mean**", key_label(k), means.at(k), nullptr);
    return o.str();
}

// ms/frame beside the GPU's time of the same frames (EXT_disjoint_timer_query), per technique over
// the sweep's scene frames, and each pass's GPU time with the light moving (of the first scene
// frame); a line saying why where no row has them.
std::string gpu_table(const Sweep& w, const std::vector<const Row*>& all) {
    std::ostringstream o;
    o << "\n## GPU time per frame and per pass (GL_TIME_ELAPSED_EXT)\n\n";
    if (std::none_of(all.begin(), all.end(), [](const Row* r) { return r->gpu_moving >= 0.0; })) {
        o << "GPU timer: not available on this context (no EXT_disjoint_timer_query)" << (w.from_csv.empty() ? "" : " or not in the CSV")
          << ".\n";
        return o.str();
    }
    o << "GPU ms: the GPU's time of each pass (GL_TIME_ELAPSED_EXT around it) summed over the frame, per row the median "
         "of the rounds' medians like ms/frame (the wall time to glFinish), here the mean over the scene frames. Per pass: "
         "the light moving, "
      << (all.empty() ? std::string() : "`" + all.front()->scene + "`") << ".\n\n"
      << "| technique | map | ms/frame moving | GPU ms moving | ms/frame still | GPU ms still | GPU ms per pass (moving) |\n"
      << "|---|---:|---:|---:|---:|---:|---|\n";
    for (const Key& k : keys_in_order(all)) {
        std::vector<double> wall_m, wall_s, gpu_m, gpu_s;
        std::string passes;
        for (const Row* r : all) {
            if (r->technique != k.technique || r->map != k.map) continue;
            wall_m.push_back(r->ms_moving), wall_s.push_back(r->ms_still);
            if (r->gpu_moving >= 0.0) gpu_m.push_back(r->gpu_moving);
            if (r->gpu_still >= 0.0) gpu_s.push_back(r->gpu_still);
            if (passes.empty() && r->scene == all.front()->scene) passes = r->gpu_passes;
        }
        const auto mean = [](const std::vector<double>& v) {
            return v.empty() ? std::string("-") : fixed(std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()), 2);
        };
        o << "| " << k.technique << " | " << (k.map ? std::to_string(k.map) : "-") << " | " << mean(wall_m) << " | " << mean(gpu_m)
          << " | " << mean(wall_s) << " | " << mean(gpu_s) << " | " << (passes.empty() ? "-" : passes) << " |\n";
    }
    return o.str();
}

std::string markdown(const Sweep& w, double elapsed, const std::vector<Key>& front) {
    std::ostringstream o;
    const auto all = select(w, [](const Row&) { return true; });
    const auto keys = keys_in_order(all);
    const auto means = means_by_key(all);
    const std::set<Key> on_front(front.begin(), front.end());
    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));

    o << "# penumbra bench: accuracy, time and memory of each shadow technique\n\n";
    if (w.from_csv.empty()) {
        o << "Generated by `" << w.command_line << "` on " << date << " in " << duration_str(elapsed) << ": " << w.context << ", "
          << w.gl_renderer << "; 1-minute load average " << w.load_before << " before the run, " << w.load_after
          << " after it (2 cores: other jobs on the machine slow every technique alike, as the timing rounds interleave).\n"
          << "Frames of " << w.width << "x" << w.height << "; time: " << w.o.rounds << " interleaved round(s) of " << w.o.frames
          << " timed frames per technique, each frame finished with `glFinish`, the median of the rounds' medians; "
          << "settings shared by every run: `" << render::to_args(w.base) << "` (technique, encoding, filter and map size vary).\n\n";
    } else {
        o << "Rebuilt on " << date << " by `penumbra bench --from-csv " << w.from_csv << "` from rows measured earlier (each row's "
          << "exact settings are in the CSV's last column). Frames of " << w.width << "x" << w.height << ".\n\n";
    }
    o << "Scene frames: ";
    for (size_t i = 0; i < w.scenes.size(); ++i) o << (i ? ", " : "") << "`" << w.scenes[i].label << "`";
    o << ". Error: % of the valid pixels (see `docs/tradeoffs.md` for the definitions) against the ray-traced hard-shadow "
         "truth; *vs area light*: mean absolute visibility error against an area light of 1 % of the scene's diagonal "
         "(0.01 rad for a directional light), "
      << (w.from_csv.empty() ? std::to_string(w.o.soft_samples) : "some") << " samples per pixel. *Moving*: the light (and the teapot) move, so the map is redrawn every frame; "
         "*still*: the same frame again, the map reused; shadow pass = moving - still, camera pass = still. Memory: the shadow "
         "map's colour texture plus its depth buffer (or the depth texture alone).\n\n";
    if (w.o.quick) o << "**Quick mode: small frames and few of them; the timings mean nothing.**\n\n";

    o << "## All scenes (mean over the " << w.scenes.size() << " scene frames)\n\n"
      << "| technique | map | " << measure::score_table_headings() << " | ms/frame moving | "
         "ms/frame still | shadow pass ms | camera pass ms | shadow memory | Pareto |\n"
      << "|---|---:|" << measure::score_table_rule() << "---:|---:|---:|---:|---:|:-:|\n";
    for (const Key& k : keys) {
        const Mean& m = means.at(k);
        o << "| " << k.technique << " | " << (k.map ? std::to_string(k.map) : "-") << " | " << measure::score_table_cells(m.score)
          << " | " << fixed(m.moving, 2) << " | " << fixed(m.still, 2) << " | " << (is_volumes(k.technique) ? "-" : fixed(m.shadow, 2))
          << " | " << fixed(m.camera, 2) << " | " << bytes_str(m.bytes) << " | "
          << (on_front.count(k) ? "yes" : k.map || is_volumes(k.technique) ? "" : "ref.") << " |\n";
    }
    o << gpu_table(w, all);
    o << volumes_against_map(w, all);

    // The course scene at the default map size: the closing note's figures.
    std::vector<const Row*> course;
    for (const Row* r : all)
        if (r->scene.rfind("course@", 0) == 0) course.push_back(r);
    if (!course.empty()) {
        std::set<std::string> ts;
        for (const Row* r : course) ts.insert(r->scene);
        std::string tlist;
        for (const auto& t : ts) tlist += (tlist.empty() ? "" : ", ") + t.substr(7);
        for (int map : {1024}) {
            std::vector<const Row*> sel;
            for (const Row* r : course)
                if (r->map == map || r->map == 0) sel.push_back(r);
            if (sel.empty()) continue;
            const auto cm = means_by_key(sel);
            o << "\n## The course scene, map " << map << " (mean over t = " << tlist << " s)\n\n"
              << "| technique | " << measure::score_table_headings() << " | ms/frame moving | ms/frame still | shadow memory |\n"
              << "|---|" << measure::score_table_rule() << "---:|---:|---:|\n";
            for (const Key& k : keys_in_order(sel)) {
                const Mean& m = cm.at(k);
                o << "| " << k.technique << " | " << measure::score_table_cells(m.score) << " | " << fixed(m.moving, 2) << " | "
                  << fixed(m.still, 2) << " | " << bytes_str(m.bytes) << " |\n";
            }
        }
    }

    o << defaults_against_before(all);

    // Error % per scene at one map size (the middle of the sweep), and error and time by map size.
    const int mid_map = w.o.maps[w.o.maps.size() / 2];
    std::vector<std::string> scene_labels;
    for (const auto& s : w.scenes) scene_labels.push_back(s.label);
    o << "\n## Error % per scene frame, map " << mid_map << "\n\n| technique |";
    for (const auto& l : scene_labels) o << " " << l << " |";
    o << "\n|---|";
    for (size_t i = 0; i < scene_labels.size(); ++i) o << "---:|";
    o << "\n";
    std::vector<std::string> techniques;
    for (const Key& k : keys)
        if (std::find(techniques.begin(), techniques.end(), k.technique) == techniques.end()) techniques.push_back(k.technique);
    for (const auto& t : techniques) {
        o << "| " << t << " |";
        for (const auto& l : scene_labels) {
            const Row* found = nullptr;
            for (const Row* r : all)
                if (r->technique == t && r->scene == l && (r->map == mid_map || r->map == 0)) found = r;
            o << " " << (found ? fixed(found->score.error_pct, 2) : "-") << " |";
        }
        o << "\n";
    }
    // The share of the map the receivers in view cover: one figure per scene frame (the fit does
    // not depend on the encoding, the filter or the map size).
    std::vector<std::pair<std::string, double>> uses;
    for (const auto& l : scene_labels)
        for (const Row* r : all)
            if (r->scene == l && r->texel_use_pct >= 0.0) {
                uses.emplace_back(l, r->texel_use_pct);
                break;
            }
    if (!uses.empty()) {
        o << "\n## Texel use: the share of the shadow map covered by the receivers in view\n\n| scene frame | texel use % |\n|---|---:|\n";
        for (const auto& [l, u] : uses) o << "| " << l << " | " << fixed(u, 1) << " |\n";
    }
    for (int table = 0; table < 2; ++table) {
        o << "\n## " << (table == 0 ? "Error % (all scenes)" : "ms/frame with the light moving (all scenes)") << " by map size\n\n| technique |";
        for (int m : w.o.maps) o << " " << m << " |";
        o << "\n|---|";
        for (size_t i = 0; i < w.o.maps.size(); ++i) o << "---:|";
        o << "\n";
        for (const auto& t : techniques) {
            if (std::none_of(all.begin(), all.end(), [&](const Row* r) { return r->technique == t && r->map > 0; })) continue;
            o << "| " << t << " |";
            for (int m : w.o.maps) {
                const auto it = means.find({t, m});
                o << " " << (it == means.end() ? "-" : fixed(table == 0 ? it->second.score.error_pct : it->second.moving, 2)) << " |";
            }
            o << "\n";
        }
    }
    o << silhouette_table(w);
    o << effects_table(w);
    o << lights_table(w);
    o << budget_table(w);
    o << error_table(w);
    if (!w.notes.empty()) {
        o << "\n## Notes\n\n";
        for (const auto& n : w.notes) o << "- " << n << "\n";
    }
    o << "\n![error against time](tradeoff.svg)\n\n![mean absolute error against time](tradeoff_mae.svg)\n";
    return o.str();
}



}  // namespace

std::string key_label(const Key& k) { return k.map ? k.technique + " " + std::to_string(k.map) : k.technique; }

Report write_report(const Sweep& w, const fs::path& dir, Clock::time_point t0) {
    Report out;
    const auto all = select(w, [](const Row&) { return true; });
    const tools::Plot plot = make_plot(w, all, "Shadow error against frame time: every encoding x filter x map size", false, &out.front);
    const tools::Plot mae_plot =
        make_plot(w, all, "Mean absolute visibility error (counts PCF's greys) against frame time", true, nullptr);
    write_text(dir / "results.csv", to_csv(w));
    write_text(dir / "tradeoff.svg", plot_svg(plot, 1100, 700));
    write_or_throw((dir / "tradeoff.png").string(), plot_png(plot, 1100, 700));
    write_text(dir / "tradeoff_mae.svg", plot_svg(mae_plot, 1100, 700));
    write_or_throw((dir / "tradeoff_mae.png").string(), plot_png(mae_plot, 1100, 700));
    out.elapsed = seconds_since(t0);
    if (!w.lights.empty()) {
        const Plot lp = lights_plot(w);
        write_text(dir / "lights.svg", plot_svg(lp, 900, 560));
        write_or_throw((dir / "lights.png").string(), plot_png(lp, 900, 560));
    }
    write_text(dir / "results.md", markdown(w, out.elapsed, out.front));
    return out;
}


}  // namespace penumbra::tools::bench
