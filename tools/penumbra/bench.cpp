// penumbra bench: every technique on the same frames, scored against the ray-traced ground
// truth, timed with the light moving (shadow map redrawn every frame) and with a still scene
// (the map reused), with the memory of its shadow targets; a CSV, a Markdown table and a plot
// of error against time with the Pareto front (SVG and PNG). This file is the sweep; the outputs
// are bench_report.cpp, penumbra truth and the truth helpers truth_command.cpp (bench.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bench.h"
#include "cli_options.h"
#include "gl/caps.h"
#include "gl/check.h"
#include "measure.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "plan/options.h"
#include "render/renderer.h"
#include "plan/techniques/reports.h"
#include "plan/techniques/technique.h"
#include "scene/primitives.h"
#include "scene/printable.h"
#include "scenes/probe_scenes.h"
#include "scene/scene_source.h"

namespace fs = std::filesystem;

namespace penumbra::tools {

namespace bench {

SceneSpec parse_scene_spec(const std::string& spec) {
    SceneSpec s;
    s.name = spec;
    const auto at = spec.rfind('@');
    if (at != std::string::npos) {
        const std::string t = spec.substr(at + 1);
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(v))
            throw CommandError{"--scenes: '" + scene::printable(spec) + "': expected NAME@SECONDS (finite)", 2};
        if (const std::string err = render::check_value(render::option_info("time"), t); !err.empty())
            throw CommandError{"--scenes '" + scene::printable(spec) + "': " + err, 2};
        s.name = spec.substr(0, at);
        s.time = v;
    }
    if (s.name == "teapot") s.label = "course@" + fixed(s.time, 2);
    else s.label = scene::printable(fs::path(s.name).stem().string());  // into CSV, SVG and Markdown: UTF-8, one line
    return s;
}

std::vector<std::uint8_t> red_channel(const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint8_t> out(rgba.size() / 4);
    for (size_t i = 0; i < out.size(); ++i) out[i] = rgba[4 * i];
    return out;
}

// A static scene's "moving" frames: the light turned about the vertical axis through the scene's
// centre, half a degree more each frame, so the map must be redrawn every time.
void turn_light(scene::Light& light, const scene::Light& original, const glm::vec3& centre, int frame) {
    const glm::mat4 rot = glm::rotate(glm::mat4(1.0f), glm::radians(0.5f * static_cast<float>(frame)), glm::vec3(0, 1, 0));
    light.position = centre + glm::vec3(rot * glm::vec4(original.position - centre, 1.0f));
    light.direction = glm::normalize(glm::vec3(rot * glm::vec4(original.direction, 0.0f)));
}

std::string technique_label(const render::Settings& s) { return render::technique_module(s.technique).label(s); }

std::string row_args(const render::Options& base, const SceneSpec& spec, const render::Settings& s) {
    render::Options labelled = base;
    labelled.job.scene = spec.name;
    labelled.job.time = spec.time;
    labelled.settings = s;
    return render::to_args(labelled);
}

void set_technique(Row& row, const render::Settings& s, const std::string& label) {
    row.technique = label;
    const bool map = render::technique_module(s.technique).depth_map();
    row.encoding = map ? std::string(shadow::to_string(s.encoding)) : "-";
    row.filter = map ? std::string(shadow::to_string(s.filter)) : "-";
    row.map = map ? s.map_size : 0;
}

}  // namespace bench

namespace {

using namespace bench;

// A list option of the bench (--encodings r8,rgba): each value checked by the option table's
// entry for `option` and read into a Settings.
template <typename T>
std::vector<T> settings_list(const std::vector<std::string>& values, const char* option, T render::Settings::*field) {
    std::vector<T> out;
    for (const auto& v : values) {
        render::Settings s;
        if (const std::string err = render::parse_option(s, option, v); !err.empty()) throw CommandError{err, 2};
        out.push_back(s.*field);
    }
    return out;
}

}  // namespace

