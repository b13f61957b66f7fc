// penumbra bench: every technique on the same frames, scored against the ray-traced ground
// truth, timed with the light moving (shadow map redrawn every frame) and with a still scene
// (the map reused), with the memory of its shadow targets; a CSV, a Markdown table and a plot
// of error against time with the Pareto front (SVG and PNG).
// penumbra truth: the ground truth of one frame as PNGs, and the score of any visibility PNG.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/caps.h"
#include "gl/check.h"
#include "measure.h"
#include "measure/metrics.h"
#include "platform/platform.h"
#include "plot.h"
#include "measure/image_io.h"
#include "render/renderer.h"
#include "render/settings.h"
#include "scene/scene_source.h"
#include "measure/ray_tracer.h"

namespace fs = std::filesystem;

namespace penumbra::tools {

using measure::Pixels;
using measure::read_png;
using measure::write_png;
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string duration_str(double s) {
    char b[32];
    const int total = static_cast<int>(std::lround(s));
    if (total >= 60) std::snprintf(b, sizeof b, "%dm%02ds", total / 60, total % 60);
    else std::snprintf(b, sizeof b, "%.1fs", s);
    return b;
}

std::string fixed(double v, int digits) {
    char b[48];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

std::unique_ptr<platform::Platform> make_context() {
    std::string error;
    auto p = platform::create_headless(error);
    if (!p) throw CommandError{error, 1};
    return p;
}

// "teapot@0.6", "teapot" (t = 0), "FILE.gltf", "FILE.gltf@2" (a glTF scene is static).
struct SceneSpec {
    std::string name;
    double time = 0.0;
    std::string label;  // "course@0.60", "bench_easy"
};

SceneSpec parse_scene_spec(const std::string& spec) {
    SceneSpec s;
    s.name = spec;
    const auto at = spec.rfind('@');
    if (at != std::string::npos) {
        const std::string t = spec.substr(at + 1);
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(v))
            throw CommandError{"--scenes: '" + spec + "': expected NAME@SECONDS", 2};
        s.name = spec.substr(0, at);
        s.time = v;
    }
    if (s.name == "teapot") s.label = "course@" + fixed(s.time, 2);
    else s.label = fs::path(s.name).stem().string();
    return s;
}


// The area light the soft truth uses unless told otherwise: 1% of the scene's diagonal for a
// point or spot light (a bulb), 0.01 rad (about twice the sun's) for a directional light.
float default_light_radius(const scene::Scene& s) {
    if (s.light.type == scene::LightType::Directional) return 0.01f;
    const scene::Bounds b = scene::scene_bounds(s);
    return b.empty() ? 0.01f : 0.01f * glm::length(b.max - b.min);
}

std::vector<std::uint8_t> red_channel(const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint8_t> out(rgba.size() / 4);
    for (size_t i = 0; i < out.size(); ++i) out[i] = rgba[4 * i];
    return out;
}

void write_or_throw(const std::string& path, const Pixels& px) {
    if (const std::string err = write_png(path, px); !err.empty()) throw CommandError{err, 1};
}

Pixels grey_image(int w, int h, std::vector<std::uint8_t> data) { return Pixels{w, h, 1, std::move(data)}; }

// The truth as a picture: lit white, shadowed black; pixels left out of the comparison in colour.
Pixels classes_image(const measure::TruthImage& t) {
    Pixels px{t.width, t.height, 3, std::vector<std::uint8_t>(t.lit.size() * 3)};
    for (size_t i = 0; i < t.lit.size(); ++i) {
        std::uint8_t r = 0, g = 0, b = 0;
        switch (static_cast<measure::PixelClass>(t.pixel_class[i])) {
            case measure::PixelClass::Valid: r = g = b = t.lit[i] ? 255 : 0; break;
            case measure::PixelClass::Background: r = 30, g = 40, b = 70; break;
            case measure::PixelClass::Silhouette: r = 230, g = 60, b = 200; break;
            case measure::PixelClass::NotReceiver: r = 120, g = 90, b = 40; break;
            case measure::PixelClass::FacingAway: r = 70, g = 110, b = 140; break;
            case measure::PixelClass::OutsideCone: r = 90, g = 70, b = 110; break;
        }
        px.data[3 * i] = r;
        px.data[3 * i + 1] = g;
        px.data[3 * i + 2] = b;
    }
    return px;
}

// A rendered visibility against the truth: agreement in greys, false shadow red, false lit blue.
Pixels error_image(const std::vector<std::uint8_t>& rendered, const measure::TruthImage& t) {
    const auto cls = measure::classify(rendered, t.lit, t.valid_mask());
    Pixels px{t.width, t.height, 3, std::vector<std::uint8_t>(cls.size() * 3)};
    for (size_t i = 0; i < cls.size(); ++i) {
        std::uint8_t r, g, b;
        switch (cls[i]) {
            case 0: r = g = b = t.lit[i] ? 225 : 70; break;
            case 1: r = 235, g = 40, b = 30; break;   // false shadow
            case 2: r = 30, g = 110, b = 255; break;  // false lit
            default: r = g = b = t.object[i] < 0 ? 15 : 140; break;
        }
        px.data[3 * i] = r;
        px.data[3 * i + 1] = g;
        px.data[3 * i + 2] = b;
    }
    return px;
}

std::string score_line(const measure::Score& s) {
    std::string line = "valid " + std::to_string(s.valid) + " px, false shadow " + fixed(s.false_shadow_pct, 3) +
                       " %, false lit " + fixed(s.false_lit_pct, 3) + " %, error " + fixed(s.error_pct, 3) +
                       " %, mean abs error " + fixed(s.mae_pct, 3) + " %";
    if (s.mae_soft_pct >= 0.0) line += ", vs area light " + fixed(s.mae_soft_pct, 3) + " %";
    return line;
}

std::string class_summary(const measure::TruthImage& t) {
    const double n = static_cast<double>(t.lit.size());
    std::string out;
    for (int c = 0; c < measure::kPixelClassCount; ++c) {
        const auto pc = static_cast<measure::PixelClass>(c);
        out += (c ? ", " : "") + std::string(measure::to_string(pc)) + " " + fixed(100.0 * static_cast<double>(t.count(pc)) / n, 1) + " %";
    }
    return out;
}

// The camera matrix the renderer uses for this scene at this size: ask it (one frame, no shadows).
glm::mat4 renderer_view_proj(render::Renderer& r, const scene::Scene& s, int width, int height) {
    render::Settings none;
    none.technique = render::Technique::None;
    none.width = width;
    none.height = height;
    none.aov = render::Aov::Visibility;
    r.render(s, none);
    return r.camera_view_proj();
}

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
};

