// penumbra: the headless renderer's command line. Subcommands:
//   render   one scene, one set of settings, a PNG (or a timing with --frames)
//   gallery  the course scene in every encoding x filter, colour + visibility + light depth
//   shaders  write every shader variant's GLSL ES 1.00 source (for glslangValidator)
//   caps     what the headless context can do
// Bad input gets one line naming the problem, a non-zero exit, and no output file.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "gl/caps.h"
#include "gl/check.h"
#include "platform/platform.h"
#ifdef PENUMBRA_HAVE_TRUTH
#include "bias_sweep.h"
#endif
#include "measure/image_io.h"
#include "render/renderer.h"
#include "render/settings.h"
#include "render/shader_library.h"
#include "scene/scene_source.h"
#include "measure.h"
#include "measure_commands.h"

namespace fs = std::filesystem;
using namespace penumbra;

namespace {

// Failures that end the run with one line on stderr (the measuring commands' type).
using Failure = tools::CommandError;
using tools::open_scene;

std::unique_ptr<platform::Platform> make_context() {
    std::string error;
    auto p = platform::create_headless(error);
    if (!p) throw Failure{error};
    return p;
}

int channels_for(render::Aov aov) { return aov == render::Aov::Color ? 3 : 1; }

void write_image(render::Renderer& r, const render::Settings& s, const std::string& path) {
    const auto px = measure::from_rgba(r.read_image(), s.width, s.height, channels_for(s.aov));
    const std::string err = measure::write_png(path, px);
    if (!err.empty()) throw Failure{err};
}


// ---- render ---------------------------------------------------------------------------------

int run_render(const render::Settings& s, bool verbose) {
    if (!s.out.empty()) {
        const fs::path out(s.out);
        if (out.extension() != ".png") throw Failure{"--out " + s.out + ": the file name must end in .png", 2};
        std::error_code ec;
        if (out.has_parent_path() && !fs::is_directory(out.parent_path(), ec))
            throw Failure{"--out " + s.out + ": folder " + out.parent_path().string() + " does not exist", 2};
    }
    scene::SceneSource src = open_scene(s.scene);
    auto ctx = make_context();
    render::Renderer r(gl::probe_caps());
    if (verbose)
        std::cerr << ctx->description() << "\n"
                  << r.caps().summary() << "\nfloat -> unorm8 conversion: " << shadow::to_string(r.unorm_rounding())
                  << " (probed; the packing is compiled for it)\nsettings: " << render::to_args(s) << "\n";
    if (const std::string problem = r.check(src.at(s.time), s); !problem.empty()) throw Failure{problem, 2};

    std::vector<double> ms;
    for (int i = 0; i < s.frames; ++i) {
        const double t = s.time + static_cast<double>(i) / 60.0;
        const auto start = std::chrono::steady_clock::now();
        const render::FramePlan& plan = r.render(src.at(t), s);
        r.finish();
        const auto end = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        if (i == 0)
            for (const auto& n : plan.notes) std::cerr << "penumbra: note: " << n << "\n";
        if (verbose && (i == 0 || i == s.frames - 1))
            std::cerr << "frame " << i << " (t = " << t << "):\n" << plan.describe();
    }
    if (s.frames > 1) {
        std::vector<double> sorted = ms;
        std::sort(sorted.begin(), sorted.end());
        const size_t n = sorted.size();
        const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        std::printf("%d frames, median %.3f ms/frame (min %.3f, max %.3f), each finished with glFinish; %s\n",
                    s.frames, median, sorted.front(), sorted.back(), render::to_args(s).c_str());
    }
    if (!s.out.empty()) {
        write_image(r, s, s.out);
        if (verbose) std::cerr << "wrote " << s.out << "\n";
    }
    return 0;
}

// ---- gallery --------------------------------------------------------------------------------

int run_gallery(const std::string& dir, render::Settings base) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Failure{"--out-dir " + dir + ": cannot create (" + ec.message() + ")", 2};
    scene::SceneSource src = open_scene(base.scene);
    auto ctx = make_context();
    render::Renderer r(gl::probe_caps());