void bench::apply_set(const std::vector<std::string>& set, const std::vector<std::string>& swept, render::Settings& s) {
    for (const auto& kv : set) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos) throw CommandError{"--set " + kv + ": expected NAME=VALUE", 2};
        const std::string name = kv.substr(0, eq), value = kv.substr(eq + 1);
        const auto* opt = render::find_option(render::option_table(), name);
        if (opt && (opt->info.part == render::OptionPart::Job || std::count(swept.begin(), swept.end(), name)))
            throw CommandError{"--set " + name + ": the bench sweeps or sets this one itself", 2};
        if (const std::string err = render::parse_option(s, name, value); !err.empty()) throw CommandError{err, 2};
    }
}

namespace {

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
                                                      "tests/data/bench_hard.gltf", "tests/data/bench_curved.gltf",
                                                      "tests/data/alpha_cutouts.gltf"};
    }
    for (const auto& s : o.scenes) w.scenes.push_back(parse_scene_spec(s));
    // The lists default to every choice of the option table and are checked by it.
    for (const auto& c : render::option_info("encoding").choices)
        if (in.encodings.empty()) o.encodings.emplace_back(c.value);
    // PCSS needs a light with a size: it is measured by bench --soft against the area-light
    // truth (at the point lights here it would be the hard lookup again); --filters pcss asks for it.
    for (const auto& c : render::option_info("filter").choices)
        if (in.filters.empty() && c.value != "pcss") o.filters.emplace_back(c.value);
    w.encodings = settings_list(o.encodings, "encoding", &render::Settings::encoding);
    w.filters = settings_list(o.filters, "filter", &render::Settings::filter);
    for (int m : o.maps)
        if (const std::string err = render::check_value(render::option_info("map-size"), std::to_string(m)); !err.empty())
            throw CommandError{"--maps: " + err.substr(err.find(": ") + 2), 2};
    if (const std::string err = render::parse_option(w.base, "size", o.size); !err.empty()) throw CommandError{err, 2};
    w.width = w.base.job.width;
    w.height = w.base.job.height;
    apply_set(o.set, {"encoding", "filter", "map-size", "aov", "technique", "volume-method"}, w.base.settings);
    return w;
}

void set_volume_stats(Row& row, const render::VolumeStats& v) {
    row.silhouette_edges = v.silhouette_edges;
    row.volume_triangles = v.triangles;
    row.zpass_casters = v.zpass_casters;
    row.zfail_casters = v.zfail_casters;
    // At the CSV's precision (3 decimals), so the tables made now and those --from-csv rebuilds
    // from the CSV round the same number (0.5855 and its CSV's 0.585 print as 0.59 and 0.58).
    row.fill_per_pixel = std::round(v.fill_per_pixel * 1000.0) / 1000.0;
}

std::string load_average() {
    std::ifstream f("/proc/loadavg");
    std::string one;
    return f >> one ? one : std::string("?");
}

// The silhouette sweep's scene: a UV sphere of radius 1 with `segments` slices and segments / 2
// stacks, its centre 2 above a 10 x 10 ground quad, under a point light up and to the side (its
// shadow an ellipse on the ground), seen from above at about 35 degrees.
scene::Scene sphere_scene(int segments) {
    scene::Scene s = scene::make_sphere_over_plane();
    s.meshes[1] = scene::make_sphere(1.0f, segments, segments / 2);
    s.light = scene::Light{};
    s.light.type = scene::LightType::Point;
    s.light.position = glm::vec3(2.0f, 6.0f, 1.5f);
    s.light.direction = glm::normalize(glm::vec3(0.0f, 2.0f, 0.0f) - s.light.position);
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 5.0f, 6.5f), glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return s;
}