std::string technique_label(const render::Settings& s) {
    if (s.technique != render::Technique::ShadowMap) return std::string(render::to_string(s.technique));
    return std::string(shadow::to_string(s.encoding)) + " " + std::string(shadow::to_string(s.filter));
}

std::string bytes_str(std::size_t b) {
    if (b == 0) return "0";
    if (b >= (1u << 20)) return fixed(static_cast<double>(b) / (1u << 20), b >= (16u << 20) ? 0 : 1) + " MiB";
    return fixed(static_cast<double>(b) / 1024.0, 0) + " KiB";
}

// ---- the sweep -------------------------------------------------------------------------------

struct Sweep {
    BenchOptions o;
    int width = 512, height = 512;
    std::vector<SceneSpec> scenes;
    std::vector<shadow::Encoding> encodings;
    std::vector<shadow::Filter> filters;
    render::Settings base;
    std::string gl_renderer, context;
    std::vector<Row> rows;
    std::vector<std::string> notes;
    std::string command_line;
    std::string from_csv;  // rows read back from this file instead of measured
    std::string load_before, load_after;  // the machine's 1-minute load average around the run
};

template <typename T>
std::vector<T> parse_list(const std::vector<std::string>& names, const char* option,
                          const std::vector<std::pair<std::string, T>>& known) {
    std::vector<T> out;
    for (const auto& n : names) {
        auto it = std::find_if(known.begin(), known.end(), [&](const auto& k) { return k.first == n; });
        if (it == known.end()) throw CommandError{std::string(option) + ": unknown value '" + n + "'", 2};
        out.push_back(it->second);
    }
    return out;
}

Sweep configure(const BenchOptions& in) {
    Sweep w;
    w.o = in;
    BenchOptions& o = w.o;
    if (o.size.empty()) o.size = o.quick ? "128x128" : "512x512";
    if (o.frames <= 0) o.frames = o.quick ? 5 : 20;
    if (o.rounds <= 0) o.rounds = o.quick ? 1 : 3;
    if (o.maps.empty()) o.maps = o.quick ? std::vector<int>{256, 1024} : std::vector<int>{256, 512, 1024, 2048, 4096};
    if (o.soft_samples < 0) o.soft_samples = o.quick ? 16 : 64;
    if (o.scenes.empty()) {
        o.scenes = o.quick ? std::vector<std::string>{"teapot@0.6", "tests/data/bench_easy.gltf"}
                           : std::vector<std::string>{"teapot@0", "teapot@0.6", "teapot@2.25", "teapot@7",
                                                      "tests/data/bench_easy.gltf", "tests/data/bench_medium.gltf",
                                                      "tests/data/bench_hard.gltf"};
    }
    for (const auto& s : o.scenes) w.scenes.push_back(parse_scene_spec(s));
    std::vector<std::pair<std::string, shadow::Encoding>> encs;
    for (auto e : shadow::kAllEncodings) encs.emplace_back(std::string(shadow::to_string(e)), e);
    std::vector<std::pair<std::string, shadow::Filter>> fils;
    for (auto f : shadow::kAllFilters) fils.emplace_back(std::string(shadow::to_string(f)), f);
    if (o.encodings.empty()) for (const auto& e : encs) o.encodings.push_back(e.first);
    if (o.filters.empty()) for (const auto& f : fils) o.filters.push_back(f.first);
    w.encodings = parse_list(o.encodings, "--encodings", encs);
    w.filters = parse_list(o.filters, "--filters", fils);
    for (int m : o.maps)
        if (m <= 0) throw CommandError{"--maps: sizes must be positive", 2};
    if (const std::string err = render::parse_option(w.base, "size", o.size); !err.empty()) throw CommandError{err, 2};
    w.width = w.base.width;
    w.height = w.base.height;
    for (const auto& kv : o.set) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos) throw CommandError{"--set " + kv + ": expected NAME=VALUE", 2};
        const std::string name = kv.substr(0, eq), value = kv.substr(eq + 1);
        for (const char* owned : {"scene", "time", "size", "encoding", "filter", "map-size", "aov", "technique", "out", "frames"})
            if (name == owned) throw CommandError{"--set " + name + ": the bench sweeps or sets this one itself", 2};
        if (const std::string err = render::parse_option(w.base, name, value); !err.empty()) throw CommandError{err, 2};
    }
    return w;
}

