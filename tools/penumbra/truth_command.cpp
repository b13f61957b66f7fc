// penumbra truth: the ground truth of one frame as PNGs, and the score of any visibility PNG;
// and the truth helpers the bench's sweep uses too (bench.h).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "gl/caps.h"
#include "measure/image_io.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "measure/score_columns.h"
#include "platform/platform.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scene/printable.h"
#include "scene/scene_source.h"
#include "cli_options.h"

namespace fs = std::filesystem;

namespace penumbra::tools {

using measure::Pixels;
using measure::read_png;
using measure::write_png;

namespace bench {

std::unique_ptr<platform::Platform> make_context() {
    std::string error;
    auto p = platform::create_headless(error);
    if (!p) throw CommandError{error, 1};
    return p;
}

float default_light_radius(const scene::Scene& s) {
    if (s.light.type == scene::LightType::Directional) return 0.01f;
    const scene::Bounds b = scene::scene_bounds(s);
    return b.empty() ? 0.01f : 0.01f * glm::length(b.max - b.min);
}

void write_or_throw(const std::string& path, const Pixels& px) {
    if (const std::string err = write_png(path, px); !err.empty()) throw CommandError{err, 2};  // an unwritable output
}

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
            case measure::PixelClass::NotModelled: r = 200, g = 150, b = 40; break;
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

std::string class_summary(const measure::TruthImage& t) {
    const double n = static_cast<double>(t.lit.size());
    std::string out;
    for (int c = 0; c < measure::kPixelClassCount; ++c) {
        const auto pc = static_cast<measure::PixelClass>(c);
        out += (c ? ", " : "") + std::string(measure::to_string(pc)) + " " + fixed(100.0 * static_cast<double>(t.count(pc)) / n, 1) + " %";
    }
    return out;
}

// The camera matrix the renderer uses for this scene at this size: every plan's (camera_view), no
// context needed.
glm::mat4 renderer_view_proj(const scene::Scene& s, int width, int height) {
    return render::camera_view(s, render::offscreen(width, height)).view_proj;
}

}  // namespace bench

namespace {

using namespace bench;

Pixels grey_image(int w, int h, std::vector<std::uint8_t> data) { return Pixels{w, h, 1, std::move(data)}; }

std::string score_line(const measure::Score& s) {
    std::string line = "valid " + std::to_string(s.valid) + " px, false shadow " + fixed(s.false_shadow_pct, 3) +
                       " %, false lit " + fixed(s.false_lit_pct, 3) + " %, error " + fixed(s.error_pct, 3) +
                       " %, mean abs error " + fixed(s.mae_pct, 3) + " %";
    if (s.mae_soft_pct >= 0.0) line += ", vs area light " + fixed(s.mae_soft_pct, 3) + " %";
    return line;
}

}  // namespace

void run_truth(const TruthCommandOptions& o) {
    if (o.score_columns) {
        std::printf("%s\n", measure::score_columns_json().dump(2).c_str());
        return;
    }
    if (o.json && o.score.empty()) throw CommandError{"--json: needs --score (it prints the score)", 2};
    // Every option before any work (no folder is created for a command that cannot run): the
    // numbers are the table's (run_measure_commands checked them as typed; these are the same rules).
    render::Options size;
    if (const std::string err = render::parse_option(size, "size", o.size); !err.empty()) throw CommandError{err, 2};
    if (const std::string err = render::check_value(render::option_info("time"), render::format_number(o.time)); !err.empty())
        throw CommandError{err, 2};
    if (o.soft_samples < 0 || o.soft_samples > render::kMaxSoftSamples)
        throw CommandError{"--soft-samples: must lie in [0, " + std::to_string(render::kMaxSoftSamples) + "], got '" +
                               std::to_string(o.soft_samples) + "'", 2};
    if (!std::isfinite(o.light_radius) || o.light_radius > render::kMaxLightRadius)
        throw CommandError{"--light-radius: must be a finite number <= " + render::format_number(render::kMaxLightRadius) +
                               ", got '" + render::format_number(o.light_radius) + "'", 2};
    if (o.eye != "scene" && o.eye != "in-shadow")
        throw CommandError{"--eye: unknown value '" + scene::printable(o.eye) + "' (scene, in-shadow)", 2};
    if (o.blend_shadows != "off" && o.blend_shadows != "on")
        throw CommandError{"--blend-shadows: unknown value '" + scene::printable(o.blend_shadows) + "' (off, on)", 2};
    std::optional<Pixels> scored;
    if (!o.score.empty()) {
        Pixels px;
        if (const std::string err = read_png(o.score, px, 0); !err.empty()) throw CommandError{"--score: " + err, 2};
        if (px.width != size.job.width || px.height != size.job.height)
            throw CommandError{"--score " + scene::printable(o.score) + ": " + std::to_string(px.width) + "x" +
                                   std::to_string(px.height) + ", but --size is " + o.size, 2};
        scored = std::move(px);
    }
    scene::SceneSource src =
        open_scene(o.scene, o.eye == "in-shadow" ? scene::Eye::InShadow : scene::Eye::Scene, o.allow_outside);
    prepare_output_dir("--out-dir", o.out_dir);
    const scene::Scene s = src.at(o.time);
    measure::TruthOptions to;
    to.width = size.job.width;
    to.height = size.job.height;
    to.view_proj = renderer_view_proj(s, size.job.width, size.job.height);
    to.soft_samples = o.soft_samples;
    // --light-radius, else the scene's light's own (glTF extras), else the bench's default.
    to.light_radius = o.light_radius >= 0.0f ? o.light_radius : s.light.radius > 0.0f ? s.light.radius : default_light_radius(s);
    const auto t0 = Clock::now();
    const measure::TruthImage t = measure::RayTracer(s, o.blend_shadows == "on").render(to);
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
    // With --json, stdout holds the JSON object alone; this line goes to stderr.
    std::fprintf(o.json ? stderr : stdout, "truth of %s at t = %g, %dx%d, in %.2f s: %s; wrote visibility.png, mask.png, classes.png%s to %s\n",
                 scene::printable(o.scene).c_str(), o.time, t.width, t.height, secs, class_summary(t).c_str(),
                 t.soft.empty() ? "" : ", area_light.png", scene::printable(o.out_dir).c_str());
    if (scored) {
        std::vector<std::uint8_t> rendered(t.lit.size());
        const size_t ch = static_cast<size_t>(scored->channels);
        for (size_t i = 0; i < rendered.size(); ++i) rendered[i] = scored->data[i * ch];
        const measure::Score sc = measure::score(rendered, t.lit, t.valid_mask(), t.soft.empty() ? nullptr : &t.soft);
        write_or_throw((dir / "errors.png").string(), error_image(rendered, t));
        if (o.json) {
            // JSON is UTF-8: a scene path that is not (raw bytes) goes in escaped.
            nlohmann::ordered_json j = {
                {"scene", scene::printable(o.scene)}, {"time", o.time}, {"width", t.width}, {"height", t.height}};
            j.update(measure::score_json(sc));
            std::printf("%s\n", j.dump().c_str());
        } else {
            std::printf("score of %s: %s; wrote errors.png\n", scene::printable(o.score).c_str(), score_line(sc).c_str());
        }
    }
}

}  // namespace penumbra::tools