    struct Row {
        std::string label;
        render::Settings s;
    };
    std::vector<Row> rows;
    const render::Aov aovs[] = {render::Aov::Color, render::Aov::Visibility, render::Aov::LightDepth};
    for (auto e : shadow::kAllEncodings)
        for (auto f : shadow::kAllFilters) {
            if (e == shadow::Encoding::DepthTex && !r.caps().depth_texture) continue;
            render::Settings s = base;
            s.technique = render::Technique::ShadowMap;
            s.encoding = e;
            s.filter = f;
            rows.push_back({std::string(shadow::to_string(e)) + "-" + std::string(shadow::to_string(f)), s});
        }
    for (auto t : {render::Technique::Planar, render::Technique::None}) {
        render::Settings s = base;
        s.technique = t;
        rows.push_back({std::string(render::to_string(t)), s});
    }

    std::ofstream html;
    const std::string index = (fs::path(dir) / "index.html").string();
    std::string body;
    size_t done = 0, written = 0;
    const size_t total = rows.size() * 3;
    for (const auto& row : rows) {
        body += "<tr><th>" + row.label + "</th>";
        for (auto aov : aovs) {
            render::Settings s = row.s;
            s.aov = aov;
            const std::string name = row.label + "-" + std::string(render::to_string(aov)) + ".png";
            ++done;
            if (aov == render::Aov::LightDepth && s.technique != render::Technique::ShadowMap) {
                body += "<td>(no shadow map)</td>";
                continue;
            }
            if (const std::string problem = r.check(src.at(s.time), s); !problem.empty()) throw Failure{problem, 2};
            std::fprintf(stderr, "[%2zu/%zu] %s\n", done, total, name.c_str());
            r.render(src.at(s.time), s);
            write_image(r, s, (fs::path(dir) / name).string());
            ++written;
            body += "<td><img src=\"" + name + "\" width=\"256\" title=\"" + render::to_args(s) + "\"></td>";
        }
        body += "</tr>\n";
    }
    const std::string page =
        "<!doctype html><meta charset=\"utf-8\"><title>penumbra gallery</title>\n"
        "<style>body{font-family:sans-serif;background:#222;color:#eee}td,th{padding:4px}</style>\n"
        "<h1>The course scene at t = " + std::to_string(base.time) + "</h1>\n<p>" + r.caps().renderer +
        "; hover an image for its exact settings.</p>\n<table><tr><th></th><th>colour</th><th>visibility</th>"
        "<th>light depth</th></tr>\n" + body + "</table>\n";
    std::ofstream f(index);
    f << page;
    if (!f) throw Failure{index + ": cannot write"};
    std::printf("wrote %zu images and %s\n", written, index.c_str());
    return 0;
}

// ---- shaders, caps --------------------------------------------------------------------------

int run_shaders(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Failure{"--out " + dir + ": cannot create (" + ec.message() + ")", 2};
    size_t n = 0;
    const auto write = [&](const std::string& file, const std::string& text) {
        std::ofstream f(fs::path(dir) / file);
        f << text;
        if (!f) throw Failure{dir + "/" + file + ": cannot write"};
        ++n;
    };
    // Each file as it is (no defines), then each variant; the extension tells the stage.
    for (const auto& v : render::all_variants()) {
        std::string tag;
        for (const auto& d : v.defines) tag += "_" + d;
        const auto stem = [](const std::string& f) { return f.substr(0, f.find('.')); };
        write(stem(v.vertex) + "_plain.vert", render::variant_source(v.vertex, {}));
        write(stem(v.fragment) + "_plain.frag", render::variant_source(v.fragment, {}));
        write(stem(v.vertex) + tag + ".vert", render::variant_source(v.vertex, v.defines));
        write(stem(v.fragment) + tag + ".frag", render::variant_source(v.fragment, v.defines));
    }
    std::printf("wrote %zu shader files to %s\n", n, dir.c_str());
    return 0;
}