// A static scene's "moving" frames: the light turned about the vertical axis through the scene's
// centre, half a degree more each frame, so the map must be redrawn every time.
void turn_light(scene::Light& light, const scene::Light& original, const glm::vec3& centre, int frame) {
    const glm::mat4 rot = glm::rotate(glm::mat4(1.0f), glm::radians(0.5f * static_cast<float>(frame)), glm::vec3(0, 1, 0));
    light.position = centre + glm::vec3(rot * glm::vec4(original.position - centre, 1.0f));
    light.direction = glm::normalize(glm::vec3(rot * glm::vec4(original.direction, 0.0f)));
}

struct Timing {
    double median_ms = 0.0;
    int redrawn = 0;
};

// Renders `frames` frames after `warmup` untimed ones, each finished with glFinish.
template <typename SceneAt>
Timing time_frames(render::Renderer& r, const render::Settings& s, int warmup, int frames, SceneAt scene_at) {
    std::vector<double> ms;
    Timing t;
    for (int i = 0; i < warmup + frames; ++i) {
        const scene::Scene& sc = scene_at(i);
        const auto start = Clock::now();
        const render::FramePlan& plan = r.render(sc, s);
        r.finish();
        const double elapsed = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (i >= warmup) {
            ms.push_back(elapsed);
            t.redrawn += plan.shadow_redrawn ? 1 : 0;
        }
    }
    t.median_ms = measure::median(ms);
    return t;
}

std::string load_average() {
    std::ifstream f("/proc/loadavg");
    std::string one;
    return f >> one ? one : std::string("?");
}