// Shadow volumes as the silhouette grows: the sphere at each of kSphereSegments, drawn with
// volumes (auto) and with the shadow map (rgba hard, map 1024), scored against the hard truth of
// each frame and timed in interleaved rounds like the sweep (the light turning for the moving frames).
void silhouette_sweep(Sweep& w, render::Renderer& r, const render::FrameInputs& in) {
    const BenchOptions& o = w.o;
    std::vector<Planned> techniques;
    {
        render::Settings s = w.base.settings;
        s.technique = render::technique_named("volumes");
        s.volume_method = render::VolumeMethod::Auto;
        techniques.push_back({s, technique_label(s)});
        s = w.base.settings;
        s.technique = render::technique_named("shadowmap");
        s.encoding = shadow::Encoding::RGBA;
        s.filter = shadow::Filter::Hard;
        s.map_size = 1024;
        techniques.push_back({s, technique_label(s)});
    }
    struct Case {
        scene::Scene still, turning;
        glm::vec3 centre{0.0f};
        std::vector<Row> rows;
        std::vector<std::vector<double>> moving, still_ms;
        std::vector<GpuRounds> gpu;
    };
    std::vector<Case> cases;
    const auto t0 = Clock::now();
    for (int segments : kSphereSegments) {
        Case c;
        c.still = sphere_scene(segments);
        c.turning = c.still;
        c.centre = scene::scene_bounds(c.still).center();
        r.load(c.still);
        measure::TruthOptions to = frame_truth_options(c.still, w.width, w.height);
        to.soft_samples = 0;  // the hard truth: the error column
        const measure::TruthImage truth = measure::RayTracer(c.still).render(to);
        const auto valid = truth.valid_mask();
        for (const Planned& planned : techniques) {
            render::Settings s = planned.settings;
            Row row;
            row.section = kSilhouetteSection;
            row.segments = segments;
            row.scene = "sphere-" + std::to_string(segments);
            set_technique(row, s, planned.label);
            render::Options labelled = w.base;
            labelled.job.scene = row.scene;  // made in code (sphere_scene), not a file
            labelled.settings = s;
            row.settings = render::to_args(labelled);
            if (const std::string problem = r.check(c.still, s, in); !problem.empty())
                throw CommandError{"bench: the silhouette sweep's " + row.scene + ": " + row.technique + ": " + problem, 1};
            s.aov = render::Aov::Visibility;
            const render::FramePlan& plan = r.render(c.still, s, in);
            if (const auto* m = plan.resource("shadow-map")) row.bytes = m->desc.bytes();
            if (const render::VolumeStats* v = render::volumes_of(plan)) set_volume_stats(row, *v);
            row.score = measure::score(red_channel(r.read_image()), truth.lit, valid, nullptr);
            std::fprintf(stderr, "silhouette %-10s %-12s error %6.2f %%%s\n", row.scene.c_str(), row.technique.c_str(),
                         row.score.error_pct,
                         row.silhouette_edges >= 0 ? (", " + std::to_string(row.silhouette_edges) + " silhouette edges, fill " +
                                                      fixed(row.fill_per_pixel, 2) + " per pixel").c_str()
                                                   : "");
            c.rows.push_back(row);
        }
        c.moving.resize(techniques.size());
        c.still_ms.resize(techniques.size());
        c.gpu.resize(techniques.size());
        cases.push_back(std::move(c));
    }
    gl::check_errors("the silhouette sweep's accuracy pass");
    for (int round = 0; round < o.rounds; ++round)
        for (Case& c : cases) {
            r.load(c.still);
            const auto moving_at = [&](int i) -> const scene::Scene& {
                turn_light(c.turning.light, c.still.light, c.centre, i + 1);
                return c.turning;
            };
            const auto still_at = [&](int) -> const scene::Scene& { return c.still; };
            for (size_t t = 0; t < techniques.size(); ++t) {
                render::Settings s = techniques[t].settings;
                s.aov = render::Aov::Color;
                const Timing moving = time_frames(r, s, in, 2, o.frames, moving_at);
                const Timing still_t = time_frames(r, s, in, 1, o.frames, still_at);
                c.moving[t].push_back(moving.median_ms);
                c.still_ms[t].push_back(still_t.median_ms);
                c.gpu[t].add(moving, still_t);
            }
            gl::check_errors("the silhouette sweep's timing pass");
        }
    for (Case& c : cases)
        for (size_t t = 0; t < techniques.size(); ++t) {
            Row& row = c.rows[t];
            row.ms_moving = measure::median(c.moving[t]);
            row.ms_still = measure::median(c.still_ms[t]);
            row.ms_camera = row.ms_still;
            row.ms_shadow = row.map ? std::max(0.0, row.ms_moving - row.ms_still) : 0.0;
            row.frames = o.frames * o.rounds;
            c.gpu[t].set(row);
            w.silhouette.push_back(row);
        }
    std::fprintf(stderr, "silhouette sweep: %zu spheres x %zu techniques in %s\n", cases.size(), techniques.size(),
                 duration_str(seconds_since(t0)).c_str());
}

