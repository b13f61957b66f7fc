// --max-error: see max_error.h.
#include "max_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "budget_frames.h"

namespace penumbra::tools {

namespace {

constexpr int kTimedFrames = 3;
constexpr double kLongFrameMs = 250.0;
constexpr double kHeavyFrameMs = 1000.0;

// The model's cost order is the course's, where shadow volumes cost about as much as a 2048 map; a
// scene of few, simple casters draws them far cheaper, one of many detailed casters far dearer
// (docs/budget.md has the figures). So on this frame the volumes and the map whose model
// cost is nearest theirs are timed, and the volumes' cost is that map's times the ratio of the
// times; the maps keep the model's ratios among themselves. Each timed frame is planned without
// a previous plan, so nothing is kept from the frame before (the map drawn, the volumes' silhouette
// found again): what a moving frame costs, planning included. One untimed frame of each first
// (its variants compile, its targets are made), then the median of kTimedFrames; where that first
// frame took over kLongFrameMs, the next one alone; over kHeavyFrameMs, the first itself. A first
// frame of a few hundred ms may be the allocation (a cube's six large faces: docs/budget.md); one
// of seconds is the scene's, and another would only repeat it.
void measure_volumes_cost(ErrorChoice& c, render::Renderer& r, const scene::Scene& scene, const render::FrameInputs& in) {
    const auto volumes = std::find_if(c.rungs.begin(), c.rungs.end(), [](const ErrorRung& g) { return g.map == 0; });
    if (volumes == c.rungs.end()) return;
    ErrorRung* ref = nullptr;
    for (ErrorRung& g : c.rungs)
        if (g.map > 0 && (!ref || std::fabs(std::log(g.cost / volumes->cost)) < std::fabs(std::log(ref->cost / volumes->cost))))
            ref = &g;
    if (!ref) return;
    using Clock = std::chrono::steady_clock;
    const auto median_ms = [&](const render::Settings& s) {
        std::vector<double> ms;
        bool first_long = false;
        for (int i = 0; i <= kTimedFrames; ++i) {
            const auto t0 = Clock::now();
            r.execute(scene, render::plan(scene, s, r.caps(), in, nullptr));
            r.finish();
            const double t = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
            if (i == 0 && t > kHeavyFrameMs) return t;
            if (i == 1 && first_long) return t;
            if (i == 0) first_long = t > kLongFrameMs;
            if (i > 0) ms.push_back(t);
        }
        std::sort(ms.begin(), ms.end());
        return ms[ms.size() / 2];
    };
    const double m = median_ms(ref->settings), v = median_ms(volumes->settings);
    if (!(m > 0.0) || !(v > 0.0)) return;
    ref->ms = m;
    volumes->ms = v;
    volumes->cost = ref->cost * v / m;
}

}  // namespace

std::optional<ErrorChoice> choose_for_error(double max_pct, const render::Settings& s, render::Renderer& r,
                                            const scene::Scene& scene, const render::FrameInputs& in, std::string& refusal) {
    refusal = render::max_error_refusal(s);
    if (!refusal.empty()) return std::nullopt;  // before the ladder's check draws anything
    std::optional<ErrorChoice> c = render::choose_for_error(max_pct, s, budget_for(1.0, s, r, scene, in), r, scene, in, refusal);
    if (c) {
        measure_volumes_cost(*c, r, scene, in);
        render::order_by_cost(*c);
        render::pick_rung(*c, max_pct);
    }
    return c;
}

std::optional<ErrorChoice> make_error_choice(const render::Options& o, render::Renderer& r, const scene::Scene& scene,
                                             const render::FrameInputs& in, std::string& refusal) {
    refusal.clear();
    if (o.job.max_error <= 0.0) return std::nullopt;
    if (o.job.budget_ms > 0.0) {
        refusal = "--max-error and --budget-ms: give one (a time to fit, or an error to keep within)";
        return std::nullopt;
    }
    return choose_for_error(o.job.max_error, o.settings, r, scene, in, refusal);
}

}  // namespace penumbra::tools