void run_sweep(Sweep& w) {
    const auto t0 = Clock::now();
    auto ctx = make_context();
    w.context = ctx->description();
    w.load_before = load_average();
    const BenchOptions& o = w.o;

    std::vector<render::Settings> techniques;
    for (auto e : w.encodings)
        for (auto f : w.filters)
            for (int m : o.maps) {
                render::Settings s = w.base;
                s.technique = render::Technique::ShadowMap;
                s.encoding = e;
                s.filter = f;
                s.map_size = m;
                techniques.push_back(s);
            }
    if (o.references)
        for (auto t : {render::Technique::None, render::Technique::Planar}) {
            render::Settings s = w.base;
            s.technique = t;
            techniques.push_back(s);
        }
    // Work units: one accuracy frame and `rounds` timing runs per technique and scene.
    const size_t total = techniques.size() * w.scenes.size() * static_cast<size_t>(1 + o.rounds);
    size_t done = 0, timed = 0;
    double timed_seconds = 0.0;
    std::fprintf(stderr, "bench: %zu scene frames x %zu techniques at %dx%d, %d rounds of %d timed frames per run%s\n",
                 w.scenes.size(), techniques.size(), w.width, w.height, o.rounds, o.frames,
                 o.quick ? " (quick: timings are not meaningful)" : "");

    // One renderer for everything (one context, one state cache); load() switches scenes.
    render::Renderer r(gl::probe_caps());
    w.gl_renderer = r.caps().renderer;

    struct Pending {
        Row row;
        render::Settings s;
        std::vector<double> moving, still;
    };
    struct SceneState {
        SceneSpec spec;
        scene::SceneSource src;
        scene::Scene still;    // a copy: the moving runs animate src
        scene::Scene turning;  // a static scene's moving frames turn this one's light
        glm::vec3 centre{0.0f};
        std::vector<Pending> pending;
    };
    std::vector<std::unique_ptr<SceneState>> states;

    const fs::path images = fs::path(o.out_dir) / "images";
    for (size_t si = 0; si < w.scenes.size(); ++si) {
        auto st = std::make_unique<SceneState>();
        st->spec = w.scenes[si];
        const SceneSpec& spec = st->spec;
        st->src = open_scene(spec.name);
        st->still = st->src.at(spec.time);
        st->turning = st->still;
        st->centre = scene::scene_bounds(st->still).center();
        const scene::Scene& still = st->still;
        r.load(still);

        // The truth for this frame, once for every technique.
        const auto tt = Clock::now();
        measure::TruthOptions to;
        to.width = w.width;
        to.height = w.height;
        to.view_proj = renderer_view_proj(r, still, w.width, w.height);
        to.soft_samples = o.soft_samples;
        to.light_radius = default_light_radius(still);
        const measure::TruthImage truth = measure::RayTracer(still).render(to);
        std::fprintf(stderr, "truth %s: %s in %.1f s (%s)\n", spec.label.c_str(),
                     o.soft_samples > 0 ? ("hard + " + std::to_string(o.soft_samples) + " area-light samples").c_str() : "hard",
                     seconds_since(tt), class_summary(truth).c_str());
        const auto valid = truth.valid_mask();
        const bool pictures = si == 0 || (spec.name == "teapot" && std::fabs(spec.time - 0.6) < 1e-9);
        if (pictures) {
            std::error_code ec;
            fs::create_directories(images, ec);
            write_or_throw((images / (spec.label + "-truth.png")).string(), classes_image(truth));
        }

        // Accuracy: the visibility AOV of the very frame the truth shows, for every technique.
        for (const render::Settings& base : techniques) {
            render::Settings s = base;
            s.time = spec.time;
            s.scene = spec.name;
            Row row;
            row.scene = spec.label;
            row.time = spec.time;
            row.technique = technique_label(s);
            row.encoding = s.technique == render::Technique::ShadowMap ? std::string(shadow::to_string(s.encoding)) : "-";
            row.filter = s.technique == render::Technique::ShadowMap ? std::string(shadow::to_string(s.filter)) : "-";
            row.map = s.technique == render::Technique::ShadowMap ? s.map_size : 0;
            row.settings = render::to_args(s);
            ++done;
            if (const std::string problem = r.check(still, s); !problem.empty()) {
                w.notes.push_back(spec.label + ": " + row.technique + " skipped: " + problem);
                std::fprintf(stderr, "[%4zu/%zu] %s %s: skipped (%s)\n", done, total, spec.label.c_str(), row.technique.c_str(),
                             problem.c_str());
                done += static_cast<size_t>(o.rounds);
                continue;
            }
            s.aov = render::Aov::Visibility;
            const render::FramePlan& plan = r.render(still, s);
            if (s.technique == render::Technique::ShadowMap && plan.map_size != s.map_size) {
                row.map = plan.map_size;
                w.notes.push_back(spec.label + ": " + row.technique + " map " + std::to_string(s.map_size) + " clamped to " +
                                  std::to_string(plan.map_size));
            }
            const auto vis = red_channel(r.read_image());
            row.score = measure::score(vis, truth.lit, valid, o.soft_samples > 0 ? &truth.soft : nullptr);
            row.bytes = s.technique == render::Technique::ShadowMap ? r.shadow_map_bytes() : 0;
            if (pictures && (s.map_size == 1024 || s.technique != render::Technique::ShadowMap)) {
                std::string name = spec.label + "-" + row.technique + (row.map ? "-" + std::to_string(row.map) : "") + "-errors.png";
                std::replace(name.begin(), name.end(), ' ', '-');
                write_or_throw((images / name).string(), error_image(vis, truth));
            }
            std::fprintf(stderr, "[%4zu/%zu] %-12s %-16s %-9s error %6.2f %% (false shadow %5.2f, false lit %5.2f) | %s elapsed\n",
                         done, total, spec.label.c_str(), row.technique.c_str(),
                         row.map ? ("map " + std::to_string(row.map)).c_str() : "", row.score.error_pct,
                         row.score.false_shadow_pct, row.score.false_lit_pct, duration_str(seconds_since(t0)).c_str());
            s.aov = render::Aov::Color;  // time the frame a user sees
            st->pending.push_back({row, s, {}, {}});
        }
        gl::check_errors("the bench's accuracy pass");
        states.push_back(std::move(st));
    }

    // Time, in rounds over every scene and technique, so a disturbance on the machine (another
    // job starting) hits all alike; each value is the median over the rounds of each round's
    // median over its frames.
    for (int round = 0; round < o.rounds; ++round)
        for (auto& stp : states) {
            SceneState& st = *stp;
            r.load(st.still);
            const auto moving_at = [&](int i) -> const scene::Scene& {
                if (st.src.animated()) return st.src.at(st.spec.time + static_cast<double>(i + 1) / 60.0);
                turn_light(st.turning.light, st.still.light, st.centre, i + 1);
                return st.turning;
            };
            const auto still_at = [&](int) -> const scene::Scene& { return st.still; };
            for (Pending& p : st.pending) {
                const auto tc = Clock::now();
                const Timing moving = time_frames(r, p.s, 2, o.frames, moving_at);
                const Timing still_t = time_frames(r, p.s, 1, o.frames, still_at);
                p.moving.push_back(moving.median_ms);
                p.still.push_back(still_t.median_ms);
                p.row.redrawn_moving += moving.redrawn;
                p.row.redrawn_still += still_t.redrawn;
                ++done;
                timed_seconds += seconds_since(tc);
                ++timed;
                const double left = timed_seconds / static_cast<double>(timed) * static_cast<double>(total - done);
                std::fprintf(stderr, "[%4zu/%zu] %-12s %-16s %-9s round %d/%d: %7.2f ms moving %7.2f ms still | %s elapsed, ~%s left\n",
                             done, total, p.row.scene.c_str(), p.row.technique.c_str(),
                             p.row.map ? ("map " + std::to_string(p.row.map)).c_str() : "", round + 1, o.rounds,
                             moving.median_ms, still_t.median_ms, duration_str(seconds_since(t0)).c_str(),
                             duration_str(left).c_str());
            }
            gl::check_errors("the bench's timing pass");
        }

    for (auto& stp : states)
        for (Pending& p : stp->pending) {
            Row& row = p.row;
            row.ms_moving = measure::median(p.moving);
            row.ms_still = measure::median(p.still);
            // The still scene reuses the map, so its frame is the camera pass alone; what the
            // moving frame costs beyond it is the shadow pass.
            const bool has_map = p.s.technique == render::Technique::ShadowMap;
            row.ms_camera = row.ms_still;
            row.ms_shadow = has_map ? std::max(0.0, row.ms_moving - row.ms_still) : 0.0;
            row.frames = o.frames * o.rounds;
            if (has_map && (row.redrawn_moving != row.frames || row.redrawn_still != 0))
                w.notes.push_back(row.scene + ": " + row.technique + " map " + std::to_string(row.map) + ": the map was redrawn in " +
                                  std::to_string(row.redrawn_moving) + " of " + std::to_string(row.frames) + " moving frames and " +
                                  std::to_string(row.redrawn_still) + " still frames");
            w.rows.push_back(row);
        }
    w.load_after = load_average();
}