void run_sweep(Sweep& w) {
    const auto t0 = Clock::now();
    auto ctx = make_context();
    w.context = ctx->description();
    w.load_before = load_average();
    const BenchOptions& o = w.o;

    // Each encoding and filter at each map size and, with the references, at --map-size auto
    // (issue 56: labelled "... (map auto)", the row's map the size the plan chose).
    std::vector<int> sizes = o.maps;
    if (o.references) sizes.push_back(render::Settings::kAutoMapSize);
    std::vector<Planned> techniques;
    for (auto e : w.encodings)
        for (auto f : w.filters)
            for (int m : sizes) {
                render::Settings s = w.base.settings;
                s.technique = render::technique_named("shadowmap");
                s.encoding = e;
                s.filter = f;
                s.map_size = m;
                const bool auto_size = m == render::Settings::kAutoMapSize;
                techniques.push_back({s, technique_label(s) + (auto_size ? kAutoSuffix : "")});
            }
    for (Planned& b : before_rows(w)) techniques.push_back(std::move(b));
    // Shadow volumes, each way of counting: exact hard shadows at a cost that grows with the
    // silhouettes and the shadows' area on screen rather than with a map.
    for (auto m : render::kAllVolumeMethods) {
        render::Settings s = w.base.settings;
        s.technique = render::technique_named("volumes");
        s.volume_method = m;
        techniques.push_back({s, technique_label(s)});
    }
    if (o.references)
        for (const char* t : {"none", "planar"}) {
            render::Settings s = w.base.settings;
            s.technique = render::technique_named(t);
            techniques.push_back({s, technique_label(s)});
        }
    // Work units: one accuracy frame and `rounds` timing runs per technique and scene.
    const size_t total = techniques.size() * w.scenes.size() * static_cast<size_t>(1 + o.rounds);
    size_t done = 0, timed = 0;
    double timed_seconds = 0.0;
    std::fprintf(stderr, "bench: %zu scene frames x %zu techniques at %dx%d, %d rounds of %d timed frames per run%s\n",
                 w.scenes.size(), techniques.size(), w.width, w.height, o.rounds, o.frames,
                 o.quick ? " (quick: timings are not meaningful)" : "");

    // One renderer for everything (one context, one state cache); load() switches scenes.
    render::Renderer r(gl::probe_caps(*ctx));
    w.gl_renderer = r.caps().renderer;
    const render::FrameInputs in = render::offscreen(w.width, w.height);

    struct Pending {
        Row row;
        render::Settings s;
        std::vector<double> moving, still;
        GpuRounds gpu;
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
        st->src = open_scene(spec.name, scene::Eye::Scene, o.allow_outside);
        st->still = st->src.at(spec.time);
        st->turning = st->still;
        st->centre = scene::scene_bounds(st->still).center();
        const scene::Scene& still = st->still;
        r.load(still);

        // The truth for this frame, once for every technique.
        const auto tt = Clock::now();
        measure::TruthOptions to = frame_truth_options(still, w.width, w.height);
        to.soft_samples = o.soft_samples;
        to.light_radius = default_light_radius(still);
        const measure::TruthImage truth = measure::RayTracer(still).render(to);
        std::fprintf(stderr, "truth %s: %s in %.1f s (%s)\n", spec.label.c_str(),
                     o.soft_samples > 0 ? ("hard + " + std::to_string(o.soft_samples) + " area-light samples").c_str() : "hard",
                     seconds_since(tt), class_summary(truth).c_str());
        const auto valid = truth.valid_mask();
        const bool pictures = si == 0 || (spec.name == "teapot" && std::fabs(spec.time - 0.6) < 1e-9);
        if (pictures) {
            prepare_output_dir("--out-dir", images.string());  // created, or exit status 2 with the reason
            write_or_throw((images / (spec.label + "-truth.png")).string(), classes_image(truth));
        }

        // Accuracy: the visibility AOV of the very frame the truth shows, for every technique.
        for (const Planned& planned : techniques) {
            render::Settings s = planned.settings;
            Row row;
            row.scene = spec.label;
            row.time = spec.time;
            set_technique(row, s, planned.label);
            row.settings = row_args(w.base, spec, s);  // what the row was made with
            ++done;
            if (const std::string problem = r.check(still, s, in); !problem.empty()) {
                w.notes.push_back(spec.label + ": " + row.technique + " skipped: " + problem);
                std::fprintf(stderr, "[%4zu/%zu] %s %s: skipped (%s)\n", done, total, spec.label.c_str(), row.technique.c_str(),
                             problem.c_str());
                done += static_cast<size_t>(o.rounds);
                continue;
            }
            s.aov = render::Aov::Visibility;
            const render::FramePlan& plan = r.render(still, s, in);
            const render::PlannedResource* map = plan.resource("shadow-map");
            // The map's side as drawn: a cube's face (its atlas is 3 faces wide), else the map's.
            const int drawn = !map ? 0 : render::cube_of(plan) ? render::cube_of(plan)->tile : map->desc.width;
            if (render::technique_module(s.technique).depth_map() && map && s.map_size == render::Settings::kAutoMapSize) {
                row.map = drawn;
            } else if (render::technique_module(s.technique).depth_map() && map && drawn != s.map_size) {
                row.map = drawn;
                w.notes.push_back(spec.label + ": " + row.technique + " map " + std::to_string(s.map_size) + " clamped to " +
                                  std::to_string(drawn));
            }
            const auto vis = red_channel(r.read_image());
            row.score = measure::score(vis, truth.lit, valid, o.soft_samples > 0 ? &truth.soft : nullptr);
            row.bytes = map ? map->desc.bytes() : 0;
            if (map && render::texel_use_of(plan)) row.texel_use_pct = 100.0 * static_cast<double>(*render::texel_use_of(plan));
            if (const render::VolumeStats* v = render::volumes_of(plan)) set_volume_stats(row, *v);
            const bool pictured = render::technique_module(s.technique).representative(s);
            if (pictures && pictured) {
                std::string name = spec.label + "-" + row.technique + (row.map ? "-" + std::to_string(row.map) : "") + "-errors.png";
                std::replace(name.begin(), name.end(), ' ', '-');
                name.erase(std::remove_if(name.begin(), name.end(), [](char ch) { return ch == '(' || ch == ')'; }), name.end());
                write_or_throw((images / name).string(), error_image(vis, truth));
            }
            std::fprintf(stderr, "[%4zu/%zu] %-12s %-16s %-9s error %6.2f %% (false shadow %5.2f, false lit %5.2f) | %s elapsed\n",
                         done, total, spec.label.c_str(), row.technique.c_str(),
                         row.map ? ("map " + std::to_string(row.map)).c_str() : "", row.score.error_pct,
                         row.score.false_shadow_pct, row.score.false_lit_pct, duration_str(seconds_since(t0)).c_str());
            s.aov = render::Aov::Color;  // time the frame a user sees
            st->pending.push_back({row, s, {}, {}, {}});
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
                const Timing moving = time_frames(r, p.s, in, 2, o.frames, moving_at);
                const Timing still_t = time_frames(r, p.s, in, 1, o.frames, still_at);
                p.moving.push_back(moving.median_ms);
                p.still.push_back(still_t.median_ms);
                p.gpu.add(moving, still_t);
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
            const bool has_map = render::technique_module(p.s.technique).depth_map();
            row.ms_camera = row.ms_still;
            row.ms_shadow = has_map ? std::max(0.0, row.ms_moving - row.ms_still) : 0.0;
            row.frames = o.frames * o.rounds;
            p.gpu.set(row);
            if (has_map && (row.redrawn_moving != row.frames || row.redrawn_still != 0))
                w.notes.push_back(row.scene + ": " + row.technique + " map " + std::to_string(row.map) + ": the map was redrawn in " +
                                  std::to_string(row.redrawn_moving) + " of " + std::to_string(row.frames) + " moving frames and " +
                                  std::to_string(row.redrawn_still) + " still frames");
            w.rows.push_back(row);
        }
    silhouette_sweep(w, r, in);
    effects_sweep(w, r, in);
    lights_sweep(w, r, in);
    budget_sweep(w, r, in);
    error_sweep(w, r, in);
    w.load_after = load_average();
}

}  // namespace

