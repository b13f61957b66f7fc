// penumbra bench --soft: the soft-shadow methods against the ray-traced area-light truth.
//
// For each scene frame and each light radius (a fraction of the scene's size: x the diagonal of
// the scene's bounds for point and spot lights, an angular radius atan(fraction) for a directional
// light), every soft method renders the frame's visibility AOV with the light given that radius
// (--light-radius), scored against the area-light truth of the same radius (measure::Score:
// mae_soft_pct over the valid pixels, mae_penumbra_pct over the penumbra only), and is timed with
// the light (and the teapot) moving, so every shadow map is redrawn each frame. Methods: the hard
// shadow map and PCF 4x4 (blind to the light's size), PCSS at three search/filter tap counts,
// Heckbert-Herf (--area-samples N) on the hard shadow map, and Gooch's planes where the option
// table knows --technique gooch. Also the convergence of Heckbert-Herf with N on the course scene
// (accuracy only), and (--truth-noise, and in a full run) the truth's own noise.
// Outputs: soft.csv, soft.md, soft.svg/.png (the Pareto plot), soft_convergence.svg/.png and
// soft_truth_noise.csv in --out-dir; docs/soft.md explains them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench.h"
#include "gl/caps.h"
#include "gl/check.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "measure/score_columns.h"
#include "plot.h"
#include "render/options.h"
#include "render/renderer.h"
#include "scene/scene_source.h"

namespace fs = std::filesystem;