// ---- outputs ---------------------------------------------------------------------------------

void write_text(const fs::path& path, const std::string& text) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
        f << text;
        if (!f) throw CommandError{path.string() + ": cannot write", 1};
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw CommandError{path.string() + ": cannot write (" + ec.message() + ")", 1};
}

std::string csv(const Sweep& w) {
    std::ostringstream o;
    o << "scene,time,width,height,technique,encoding,filter,map_size,valid_pixels,truth_shadowed_pct,false_shadow_pct,"
         "false_lit_pct,error_pct,mae_pct,mae_area_light_pct,ms_moving,ms_still,ms_shadow_pass,ms_camera_pass,"
         "frames,redrawn_moving,redrawn_still,shadow_map_bytes,settings\n";
    for (const Row& r : w.rows) {
        const double shadowed = r.score.valid ? 100.0 * static_cast<double>(r.score.truth_shadowed) / static_cast<double>(r.score.valid) : 0.0;
        o << r.scene << "," << fixed(r.time, 3) << "," << w.width << "," << w.height << "," << r.technique << "," << r.encoding << ","
          << r.filter << "," << r.map << "," << r.score.valid << "," << fixed(shadowed, 3) << "," << fixed(r.score.false_shadow_pct, 4)
          << "," << fixed(r.score.false_lit_pct, 4) << "," << fixed(r.score.error_pct, 4) << "," << fixed(r.score.mae_pct, 4) << ","
          << (r.score.mae_soft_pct >= 0.0 ? fixed(r.score.mae_soft_pct, 4) : "") << "," << fixed(r.ms_moving, 3) << ","
          << fixed(r.ms_still, 3) << "," << fixed(r.ms_shadow, 3) << "," << fixed(r.ms_camera, 3) << "," << r.frames << ","
          << r.redrawn_moving << "," << r.redrawn_still << "," << r.bytes << ",\"" << r.settings << "\"\n";
    }
    return o.str();
}

// Means over a set of rows (one technique and map size over several scenes).
struct Mean {
    double fs = 0, fl = 0, err = 0, mae = 0, soft = 0, moving = 0, still = 0, shadow = 0, camera = 0;
    std::size_t bytes = 0;
    int n = 0;
    bool has_soft = false;
};

Mean mean_of(const std::vector<const Row*>& rows) {
    Mean m;
    for (const Row* r : rows) {
        m.fs += r->score.false_shadow_pct;
        m.fl += r->score.false_lit_pct;
        m.err += r->score.error_pct;
        m.mae += r->score.mae_pct;
        if (r->score.mae_soft_pct >= 0.0) {
            m.soft += r->score.mae_soft_pct;
            m.has_soft = true;
        }
        m.moving += r->ms_moving;
        m.still += r->ms_still;
        m.shadow += r->ms_shadow;
        m.camera += r->ms_camera;
        m.bytes = std::max(m.bytes, r->bytes);
        ++m.n;
    }
    if (m.n) {
        const double n = m.n;
        m.fs /= n, m.fl /= n, m.err /= n, m.mae /= n, m.soft /= n, m.moving /= n, m.still /= n, m.shadow /= n, m.camera /= n;
    }
    return m;
}

struct Key {
    std::string technique;
    int map = 0;
    bool operator<(const Key& o) const { return technique != o.technique ? technique < o.technique : map < o.map; }
};

// Techniques in sweep order (encodings x filters, then the references).
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

