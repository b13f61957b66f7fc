// penumbra bench --cascades: cascaded shadow maps against one map on a large scene (by default
// tests/data/terrain_km.gltf: a kilometre of hills under a low sun, the camera near the ground),
// or, for a scene lit by a point light (tests/data/bulb_room.gltf), a cube's six faces against one
// perspective map. Each configuration (cascades x map size, snapping, blending) gets: the visibility AOV against
// the ray-traced truth in bands of the camera's view depth (near to far), ms/frame of a slowly
// panning camera (the maps redrawn every frame), the map's bytes, each cascade's texel size, and
// the shimmer: the share of pixels whose lit state flips from frame to frame of the pan, against
// the truth's share. -> cascades.csv, cascades.md, cascades.svg/.png (error by band).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bench.h"
#include "cli_options.h"
#include "gl/caps.h"
#include "gl/check.h"
#include "measure/metrics.h"
#include "plan/techniques/reports.h"
#include "plan/options.h"

namespace fs = std::filesystem;

namespace penumbra::tools::bench {

namespace {

struct Config {
    std::string label;  // "4 x 2048", "4 x 2048 not snapped", "cube 6 x 1024"
    int cascades = 1;   // render::Settings::kCube: a cube
    int map = 1024;
    bool snap = true;
    float blend = 0.1f;
    bool cube_map = false;  // a cube as a GL cube map (--cube-layout cubemap), not the atlas
};

struct CascadeRow {
    Config c;
    measure::Score all;
    std::vector<measure::BandScore> bands;
    double ms = 0.0;                 // median ms/frame of the pan
    double redrawn = 0.0;            // percent of the pan's timed frames that drew the map (not kept)
    double flips = 0.0, truth_flips = 0.0;  // percent of pixels per frame
    std::size_t bytes = 0;           // the map (atlas)
    std::vector<float> texels;       // each cascade's texel, world units (one map: its texel across)
};

constexpr float kPanDegrees = 0.05f;  // a frame of the pan
constexpr int kShimmerFrames = 6;

std::vector<Config> configs(bool quick, bool point_light) {
    constexpr int kCube = render::Settings::kCube;
    if (point_light && quick)
        return {{"1 x 1024", 1, 1024, true, 0.1f},
                {"cube 6 x 512", kCube, 512, true, 0.1f},
                {"cube map 6 x 512", kCube, 512, true, 0.1f, true}};
    if (point_light)
        return {{"1 x 2048", 1, 2048, true, 0.1f},
                {"1 x 4096", 1, 4096, true, 0.1f},
                {"cube 6 x 512", kCube, 512, true, 0.1f},
                {"cube 6 x 1024", kCube, 1024, true, 0.1f},
                {"cube 6 x 2048", kCube, 2048, true, 0.1f},
                {"cube map 6 x 512", kCube, 512, true, 0.1f, true},
                {"cube map 6 x 1024", kCube, 1024, true, 0.1f, true},
                {"cube map 6 x 2048", kCube, 2048, true, 0.1f, true}};
    if (quick) return {{"1 x 1024", 1, 1024, true, 0.1f}, {"4 x 512", 4, 512, true, 0.1f}, {"4 x 512 not snapped", 4, 512, false, 0.1f}};
    return {{"1 x 4096", 1, 4096, true, 0.1f},
            {"1 x 2048", 1, 2048, true, 0.1f},
            {"2 x 2048", 2, 2048, true, 0.1f},
            {"4 x 1024", 4, 1024, true, 0.1f},
            {"4 x 2048", 4, 2048, true, 0.1f},
            {"4 x 2048 not snapped", 4, 2048, false, 0.1f},
            {"4 x 2048 no blend", 4, 2048, true, 0.0f}};
}

render::Settings settings_of(const render::Options& base, const Config& c) {
    render::Settings s = base.settings;
    s.cascades = c.cascades;
    s.map_size = c.map;
    s.cascade_snap = c.snap;
    s.cascade_blend = c.blend;
    s.cube_map = c.cube_map;
    return s;
}

glm::mat4 panned(const glm::mat4& view, int frame) {
    return glm::rotate(glm::mat4(1.0f), glm::radians(kPanDegrees * static_cast<float>(frame)), glm::vec3(0.0f, 1.0f, 0.0f)) *
           view;
}

// Four bands of view depth, equal in ratio, over the valid pixels' depths (2 significant digits).
std::vector<double> band_edges(const std::vector<float>& depth, const std::vector<std::uint8_t>& valid) {
    double lo = 1e30, hi = 0.0;
    for (size_t i = 0; i < depth.size(); ++i)
        if (valid[i] && depth[i] > 0.0f) {
            lo = std::min(lo, static_cast<double>(depth[i]));
            hi = std::max(hi, static_cast<double>(depth[i]));
        }
    if (!(hi > lo)) return {0.0, 1e30};
    std::vector<double> e = {0.0};
    for (int i = 1; i < 4; ++i) {
        const double v = lo * std::pow(hi / lo, i / 4.0);
        const double unit = std::pow(10.0, std::floor(std::log10(v)) - 1.0);
        e.push_back(std::round(v / unit) * unit);
    }
    e.push_back(1e30);
    return e;
}

std::string band_name(const measure::BandScore& b) {
    return b.to > 1e29 ? fixed(b.from, b.from < 10 ? 1 : 0) + "+" : fixed(b.from, b.from < 10 ? 1 : 0) + ".." + fixed(b.to, b.to < 10 ? 1 : 0);
}

std::string texel_list(const std::vector<float>& t) {
    std::string s;
    for (float v : t) {
        char b[32];
        std::snprintf(b, sizeof b, "%s%.3g", s.empty() ? "" : " / ", static_cast<double>(v));
        s += b;
    }
    return s;
}

}  // namespace

void run_cascades_bench(const BenchOptions& in) {
    const auto t0 = Clock::now();
    BenchOptions o = in;
    if (o.size.empty()) o.size = o.quick ? "256x256" : "512x512";
    if (o.frames <= 0) o.frames = o.quick ? 5 : 20;
    if (o.rounds <= 0) o.rounds = o.quick ? 1 : 3;
    if (o.scenes.size() > 1) throw CommandError{"bench --cascades: one scene (--scenes FILE.gltf)", 2};
    const std::string scene_name = o.scenes.empty() ? "tests/data/terrain_km.gltf" : o.scenes.front();
    render::Options base;
    apply_set(o.set, {"cascades", "map-size", "cascade-snap", "cascade-blend", "aov"}, base.settings);
    if (const std::string err = render::parse_option(base, "size", o.size); !err.empty()) throw CommandError{err, 2};
    const int w = base.job.width, h = base.job.height;
    scene::SceneSource src = open_scene(scene_name, scene::Eye::Scene, o.allow_outside);
    prepare_output_dir("--out-dir", o.out_dir);
    const scene::Scene still = src.at(0.0);
    const bool point_light = still.light.type == scene::LightType::Point;
    if (still.light.type == scene::LightType::Spot)
        std::fprintf(stderr, "note: %s has a spot light: every configuration is one map\n",
                     scene::printable(scene_name).c_str());

    auto ctx = make_context();
    const gl::Caps caps = gl::probe_caps(*ctx);
    render::Renderer r(caps);
    r.load(still);
    render::FrameInputs in0 = render::offscreen(w, h);
    in0.view = still.camera.view;

    // The truth of each frame of the pan (the first is the scored frame).
    std::vector<measure::TruthImage> truths;
    std::vector<glm::mat4> views;
    for (int f = 0; f < kShimmerFrames; ++f) {
        views.push_back(panned(still.camera.view, f));
        render::FrameInputs fi = in0;
        fi.view = views.back();
        measure::TruthOptions to;
        to.width = w;
        to.height = h;
        to.view_proj = render::camera_view(still, fi).view_proj;
        truths.push_back(measure::RayTracer(still).render(to));
    }
    const auto valid0 = truths.front().valid_mask();
    const std::vector<float> depth = truths.front().view_depth(views.front());
    const std::vector<double> edges = band_edges(depth, valid0);
    double truth_flips = 0.0;
    for (int f = 1; f < kShimmerFrames; ++f)
        truth_flips += measure::flip_pct(truths[f - 1].lit, truths[f].lit, truths[f - 1].valid_mask(), truths[f].valid_mask()) /
                       (kShimmerFrames - 1);

    std::vector<CascadeRow> rows;
    for (const Config& c : configs(o.quick, point_light)) {
        CascadeRow row;
        row.c = c;
        render::Settings s = settings_of(base, c);
        s.aov = render::Aov::Visibility;
        if (const std::string problem = r.check(still, s, in0); !problem.empty())
            throw CommandError{"bench --cascades: " + c.label + ": " + problem, 1};
        std::vector<std::uint8_t> prev;
        for (int f = 0; f < kShimmerFrames; ++f) {
            render::FrameInputs fi = in0;
            fi.view = views[static_cast<size_t>(f)];
            const render::FramePlan& plan = r.render(still, s, fi);
            const auto vis = red_channel(r.read_image());
            if (f == 0) {
                row.all = measure::score(vis, truths.front().lit, valid0);
                row.bands = measure::score_by_band(vis, truths.front().lit, valid0, depth, edges);
                row.bytes = plan.resource("shadow-map") ? plan.resource("shadow-map")->desc.bytes() : 0;
                for (const auto& k : render::cascades_of(plan)) row.texels.push_back(k.texel);
                if (render::cube_of(plan)) {
                    // A face's texel 1 unit from the light, along its axis (tangents 2T / tile).
                    row.texels.push_back(2.0f * render::cube_of(plan)->tangent / static_cast<float>(render::cube_of(plan)->tile));
                } else if (render::cascades_of(plan).empty() && render::light_frustum_of(plan) && !render::light_frustum_of(plan)->perspective)
                    row.texels.push_back(2.0f / render::light_frustum_of(plan)->proj[0][0] / static_cast<float>(c.map));
            } else {
                row.flips += measure::flip_pct(measure::lit_flags(prev), measure::lit_flags(vis),
                                               truths[f - 1].valid_mask(), truths[f].valid_mask()) /
                             (kShimmerFrames - 1);
            }
            prev = vis;
        }
        row.truth_flips = truth_flips;
        std::fprintf(stderr, "cascades %-22s error %6.3f %%, flips %.4f %% (truth %.4f %%), map %s\n", c.label.c_str(),
                     row.all.error_pct, row.flips, truth_flips, bytes_str(row.bytes).c_str());
        rows.push_back(std::move(row));
    }
    gl::check_errors("the cascades' accuracy pass");

    // ms/frame: rounds interleaved over the configurations, each the pan's frames. A point light
    // also moves a millimetre a frame, so that a cube's faces are redrawn every frame as the one
    // map is (a still light's faces are kept: the plan reuses them).
    std::vector<std::vector<double>> rounds(rows.size());
    render::FrameInputs pan = in0;
    pan.view.reset();  // the scene's camera, panned below
    for (int k = 0; k < o.rounds; ++k)
        for (size_t i = 0; i < rows.size(); ++i) {
            const render::Settings s = settings_of(base, rows[i].c);
            scene::Scene sc = still;
            const Timing t = time_frames(r, s, pan, 1, o.frames, [&](int frame) -> const scene::Scene& {
                sc.camera.view = panned(still.camera.view, frame);
                if (point_light) sc.light.position = still.light.position + glm::vec3(0.001f * static_cast<float>(frame), 0.0f, 0.0f);
                return sc;
            });
            rounds[i].push_back(t.median_ms);
            rows[i].redrawn += 100.0 * t.redrawn / (static_cast<double>(o.frames) * o.rounds);
        }
    for (size_t i = 0; i < rows.size(); ++i) rows[i].ms = measure::median(rounds[i]);
    gl::check_errors("the cascades' timing pass");

    // The reports.
    const fs::path dir(o.out_dir);
    std::ostringstream csv;
    csv << "config,cascades,map,snap,blend,map_bytes,ms_per_frame,redrawn_pct,error_pct,flips_pct,truth_flips_pct,texels";
    for (const auto& b : rows.front().bands) csv << ",error_pct_" << band_name(b);
    csv << "\n";
    for (const CascadeRow& row : rows) {
        csv << row.c.label << ","
            << (row.c.cascades == render::Settings::kCube ? std::string("cube") : std::to_string(row.c.cascades)) << "," << row.c.map << "," << (row.c.snap ? "on" : "off") << ","
            << row.c.blend << "," << row.bytes << "," << fixed(row.ms, 3) << "," << fixed(row.redrawn, 1) << "," << fixed(row.all.error_pct, 4) << ","
            << fixed(row.flips, 4) << "," << fixed(row.truth_flips, 4) << "," << texel_list(row.texels);
        for (const auto& b : row.bands) csv << "," << fixed(b.score.error_pct, 4);
        csv << "\n";
    }
    write_text(dir / "cascades.csv", csv.str());

    std::string set_args;
    for (const auto& kv : o.set) set_args += " --set " + scene::printable(kv);
    const CascadeRow& ref = rows.front();
    std::ostringstream md;
    md << (point_light ? "# A point light's cube against one perspective map\n\n" : "# Cascaded shadow maps against one map\n\n")
       << "`penumbra bench --cascades" << (o.quick ? " --quick" : "") << set_args << "` on " << scene::printable(scene_name) << ", "
       << w << "x" << h << ", " << caps.renderer << ", one run (" << duration_str(seconds_since(t0)) << "). "
       << "Error: the visibility AOV against the ray-traced truth (false shadow + false lit, % of the valid pixels), "
          "over the whole frame and per band of the camera's view depth (world units; equal ratios over the valid "
          "pixels' depths). ms/frame: the median of "
       << o.rounds << " interleaved round(s) of " << o.frames << " frames of a pan (" << kPanDegrees
       << " degrees a frame" << (point_light ? ", the light 1 mm further each frame" : "")
       << "), each finished with glFinish; x: over the first row; redrawn: the share of those frames that drew "
          "the map (the rest kept it from the frame before). Flips: the share "
          "of pixels whose lit state changes from one frame of the pan to the next ("
       << kShimmerFrames - 1 << " steps), x: over the truth's own share (" << fixed(truth_flips, 4)
       << " %), the flips the moving view explains. Texel: the world size of one texel of each cascade's map "
          "(nearest first); a cube's: a face's texel one unit from the light; none for one perspective map.\n\n"
          "| configuration | map bytes | ms/frame | x | redrawn | error % |";
    for (const auto& b : ref.bands) md << " " << band_name(b) << " % |";
    md << " flips % | x truth | texel |\n|---|---:|---:|---:|---:|---:|";
    for (size_t i = 0; i < ref.bands.size(); ++i) md << "---:|";
    md << "---:|---:|---|\n";
    for (const CascadeRow& row : rows) {
        md << "| " << row.c.label << " | " << bytes_str(row.bytes) << " | " << fixed(row.ms, 2) << " | "
           << (ref.ms > 0.0 ? fixed(row.ms / ref.ms, 2) : "-") << " | " << fixed(row.redrawn, 0) << " % | "
           << fixed(row.all.error_pct, 3) << " |";
        for (const auto& b : row.bands) md << " " << fixed(b.score.error_pct, 3) << " |";
        md << " " << fixed(row.flips, 4) << " | " << (truth_flips > 0.0 ? fixed(row.flips / truth_flips, 2) : "-") << " | "
           << texel_list(row.texels) << " |\n";
    }
    md << "\nPixels per band:";
    for (const auto& b : ref.bands) md << " " << band_name(b) << " " << b.score.valid << ";";
    md << "\n\n![error by band](cascades.svg)\n";
    write_text(dir / "cascades.md", md.str());

    Plot p;
    p.title = "Error against the truth by distance from the camera";
    p.subtitle = scene::printable(scene_name) + ", " + std::to_string(w) + "x" + std::to_string(h) + ", " + caps.renderer;
    p.xlabel = "view depth, band's middle (log)";
    p.ylabel = "error %";
    p.log_x = true;
    p.colors = {"#1f77b4", "#aec7e8", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"};
    p.color_title = "configuration (colour)";
    p.marker_title = "";
    for (size_t i = 0; i < rows.size(); ++i) {
        const int colour = static_cast<int>(i % p.colors.size());
        p.color_legend.push_back({rows[i].c.label, colour});
        for (const auto& b : rows[i].bands) {
            if (b.score.valid == 0) continue;
            PlotPoint pt;
            const double lo = std::max(b.from, edges[1] / 2.0);
            const double hi = b.to > 1e29 ? lo * 4.0 : b.to;
            pt.x = std::sqrt(lo * hi);
            pt.y = b.score.error_pct;
            pt.color = colour;
            pt.marker = rows[i].c.cascades > 1 ? Marker::Square : Marker::Circle;  // cascades or a cube
            pt.tooltip = rows[i].c.label + ", " + band_name(b) + ": " + fixed(b.score.error_pct, 3) + " %";
            p.points.push_back(pt);
        }
    }
    p.notes.push_back("circles: one map");
    p.notes.push_back(point_light ? "squares: a cube" : "squares: cascades");
    write_text(dir / "cascades.svg", plot_svg(p, 900, 560));
    write_or_throw((dir / "cascades.png").string(), plot_png(p, 900, 560));
    std::printf("bench --cascades: %zu configurations in %s; wrote %s/cascades.csv, cascades.md, cascades.svg/.png\n",
                rows.size(), duration_str(seconds_since(t0)).c_str(), scene::printable(o.out_dir).c_str());
}

}  // namespace penumbra::tools::bench