void run_bench(const BenchOptions& in) {
    if (in.scale) {
        if (in.cascades || in.soft || in.truth_noise || !in.from_csv.empty())
            throw CommandError{"--scale: not with --cascades, --soft, --truth-noise or --from-csv", 2};
        run_scale_bench(in);
        return;
    }
    if (in.cascades) {
        if (in.soft || in.truth_noise || !in.from_csv.empty())
            throw CommandError{"--cascades: not with --soft, --truth-noise or --from-csv", 2};
        run_cascades_bench(in);
        return;
    }
    if (in.soft || in.truth_noise) {
        run_soft_bench(in);
        return;
    }
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
            for (size_t i = 0; i < in.scenes.size(); ++i) c << (i ? "," : "") << scene::printable(in.scenes[i]);
        }
        if (!in.maps.empty()) {
            c << " --maps ";
            for (size_t i = 0; i < in.maps.size(); ++i) c << (i ? "," : "") << in.maps[i];
        }
        for (const auto& s : in.set) c << " --set " << scene::printable(s);
        w.command_line = c.str();
    }
    // Every scene must open before the folder is made and the long part starts.
    if (in.from_csv.empty())
        for (const auto& s : w.scenes) open_scene(s.name, scene::Eye::Scene, w.o.allow_outside);
    prepare_output_dir("--out-dir", w.o.out_dir);
    if (!in.from_csv.empty()) {
        w.from_csv = in.from_csv;
        read_csv(w, in.from_csv);
    } else {
        run_sweep(w);
    }
    if (w.rows.empty()) throw CommandError{"bench: nothing was measured", 1};

    const Report report = write_report(w, fs::path(w.o.out_dir), t0);
    const double elapsed = report.elapsed;
    const std::vector<Key>& front = report.front;
    for (const auto& n : w.notes) std::fprintf(stderr, "note: %s\n", n.c_str());
    std::printf("bench: %zu runs in %s; wrote %s/results.csv, results.md, tradeoff.svg/.png, tradeoff_mae.svg/.png\n", w.rows.size(),
                duration_str(elapsed).c_str(), w.o.out_dir.c_str());
    std::printf("Pareto front (error %% against ms/frame, all scenes):");
    for (const Key& k : front) std::printf(" [%s]", key_label(k).c_str());
    std::printf("\n");
}

}  // namespace penumbra::tools