std::string key_label(const Key& k) { return k.map ? k.technique + " " + std::to_string(k.map) : k.technique; }

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
    p.colors = {"#d95f02", "#7570b3", "#1b9e77", "#666666", "#e7298a"};
    p.color_legend = {{"r8", 0}, {"rgba", 1}, {"depthtex", 2}, {"no shadow map", 3}};
    const auto known = [](const std::string& enc) {
        return enc == "r8" || enc == "rgba" || enc == "depthtex" || enc == "none" || enc == "planar";
    };
    for (const Key& k : keys)
        if (!known(k.technique.substr(0, k.technique.find(' ')))) {
            p.color_legend.push_back({"other (e.g. three.js)", 4});
            break;
        }
    p.marker_legend = {{"hard", Marker::Circle}, {"pcf2x2", Marker::Square}, {"pcf4x4", Marker::Triangle},
                       {"planar", Marker::Diamond}, {"none", Marker::Cross}};
    p.notes = {"marker size: map 256 ... 4096", "front: shadow maps only;", "planar and none are references",
               "hover (SVG) for the exact", "settings of each point"};
    // The front is over the shadow-map techniques: planar shadows need a flat ground and cast no
    // shadow on anything else, and none is no answer; both are drawn as references.
    std::vector<measure::Point2> pts;
    std::vector<Key> order;
    for (const Key& k : keys) {
        const Mean& m = means.at(k);
        tools::PlotPoint pt;
        pt.x = m.moving;
        pt.y = mae ? m.mae : m.err;
        const std::string enc = k.technique.substr(0, k.technique.find(' '));
        const std::string fil = k.technique.find(' ') == std::string::npos ? "" : k.technique.substr(k.technique.find(' ') + 1);
        pt.color = enc == "r8" ? 0 : enc == "rgba" ? 1 : enc == "depthtex" ? 2 : known(enc) ? 3 : 4;
        pt.marker = fil == "hard" ? Marker::Circle : fil == "pcf2x2" ? Marker::Square : fil == "pcf4x4" ? Marker::Triangle
                    : enc == "planar" ? Marker::Diamond : Marker::Cross;
        pt.radius = k.map ? 3.0 + 1.1 * std::log2(static_cast<double>(k.map) / 256.0) : 5.0;
        pt.label = key_label(k);
        pt.tooltip = key_label(k) + ": error " + fixed(m.err, 2) + " % (false shadow " + fixed(m.fs, 2) + ", false lit " +
                     fixed(m.fl, 2) + "), mean abs error " + fixed(m.mae, 2) + " %, " + fixed(m.moving, 2) + " ms/frame moving, " +
                     fixed(m.still, 2) + " still, " + bytes_str(m.bytes);
        p.points.push_back(pt);
        pts.push_back({k.map ? m.moving : NAN, pt.y});
        order.push_back(k);
    }
    p.front = measure::pareto_front(pts, 0.01);  // the tables' precision
    if (front_keys)
        for (size_t i : p.front) front_keys->push_back(order[i]);
    return p;
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
      << "| technique | map | false shadow % | false lit % | error % | mean abs error % | vs area light % | ms/frame moving | "
         "ms/frame still | shadow pass ms | camera pass ms | shadow memory | Pareto |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
    for (const Key& k : keys) {
        const Mean& m = means.at(k);
        o << "| " << k.technique << " | " << (k.map ? std::to_string(k.map) : "-") << " | " << fixed(m.fs, 2) << " | " << fixed(m.fl, 2)
          << " | " << fixed(m.err, 2) << " | " << fixed(m.mae, 2) << " | " << (m.has_soft ? fixed(m.soft, 2) : "-") << " | "
          << fixed(m.moving, 2) << " | " << fixed(m.still, 2) << " | " << fixed(m.shadow, 2) << " | " << fixed(m.camera, 2) << " | "
          << bytes_str(m.bytes) << " | " << (on_front.count(k) ? "yes" : k.map ? "" : "ref.") << " |\n";
    }

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
              << "| technique | false shadow % | false lit % | error % | mean abs error % | vs area light % | ms/frame moving | "
                 "ms/frame still | shadow memory |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
            for (const Key& k : keys_in_order(sel)) {
                const Mean& m = cm.at(k);
                o << "| " << k.technique << " | " << fixed(m.fs, 2) << " | " << fixed(m.fl, 2) << " | " << fixed(m.err, 2) << " | "
                  << fixed(m.mae, 2) << " | " << (m.has_soft ? fixed(m.soft, 2) : "-") << " | " << fixed(m.moving, 2) << " | "
                  << fixed(m.still, 2) << " | " << bytes_str(m.bytes) << " |\n";
            }
        }
    }

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
    for (int table = 0; table < 2; ++table) {
        o << "\n## " << (table == 0 ? "Error % (all scenes)" : "ms/frame with the light moving (all scenes)") << " by map size\n\n| technique |";
        for (int m : w.o.maps) o << " " << m << " |";
        o << "\n|---|";
        for (size_t i = 0; i < w.o.maps.size(); ++i) o << "---:|";
        o << "\n";
        for (const auto& t : techniques) {
            if (t == "none" || t == "planar") continue;
            o << "| " << t << " |";
            for (int m : w.o.maps) {
                const auto it = means.find({t, m});
                o << " " << (it == means.end() ? "-" : fixed(table == 0 ? it->second.err : it->second.moving, 2)) << " |";
            }
            o << "\n";
        }
    }
    if (!w.notes.empty()) {
        o << "\n## Notes\n\n";
        for (const auto& n : w.notes) o << "- " << n << "\n";
    }
    o << "\n![error against time](tradeoff.svg)\n\n![mean absolute error against time](tradeoff_mae.svg)\n";
    return o.str();
}

// One CSV line into fields (double quotes protect commas; "" is a quote).
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
            else if (c == '"') quoted = false;
            else out.back() += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            out.emplace_back();
        } else if (c != '\r') {
            out.back() += c;
        }
    }
    return out;
}

