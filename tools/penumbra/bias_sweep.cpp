#include "bias_sweep.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "cli_options.h"
#include "gl/caps.h"
#include "measure/metrics.h"
#include "platform/platform.h"
#include "plan/options.h"
#include "render/renderer.h"
#include "scenes/course_scene.h"
#include "scenes/probe_scenes.h"
#include "measure/ray_tracer.h"

namespace penumbra::tools {

namespace fs = std::filesystem;

namespace {

struct Row {
    std::string scene;
    float elevation = 0.0f;
    shadow::Encoding encoding = shadow::Encoding::RGBA;
    shadow::Precision precision = shadow::Precision::Highp;
    std::string bias_label;  // a number, "sheet" or "auto"
    float bias = 0.0f;       // the constant part that was used
    measure::Score score;
};

// The scene with its light at `elevation`: the box on the plane under a directional light, or
// the course scene (teapot in the air, t = 0.6) with its point light at the same distance from
// the table's centre as in the exercise.
scene::Scene scene_at(const std::string& name, float elevation) {
    if (name == "box-on-plane") return scene::make_box_on_plane(elevation);
    auto course = scene::make_course_scene(10);
    scene::animate_course(course, 0.0, 0.6);
    const float distance = std::sqrt(2.0f * 2.0f + 3.0f * 3.0f);
    scene::place_light(course.scene, glm::vec3(0.0f), distance, elevation, 30.0f);
    return course.scene;
}

std::string fmt(double v, int precision = 4) {
    std::ostringstream o;
    o.precision(precision);
    o << v;
    return o.str();
}

// One chart: rate (%) against bias (log axis) for each elevation; solid = false shadow (acne),
// dashed = false lit (peter-panning); the sheet's thresholds as vertical lines; --bias auto's
// result as a marker at the right edge for each elevation.
void write_chart(const std::string& path, const std::string& title, const std::vector<Row>& rows,
                 const std::vector<float>& elevations) {
    const double W = 800, H = 420, left = 60, right = 190, top = 40, bottom = 50;
    const double pw = W - left - right, ph = H - top - bottom;
    const double lo = std::log10(1e-5), hi = std::log10(0.05);
    double ymax = 1.0;
    for (const auto& r : rows) ymax = std::max({ymax, r.score.false_shadow_pct, r.score.false_lit_pct});
    ymax = std::ceil(ymax / 5.0) * 5.0;
    const auto X = [&](double b) { return left + (std::log10(std::max(b, 1e-5)) - lo) / (hi - lo) * pw; };
    const auto Y = [&](double pct) { return top + ph - pct / ymax * ph; };
    const char* colours[] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02", "#a6761d", "#666666"};

    std::ostringstream svg;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
        << "' font-family='sans-serif' font-size='11'>\n<rect width='100%' height='100%' fill='white'/>\n"
        << "<text x='" << left << "' y='22' font-size='14'>" << title << "</text>\n";
    // Axes and grid.
    svg << "<rect x='" << left << "' y='" << top << "' width='" << pw << "' height='" << ph
        << "' fill='none' stroke='#444'/>\n";
    for (double e = -5; e <= -1.0001 + 0.7; e += 1) {
        const double b = std::pow(10.0, e);
        if (b > 0.05) break;
        svg << "<line x1='" << X(b) << "' x2='" << X(b) << "' y1='" << top << "' y2='" << top + ph
            << "' stroke='#ddd'/><text x='" << X(b) - 12 << "' y='" << top + ph + 15 << "'>1e" << e << "</text>\n";
    }
    for (int i = 0; i <= 5; ++i) {
        const double v = ymax * i / 5.0;
        svg << "<line x1='" << left << "' x2='" << left + pw << "' y1='" << Y(v) << "' y2='" << Y(v)
            << "' stroke='#eee'/><text x='" << left - 35 << "' y='" << Y(v) + 4 << "'>" << fmt(v, 3) << "%</text>\n";
    }
    svg << "<text x='" << left + pw / 2 - 30 << "' y='" << H - 10 << "'>bias (log)</text>\n";
    int nth = 0;
    for (const auto& [b, label] : {std::pair<double, const char*>{0.005, "0.005 (r8: 2^-8+e)"},
                                   std::pair<double, const char*>{0.0015, "0.0015 (2^-10+e)"}}) {
        svg << "<line x1='" << X(b) << "' x2='" << X(b) << "' y1='" << top << "' y2='" << top + ph
            << "' stroke='black' stroke-dasharray='2,3'/><text x='" << X(b) + 3 << "' y='" << top + 12 + 14 * nth++
            << "'>" << label << "</text>\n";
    }
    for (size_t k = 0; k < elevations.size(); ++k) {
        const char* c = colours[k % 8];
        std::string acne, peter;
        for (const auto& r : rows) {
            if (r.elevation != elevations[k] || r.bias_label == "auto" || r.bias_label == "sheet") continue;
            acne += fmt(X(r.bias)) + "," + fmt(Y(r.score.false_shadow_pct)) + " ";
            peter += fmt(X(r.bias)) + "," + fmt(Y(r.score.false_lit_pct)) + " ";
        }
        svg << "<polyline fill='none' stroke='" << c << "' stroke-width='1.6' points='" << acne << "'/>\n"
            << "<polyline fill='none' stroke='" << c << "' stroke-width='1.6' stroke-dasharray='5,3' points='" << peter
            << "'/>\n";
        for (const auto& r : rows)
            if (r.elevation == elevations[k] && r.bias_label == "auto") {
                svg << "<circle cx='" << left + pw + 8 << "' cy='" << Y(r.score.false_shadow_pct) << "' r='3.5' fill='" << c
                    << "'/><rect x='" << left + pw + 14 << "' y='" << Y(r.score.false_lit_pct) - 3
                    << "' width='6' height='6' fill='none' stroke='" << c << "'/>\n";
            }
        svg << "<text x='" << W - right + 40 << "' y='" << top + 14 + 14 * static_cast<double>(k) << "' fill='" << c << "'>"
            << fmt(elevations[k]) << "&#176; elevation</text>\n";
    }
    const double legend_end = top + 14 + 14 * static_cast<double>(elevations.size());
    svg << "<text x='" << left + pw + 2 << "' y='" << top + ph + 15 << "'>auto</text>\n"
        << "<text x='" << W - right + 40 << "' y='" << legend_end + 10
        << "'>solid/&#9679;: acne</text>\n<text x='" << W - right + 40 << "' y='" << legend_end + 24
        << "'>dashed/&#9633;: peter-panning</text>\n</svg>\n";
    write_output(path, svg.str());
}

}  // namespace

int run_bias_sweep(const BiasSweepOptions& o) {
    prepare_output_dir("--out-dir", o.out_dir);  // exit status 2 with the system's reason
    std::string error;
    auto ctx = platform::create_headless(error);
    if (!ctx) throw std::runtime_error(error);
    render::Renderer renderer(gl::probe_caps(*ctx));
    const render::FrameInputs in = render::offscreen(o.size, o.size);

    const std::vector<std::string> scenes = {"box-on-plane", "course"};
    const std::vector<float> elevations =
        o.quick ? std::vector<float>{10, 30, 60} : std::vector<float>{2, 5, 10, 20, 30, 45, 60, 90};
    std::vector<std::string> biases = o.quick ? std::vector<std::string>{"0.0001", "0.0015", "0.005", "sheet", "auto"}
                                              : std::vector<std::string>{"1e-05", "3e-05", "0.0001", "0.0003",
                                                                         "0.001", "0.0015", "0.003", "0.005", "0.01",
                                                                         "0.02", "0.05", "sheet", "auto"};
    const shadow::Precision precisions[] = {shadow::Precision::Highp, shadow::Precision::Mediump};

    std::vector<Row> rows;
    const size_t total = scenes.size() * elevations.size();
    size_t step = 0;
    for (const auto& name : scenes)
        for (float elevation : elevations) {
            ++step;
            std::fprintf(stderr, "[%zu/%zu] %s at %g degrees\n", step, total, name.c_str(), static_cast<double>(elevation));
            const scene::Scene sc = scene_at(name, elevation);
            render::Settings s;
            s.map_size = o.map_size;
            s.filter = shadow::Filter::Hard;
            s.aov = render::Aov::Visibility;
            renderer.load(sc);

            measure::TruthOptions to;
            to.width = to.height = o.size;
            to.view_proj = renderer.plan(sc, s, in).camera.view_proj;
            const measure::RayTracer tracer(sc);
            const measure::TruthImage truth_image = tracer.render(to);
            const auto valid = truth_image.valid_mask();
            for (auto e : shadow::kAllEncodings)
                for (auto p : precisions)
                    for (const auto& b : biases) {
                        s.encoding = e;
                        s.precision = p;
                        if (const std::string err = render::parse_option(s, "bias", b); !err.empty())
                            throw std::runtime_error(err);
                        renderer.render(sc, s, in);
                        const auto rgba = renderer.read_image();
                        std::vector<std::uint8_t> vis(rgba.size() / 4);
                        for (size_t i = 0; i < vis.size(); ++i) vis[i] = rgba[i * 4];
                        Row r;
                        r.scene = name;
                        r.elevation = elevation;
                        r.encoding = e;
                        r.precision = p;
                        r.bias_label = b;
                        r.bias = s.effective_bias();
                        r.score = measure::score(vis, truth_image.lit, valid);
                        rows.push_back(r);
                    }
        }

    // CSV: every measurement.
    const std::string csv_path = (fs::path(o.out_dir) / "bias_sweep.csv").string();
    {
        std::ostringstream csv;
        csv << "scene,elevation_deg,encoding,precision,filter,bias,bias_constant,valid_pixels,false_shadow_pct,"
               "false_lit_pct,error_pct\n";
        for (const auto& r : rows)
            csv << r.scene << "," << r.elevation << "," << shadow::to_string(r.encoding) << ","
                << shadow::to_string(r.precision) << ",hard," << r.bias_label << "," << r.bias << "," << r.score.valid
                << "," << fmt(r.score.false_shadow_pct) << "," << fmt(r.score.false_lit_pct) << ","
                << fmt(r.score.error_pct) << "\n";
        write_output(csv_path, csv.str());
    }

    // Markdown: the fixed defaults against auto, per elevation.
    const std::string md_path = (fs::path(o.out_dir) / "bias_sweep.md").string();
    {
        std::map<std::string, const Row*> find;
        const auto key = [](const std::string& sc, float el, shadow::Encoding e, shadow::Precision p, const std::string& b) {
            return sc + "|" + fmt(el) + "|" + std::string(shadow::to_string(e)) + "|" +
                   std::string(shadow::to_string(p)) + "|" + b;
        };
        for (const auto& r : rows) find[key(r.scene, r.elevation, r.encoding, r.precision, r.bias_label)] = &r;
        std::ostringstream md;
        md << "# Bias: the sheet's fixed defaults against --bias auto\n\n"
           << "Acne = false-shadow %, peter-panning = false-lit % of the valid pixels (ray-traced truth), hard filter, "
           << o.size << "x" << o.size << ", map " << o.map_size << ". Regenerate: `build/penumbra bias-sweep"
           << (o.quick ? " --quick" : "") << "`.\n\n";
        for (const auto& name : scenes) {
            md << "## " << name << "\n\n| elevation | encoding | precision | sheet: acne | sheet: peter-panning | "
                  "auto: acne | auto: peter-panning |\n|---|---|---|---|---|---|---|\n";
            for (float el : elevations)
                for (auto e : shadow::kAllEncodings)
                    for (auto p : precisions) {
                        const Row* d = find[key(name, el, e, p, "sheet")];
                        const Row* a = find[key(name, el, e, p, "auto")];
                        if (!d || !a) continue;
                        md << "| " << el << "&#176; | " << shadow::to_string(e) << " | " << shadow::to_string(p) << " | "
                           << fmt(d->score.false_shadow_pct, 3) << " | " << fmt(d->score.false_lit_pct, 3) << " | "
                           << fmt(a->score.false_shadow_pct, 3) << " | " << fmt(a->score.false_lit_pct, 3) << " |\n";
                    }
            md << "\n";
        }
        write_output(md_path, md.str());
    }

    // One chart per scene, encoding and precision.
    size_t charts = 0;
    for (const auto& name : scenes)
        for (auto e : shadow::kAllEncodings)
            for (auto p : precisions) {
                std::vector<Row> sel;
                for (const auto& r : rows)
                    if (r.scene == name && r.encoding == e && r.precision == p) sel.push_back(r);
                const std::string file = "bias_" + name + "_" + std::string(shadow::to_string(e)) + "_" +
                                         std::string(shadow::to_string(p)) + ".svg";
                write_chart((fs::path(o.out_dir) / file).string(),
                            name + ", " + std::string(shadow::to_string(e)) + ", " + std::string(shadow::to_string(p)) +
                                ": acne and peter-panning against bias",
                            sel, elevations);
                ++charts;
            }
    std::printf("%zu measurements; wrote %s, %s and %zu charts in %s\n", rows.size(), csv_path.c_str(), md_path.c_str(),
                charts, o.out_dir.c_str());
    return 0;
}

}  // namespace penumbra::tools
