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

#include "soft_bench.h"
#include "cli_options.h"
#include "gl/caps.h"
#include "gl/check.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "measure/score_columns.h"
#include "plot.h"
#include "plan/options.h"
#include "render/renderer.h"
#include "scene/printable.h"
#include "scene/scene_source.h"

namespace fs = std::filesystem;

namespace penumbra::tools {
namespace {

using namespace bench;

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
    s.technique = render::technique_named("shadowmap");
    s.encoding = shadow::Encoding::RGBA;
    s.filter = f;
    s.map_size = 1024;
    return s;
}

// The interleaved rows' K (--area-interleave): 2, the better of 2 and 4 on the bench scenes (docs/soft.md).
constexpr int kBenchInterleave = 2;

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
    // The blocker estimate before the layered one (--pcss-blockers mean), beside it at 16/16.
    {
        Method m{"pcss 16/16 mean", "pcss", map_settings(shadow::Filter::PCSS), 1};
        m.s.pcss_layered = false;
        w.methods.push_back(m);
    }
    for (int n : o.quick ? std::vector<int>{4, 16, 64} : std::vector<int>{4, 16, 64, 256}) w.methods.push_back(hh_method(n));
    // --area-interleave: the same N per frame, each pixel of a K x K tile a different N / K^2 of
    // them, filtered over the tile (the first round: what a moving frame shows).
    for (int n : {16, 64}) {
        Method m = hh_method(n);
        m.name += " interleaved";
        m.s.area_interleave = kBenchInterleave;
        w.methods.push_back(m);
    }
    // --post shadow-blur: the hard map's visibility blurred in screen space, a fixed radius in
    // pixels whatever the light's size or the receiver's distance from the caster.
    for (int r : o.quick ? std::vector<int>{4} : std::vector<int>{4, 8, 16}) {
        Method m{"shadow-blur " + std::to_string(r), "screen blur", map_settings(shadow::Filter::Hard), 1};
        m.s.post = {{render::PostKind::ShadowBlur, static_cast<float>(r)}};
        w.methods.push_back(m);
    }
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

// ---- the sweep -----------------------------------------------------------------------------------

void run_soft(SoftRun& w) {
    const auto t0 = Clock::now();
    auto ctx = make_context();
    w.context = ctx->description();
    w.load_before = load_average();
    render::Renderer r(gl::probe_caps(*ctx));
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
        scene::SceneSource src = open_scene(spec.name, scene::Eye::Scene, w.o.allow_outside);
        const scene::Scene still = src.at(spec.time);
        scene::Scene turning = still;
        const glm::vec3 centre = scene::scene_bounds(still).center();
        r.load(still);
        const measure::RayTracer tracer(still);
        const bool convergence = static_cast<size_t>(&spec - w.scenes.data()) == convergence_scene;
        for (double fraction : w.fractions) {
            const double radius = radius_for(still, fraction);
            measure::TruthOptions to = frame_truth_options(still, w.width, w.height);
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
            for (size_t i = 0; i < in.scenes.size(); ++i) c << (i ? "," : "") << scene::printable(in.scenes[i]);
        }
        if (!in.radii.empty()) {
            c << " --radii ";
            for (size_t i = 0; i < in.radii.size(); ++i) c << (i ? "," : "") << in.radii[i];
        }
        w.command_line = c.str();
    }
    if (!in.from_csv.empty()) throw CommandError{"--from-csv: not with --soft or --truth-noise", 2};
    // Every scene opens before the folder is made and the long part starts.
    if (in.soft)
        for (const auto& s : w.scenes) open_scene(s.name, scene::Eye::Scene, w.o.allow_outside);
    const fs::path dir(w.o.out_dir);
    prepare_output_dir("--out-dir", w.o.out_dir);
    if (w.noise) {
        truth_noise(w);
        write_text(dir / "soft_truth_noise.csv", noise_csv(w));
    }
    if (!in.soft) {
        std::printf("%s", noise_table(w).c_str());
        std::printf("bench --truth-noise: wrote %s/soft_truth_noise.csv in %s\n", scene::printable(w.o.out_dir).c_str(),
                    duration_str(seconds_since(t0)).c_str());
        return;
    }
    run_soft(w);
    if (w.rows.empty()) throw CommandError{"bench --soft: nothing was measured", 1};
    std::vector<std::string> front;
    const Plot pareto = pareto_plot(w, &front);
    const Plot conv = convergence_plot(w);
    write_text(dir / "soft.csv", soft_csv(w));
    write_text(dir / "soft.svg", plot_svg(pareto, 1100, 700));
    write_or_throw((dir / "soft.png").string(), plot_png(pareto, 1100, 700));
    if (!conv.points.empty()) {
        write_text(dir / "soft_convergence.svg", plot_svg(conv, 900, 560));
        write_or_throw((dir / "soft_convergence.png").string(), plot_png(conv, 900, 560));
    }
    const double elapsed = seconds_since(t0);
    write_text(dir / "soft.md", soft_markdown(w, elapsed, front));
    for (const auto& n : w.notes) std::fprintf(stderr, "note: %s\n", n.c_str());
    std::printf("bench --soft: %zu rows in %s; wrote %s/soft.csv, soft.md, soft.svg/.png, soft_convergence.svg/.png%s\n", w.rows.size(),
                duration_str(elapsed).c_str(), w.o.out_dir.c_str(), w.noise ? ", soft_truth_noise.csv" : "");
    std::printf("Pareto front (vs area light %% against ms/frame, all scenes and radii):");
    for (const auto& f : front) std::printf(" [%s]", f.c_str());
    std::printf("\n");
}

}  // namespace penumbra::tools
