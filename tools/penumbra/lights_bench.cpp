// penumbra bench: forward against deferred shading (plan/frames/deferred.h) with a growing number of
// point lights, on the first course frame of the sweep's scenes under the sweep's default
// technique. Each row: ms/frame timed like the sweep's (interleaved rounds; moving: the course
// animated 1/60 s a frame; still: the same frame again), the bytes of every target of the frame
// (the shadow map, the camera's image, the G-buffer, the light sum), and the visibility AOV scored
// against the hard truth (the lights are unshadowed: the shadow is the main light's, the same
// in both shadings). The crossing, where deferred becomes the cheaper, is interpolated in log N.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench.h"
#include "gl/check.h"
#include "measure/effect_truth.h"
#include "measure/metrics.h"
#include "plan/options.h"
#include "scene/scene_source.h"

namespace penumbra::tools::bench {

namespace {

constexpr int kLights[] = {0, 1, 2, 4, 8, 16, 32, 64, 128, 256};
constexpr int kQuickLights[] = {0, 8, 64};

std::size_t plan_bytes(const render::FramePlan& plan) {
    std::size_t b = 0;
    for (const render::PlannedResource& r : plan.resources) b += r.desc.bytes();
    return b;
}

const Row* find(const Sweep& w, const std::string& shading, int lights) {
    for (const Row& r : w.lights)
        if (r.shading == shading && r.lights == lights) return &r;
    return nullptr;
}

}  // namespace

void lights_sweep(Sweep& w, render::Renderer& r, const render::FrameInputs& in) {
    const BenchOptions& o = w.o;
    const SceneSpec* spec = course_frame(w, "forward against deferred is");
    if (!spec) return;
    const auto t0 = Clock::now();
    scene::SceneSource src = open_scene(spec->name, scene::Eye::Scene, o.allow_outside);
    const scene::Scene still = src.at(spec->time);
    r.load(still);
    const measure::TruthOptions to = frame_truth_options(still, w.width, w.height);
    const measure::EffectTruth truth = measure::trace_effects(still, false, false, to);
    const auto valid = truth.image.valid_mask();

    std::vector<PendingRow> pending;
    const std::vector<int> counts = o.quick ? std::vector<int>(std::begin(kQuickLights), std::end(kQuickLights))
                                            : std::vector<int>(std::begin(kLights), std::end(kLights));
    for (int n : counts)
        for (render::Shading shading : render::kAllShadings) {
            render::Settings s = w.base.settings;
            s.shading = shading;
            s.lights = n;
            Row row;
            row.section = kLightsSection;
            row.scene = spec->label;
            row.time = spec->time;
            set_technique(row, s, technique_label(s));
            row.shading = std::string(render::to_string(shading));
            row.lights = n;
            row.settings = row_args(w.base, *spec, s);
            if (const std::string problem = r.check(still, s, in); !problem.empty()) {
                w.notes.push_back(spec->label + ": --shading " + row.shading + " --lights " + std::to_string(n) +
                                  " skipped: " + problem);
                continue;
            }
            row.bytes = plan_bytes(r.plan(still, s, in));
            render::Settings vis = s;
            vis.aov = render::Aov::Visibility;
            r.render(still, vis, in);
            row.score = measure::score(red_channel(r.read_image()), truth.image.lit, valid);
            std::fprintf(stderr, "lights  %-12s %-9s %3d light(s): error %6.2f %%, targets %s\n", spec->label.c_str(),
                         row.shading.c_str(), n, row.score.error_pct, bytes_str(row.bytes).c_str());
            pending.push_back({row, s, {}, {}, {}});
        }
    gl::check_errors("the lights' accuracy pass");

    time_course_rows(w, r, in, src, still, spec->time, pending, w.lights, "the lights' timing pass");
    std::fprintf(stderr, "lights: %zu rows on %s in %s\n", w.lights.size(), spec->label.c_str(),
                 duration_str(seconds_since(t0)).c_str());
}

double lights_crossing(const Sweep& w) {
    std::vector<int> counts;
    for (const Row& r : w.lights)
        if (r.lights > 0 && std::find(counts.begin(), counts.end(), r.lights) == counts.end()) counts.push_back(r.lights);
    std::sort(counts.begin(), counts.end());
    double prev_n = -1.0, prev_gap = 0.0;  // gap = deferred - forward, ms moving
    for (int n : counts) {
        const Row* f = find(w, "forward", n);
        const Row* d = find(w, "deferred", n);
        if (!f || !d) continue;
        const double gap = d->ms_moving - f->ms_moving;
        if (gap <= 0.0) {
            if (prev_n < 0.0) return n;  // deferred is cheaper from the first count on
            const double t = prev_gap / (prev_gap - gap);
            return std::exp(std::log(prev_n) + t * (std::log(static_cast<double>(n)) - std::log(prev_n)));
        }
        prev_n = n;
        prev_gap = gap;
    }
    return -1.0;
}

std::string lights_table(const Sweep& w) {
    if (w.lights.empty()) return "";
    std::vector<int> counts;
    for (const Row& r : w.lights)
        if (std::find(counts.begin(), counts.end(), r.lights) == counts.end()) counts.push_back(r.lights);
    std::sort(counts.begin(), counts.end());
    std::ostringstream o;
    const Row& first = w.lights.front();
    o << "\n## Forward against deferred shading on " << first.scene << "\n\n"
      << "--lights N point lights (plan/lights.h) beside the main light under " << first.technique << ", " << w.width
      << "x" << w.height << ", the same run. Forward: every object drawn once per batch of 16 lights; deferred: the "
         "objects drawn once into a G-buffer, the main light over every pixel, each point light over its range's screen "
         "square. ms/frame moving: the median of "
      << w.o.rounds << " interleaved round(s) of " << w.o.frames
      << " frames with the course animated. Targets: the bytes of every target of the frame. Error: the visibility "
         "AOV against the ray-traced hard truth (the point lights cast no shadows).\n\n"
      << "| lights | forward ms | deferred ms | deferred / forward | forward targets | deferred targets | forward error % "
         "| deferred error % |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (int n : counts) {
        const Row* f = find(w, "forward", n);
        const Row* d = find(w, "deferred", n);
        o << "| " << n << " | " << (f ? fixed(f->ms_moving, 2) : "-") << " | " << (d ? fixed(d->ms_moving, 2) : "-") << " | "
          << (f && d && f->ms_moving > 0.0 ? fixed(d->ms_moving / f->ms_moving, 2) : "-") << " | "
          << (f ? bytes_str(f->bytes) : "-") << " | " << (d ? bytes_str(d->bytes) : "-") << " | "
          << (f ? fixed(f->score.error_pct, 2) : "-") << " | " << (d ? fixed(d->score.error_pct, 2) : "-") << " |\n";
    }
    const double x = lights_crossing(w);
    o << "\n" << (x > 0.0 ? "Deferred becomes the cheaper at about " + fixed(x, 1) + " lights (interpolated in log N)."
                          : std::string("Deferred is not the cheaper at any count measured."))
      << "\n\n![ms/frame against lights](lights.svg)\n";
    return o.str();
}