// Reads rows written by csv() (or by another harness with the same columns, e.g. three.js runs
// scored with `penumbra truth --score`): the scenes, sizes and map sizes follow from the rows.
void read_csv(Sweep& w, const std::string& path) {
    std::ifstream f(path);
    if (!f) throw CommandError{"--from-csv " + path + ": cannot open", 2};
    std::string line;
    if (!std::getline(f, line)) throw CommandError{"--from-csv " + path + ": empty file", 2};
    const auto header = csv_fields(line);
    std::map<std::string, size_t> col;
    for (size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
    for (const char* need : {"scene", "time", "width", "height", "technique", "map_size", "valid_pixels", "false_shadow_pct",
                             "false_lit_pct", "error_pct", "mae_pct", "ms_moving", "ms_still"})
        if (!col.count(need)) throw CommandError{"--from-csv " + path + ": no column '" + need + "'", 2};
    size_t line_no = 1;
    std::vector<std::string> labels;
    std::set<int> maps;
    while (std::getline(f, line)) {
        ++line_no;
        if (line.empty()) continue;
        const auto v = csv_fields(line);
        const auto get = [&](const char* name) -> std::string {
            const auto it = col.find(name);
            return it != col.end() && it->second < v.size() ? v[it->second] : std::string();
        };
        const auto num = [&](const char* name, double fallback) {
            const std::string t = get(name);
            if (t.empty()) return fallback;
            char* end = nullptr;
            const double d = std::strtod(t.c_str(), &end);
            if (end != t.c_str() + t.size())
                throw CommandError{"--from-csv " + path + ":" + std::to_string(line_no) + ": " + name + " '" + t + "' is not a number", 2};
            return d;
        };
        Row r;
        r.scene = get("scene");
        r.time = num("time", 0.0);
        w.width = static_cast<int>(num("width", w.width));
        w.height = static_cast<int>(num("height", w.height));
        r.technique = get("technique");
        r.encoding = get("encoding");
        r.filter = get("filter");
        r.map = static_cast<int>(num("map_size", 0));
        r.settings = get("settings");
        r.score.valid = static_cast<std::size_t>(num("valid_pixels", 0));
        r.score.truth_shadowed = static_cast<std::size_t>(num("truth_shadowed_pct", 0) / 100.0 * static_cast<double>(r.score.valid) + 0.5);
        r.score.false_shadow_pct = num("false_shadow_pct", 0);
        r.score.false_lit_pct = num("false_lit_pct", 0);
        r.score.error_pct = num("error_pct", 0);
        r.score.mae_pct = num("mae_pct", 0);
        r.score.mae_soft_pct = num("mae_area_light_pct", -1.0);
        r.ms_moving = num("ms_moving", 0);
        r.ms_still = num("ms_still", 0);
        r.ms_shadow = num("ms_shadow_pass", std::max(0.0, r.ms_moving - r.ms_still));
        r.ms_camera = num("ms_camera_pass", r.ms_still);
        r.frames = static_cast<int>(num("frames", 0));
        r.redrawn_moving = static_cast<int>(num("redrawn_moving", 0));
        r.redrawn_still = static_cast<int>(num("redrawn_still", 0));
        r.bytes = static_cast<std::size_t>(num("shadow_map_bytes", 0));
        if (r.scene.empty() || r.technique.empty())
            throw CommandError{"--from-csv " + path + ":" + std::to_string(line_no) + ": no scene or technique", 2};
        if (std::find(labels.begin(), labels.end(), r.scene) == labels.end()) labels.push_back(r.scene);
        if (r.map > 0) maps.insert(r.map);
        w.rows.push_back(r);
    }
    if (w.rows.empty()) throw CommandError{"--from-csv " + path + ": no rows", 2};
    w.scenes.clear();
    for (const auto& l : labels) w.scenes.push_back({l, 0.0, l});
    w.o.maps.assign(maps.begin(), maps.end());
    if (w.o.maps.empty()) w.o.maps = {0};
}

}  // namespace