namespace penumbra::tools {
namespace {

using namespace bench;

constexpr const char* kSweepSection = "sweep";
constexpr const char* kConvergenceSection = "convergence";
// The truth-noise study: the course scene at this radius (world units) and time, these sample counts.
constexpr double kNoiseRadius = 0.3;
constexpr double kNoiseTime = 0.6;

struct Method {
    std::string name;    // "hard", "pcf4x4", "pcss 16/16", "hh 64", "gooch"
    std::string family;  // "shadow map", "pcss", "heckbert-herf", "gooch"
    render::Settings s;
    int samples = 1;     // Heckbert-Herf's N (1 for the others)
};

struct SoftRow {
    std::string section;  // kSweepSection or kConvergenceSection
    std::string scene;    // "course@0.60", "bench_easy"
    std::string light;    // "point", "spot", "directional"
    double fraction = 0.0;
    double radius = 0.0;  // world units (point, spot) or radians (directional)
    std::string method, family;
    int samples = 1;
    std::string settings;
    measure::Score score;
    double ms = -1.0;  // median ms/frame with the light moving; < 0: not timed
    int frames = 0;
};

struct NoiseRow {
    int n = 0;
    double radius = 0.0;  // world units
    double mean_abs_pct = 0.0;           // mean |soft(N) - soft(4N)| over the valid pixels, %
    double mean_abs_penumbra_pct = 0.0;  // the same over the pixels in the penumbra of soft(4N)
    double max_abs = 0.0;
    std::size_t valid = 0, penumbra = 0;
    double seconds = 0.0;  // tracing soft(N)
};

struct SoftRun {
    BenchOptions o;
    int width = 512, height = 512;
    std::vector<SceneSpec> scenes;
    std::vector<double> fractions;
    std::vector<Method> methods;
    std::vector<int> convergence_n;
    int truth_samples = 1024;
    int frames = 10;
    bool gooch = false;
    bool noise = false;
    std::string gl_renderer, context, command_line, load_before, load_after;
    std::vector<SoftRow> rows;
    std::vector<NoiseRow> noise_rows;
    int noise_width = 512, noise_height = 512;
    std::vector<std::string> notes;
};

const char* light_name(scene::LightType t) {
    switch (t) {
        case scene::LightType::Point: return "point";
        case scene::LightType::Spot: return "spot";
        case scene::LightType::Directional: return "directional";
    }
    return "?";
}

// The light radius of `fraction` of the scene's size: x the bounds' diagonal (world units) for a
// point or spot light, an angular radius of atan(fraction) for a directional one.
double radius_for(const scene::Scene& s, double fraction) {
    if (s.light.type == scene::LightType::Directional) return std::atan(fraction);
    const scene::Bounds b = scene::scene_bounds(s);
    return fraction * static_cast<double>(glm::length(b.max - b.min));
}

// Heckbert-Herf's N costs N shadow passes: fewer timed frames (at least 2).
int frames_for(const SoftRun& w, const Method& m) {
    return m.samples <= 1 ? w.frames : std::max(2, std::min(w.frames, 8 * w.frames / m.samples));
}

render::Settings map_settings(shadow::Filter f) {
    render::Settings s;
    s.technique = render::Technique::ShadowMap;
    s.encoding = shadow::Encoding::RGBA;
    s.filter = f;
    s.map_size = 1024;
    return s;
}

Method hh_method(int n) {
    Method m{"hh " + std::to_string(n), "heckbert-herf", map_settings(shadow::Filter::Hard), n};
    m.s.area_samples = n;
    return m;
}

SoftRun configure(const BenchOptions& in) {
    SoftRun w;
    w.o = in;
    BenchOptions& o = w.o;
    if (o.size.empty()) o.size = o.quick ? "128x128" : "512x512";
    w.frames = o.frames > 0 ? o.frames : o.quick ? 2 : 10;
    w.truth_samples = o.soft_samples > 0 ? o.soft_samples : o.quick ? 256 : 512;  // docs/soft.md: its noise
    if (o.scenes.empty())
        o.scenes = o.quick ? std::vector<std::string>{"teapot@0.6"}
                           : std::vector<std::string>{"teapot@0.6", "tests/data/bench_easy.gltf", "tests/data/bench_medium.gltf",
                                                      "tests/data/bench_hard.gltf", "tests/data/bench_curved.gltf"};
    for (const auto& s : o.scenes) w.scenes.push_back(parse_scene_spec(s));
    w.fractions = !o.radii.empty() ? o.radii : o.quick ? std::vector<double>{0.15} : std::vector<double>{0.02, 0.05, 0.15};
    for (double f : w.fractions)
        if (!(f > 0.0 && f < 1.0)) throw CommandError{"--radii: " + fixed(f, 4) + " is not a fraction in (0, 1)", 2};
    render::Options size;
    if (const std::string err = render::parse_option(size, "size", o.size); !err.empty()) throw CommandError{err, 2};
    w.width = size.job.width;
    w.height = size.job.height;
    w.noise = o.truth_noise;

    w.methods.push_back({"hard", "shadow map", map_settings(shadow::Filter::Hard), 1});
    w.methods.push_back({"pcf4x4", "shadow map", map_settings(shadow::Filter::PCF4x4), 1});
    for (int taps : o.quick ? std::vector<int>{16} : std::vector<int>{8, 16, 32}) {
        Method m{"pcss " + std::to_string(taps) + "/" + std::to_string(taps), "pcss", map_settings(shadow::Filter::PCSS), 1};
        m.s.pcss_search = taps;
        m.s.pcss_taps = taps;
        w.methods.push_back(m);
    }
    for (int n : o.quick ? std::vector<int>{4, 16, 64} : std::vector<int>{4, 16, 64, 256}) w.methods.push_back(hh_method(n));
    // Gooch's planes, where this build's option table has them (a helper adds them alongside).
    {
        render::Settings g = map_settings(shadow::Filter::Hard);
        if (render::parse_option(g, "technique", "gooch").empty()) {
            w.gooch = true;
            w.methods.push_back({"gooch", "gooch", g, 1});
        } else {
            w.notes.push_back("--technique gooch is not in this build's option table: no Gooch rows");
        }
    }
    for (int n = 1; n <= (o.quick ? 64 : 256); n *= 2) w.convergence_n.push_back(n);
    return w;
}

std::string load_average() {
    std::ifstream f("/proc/loadavg");
    std::string one;
    return f >> one ? one : std::string("?");
}


// ---- the truth's own noise ---------------------------------------------------------------------

// mean |soft(N) - soft(4N)| over the valid pixels of the course scene at t = 0.6, radius 0.3: the
// stratified estimate's error at N, measured against one with four times the samples.
void truth_noise(SoftRun& w) {
    const bool quick = w.o.quick;
    w.noise_width = quick ? 128 : 512;
    w.noise_height = quick ? 128 : 512;
    const std::vector<int> ns = w.o.soft_samples > 0 ? std::vector<int>{w.o.soft_samples}
                                : quick ? std::vector<int>{16, 64} : std::vector<int>{64, 256, 1024};
    scene::SceneSource src = open_scene("teapot");
    const scene::Scene s = src.at(kNoiseTime);
    // --radii: fractions of the scene's size instead of the radius 0.3.
    std::vector<double> radii = {kNoiseRadius};
    if (!w.o.radii.empty()) {
        radii.clear();
        for (double f : w.fractions) radii.push_back(radius_for(s, f));
    }
    for (double radius : radii) {
    const measure::RayTracer tracer(s);
    measure::TruthOptions to;
    to.width = w.noise_width;
    to.height = w.noise_height;
    to.view_proj = renderer_view_proj(s, to.width, to.height);
    to.light_radius = static_cast<float>(radius);
    std::map<int, measure::TruthImage> truths;
    std::map<int, double> secs;
    for (int n : ns)
        for (int k : {n, 4 * n}) {
            if (truths.count(k)) continue;
            to.soft_samples = k;
            const auto t0 = Clock::now();
            truths.emplace(k, tracer.render(to));
            secs[k] = seconds_since(t0);
            std::fprintf(stderr, "truth noise: course@%.2f radius %.3f, %d samples per pixel in %.1f s\n", kNoiseTime, radius, k,
                         secs[k]);
        }
    for (int n : ns) {
        const measure::TruthImage& a = truths.at(n);
        const measure::TruthImage& b = truths.at(4 * n);
        NoiseRow row;
        row.n = n;
        row.radius = radius;
        row.seconds = secs.at(n);
        double sum = 0.0, pen = 0.0;
        for (size_t i = 0; i < a.soft.size(); ++i) {
            if (!a.valid(i)) continue;
            const double d = std::fabs(static_cast<double>(a.soft[i]) - static_cast<double>(b.soft[i]));
            ++row.valid;
            sum += d;
            row.max_abs = std::max(row.max_abs, d);
            if (b.soft[i] > 0.0f && b.soft[i] < 1.0f) {
                ++row.penumbra;
                pen += d;
            }
        }
        row.mean_abs_pct = row.valid ? 100.0 * sum / static_cast<double>(row.valid) : 0.0;
        row.mean_abs_penumbra_pct = row.penumbra ? 100.0 * pen / static_cast<double>(row.penumbra) : 0.0;
        w.noise_rows.push_back(row);
        std::fprintf(stderr, "truth noise: radius %.3f, N = %4d: mean |soft(N) - soft(4N)| = %.4f %% (in the penumbra %.3f %%, max %.3f)\n", radius, n,
                     row.mean_abs_pct, row.mean_abs_penumbra_pct, row.max_abs);
    }
    }
}

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

// ---- the sweep -----------------------------------------------------------------------------------

void run_soft(SoftRun& w) {
    const auto t0 = Clock::now();
    auto ctx = make_context();
    w.context = ctx->description();
    w.load_before = load_average();
    render::Renderer r(gl::probe_caps(ctx->api()));
    w.gl_renderer = r.caps().renderer;
    const render::FrameInputs in = render::offscreen(w.width, w.height);
    const size_t total = w.scenes.size() * w.fractions.size() * w.methods.size();
    size_t done = 0;
    std::fprintf(stderr, "bench --soft: %zu scene frames x %zu radii x %zu methods at %dx%d, truth %d samples per pixel, %d timed frames%s\n",
                 w.scenes.size(), w.fractions.size(), w.methods.size(), w.width, w.height, w.truth_samples, w.frames,
                 w.o.quick ? " (quick: timings are not meaningful)" : "");
    // The convergence study on the course scene (the first scene when there is none).
    size_t convergence_scene = 0;
    for (size_t i = w.scenes.size(); i-- > 0;)
        if (w.scenes[i].name == "teapot") convergence_scene = i;
    for (const SceneSpec& spec : w.scenes) {
        scene::SceneSource src = open_scene(spec.name);
        const scene::Scene still = src.at(spec.time);
        scene::Scene turning = still;
        const glm::vec3 centre = scene::scene_bounds(still).center();
        r.load(still);
        const measure::RayTracer tracer(still);
        const bool convergence = static_cast<size_t>(&spec - w.scenes.data()) == convergence_scene;
        for (double fraction : w.fractions) {
            const double radius = radius_for(still, fraction);
            measure::TruthOptions to;
            to.width = w.width;
            to.height = w.height;
            to.view_proj = renderer_view_proj(still, w.width, w.height);
            to.soft_samples = w.truth_samples;
            to.light_radius = static_cast<float>(radius);
            const auto tt = Clock::now();
            const measure::TruthImage truth = tracer.render(to);
            const auto valid = truth.valid_mask();
            std::fprintf(stderr, "truth %s, %s light, radius %.3f (%.2f of the scene): %d samples per pixel in %.1f s\n",
                         spec.label.c_str(), light_name(still.light.type), radius, fraction, w.truth_samples, seconds_since(tt));

            const auto base_row = [&](const Method& m, render::Settings& s) {
                SoftRow row;
                row.scene = spec.label;
                row.light = light_name(still.light.type);
                row.fraction = fraction;
                row.radius = radius;
                row.method = m.name;
                row.family = m.family;
                row.samples = m.samples;
                s.light_radius = static_cast<float>(radius);
                render::Options labelled;
                labelled.job.scene = spec.name;
                labelled.job.time = spec.time;
                labelled.job.width = w.width;
                labelled.job.height = w.height;
                labelled.settings = s;
                row.settings = render::to_args(labelled);
                return row;
            };
            const auto score_of = [&](render::Settings s) {
                s.aov = render::Aov::Visibility;
                r.render(still, s, in);
                return measure::score(red_channel(r.read_image()), truth.lit, valid, &truth.soft);
            };

            for (const Method& m : w.methods) {
                ++done;
                render::Settings s = m.s;
                SoftRow row = base_row(m, s);
                row.section = kSweepSection;
                if (const std::string problem = r.check(still, s, in); !problem.empty()) {
                    w.notes.push_back(spec.label + " radius " + fixed(fraction, 2) + ": " + m.name + " skipped: " + problem);
                    std::fprintf(stderr, "[%3zu/%zu] %s: %s skipped (%s)\n", done, total, spec.label.c_str(), m.name.c_str(), problem.c_str());
                    continue;
                }
                row.score = score_of(s);
                // Time the frame a user sees, with the light (and the teapot) moving.
                s.aov = render::Aov::Color;
                const auto moving_at = [&](int i) -> const scene::Scene& {
                    if (src.animated()) return src.at(spec.time + static_cast<double>(i + 1) / 60.0);
                    turn_light(turning.light, still.light, centre, i + 1);
                    return turning;
                };
                row.frames = frames_for(w, m);
                std::vector<double> rounds;
                for (int k = 0; k < std::max(1, w.o.rounds); ++k)
                    rounds.push_back(time_frames(r, s, in, 1, row.frames, moving_at).median_ms);
                row.ms = measure::median(rounds);
                row.frames *= std::max(1, w.o.rounds);
                std::fprintf(stderr, "[%3zu/%zu] %-12s r %.2f %-11s vs area light %6.3f %%, in penumbra %6.2f %% (%zu px), %8.2f ms | %s\n",
                             done, total, spec.label.c_str(), fraction, m.name.c_str(), row.score.mae_soft_pct,
                             row.score.mae_penumbra_pct, row.score.penumbra, row.ms, duration_str(seconds_since(t0)).c_str());
                w.rows.push_back(row);
            }
            gl::check_errors("the soft bench's sweep");
            if (convergence)
                for (int n : w.convergence_n) {
                    const Method m = hh_method(n);
                    render::Settings s = m.s;
                    SoftRow row = base_row(m, s);
                    row.section = kConvergenceSection;
                    row.score = score_of(s);
                    std::fprintf(stderr, "convergence %s r %.2f: hh %3d vs area light %6.3f %%, in penumbra %6.2f %%\n",
                                 spec.label.c_str(), fraction, n, row.score.mae_soft_pct, row.score.mae_penumbra_pct);
                    w.rows.push_back(row);
                }
        }
    }
    w.load_after = load_average();
}

// ---- the report ----------------------------------------------------------------------------------

std::string csv(const SoftRun& w) {
    std::ostringstream o;
    o << "section,scene,light,radius_fraction,light_radius,method,family,samples," << measure::score_csv_header()
      << ",ms_per_frame,frames,settings\n";
    for (const SoftRow& r : w.rows)
        o << r.section << "," << r.scene << "," << r.light << "," << r.fraction << "," << fixed(r.radius, 5) << "," << r.method << ","
          << r.family << "," << r.samples << "," << measure::score_csv_cells(r.score) << "," << (r.ms >= 0.0 ? fixed(r.ms, 3) : "")
          << "," << r.frames << ",\"" << r.settings << "\"\n";
    return o.str();
}

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
    return family == "pcss" ? 1 : family == "heckbert-herf" ? 2 : family == "gooch" ? 3 : 0;
}

Plot pareto_plot(const SoftRun& w, std::vector<std::string>* front_names) {
    Plot p;
    p.title = "Soft shadows: error against the area-light truth, and time";
    p.subtitle = "mean over " + std::to_string(w.scenes.size()) + " scene frame(s) x " + std::to_string(w.fractions.size()) +
                 " light radii at " + std::to_string(w.width) + "x" + std::to_string(w.height) +
                 "; time: median ms/frame, light moving" + (w.gl_renderer.empty() ? "" : "; " + w.gl_renderer);
    p.xlabel = "ms per frame, light moving (log scale)";
    p.ylabel = "mean |visibility - area-light truth| %";
    p.colors = {"#666666", "#d95f02", "#1b9e77", "#7570b3"};
    p.color_title = "method (colour)";
    p.marker_title = "variant (shape)";
    p.color_legend = {{"shadow map (hard, PCF)", 0}, {"PCSS", 1}, {"Heckbert-Herf", 2}};
    if (w.gooch) p.color_legend.push_back({"Gooch", 3});
    p.marker_legend = {{"hard / 4 samples / 8 taps", Marker::Circle}, {"pcf4x4 / 16", Marker::Triangle},
                       {"32 taps / 64 samples", Marker::Square}, {"256 samples", Marker::Diamond}};
    p.notes = {"rgba shadow map 1024 for all", "hover (SVG) for the figures"};
    std::vector<measure::Point2> pts;
    std::vector<std::string> names;
    for (const auto& [name, a] : means(w, [](const SoftRow&) { return true; })) {
        const Method& m = *std::find_if(w.methods.begin(), w.methods.end(), [&](const Method& x) { return x.name == name; });
        PlotPoint pt;
        pt.x = a.ms;
        pt.y = a.soft;
        pt.color = family_color(m.family);
        const bool big = m.samples == 64 || m.s.pcss_taps == 32;
        pt.marker = m.samples == 256                                                  ? Marker::Diamond
                    : big && (m.family == "pcss" || m.family == "heckbert-herf")      ? Marker::Square
                    : name == "pcf4x4" || m.samples == 16 || name == "pcss 16/16"     ? Marker::Triangle
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

std::string markdown(const SoftRun& w, double elapsed, const std::vector<std::string>& front) {
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

}  // namespace

void bench::run_soft_bench(const BenchOptions& in) {
    const auto t0 = Clock::now();
    SoftRun w = configure(in);
    {
        std::ostringstream c;
        c << "penumbra bench " << (in.soft ? "--soft" : "--truth-noise");
        if (in.soft && in.truth_noise) c << " --truth-noise";
        if (w.o.quick) c << " --quick";
        if (!in.size.empty()) c << " --size " << w.o.size;
        if (in.frames > 0) c << " --frames " << in.frames;
        if (in.rounds > 0) c << " --rounds " << in.rounds;
        if (in.soft_samples > 0) c << " --soft-samples " << in.soft_samples;
        if (!in.scenes.empty()) {
            c << " --scenes ";
            for (size_t i = 0; i < in.scenes.size(); ++i) c << (i ? "," : "") << in.scenes[i];
        }
        if (!in.radii.empty()) {
            c << " --radii ";
            for (size_t i = 0; i < in.radii.size(); ++i) c << (i ? "," : "") << in.radii[i];
        }
        w.command_line = c.str();
    }
    if (!in.from_csv.empty()) throw CommandError{"--from-csv: not with --soft or --truth-noise", 2};
    const fs::path dir(w.o.out_dir);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw CommandError{"--out-dir " + w.o.out_dir + ": cannot create", 2};
    if (w.noise) {
        truth_noise(w);
        write_text(dir / "soft_truth_noise.csv", noise_csv(w));
    }
    if (!in.soft) {
        std::printf("%s", noise_table(w).c_str());
        std::printf("bench --truth-noise: wrote %s/soft_truth_noise.csv in %s\n", w.o.out_dir.c_str(),
                    duration_str(seconds_since(t0)).c_str());
        return;
    }
    for (const auto& s : w.scenes) open_scene(s.name);  // every scene opens before the long part
    run_soft(w);
    if (w.rows.empty()) throw CommandError{"bench --soft: nothing was measured", 1};
    std::vector<std::string> front;
    const Plot pareto = pareto_plot(w, &front);
    const Plot conv = convergence_plot(w);
    write_text(dir / "soft.csv", csv(w));
    write_text(dir / "soft.svg", plot_svg(pareto, 1100, 700));
    write_or_throw((dir / "soft.png").string(), plot_png(pareto, 1100, 700));
    if (!conv.points.empty()) {
        write_text(dir / "soft_convergence.svg", plot_svg(conv, 900, 560));
        write_or_throw((dir / "soft_convergence.png").string(), plot_png(conv, 900, 560));
    }
    const double elapsed = seconds_since(t0);
    write_text(dir / "soft.md", markdown(w, elapsed, front));
    for (const auto& n : w.notes) std::fprintf(stderr, "note: %s\n", n.c_str());
    std::printf("bench --soft: %zu rows in %s; wrote %s/soft.csv, soft.md, soft.svg/.png, soft_convergence.svg/.png%s\n", w.rows.size(),
                duration_str(elapsed).c_str(), w.o.out_dir.c_str(), w.noise ? ", soft_truth_noise.csv" : "");
    std::printf("Pareto front (vs area light %% against ms/frame, all scenes and radii):");
    for (const auto& f : front) std::printf(" [%s]", f.c_str());
    std::printf("\n");
}

}  // namespace penumbra::tools