Plot lights_plot(const Sweep& w) {
    Plot p;
    p.title = "Forward against deferred shading";
    p.subtitle = (w.lights.empty() ? std::string() : w.lights.front().scene) + ", " + std::to_string(w.width) + "x" +
                 std::to_string(w.height) + ", " + w.gl_renderer;
    p.xlabel = "point lights (log)";
    p.ylabel = "ms/frame, moving";
    p.log_x = true;
    p.colors = {"#1f77b4", "#d62728"};
    p.color_title = "shading (colour)";
    p.marker_title = "";
    p.color_legend = {{"forward", 0}, {"deferred", 1}};
    for (const Row& r : w.lights) {
        if (r.lights <= 0) continue;  // no place on a log axis
        PlotPoint pt;
        pt.x = r.lights;
        pt.y = r.ms_moving;
        pt.color = r.shading == "deferred" ? 1 : 0;
        pt.marker = r.shading == "deferred" ? Marker::Square : Marker::Circle;
        pt.tooltip = r.shading + ", " + std::to_string(r.lights) + " lights: " + fixed(r.ms_moving, 2) + " ms, " + bytes_str(r.bytes);
        p.points.push_back(pt);
    }
    const double x = lights_crossing(w);
    if (x > 0.0) {
        // The crossing on the forward series, between its two bracketing points.
        const Row* lo = nullptr;
        const Row* hi = nullptr;
        for (const Row& r : w.lights)
            if (r.shading == "forward" && r.lights > 0) {
                if (r.lights <= x && (!lo || r.lights > lo->lights)) lo = &r;
                if (r.lights >= x && (!hi || r.lights < hi->lights)) hi = &r;
            }
        if (lo && hi) {
            const double t = hi == lo ? 0.0 : (std::log(x) - std::log(lo->lights)) / (std::log(hi->lights) - std::log(lo->lights));
            PlotPoint c;
            c.x = x;
            c.y = lo->ms_moving + t * (hi->ms_moving - lo->ms_moving);
            c.color = 0;
            c.marker = Marker::Cross;
            c.radius = 7.0;
            c.callout = "crossing: ~" + fixed(x, 1) + " lights";
            c.tooltip = c.callout;
            p.points.push_back(c);
        }
    }
    p.notes.push_back("forward: a pass per 16 lights");
    p.notes.push_back("deferred: a G-buffer, then");
    p.notes.push_back("each light's screen square");
    return p;
}

}  // namespace penumbra::tools::bench