void run_bench(const BenchOptions& in) {
    const auto t0 = Clock::now();
    Sweep w = configure(in);
    {
        std::ostringstream c;
        c << "penumbra bench";
        if (w.o.quick) c << " --quick";
        if (!in.size.empty()) c << " --size " << w.o.size;
        if (in.frames > 0) c << " --frames " << w.o.frames;
        if (in.rounds > 0) c << " --rounds " << w.o.rounds;
        if (!in.scenes.empty()) {
            c << " --scenes ";
            for (size_t i = 0; i < in.scenes.size(); ++i) c << (i ? "," : "") << in.scenes[i];
        }
        if (!in.maps.empty()) {
            c << " --maps ";
            for (size_t i = 0; i < in.maps.size(); ++i) c << (i ? "," : "") << in.maps[i];
        }
        for (const auto& s : in.set) c << " --set " << s;
        w.command_line = c.str();
    }
    std::error_code ec;
    fs::create_directories(w.o.out_dir, ec);
    if (ec || !fs::is_directory(w.o.out_dir)) throw CommandError{"--out-dir " + w.o.out_dir + ": cannot create", 2};
    if (!in.from_csv.empty()) {
        w.from_csv = in.from_csv;
        read_csv(w, in.from_csv);
    } else {
        // Every scene must open before the long part starts.
        for (const auto& s : w.scenes) open_scene(s.name);
        run_sweep(w);
    }
    if (w.rows.empty()) throw CommandError{"bench: nothing was measured", 1};

    const fs::path dir(w.o.out_dir);
    std::vector<Key> front;
    const auto all = select(w, [](const Row&) { return true; });
    const tools::Plot plot = make_plot(w, all, "Shadow error against frame time: every encoding x filter x map size", false, &front);
    const tools::Plot mae_plot =
        make_plot(w, all, "Mean absolute visibility error (counts PCF's greys) against frame time", true, nullptr);
    write_text(dir / "results.csv", csv(w));
    write_text(dir / "tradeoff.svg", plot_svg(plot, 1100, 700));
    write_or_throw((dir / "tradeoff.png").string(), plot_png(plot, 1100, 700));
    write_text(dir / "tradeoff_mae.svg", plot_svg(mae_plot, 1100, 700));
    write_or_throw((dir / "tradeoff_mae.png").string(), plot_png(mae_plot, 1100, 700));
    const double elapsed = seconds_since(t0);
    write_text(dir / "results.md", markdown(w, elapsed, front));
    for (const auto& n : w.notes) std::fprintf(stderr, "note: %s\n", n.c_str());
    std::printf("bench: %zu runs in %s; wrote %s/results.csv, results.md, tradeoff.svg/.png, tradeoff_mae.svg/.png\n", w.rows.size(),
                duration_str(elapsed).c_str(), w.o.out_dir.c_str());
    std::printf("Pareto front (error %% against ms/frame, all scenes):");
    for (const Key& k : front) std::printf(" [%s]", key_label(k).c_str());
    std::printf("\n");
}

void run_truth(const TruthCommandOptions& o) {
    render::Settings size;
    if (const std::string err = render::parse_option(size, "size", o.size); !err.empty()) throw CommandError{err, 2};
    if (o.soft_samples < 0) throw CommandError{"--soft-samples: must be 0 or more", 2};
    std::optional<Pixels> scored;
    if (!o.score.empty()) {
        Pixels px;
        if (const std::string err = read_png(o.score, px, 0); !err.empty()) throw CommandError{"--score: " + err, 2};
        if (px.width != size.width || px.height != size.height)
            throw CommandError{"--score " + o.score + ": " + std::to_string(px.width) + "x" + std::to_string(px.height) +
                                   ", but --size is " + o.size, 2};
        scored = std::move(px);
    }
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    if (ec || !fs::is_directory(o.out_dir)) throw CommandError{"--out-dir " + o.out_dir + ": cannot create", 2};

    scene::SceneSource src = open_scene(o.scene);
    const scene::Scene s = src.at(o.time);
    auto ctx = make_context();
    render::Renderer r(gl::probe_caps());
    measure::TruthOptions to;
    to.width = size.width;
    to.height = size.height;
    to.view_proj = renderer_view_proj(r, s, size.width, size.height);
    to.soft_samples = o.soft_samples;
    to.light_radius = o.light_radius >= 0.0f ? o.light_radius : default_light_radius(s);
    const auto t0 = Clock::now();
    const measure::TruthImage t = measure::RayTracer(s).render(to);
    const double secs = seconds_since(t0);

    const fs::path dir(o.out_dir);
    std::vector<std::uint8_t> vis(t.lit.size()), mask(t.lit.size());
    for (size_t i = 0; i < vis.size(); ++i) {
        vis[i] = t.lit[i] ? 255 : 0;
        mask[i] = t.valid(i) ? 255 : 0;
    }
    write_or_throw((dir / "visibility.png").string(), grey_image(t.width, t.height, vis));
    write_or_throw((dir / "mask.png").string(), grey_image(t.width, t.height, mask));
    write_or_throw((dir / "classes.png").string(), classes_image(t));
    if (!t.soft.empty()) {
        std::vector<std::uint8_t> soft(t.soft.size());
        for (size_t i = 0; i < soft.size(); ++i) soft[i] = static_cast<std::uint8_t>(std::lround(255.0f * t.soft[i]));
        write_or_throw((dir / "area_light.png").string(), grey_image(t.width, t.height, soft));
    }
    std::printf("truth of %s at t = %g, %dx%d, in %.2f s: %s; wrote visibility.png, mask.png, classes.png%s to %s\n", o.scene.c_str(),
                o.time, t.width, t.height, secs, class_summary(t).c_str(), t.soft.empty() ? "" : ", area_light.png",
                o.out_dir.c_str());
    if (scored) {
        std::vector<std::uint8_t> rendered(t.lit.size());
        const size_t ch = static_cast<size_t>(scored->channels);
        for (size_t i = 0; i < rendered.size(); ++i) rendered[i] = scored->data[i * ch];
        const measure::Score sc = measure::score(rendered, t.lit, t.valid_mask(), t.soft.empty() ? nullptr : &t.soft);
        write_or_throw((dir / "errors.png").string(), error_image(rendered, t));
        std::printf("score of %s: %s; wrote errors.png\n", o.score.c_str(), score_line(sc).c_str());
    }
}

}  // namespace penumbra::tools