int run_caps() {
    auto ctx = make_context();
    std::printf("%s\n%s\n", ctx->description().c_str(), gl::probe_caps().summary().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"penumbra: shadow mapping on GLES2, headless (EGL)"};
    app.require_subcommand(1);

    // render: every Settings option, parsed by the one Settings parser.
    auto* render_cmd = app.add_subcommand("render", "render one frame (or time --frames N) to a PNG");
    std::map<std::string, std::string> raw;
    const std::map<std::string, std::string> help = {
        {"scene", "teapot (the course scene) or FILE.gltf / FILE.glb"},
        {"time", "seconds; the animation is a pure function of t"},
        {"size", "WxH of the image (default 512x512)"},
        {"encoding", "r8 | rgba | depthtex (default rgba)"},
        {"filter", "hard | pcf2x2 | pcf4x4 (default hard)"},
        {"map-size", "shadow map width = height (default 1024)"},
        {"bias", "depth offset, 'default' (r8 0.005, rgba and depthtex 0.0015) or 'auto' (quantum + receiver slope)"},
        {"precision", "highp | mediump (emulated fp16 along the depth path, as a phone computes it)"},
        {"aov", "color | visibility | light-depth"},
        {"technique", "shadowmap | planar | none (default shadowmap)"},
        {"out", "FILE.png (top row first); none: write nothing"},
        {"frames", "render N frames, t advancing 1/60 s, and print the median ms/frame"}};
    for (auto name : render::option_names()) {
        const std::string n(name);
        const auto h = help.find(n);
        render_cmd->add_option("--" + n, raw[n], h == help.end() ? "" : h->second);
    }
    bool verbose = false;
    render_cmd->add_flag("-v,--verbose", verbose, "list the context, the settings and each frame's passes");

    auto* gallery_cmd = app.add_subcommand("gallery", "the course scene in every encoding x filter, with an index.html");
    std::string gallery_dir = "out/gallery";
    std::map<std::string, std::string> graw = {{"time", "0.6"}, {"size", "512x512"}, {"map-size", "1024"}};
    gallery_cmd->add_option("--out-dir", gallery_dir, "folder for the images (default out/gallery)");
    for (const char* n : {"scene", "time", "size", "map-size"}) gallery_cmd->add_option(std::string("--") + n, graw[n]);

    auto* shaders_cmd = app.add_subcommand("shaders", "write every shader variant's source to a folder");
    std::string shader_dir;
    shaders_cmd->add_option("--out", shader_dir, "folder")->required();

    auto* caps_cmd = app.add_subcommand("caps", "print what the headless context supports");
    // export, truth, bench: measuring the trade (tools/penumbra/measure_commands.h).
    const auto measure = tools::add_measure_commands(app);

#ifdef PENUMBRA_HAVE_TRUTH
    auto* sweep_cmd = app.add_subcommand(
        "bias-sweep", "acne and peter-panning against bias, elevation, encoding and precision (docs/precision)");
    tools::BiasSweepOptions sweep;
    sweep_cmd->add_option("--out-dir", sweep.out_dir, "folder for the CSV, the table and the charts");
    sweep_cmd->add_flag("--quick", sweep.quick, "3 elevations and 5 biases, for CI");
    sweep_cmd->add_option("--size", sweep.size, "image width = height (default 256)")->check(CLI::Range(16, 4096));
    sweep_cmd->add_option("--map-size", sweep.map_size, "shadow map size (default 1024)")->check(CLI::Range(16, 8192));
#endif

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "penumbra: error: %s (see penumbra --help)\n", e.what());
        return 2;
    }

    try {
        const auto settings_from = [](CLI::App* cmd, const std::map<std::string, std::string>& values,
                                      render::Settings s) {
            for (const auto& [name, value] : values) {
                const bool given = cmd->get_option("--" + name)->count() > 0;
                if (!given && value.empty()) continue;
                if (const std::string err = render::parse_option(s, name, value); !err.empty()) throw Failure{err, 2};
            }
            return s;
        };
        if (*render_cmd) return run_render(settings_from(render_cmd, raw, render::Settings{}), verbose);
        if (*gallery_cmd) return run_gallery(gallery_dir, settings_from(gallery_cmd, graw, render::Settings{}));
        if (*shaders_cmd) return run_shaders(shader_dir);
        if (*caps_cmd) return run_caps();
        if (const int rc = tools::run_measure_commands(*measure); rc >= 0) return rc;
#ifdef PENUMBRA_HAVE_TRUTH
        if (*sweep_cmd) return tools::run_bias_sweep(sweep);
#endif
    } catch (const Failure& f) {
        std::fprintf(stderr, "penumbra: error: %s\n", f.message.c_str());
        return f.code;
    } catch (const gl::Error& e) {
        std::fprintf(stderr, "penumbra: error: GL: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
