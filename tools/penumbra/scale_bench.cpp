// penumbra bench --scale: what a frame costs as the scene grows. The scale scenes (scenes/
// scale_scenes.h: N pyramids sharing one mesh, piled in a strip or spread on a grid, under a point,
// a spot and a sun light) at 1,000, 10,000 and 100,000 objects (quick: 300 and 3,000), each at the
// defaults and with --technique none beside it: the time to plan a frame (median of a few plans),
// the time of a frame with the light turning (the map drawn every frame; median of a few, each
// finished with glFinish), and the heap the plan adds at its peak (the counting operator new,
// scene/memory_budget.h). Then, per layout and light, the slope of plan time against the object
// count in log-log, which is 1 for a cost that grows as the scene does. -> scale.csv, scale.md,
// scale.svg/.png (docs/scale.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "bench.h"
#include "cli_options.h"
#include "gl/caps.h"
#include "plan/options.h"
#include "scene/memory_budget.h"
#include "scenes/scale_scenes.h"

namespace fs = std::filesystem;

namespace penumbra::tools::bench {

namespace {

struct ScaleRow {
    scene::ScaleSpec spec;
    double plan_ms = 0.0, plan_none_ms = 0.0;    // median of the plans
    double frame_ms = 0.0, frame_none_ms = 0.0;  // median ms/frame, the light turning
    double scene_mib = 0.0;                      // the scene's own heap
    double plan_mib = 0.0, plan_none_mib = 0.0;  // the heap a plan adds at its peak
    std::size_t map_draws = 0;                   // casters drawn into the shadow maps
};

const char* layout_name(scene::ScaleLayout l) { return l == scene::ScaleLayout::Pile ? "pile" : "forest"; }
const char* light_name(scene::LightType t) {
    return t == scene::LightType::Point ? "point" : t == scene::LightType::Spot ? "spot" : "sun";
}

double mib(std::size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

// The median time of `plans` plans of the frame, and the most heap one of them added.
void time_plans(const render::Renderer& r, const scene::Scene& s, const render::Settings& settings,
                const render::FrameInputs& in, int plans, double& ms, double& heap_mib, std::size_t* map_draws) {
    std::vector<double> times;
    std::size_t added = 0;
    (void)r.plan(s, settings, in);  // untimed: the first plan of a scene warms the caches
    for (int i = 0; i < plans; ++i) {
        const std::size_t before = memory::in_use();
        memory::reset_peak();
        const auto t0 = Clock::now();
        const render::FramePlan plan = r.plan(s, settings, in);
        times.push_back(1000.0 * seconds_since(t0));
        const std::size_t top = memory::peak();
        added = std::max(added, top - std::min(top, before));
        if (map_draws) {
            *map_draws = 0;
            for (const render::Pass& p : plan.passes)
                if (p.module == "shadowmap") *map_draws += p.draws.size();
        }
    }
    ms = measure::median(times);
    heap_mib = mib(added);
}

double time_turning(render::Renderer& r, scene::Scene& s, const render::Settings& settings, const render::FrameInputs& in,
                    int frames) {
    const scene::Light original = s.light;
    const glm::vec3 centre = scene::scene_bounds(s).center();
    const Timing t = time_frames(r, settings, in, 1, frames, [&](int i) -> const scene::Scene& {
        turn_light(s.light, original, centre, i + 1);
        return s;
    });
    s.light = original;
    return t.median_ms;
}

// log(b / a) / log(nb / na): 1 where the cost grows as the object count does.
double slope(double a, double b, int na, int nb) {
    if (!(a > 0.0) || !(b > 0.0) || na == nb) return 0.0;
    return std::log(b / a) / std::log(static_cast<double>(nb) / static_cast<double>(na));
}

std::string csv(const std::vector<ScaleRow>& rows) {
    std::ostringstream c;
    c << "layout,light,objects,plan_ms,plan_none_ms,frame_ms,frame_none_ms,scene_mib,plan_mib,plan_none_mib,map_draws\n";
    for (const ScaleRow& r : rows)
        c << layout_name(r.spec.layout) << "," << light_name(r.spec.light) << "," << r.spec.count << ","
          << fixed(r.plan_ms, 2) << "," << fixed(r.plan_none_ms, 2) << "," << fixed(r.frame_ms, 2) << ","
          << fixed(r.frame_none_ms, 2) << "," << fixed(r.scene_mib, 2) << "," << fixed(r.plan_mib, 2) << ","
          << fixed(r.plan_none_mib, 2) << "," << r.map_draws << "\n";
    return c.str();
}

// Each layout and light's rows, in the order of the counts.
std::vector<std::vector<std::size_t>> series(const std::vector<ScaleRow>& rows) {
    std::vector<std::vector<std::size_t>> out;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        auto it = std::find_if(out.begin(), out.end(), [&](const std::vector<std::size_t>& s) {
            return rows[s.front()].spec.layout == rows[i].spec.layout && rows[s.front()].spec.light == rows[i].spec.light;
        });
        if (it == out.end()) out.push_back({i});
        else it->push_back(i);
    }
    return out;
}

std::string slope_text(const std::vector<ScaleRow>& rows, const std::vector<std::size_t>& s, double ScaleRow::*field) {
    std::string out;
    for (std::size_t k = 1; k < s.size(); ++k) {
        const ScaleRow& a = rows[s[k - 1]];
        const ScaleRow& b = rows[s[k]];
        out += (k > 1 ? ", " : "") + fixed(slope(a.*field, b.*field, a.spec.count, b.spec.count), 2) + " (x" +
               fixed(a.*field > 0.0 ? b.*field / a.*field : 0.0, 1) + ")";
    }
    return out;
}

void write_outputs(const std::vector<ScaleRow>& rows, const BenchOptions& o, const std::string& renderer,
                   const std::string& command, double seconds) {
    const fs::path dir = o.out_dir;
    write_text(dir / "scale.csv", csv(rows));
    char date[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
    std::ostringstream md;
    md << "# The cost of a frame against the number of objects\n\n"
       << "Generated by `" << command << "` on " << date << " in " << duration_str(seconds) << ": " << renderer
       << ". Plan: the median of the plans' times; frame: the median ms/frame with the light turning half a degree "
          "a frame (every map drawn again), each finished with glFinish; heap: what a plan adds at its peak, counted by "
          "the program's operator new. `none`: --technique none on the same scene.\n\n"
       << "| scene | objects | plan ms | plan ms, none | frame ms | frame ms, none | scene heap MiB | plan heap MiB | "
          "plan heap MiB, none | casters in the maps |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ScaleRow& r : rows)
        md << "| " << scene::scale_name(r.spec) << " | " << r.spec.count << " | " << fixed(r.plan_ms, 1) << " | "
           << fixed(r.plan_none_ms, 1) << " | " << fixed(r.frame_ms, 1) << " | " << fixed(r.frame_none_ms, 1) << " | "
           << fixed(r.scene_mib, 1) << " | " << fixed(r.plan_mib, 1) << " | " << fixed(r.plan_none_mib, 1) << " | "
           << r.map_draws << " |\n";
    md << "\nSlopes in log-log between successive counts (1: the cost grows as the scene does; 2: with its square), "
          "with the ratio:\n\n| layout, light | plan time | plan heap | frame time |\n|---|---|---|---|\n";
    for (const std::vector<std::size_t>& s : series(rows))
        md << "| " << layout_name(rows[s.front()].spec.layout) << ", " << light_name(rows[s.front()].spec.light) << " | "
           << slope_text(rows, s, &ScaleRow::plan_ms) << " | " << slope_text(rows, s, &ScaleRow::plan_mib) << " | "
           << slope_text(rows, s, &ScaleRow::frame_ms) << " |\n";
    md << "\n![plan time against objects](scale.svg)\n";
    write_text(dir / "scale.md", md.str());

    Plot p;
    p.title = "Planning a frame against the number of objects";
    p.subtitle = renderer + "; median of the plans; grey: slope 1 through the first point";
    p.xlabel = "objects (log)";
    p.ylabel = "plan ms (log)";
    p.log_x = p.log_y = true;
    p.colors = {"#1f77b4", "#ff7f0e", "#2ca02c", "#aec7e8", "#ffbb78", "#98df8a", "#bbbbbb"};
    p.color_title = "layout, light (colour)";
    p.marker_title = "";
    const std::vector<std::vector<std::size_t>> all = series(rows);
    for (std::size_t k = 0; k < all.size(); ++k) {
        const int colour = static_cast<int>(k % 6);
        const ScaleRow& first = rows[all[k].front()];
        p.color_legend.push_back({std::string(layout_name(first.spec.layout)) + ", " + light_name(first.spec.light) + ": " +
                                      slope_text(rows, all[k], &ScaleRow::plan_ms),
                                  colour});
        std::vector<std::size_t> line;
        for (std::size_t i : all[k]) {
            PlotPoint pt;
            pt.x = rows[i].spec.count;
            pt.y = rows[i].plan_ms;
            pt.color = colour;
            pt.marker = first.spec.layout == scene::ScaleLayout::Pile ? Marker::Square : Marker::Circle;
            pt.tooltip = scene::scale_name(rows[i].spec) + ": plan " + fixed(rows[i].plan_ms, 1) + " ms";
            line.push_back(p.points.size());
            p.points.push_back(pt);
        }
        p.lines.push_back(line);
    }
    if (!rows.empty()) {  // the slope-1 guide from the first series' first point
        const ScaleRow& a = rows[all.front().front()];
        const int last = rows[all.front().back()].spec.count;
        std::vector<std::size_t> guide;
        for (const int n : {a.spec.count, last}) {
            PlotPoint pt;
            pt.x = n;
            pt.y = a.plan_ms * static_cast<double>(n) / static_cast<double>(a.spec.count);
            pt.color = 6;
            pt.radius = 1.0;
            guide.push_back(p.points.size());
            p.points.push_back(pt);
        }
        p.lines.push_back(guide);
    }
    p.notes.push_back("squares: piled; circles: spread");
    p.notes.push_back("legend: slope (ratio) per step");
    write_text(dir / "scale.svg", plot_svg(p, 1080, 600));
    write_or_throw((dir / "scale.png").string(), plot_png(p, 1080, 600));
}

}  // namespace

void run_scale_bench(const BenchOptions& o) {
    const auto t0 = Clock::now();
    if (!o.scenes.empty() || !o.maps.empty() || !o.encodings.empty() || !o.filters.empty() || !o.set.empty())
        throw CommandError{"--scale: its scenes are its own (no --scenes, --maps, --encodings, --filters or --set)", 2};
    const std::vector<int> counts = o.quick ? std::vector<int>{300, 3000} : std::vector<int>{1000, 10000, 100000};
    int width = 256, height = 256;
    if (!o.size.empty() && !render::parse_size(o.size, width, height))
        throw CommandError{"--size " + o.size + ": not WxH", 2};
    const int plans = o.quick ? 1 : 5;
    const int frames = o.frames > 0 ? o.frames : o.quick ? 2 : 3;
    prepare_output_dir("--out-dir", o.out_dir);

    auto ctx = make_context();
    render::Renderer r(gl::probe_caps(*ctx));
    const render::FrameInputs in = render::offscreen(width, height);
    render::Settings defaults;
    render::Settings none;
    none.technique = render::technique_named("none");

    std::vector<ScaleRow> rows;
    for (const scene::ScaleLayout layout : {scene::ScaleLayout::Pile, scene::ScaleLayout::Forest})
        for (const scene::LightType light : {scene::LightType::Point, scene::LightType::Spot, scene::LightType::Directional})
            for (const int n : counts) {
                ScaleRow row;
                row.spec = {layout, n, light};
                const std::size_t before = memory::in_use();
                scene::Scene s = scene::make_scale_scene(row.spec);
                row.scene_mib = mib(memory::in_use() - std::min(memory::in_use(), before));
                time_plans(r, s, defaults, in, plans, row.plan_ms, row.plan_mib, &row.map_draws);
                time_plans(r, s, none, in, plans, row.plan_none_ms, row.plan_none_mib, nullptr);
                row.frame_ms = time_turning(r, s, defaults, in, frames);
                row.frame_none_ms = time_turning(r, s, none, in, frames);
                std::fprintf(stderr, "%-18s plan %8.1f ms (none %7.1f), frame %8.1f ms (none %7.1f), plan heap %6.1f MiB\n",
                             scene::scale_name(row.spec).c_str(), row.plan_ms, row.plan_none_ms, row.frame_ms,
                             row.frame_none_ms, row.plan_mib);
                rows.push_back(row);
            }
    std::string command = "penumbra bench --scale";
    if (o.quick) command += " --quick";
    if (!o.size.empty()) command += " --size " + o.size;
    if (o.frames > 0) command += " --frames " + std::to_string(o.frames);
    write_outputs(rows, o, r.caps().renderer + ", " + std::to_string(width) + "x" + std::to_string(height), command,
                  seconds_since(t0));
    std::printf("bench --scale: %zu scenes in %s; wrote %s/scale.csv, scale.md, scale.svg/.png\n", rows.size(),
                duration_str(seconds_since(t0)).c_str(), scene::printable(o.out_dir).c_str());
}

}  // namespace penumbra::tools::bench
