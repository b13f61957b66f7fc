// Inside `penumbra bench` and `penumbra truth` (not a library interface): one row of results, the
// sweep's state, and what the three files share.
//   bench.cpp          the sweep: configuration, the accuracy pass, the interleaved timing rounds
//   bench_report.cpp   the outputs: results.csv, results.md, the plots; --from-csv reads rows back
//   truth_command.cpp  penumbra truth, and the truth helpers the sweep uses too
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "measure.h"
#include "plot.h"
#include "gl/timer.h"
#include "measure/image_io.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "platform/platform.h"
#include "plan/options.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "scene/scene_source.h"

namespace penumbra::tools::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

inline std::string duration_str(double s) {
    char b[32];
    const int total = static_cast<int>(std::lround(s));
    if (total >= 60) std::snprintf(b, sizeof b, "%dm%02ds", total / 60, total % 60);
    else std::snprintf(b, sizeof b, "%.1fs", s);
    return b;
}

inline std::string fixed(double v, int digits) {
    char b[48];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

// "8.0 MiB", "512 KiB", "0".
inline std::string bytes_str(std::size_t b) {
    if (b == 0) return "0";
    if (b >= (1u << 20)) return fixed(static_cast<double>(b) / (1u << 20), b >= (16u << 20) ? 0 : 1) + " MiB";
    return fixed(static_cast<double>(b) / 1024.0, 0) + " KiB";
}

// "teapot@0.6", "teapot" (t = 0), "FILE.gltf", "FILE.gltf@2" (a glTF scene is static).
struct SceneSpec {
    std::string name;
    double time = 0.0;
    std::string label;  // "course@0.60", "bench_easy"
};

// ---- one row of results ----------------------------------------------------------------------

struct Row {
    std::string scene;
    double time = 0.0;
    std::string technique;  // "rgba pcf4x4", "none", "planar"
    std::string encoding, filter;
    int map = 0;
    std::string settings;   // render::to_args
    measure::Score score;
    double ms_moving = 0.0, ms_still = 0.0;
    double ms_shadow = 0.0, ms_camera = 0.0;
    int redrawn_moving = 0, redrawn_still = 0, frames = 0;
    std::size_t bytes = 0;
    double texel_use_pct = -1.0;  // the share of the map covered by the receivers in view; < 0: no map
    // Shadow volumes (render::VolumeStats of the scored frame); silhouette_edges < 0: no volumes.
    int silhouette_edges = -1, volume_triangles = 0, zpass_casters = 0, zfail_casters = 0;
    double fill_per_pixel = 0.0;  // stencil fragments rasterised per pixel of the image
    // Which table the row belongs to: "" the sweep's (every technique on the scene frames),
    // kSilhouetteSection (the sphere of a growing number of segments, bench.cpp silhouette_sweep)
    // or kEffectsSection (the stencil effects on the course frame, effects_bench.cpp).
    std::string section;
    int segments = 0;  // the silhouette sweep's sphere
    // The effects' rows: the --effects list ("none", "outline", "mirror,portal") and the score in
    // the mirror's and the opening's pixels alone (region.valid 0: none of them), with the pixels
    // the truth leaves out as not modelled (measure/effect_truth.h).
    std::string effects;
    measure::Score region;
    std::size_t not_modelled = 0;
    // --post rows of the effects section ("" or "none": none): timed, not scored (score.valid 0);
    // bytes then counts the post passes' targets beside the map.
    std::string post;
    // The lights section's rows: --shading and --lights.
    std::string shading;
    int lights = 0;
    // GPU time (EXT_disjoint_timer_query, gl/timer.h): the median ms/frame moving and still, and
    // each pass's median of the moving frames ("shadow-map: 0.412; camera: 1.203"); < 0 and "":
    // the context has no timer (or the rows were read from a CSV without them).
    double gpu_moving = -1.0, gpu_still = -1.0;
    std::string gpu_passes;
    // The budget section's rows: the --budget-ms they ran under (0: a rung of its ladder, fixed).
    double budget_ms = 0.0;
    // The error-target section's rows: the --max-error they chose for (0: a rung of the ladder),
    // the model's prediction (%) and the frame's shadow-edge pixels it was made from.
    double max_error = 0.0;
    double predicted_pct = -1.0;
    long edge_pixels = -1;
};

inline constexpr const char* kSilhouetteSection = "silhouette";
inline constexpr const char* kEffectsSection = "effects";
inline constexpr const char* kLightsSection = "lights";
inline constexpr const char* kBudgetSection = "budget";
inline constexpr const char* kErrorSection = "max-error";
// The silhouette sweep's spheres: slices around, half as many stacks.
inline constexpr int kSphereSegments[] = {8, 16, 32, 64, 128};

// ---- the sweep -------------------------------------------------------------------------------

struct Sweep {
    BenchOptions o;
    int width = 512, height = 512;
    std::vector<SceneSpec> scenes;
    std::vector<shadow::Encoding> encodings;
    std::vector<shadow::Filter> filters;
    render::Options base;  // the job's size and the --set options shared by every run
    std::string gl_renderer, context;
    std::vector<Row> rows;
    std::vector<Row> silhouette;  // the silhouette sweep's rows (section kSilhouetteSection)
    std::vector<Row> effects;     // the effects' rows (section kEffectsSection)
    std::string effects_frame;    // the scene frame they were measured on ("course@0.60")
    std::vector<Row> lights;      // forward against deferred (section kLightsSection)
    std::vector<Row> budget;      // --budget-ms (section kBudgetSection)
    std::vector<Row> errors;      // --max-error (section kErrorSection)
    std::vector<std::string> notes;
    std::string command_line;
    std::string from_csv;  // rows read back from this file instead of measured
    std::string load_before, load_after;  // the machine's 1-minute load average around the run
};

// A technique at a map size (0: no map): the rows of several scene frames are averaged per key.
struct Key {
    std::string technique;
    int map = 0;
    bool operator<(const Key& o) const { return technique != o.technique ? technique < o.technique : map < o.map; }
};

std::string key_label(const Key& k);

// The technique column of the shadow volumes' runs: "volumes auto", "volumes zpass", "volumes zfail".
inline constexpr const char* kVolumesPrefix = "volumes ";
inline bool is_volumes(const std::string& technique) { return technique.rfind(kVolumesPrefix, 0) == 0; }

// The technique column's suffix of the runs at the settings before issue 9 (bench.cpp, before_rows).
inline constexpr const char* kBeforeSuffix = " (before)";
// A row whose map is --map-size auto's (its map column the size chosen).
inline constexpr const char* kAutoSuffix = " (map auto)";

// ---- bench_rows.cpp: the sweep's rows beyond encodings x filters x maps ----------------------------

// A run of the sweep: its settings and the technique column of its rows.
struct Planned {
    render::Settings settings;
    std::string label;
};
std::vector<Planned> before_rows(const Sweep& w);  // the defaults before issue 9

// ---- bench.cpp: helpers the sweep and the soft-shadow bench (soft_bench.cpp) share -------------

// The technique column: "rgba pcf4x4", "volumes auto", "planar".
std::string technique_label(const render::Settings& s);
// A row's technique columns: its label, and the encoding, filter and map size of a shadow map
// ("-", "-", 0 for the other techniques).
void set_technique(Row& row, const render::Settings& s, const std::string& label);
// The row's settings as `penumbra render` takes them: the bench's options with this scene frame
// and these settings (Row::settings).
std::string row_args(const render::Options& base, const SceneSpec& spec, const render::Settings& s);

// "teapot@0.6" -> {teapot, 0.6, course@0.60}; "FILE.gltf" -> {FILE.gltf, 0, FILE's stem}.
SceneSpec parse_scene_spec(const std::string& spec);

// --set NAME=VALUE...: each a technique option into `s`; the job's options and those in `swept`
// (the bench varies them itself) are refused, as is a bad value (CommandError).
void apply_set(const std::vector<std::string>& set, const std::vector<std::string>& swept, render::Settings& s);

// The red channel of an RGBA image: the visibility AOV, one byte per pixel.
std::vector<std::uint8_t> red_channel(const std::vector<std::uint8_t>& rgba);

// A static scene's "moving" frames: the light turned about the vertical axis through the scene's
// centre, half a degree more each frame, so the map must be redrawn every time.
void turn_light(scene::Light& light, const scene::Light& original, const glm::vec3& centre, int frame);

struct Timing {
    double median_ms = 0.0;
    int redrawn = 0;
    gl::GpuSummary gpu;  // the timed frames' GPU times (frames 0: no timer on this context)
};

// Renders `frames` frames after `warmup` untimed ones, each finished with glFinish; the timed
// ones' GPU time per pass too where the context has a timer (read after the last frame).
template <typename SceneAt>
Timing time_frames(render::Renderer& r, const render::Settings& s, const render::FrameInputs& in, int warmup, int frames,
                   SceneAt scene_at) {
    std::vector<double> ms;
    Timing t;
    gl::PassTimer& timer = r.gpu_timer();
    timer.take(true);  // nothing of earlier frames
    for (int i = 0; i < warmup + frames; ++i) {
        const scene::Scene& sc = scene_at(i);
        timer.enable(i >= warmup);
        const auto start = Clock::now();
        const render::FramePlan& plan = r.render(sc, s, in);
        r.finish();
        const double elapsed = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (i >= warmup) {
            ms.push_back(elapsed);
            t.redrawn += plan.drawn("shadow-map") ? 1 : 0;
        }
    }
    timer.enable(false);
    t.gpu = gl::summarize(timer.take(true));
    t.median_ms = measure::median(ms);
    return t;
}

// A row's GPU times over the timing rounds: each round's moving and still Timing, then set() puts
// the medians over the rounds on the row (nothing where no round was measured).
struct GpuRounds {
    std::vector<double> moving, still;
    std::vector<gl::GpuSummary> moving_passes;
    void add(const Timing& moving_t, const Timing& still_t) {
        if (moving_t.gpu.frames > 0) moving.push_back(moving_t.gpu.total_ms), moving_passes.push_back(moving_t.gpu);
        if (still_t.gpu.frames > 0) still.push_back(still_t.gpu.total_ms);
    }
    void set(Row& row) const {
        if (!moving.empty()) row.gpu_moving = measure::median(moving);
        if (!still.empty()) row.gpu_still = measure::median(still);
        // Each pass's median over the rounds' medians, in the order the passes first ran.
        gl::GpuSummary s;
        std::vector<std::vector<double>> per;
        for (const gl::GpuSummary& round : moving_passes)
            for (const gl::PassMedian& p : round.passes) {
                auto it = std::find_if(s.passes.begin(), s.passes.end(), [&](const gl::PassMedian& q) { return q.name == p.name; });
                if (it == s.passes.end()) {
                    s.passes.push_back({p.name, 0.0, 0});
                    per.emplace_back();
                    it = s.passes.end() - 1;
                }
                per[static_cast<size_t>(it - s.passes.begin())].push_back(p.ms);
            }
        for (size_t i = 0; i < per.size(); ++i) s.passes[i].ms = measure::median(per[i]);
        row.gpu_passes = gl::pass_list(s);
    }
};

// ---- effects_bench.cpp: the stencil effects on the course frame ---------------------------------

// Each effect alone and all three, under the sweep's default technique and shadow volumes, on the
// first course frame of --scenes: the error against the effects' truth (the frame, and the mirror's
// and the opening's pixels alone) and ms/frame, into w.effects. No course frame: a note, no rows.
void effects_sweep(Sweep& w, render::Renderer& r, const render::FrameInputs& in);
// The first course frame of --scenes: the one at t 0.6 if there is one (the pictures' frame); null
// when no teapot frame is listed, with a note that what is `measured` ("the stencil effects are")
// was not.
const SceneSpec* course_frame(Sweep& w, const std::string& measured);

// A row of a section on the course frame waiting for its times (effects_bench.cpp, lights_bench.cpp).
struct PendingRow {
    Row row;
    render::Settings s;
    std::vector<double> moving, still;
    GpuRounds gpu;
};
// Times every pending row in w.o.rounds interleaved rounds of w.o.frames frames, moving (the
// course animated 1/60 s a frame from `time`) and still (`still` again), and appends the rows,
// their medians filled in, to `out`. `what` names the section in a GL error.
void time_course_rows(const Sweep& w, render::Renderer& r, const render::FrameInputs& in, scene::SceneSource& src,
                      const scene::Scene& still, double time, std::vector<PendingRow>& pending, std::vector<Row>& out,
                      const char* what);

// ---- lights_bench.cpp: forward against deferred shading ------------------------------------------

// --lights 0 and 1 to 256 (quick: 0, 8, 64) under forward and deferred shading, the default
// technique, on the first course frame: ms/frame, the bytes of every target, and the visibility
// scored against the hard truth, into w.lights.
void lights_sweep(Sweep& w, render::Renderer& r, const render::FrameInputs& in);
// N lights at which deferred becomes cheaper than forward, interpolated in log N between the two
// rows that bracket it; < 0 when it does not happen in the rows.
double lights_crossing(const Sweep& w);

// ---- budget_bench.cpp: --budget-ms -----------------------------------------------------------------

// --budget-ms 2, 4, 8, 16, 32 (quick: 4, 16) on the first course frame, moving: the settings each
// settled on, their time and error against the hard truth, into w.budget; and each rung of the
// ladder as a fixed setting over the same frames (budget_ms 0).
void budget_sweep(Sweep& w, render::Renderer& r, const render::FrameInputs& in);
// The fixed rung (budget_ms 0) with the least error among those whose time fits the row's budget;
// null when none does.
const Row* best_fixed(const Sweep& w, const Row& budget_row);
// The same among the sweep's rows on the same frame (timed over the sweep's own frames).
const Row* best_of_sweep(const Sweep& w, const Row& budget_row);
// results.md's table: each budget's choice beside best_fixed's. Empty without its rows.
std::string budget_table(const Sweep& w);

// ---- error_bench.cpp: --max-error ----------------------------------------------------------------

// --max-error 0.2, 0.1, 0.05, 0.025 (quick: 0.1) on every scene frame: each rung of the ladder
// with its predicted and measured error and its time (max_error 0), then the rung chosen for each
// target, into w.errors.
void error_sweep(Sweep& w, render::Renderer& r, const render::FrameInputs& in);
// The rung (max_error 0) of the row's scene with the least measured time among those whose
// measured error keeps within the row's target; null when none does.
const Row* cheapest_within(const Sweep& w, const Row& target_row);
// results.md's tables: each target's choice beside cheapest_within's, and the model rung by rung.
std::string error_table(const Sweep& w);

// ---- soft_bench.cpp: penumbra bench --soft ------------------------------------------------------

void run_soft_bench(const BenchOptions& o);

// ---- cascades_bench.cpp: penumbra bench --cascades ------------------------------------------------

void run_cascades_bench(const BenchOptions& o);

// ---- scale_bench.cpp: penumbra bench --scale ---------------------------------------------------

void run_scale_bench(const BenchOptions& o);

// ---- bench_report.cpp ------------------------------------------------------------------------

// Writes results.csv, results.md, tradeoff.svg/.png and tradeoff_mae.svg/.png into `dir`;
// `t0` is when the command started (results.md gives the time until then).
struct Report {
    std::vector<Key> front;  // the Pareto front of error against time, over all scenes
    double elapsed = 0.0;    // seconds since t0 when results.md was written
};
Report write_report(const Sweep& w, const std::filesystem::path& dir, Clock::time_point t0);

// bench_sections.cpp: the tables of the sections beside the sweep in results.md, each empty without
// its rows: the silhouette sweep's (Sweep::silhouette) and the stencil effects' (Sweep::effects).
std::string silhouette_table(const Sweep& w);
std::string effects_table(const Sweep& w);
std::string lights_table(const Sweep& w);
// ms/frame against --lights, forward and deferred, the crossing called out (lights.svg).
Plot lights_plot(const Sweep& w);

// Reads rows written by the CSV writer (or by another harness with the same columns, e.g. three.js
// runs scored with `penumbra truth --score`): the scenes, sizes and map sizes follow from the rows.
void read_csv(Sweep& w, const std::string& path);
// The rows as results.csv (bench_csv.cpp).
std::string to_csv(const Sweep& w);

// ---- truth_command.cpp: the truth of one frame, shared by the sweep and penumbra truth ----------

std::unique_ptr<platform::Platform> make_context();

// The area light the soft truth uses unless told otherwise: 1% of the scene's diagonal for a
// point or spot light (a bulb), 0.01 rad (about twice the sun's) for a directional light.
float default_light_radius(const scene::Scene& s);

// The camera matrix the renderer uses for this scene at this size: ask it (one frame, no shadows).
glm::mat4 renderer_view_proj(const scene::Scene& s, int width, int height);
// The truth's options for the frame the renderer draws of `s` at width x height (the hard truth:
// no area-light samples until the caller asks for them).
inline measure::TruthOptions frame_truth_options(const scene::Scene& s, int width, int height) {
    measure::TruthOptions to;
    to.width = width;
    to.height = height;
    to.view_proj = renderer_view_proj(s, width, height);
    return to;
}

void write_or_throw(const std::string& path, const measure::Pixels& px);
// Writes `text` whole through a temporary file, or throws CommandError, exit status 2 (write_output).
void write_text(const std::filesystem::path& path, const std::string& text);

// The truth as a picture: lit white, shadowed black; pixels left out of the comparison in colour.
measure::Pixels classes_image(const measure::TruthImage& t);

// A rendered visibility against the truth: agreement in greys, false shadow red, false lit blue.
measure::Pixels error_image(const std::vector<std::uint8_t>& rendered, const measure::TruthImage& t);

// "valid 50.3 %, background 45.4 %, ...": the share of each pixel class.
std::string class_summary(const measure::TruthImage& t);

}  // namespace penumbra::tools::bench
