// penumbra bench's budget section (issue 56): --budget-ms at 2, 4, 8, 16 and 32 ms on the first
// course frame of the sweep's scenes, the course animated 1/60 s a frame (moving: the map redrawn
// every frame). Each row: the settings that ran most of the second half of its frames (the first
// half is its settling), the median of that half, and those settings' error against the hard
// truth of the frame itself. Every rung of the ladder is timed too as a fixed setting over the same
// frames (budget_ms 0); the table puts beside each budget the best of them that fits it, and the
// best row of the sweep (timed over its own frames) that does.
#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "bench.h"
#include "budget_frames.h"
#include "gl/check.h"
#include "measure/metrics.h"
#include "plan/budget.h"

namespace penumbra::tools::bench {

namespace {

constexpr double kBudgets[] = {2, 4, 8, 16, 32};
constexpr double kQuickBudgets[] = {4, 16};
constexpr int kFrames = 160;      // per budget; the median of the last half
constexpr int kQuickFrames = 40;

// The chosen settings' error over the best fixed rung's. Exact shadows score 0 to the printed
// digit: two such are alike (1.00), and any error beside one has no finite ratio.
std::string error_ratio(double chosen, double best) {
    if (fixed(best, 3) == fixed(0.0, 3)) return fixed(chosen, 3) == fixed(0.0, 3) ? "1.00" : "over an exact rung";
    return fixed(chosen / best, 2);
}

}  // namespace

void budget_sweep(Sweep& w, render::Renderer& r, const render::FrameInputs& in) {
    const BenchOptions& o = w.o;
    const SceneSpec* spec = course_frame(w, "the budget section is");
    if (!spec) return;
    const auto t0 = Clock::now();
    scene::SceneSource src = open_scene(spec->name, scene::Eye::Scene, o.allow_outside);
    const scene::Scene still = src.at(spec->time);
    r.load(still);
    const measure::TruthOptions to = frame_truth_options(still, w.width, w.height);
    const measure::TruthImage truth = measure::RayTracer(still).render(to);
    const auto valid = truth.valid_mask();

    const int frames = o.quick ? kQuickFrames : kFrames;
    const std::vector<double> budgets = o.quick ? std::vector<double>(std::begin(kQuickBudgets), std::end(kQuickBudgets))
                                                : std::vector<double>(std::begin(kBudgets), std::end(kBudgets));
    render::Settings base = w.base.settings;
    base.technique = render::technique_named("shadowmap");
    const auto moving_at = [&](int i) -> const scene::Scene& { return src.at(spec->time + static_cast<double>(i + 1) / 60.0); };
    const auto score_still = [&](render::Settings s) {
        s.aov = render::Aov::Visibility;
        r.render(still, s, in);
        return measure::score(red_channel(r.read_image()), truth.lit, valid, nullptr);
    };
    // Every rung of the ladder as a fixed setting over the same frames, timed as the budget's rows
    // are (the median of the second half): what a budget could have had, on the frames it ran.
    {
        const render::BudgetController ladder = budget_for(1.0, base, r, still, in);
        for (int k = 0; k < ladder.rungs(); ++k) {
            const render::Settings s = ladder.at_rung(k, base);
            if (!r.check(still, s, in).empty()) continue;
            Row row;
            row.section = kBudgetSection;
            row.scene = spec->label;
            row.time = spec->time;
            set_technique(row, s, technique_label(s));
            row.settings = row_args(w.base, *spec, s);
            row.ms_moving = time_frames(r, s, in, frames / 2, frames - frames / 2, moving_at).median_ms;
            row.frames = frames - frames / 2;
            row.score = score_still(s);
            w.budget.push_back(row);
        }
    }
    for (double budget : budgets) {
        render::BudgetController b = budget_for(budget, base, r, still, in);
        if (const std::string problem = r.check(still, b.settings(), in); !problem.empty()) {
            w.notes.push_back(spec->label + ": --budget-ms skipped: " + problem);
            return;
        }
        std::vector<int> rungs;
        const std::vector<double> ms = budget_frames(r, b, in, frames, moving_at, &rungs);
        // The row is the rung that ran most of the timed half, not the last frame's: a change on the
        // last frames would give the row the time of one rung and the error of another.
        const std::vector<int> timed(rungs.begin() + frames / 2, rungs.end());
        int settled = timed.back(), most = 0;
        for (int k = 0; k < b.rungs(); ++k)
            if (const int n = static_cast<int>(std::count(timed.begin(), timed.end(), k)); n > most) most = n, settled = k;
        Row row;
        row.section = kBudgetSection;
        row.budget_ms = budget;
        row.scene = spec->label;
        row.time = spec->time;
        render::Settings s = b.at_rung(settled, base);
        set_technique(row, s, technique_label(s));
        render::Options labelled = w.base;
        labelled.job.budget_ms = budget;
        row.settings = row_args(labelled, *spec, s);
        row.ms_moving = measure::median(std::vector<double>(ms.begin() + frames / 2, ms.end()));
        row.frames = frames - frames / 2;
        row.score = score_still(s);
        std::fprintf(stderr, "budget %5.1f ms: %s map %d in %d of the %d timed frames, %.2f ms/frame, error %.3f %%; at the end: %s\n",
                     budget, row.technique.c_str(), row.map, most, row.frames, row.ms_moving, row.score.error_pct, b.why().c_str());
        // Each change, so a budget that settled away from the best fixed rung shows why.
        for (const std::string& change : b.log()) std::fprintf(stderr, "  %s\n", change.c_str());
        w.budget.push_back(row);
    }
    gl::check_errors("the budget section");
    std::fprintf(stderr, "budget section: %zu budgets x %d frames in %s\n", budgets.size(), frames,
                 duration_str(seconds_since(t0)).c_str());
}

const Row* best_fixed(const Sweep& w, const Row& budget_row) {
    const Row* best = nullptr;
    for (const Row& r : w.budget)
        if (r.budget_ms == 0.0 && r.scene == budget_row.scene && r.ms_moving > 0.0 && r.ms_moving <= budget_row.budget_ms &&
            (!best || r.score.error_pct < best->score.error_pct))
            best = &r;
    return best;
}

const Row* best_of_sweep(const Sweep& w, const Row& budget_row) {
    const Row* best = nullptr;
    for (const Row& r : w.rows)
        if (r.scene == budget_row.scene && r.score.valid > 0 && r.ms_moving > 0.0 && r.ms_moving <= budget_row.budget_ms &&
            (!best || r.score.error_pct < best->score.error_pct))
            best = &r;
    return best;
}

std::string budget_table(const Sweep& w) {
    const Row* first = nullptr;
    for (const Row& r : w.budget)
        if (r.budget_ms > 0.0 && !first) first = &r;
    if (!first) return "";
    const auto map_of = [](const Row& r) { return r.map ? std::to_string(r.map) : std::string("-"); };
    std::ostringstream o;
    o << "\n## The time budget (--budget-ms)\n\n"
      << "`--budget-ms N` on " << first->scene << " at " << w.width << "x" << w.height << ", moving (the course "
      << "animated 1/60 s a frame): the settings that ran most of the second half of its " << 2 * first->frames
      << " frames, the median ms of that half (wall time after glFinish) and the settings' error against the hard truth of the frame. Beside it, the most "
         "accurate rung of its ladder as a fixed setting whose time over the same frames (timed the same way, in this run) "
         "fits the same budget, and the most accurate row of the sweep (its own frames) that fits it.\n\n"
      << "| budget ms | chosen | map | ms/frame | / budget | error % | best fixed rung that fits | its ms | its error % | "
         "error / its | best of the sweep that fits | its ms | its error % |\n"
      << "|---:|---|---:|---:|---:|---:|---|---:|---:|---:|---|---:|---:|\n";
    for (const Row& r : w.budget) {
        if (r.budget_ms == 0.0) continue;
        o << "| " << fixed(r.budget_ms, 0) << " | " << r.technique << " | " << map_of(r) << " | " << fixed(r.ms_moving, 2) << " | "
          << fixed(r.ms_moving / r.budget_ms, 2) << " | " << fixed(r.score.error_pct, 3) << " | ";
        if (const Row* b = best_fixed(w, r))
            o << b->technique << " " << map_of(*b) << " | " << fixed(b->ms_moving, 2) << " | " << fixed(b->score.error_pct, 3) << " | "
              << error_ratio(r.score.error_pct, b->score.error_pct) << " | ";
        else
            o << "none fits | - | - | - | ";
        if (const Row* b = best_of_sweep(w, r))
            o << key_label({b->technique, b->map}) << " | " << fixed(b->ms_moving, 2) << " | " << fixed(b->score.error_pct, 3) << " |\n";
        else
            o << "none fits | - | - |\n";
    }
    o << "\nThe ladder's rungs over the same frames:\n\n| rung | ms/frame | error % |\n|---|---:|---:|\n";
    for (const Row& r : w.budget)
        if (r.budget_ms == 0.0) o << "| " << r.technique << " " << map_of(r) << " | " << fixed(r.ms_moving, 2) << " | " << fixed(r.score.error_pct, 3) << " |\n";
    return o.str();
}

}  // namespace penumbra::tools::bench
