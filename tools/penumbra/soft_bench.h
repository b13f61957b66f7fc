// Inside `penumbra bench --soft` (not a library interface): what the soft sweep measures and keeps,
// shared by the sweep (soft_bench.cpp) and its report (soft_report.cpp).
#pragma once

#include <string>
#include <vector>

#include "bench.h"
#include "measure/metrics.h"
#include "plot.h"
#include "plan/settings.h"

namespace penumbra::tools::bench {

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

// The report (soft_report.cpp): the rows as CSV and Markdown, the Pareto and convergence plots
// (front_names: the Pareto front's method names, cheapest first), the truth-noise table and CSV.
std::string soft_csv(const SoftRun& w);
std::string soft_markdown(const SoftRun& w, double elapsed, const std::vector<std::string>& front);
Plot pareto_plot(const SoftRun& w, std::vector<std::string>* front_names);
Plot convergence_plot(const SoftRun& w);
std::string noise_csv(const SoftRun& w);
std::string noise_table(const SoftRun& w);

}  // namespace penumbra::tools::bench
