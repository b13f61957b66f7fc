// penumbra: the headless renderer's command line. Subcommands:
//   render   one scene, one set of settings, a PNG (or a timing with --frames)
//   plan     the frame plan of those settings: every pass and resource (text or --json)
//   gallery  the course scene in every encoding x filter, colour + visibility + light depth
//   shaders  write every shader variant's GLSL ES 1.00 source (for glslangValidator)
//   caps     what the headless context can do
//   mipmaps  a texture's mip chain rendered level by level, against glGenerateMipmap and the CPU
// Their options come from the option table (plan/options.h) through cli_options.h.
// Bad input (an unwritable output included) gets one line naming the problem, exit status 2, and
// no output file; a failure while rendering exit status 1; never a signal (out of memory is a line too).
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "gl/caps.h"
#include "gl/check.h"
#include "platform/platform.h"
#ifdef PENUMBRA_HAVE_TRUTH
#include "bias_sweep.h"
#endif
#include "budget_frames.h"
#include "max_error.h"
#include "cli_options.h"
#include "options_doc.h"
#include "egl_device.h"
#include "measure/image_io.h"
#include "plan/options.h"
#include "render/renderer.h"
#include "render/shader_library.h"
#include "scene/memory_budget.h"
#include "plan/techniques/technique.h"
#include "scene/printable.h"
#include "scene/scene_source.h"
#include "measure.h"
#include "measure_commands.h"
#include "mipmaps_command.h"
#include "lab_command.h"
#include "render/lab.h"

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

// Grey where the image is one value per pixel (visibility, depths), colour elsewhere.
int channels_for(render::Aov aov) {
    return aov == render::Aov::Visibility || aov == render::Aov::LightDepth || aov == render::Aov::GbufferDepth ? 1 : 3;
}

void write_image(render::Renderer& r, const render::Options& o, const std::string& path) {
    const auto px = measure::from_rgba(r.read_image(), o.job.width, o.job.height, channels_for(o.settings.aov));
    const std::string err = measure::write_png(path, px);
    if (!err.empty()) throw Failure{err, 2};  // an unwritable output: bad input, as the checks before
}

// ---- render, plan ---------------------------------------------------------------------------

// --snippets FILE (render, plan): the shader lab's settings (render::lab_settings) with the file's
// functions compiled into the renderer; a file that is refused or does not compile is exit status 2.
render::Options with_snippets(render::Options o, const std::string& snippets, std::string& text) {
    if (snippets.empty()) return o;
    text = tools::read_snippets("--snippets", snippets);
    o.settings = render::lab_settings(o.settings);
    if (const std::string why = render::lab_refusal(o.settings); !why.empty()) throw Failure{"--snippets: " + why, 2};
    return o;
}

void load_snippets(render::Renderer& r, const scene::Scene& scene, const render::Options& o, const std::string& path,
                   const std::string& text, const render::FrameInputs& in) {
    if (path.empty()) return;
    if (const auto problems = render::set_snippets(r, scene, o.settings, text, in); !problems.empty())
        throw Failure{tools::snippet_problems_text(path, problems), 2};
}

// --budget-ms: what was chosen and why (stdout); -v: each change (stderr).
void print_budget(const render::BudgetController& b, bool verbose) {
    if (verbose)
        for (const auto& line : b.log()) std::cerr << "budget: " << line << "\n";
    std::printf("%s\n", b.why().c_str());
}

// --max-error: what was chosen and why (stdout); -v: every rung's prediction (stderr).
void print_error_choice(const tools::ErrorChoice& c, bool verbose) {
    if (verbose)
        for (const tools::ErrorRung& g : c.rungs) {
            char measured[64] = "";
            if (g.ms >= 0.0) std::snprintf(measured, sizeof measured, "; %.2f ms on this frame", g.ms);
            std::fprintf(stderr, "max-error: %-15s predicted %.3f %% (cost %.2fx the unshadowed frame%s)\n",
                         g.map ? ("map " + std::to_string(g.map)).c_str() : "shadow volumes", g.predicted_pct, g.cost, measured);
        }
    std::printf("%s\n", c.why.c_str());
}

int run_render(const render::Options& given, bool verbose, bool still, const std::vector<std::string>& allow_outside,
               const std::string& snippets) {
    std::string text;
    const render::Options o = with_snippets(given, snippets, text);
    const render::Job& job = o.job;
    if (!job.out.empty()) tools::check_output_file("--out", job.out, ".png");  // before any work
    scene::SceneSource src =
        open_scene(job.scene, job.eye_in_shadow ? scene::Eye::InShadow : scene::Eye::Scene, allow_outside);
    auto ctx = make_context();
    render::Renderer r(gl::probe_caps(*ctx));
    const render::FrameInputs in = render::offscreen(job.width, job.height);
    if (verbose)
        std::cerr << ctx->description() << "\n"
                  << r.caps().summary() << "\n" << r.unorm_report() << "\nsettings: " << render::to_args(o) << "\n";
    if (const std::string problem = r.check(src.at(job.time), o.settings, in); !problem.empty()) throw Failure{problem, 2};
    load_snippets(r, src.at(job.time), o, snippets, text, in);

    std::string refusal;
    std::optional<render::BudgetController> budget = tools::make_budget(o, r, src.at(job.time), in, refusal);
    if (!refusal.empty()) throw Failure{refusal, 2};
    if (budget) {
        if (const std::string problem = r.check(src.at(job.time), budget->settings(), in); !problem.empty())
            throw Failure{problem, 2};
        // One frame asked for: the budget settles over moving frames first, then the frame at --time.
        if (job.frames == 1)
            tools::budget_frames(r, *budget, in, tools::kBudgetSettleFrames, [&](int i) -> const scene::Scene& {
                return src.at(job.time + (still ? 0.0 : static_cast<double>(i) / 60.0));
            });
    }
    // --max-error: chosen once, on the frame at --time.
    const std::optional<tools::ErrorChoice> target = tools::make_error_choice(o, r, src.at(job.time), in, refusal);
    if (!refusal.empty()) throw Failure{refusal, 2};
    const render::Settings chosen = budget ? budget->settings() : target ? target->settings() : o.settings;
    if (target)
        if (const std::string problem = r.check(src.at(job.time), chosen, in); !problem.empty()) throw Failure{problem, 2};

    std::vector<double> ms;
    r.gpu_timer().enable(verbose);  // -v: each pass's GPU time too, read after the last frame
    for (int i = 0; i < job.frames; ++i) {
        const double t = job.time + (still ? 0.0 : static_cast<double>(i) / 60.0);
        const auto start = std::chrono::steady_clock::now();
        const render::FramePlan& plan = r.render(src.at(t), budget ? budget->settings() : chosen, in);
        r.finish();
        const auto end = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        if (budget && i + 1 < job.frames) budget->observe(ms.back());
        if (i == 0)
            for (const auto& n : plan.notes) std::cerr << "penumbra: note: " << n << "\n";
        if (verbose && (i == 0 || i == job.frames - 1))
            std::cerr << "frame " << i << " (t = " << t << "):\n" << plan.describe();
    }
    if (job.frames > 1) {
        std::vector<double> sorted = ms;
        std::sort(sorted.begin(), sorted.end());
        const size_t n = sorted.size();
        const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        std::printf("%d frames, median %.3f ms/frame (min %.3f, max %.3f), each finished with glFinish; %s\n",
                    job.frames, median, sorted.front(), sorted.back(), render::to_args(o).c_str());
    }
    if (budget) print_budget(*budget, verbose);
    if (target) print_error_choice(*target, verbose);
    if (verbose) {
        const auto gpu = r.gpu_timer().take(true);
        std::printf("%s", gl::describe(gl::summarize(gpu), r.gpu_timer().available(), r.gpu_timer().discarded()).c_str());
    }
    if (!job.out.empty()) {
        write_image(r, o, job.out);
        if (verbose) std::cerr << "wrote " << scene::printable(job.out) << "\n";
    }
    return 0;
}

// The plan of frame --frames (1: the first; the frames before it are rendered, so a later frame
// shows what it reuses), as text or JSON, on the headless context's real capabilities.
int run_plan(const render::Options& given, bool json, const std::vector<std::string>& allow_outside,
             const std::string& snippets) {
    std::string text;
    const render::Options o = with_snippets(given, snippets, text);
    const render::Job& job = o.job;
    scene::SceneSource src =
        open_scene(job.scene, job.eye_in_shadow ? scene::Eye::InShadow : scene::Eye::Scene, allow_outside);
    auto ctx = make_context();
    render::Renderer r(gl::probe_caps(*ctx));
    const render::FrameInputs in = render::offscreen(job.width, job.height);
    if (const std::string problem = r.check(src.at(job.time), o.settings, in); !problem.empty()) throw Failure{problem, 2};
    load_snippets(r, src.at(job.time), o, snippets, text, in);
    std::string refusal;
    std::optional<render::BudgetController> budget = tools::make_budget(o, r, src.at(job.time), in, refusal);
    if (!refusal.empty()) throw Failure{refusal, 2};
    const auto at = [&](int i) -> const scene::Scene& { return src.at(job.time + static_cast<double>(i) / 60.0); };
    render::Settings s = o.settings;
    if (budget) {
        // The frames before the planned one are the budget's measurements (at least the settling run's).
        tools::budget_frames(r, *budget, in, std::max(job.frames - 1, tools::kBudgetSettleFrames), at);
        s = budget->settings();
    }
    // --max-error: chosen on the planned frame.
    const std::optional<tools::ErrorChoice> target = tools::make_error_choice(o, r, at(job.frames - 1), in, refusal);
    if (!refusal.empty()) throw Failure{refusal, 2};
    if (target) s = target->settings();
    if (!budget)
        for (int i = 0; i + 1 < job.frames; ++i) r.render(at(i), s, in);
    render::FramePlan plan = r.plan(at(job.frames - 1), s, in);
    if (budget) plan.notes.insert(plan.notes.begin(), budget->why());
    if (target) plan.notes.insert(plan.notes.begin(), target->why);
    std::printf("%s%s", json ? plan.to_json().c_str() : plan.to_text().c_str(), json ? "\n" : "");
    return 0;
}

// ---- gallery --------------------------------------------------------------------------------

int run_gallery(const std::string& dir, const render::Options& base, const std::vector<std::string>& allow_outside) {
    scene::SceneSource src =
        open_scene(base.job.scene, base.job.eye_in_shadow ? scene::Eye::InShadow : scene::Eye::Scene, allow_outside);
    tools::prepare_output_dir("--out-dir", dir);  // created (and tried) once the scene has opened
    const scene::Scene& frame = src.at(base.job.time);
    const render::FrameInputs in = render::offscreen(base.job.width, base.job.height);
    auto ctx = make_context();
    render::Renderer r(gl::probe_caps(*ctx));

    struct Row {
        std::string label;
        render::Options o;
    };
    std::vector<Row> rows;
    const render::Aov aovs[] = {render::Aov::Color, render::Aov::Visibility, render::Aov::LightDepth};
    for (auto e : shadow::kAllEncodings)
        for (auto f : shadow::kAllFilters) {
            if (e == shadow::Encoding::DepthTex && !r.caps().depth_texture) continue;
            render::Options o = base;
            o.settings.technique = render::technique_named("shadowmap");
            o.settings.encoding = e;
            o.settings.filter = f;
            rows.push_back({std::string(shadow::to_string(e)) + "-" + std::string(shadow::to_string(f)), o});
        }
    for (const char* t : {"planar", "volumes", "none"}) {
        render::Options o = base;
        o.settings.technique = render::technique_named(t);
        rows.push_back({t, o});
    }

    const std::string index = (fs::path(dir) / "index.html").string();
    std::string body;
    size_t done = 0, written = 0;
    const size_t total = rows.size() * 3;
    for (const auto& row : rows) {
        body += "<tr><th>" + row.label + "</th>";
        for (auto aov : aovs) {
            render::Options o = row.o;
            o.settings.aov = aov;
            const std::string name = row.label + "-" + std::string(render::to_string(aov)) + ".png";
            ++done;
            if (!render::aov_problem(o.settings.technique, aov).empty()) {  // another technique's own view
                body += "<td>(no shadow map)</td>";
                continue;
            }
            if (const std::string problem = r.check(frame, o.settings, in); !problem.empty()) throw Failure{problem, 2};
            std::fprintf(stderr, "[%2zu/%zu] %s\n", done, total, name.c_str());
            r.render(frame, o.settings, in);
            write_image(r, o, (fs::path(dir) / name).string());
            ++written;
            body += "<td><img src=\"" + name + "\" width=\"256\" title=\"" + render::to_args(o) + "\"></td>";
        }
        body += "</tr>\n";
    }
    const std::string page =
        "<!doctype html><meta charset=\"utf-8\"><title>penumbra gallery</title>\n"
        "<style>body{font-family:sans-serif;background:#222;color:#eee}td,th{padding:4px}</style>\n"
        "<h1>The course scene at t = " + std::to_string(base.job.time) + "</h1>\n<p>" + r.caps().renderer +
        "; hover an image for its exact settings.</p>\n<table><tr><th></th><th>colour</th><th>visibility</th>"
        "<th>light depth</th></tr>\n" + body + "</table>\n";
    tools::write_output(index, page);
    std::printf("wrote %zu images and %s\n", written, scene::printable(index).c_str());
    return 0;
}

// ---- shaders, caps --------------------------------------------------------------------------

int run_shaders(const std::string& dir) {
    tools::prepare_output_dir("--out", dir);
    size_t n = 0;
    const auto write = [&](const std::string& file, const std::string& text) {
        tools::write_output((fs::path(dir) / file).string(), text);
        ++n;
    };
    // Each file as it is (no defines), then each variant; the extension tells the stage.
    for (const auto& v : render::all_variants()) {
        const std::string tag = v.defines.empty() ? std::string() : "_" + v.tag();
        const auto stem = [](const std::string& f) { return f.substr(0, f.find('.')); };
        write(stem(v.vertex) + "_plain.vert", render::variant_source(v.vertex, {}));
        write(stem(v.fragment) + "_plain.frag", render::variant_source(v.fragment, {}));
        write(stem(v.vertex) + tag + ".vert", render::variant_source(v.vertex, v.defines));
        write(stem(v.fragment) + tag + ".frag", render::variant_source(v.fragment, v.defines));
    }
    std::printf("wrote %zu shader files to %s\n", n, scene::printable(dir).c_str());
    return 0;
}

int run_caps() {
    auto ctx = make_context();
    std::printf("%s\n%s\n", ctx->description().c_str(), gl::probe_caps(*ctx).summary().c_str());
    render::Renderer r(gl::probe_caps(*ctx));
    std::printf("%s\n", r.unorm_report().c_str());
    tools::print_implementation(*ctx, gl::probe_caps(*ctx));
    return 0;
}

}  // namespace

namespace {
int run(int argc, char** argv);
}

int main(int argc, char** argv) {
    // A reader that goes away (penumbra plan --json | head -c 10) is an output that cannot be
    // written: a line and exit status 2, not death by SIGPIPE.
    std::signal(SIGPIPE, SIG_IGN);
    // The heap's ceiling (scene/memory_budget.h): a bad PENUMBRA_MEMORY_BUDGET is bad input.
    if (std::string error; !memory::budget_from_env(error)) {
        std::fprintf(stderr, "penumbra: error: %s\n", error.c_str());
        return 2;
    }
    const int rc = run(argc, argv);
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fprintf(stderr, "penumbra: error: cannot write to standard output (%s)\n", std::strerror(errno));
        return rc ? rc : 2;
    }
    return rc;
}

namespace {

int run(int argc, char** argv) {
    CLI::App app{"penumbra: shadow mapping on GLES2, headless (EGL)"};
    app.require_subcommand(1);

    // render and plan: every option of the table, parsed by the table.
    auto* render_cmd = app.add_subcommand("render", "render one frame (or time --frames N) to a PNG");
    const tools::TableOptions render_options(render_cmd);
    std::vector<std::string> render_allow, plan_allow, gallery_allow;
    tools::add_allow_outside(render_cmd, render_allow);
    bool verbose = false, still = false;
    render_cmd->add_flag("-v,--verbose", verbose, "list the context, the settings and each frame's passes");
    render_cmd->add_flag("--still", still, "with --frames: every frame at --time (nothing moves; what a still frame costs)");
    std::string render_snippets, plan_snippets;
    const std::string snippets_help =
        "FILE: the shader lab's functions (packDepth, unpackDepth, shadowTest, offset_lookup; docs/snippets.md) "
        "in place of the renderer's packing and lookup";
    render_cmd->add_option("--snippets", render_snippets, snippets_help);

    auto* plan_cmd = app.add_subcommand("plan", "print the frame plan: every pass (target, state, variants, draws) and resource");
    std::vector<std::string> plan_names;
    for (const auto& o : render::option_table())
        if (o.info.name != "out") plan_names.emplace_back(o.info.name);
    const tools::TableOptions plan_options(plan_cmd, plan_names);
    tools::add_allow_outside(plan_cmd, plan_allow);
    bool plan_json = false;
    plan_cmd->add_flag("--json", plan_json, "as JSON (passes, resources, uniforms, variants)");
    plan_cmd->add_option("--snippets", plan_snippets, snippets_help);

    auto* gallery_cmd = app.add_subcommand("gallery", "the course scene in every encoding x filter, with an index.html");
    std::string gallery_dir = "out/gallery";
    gallery_cmd->add_option("--out-dir", gallery_dir, "folder for the images (default out/gallery)");
    render::Options gallery_defaults;  // the course at t = 0.6
    gallery_defaults.job.time = 0.6;
    const tools::TableOptions gallery_options(gallery_cmd, {"scene", "time", "size", "map-size"}, gallery_defaults);
    tools::add_allow_outside(gallery_cmd, gallery_allow);

    auto* shaders_cmd = app.add_subcommand("shaders", "write every shader variant's source to a folder");
    std::string shader_dir;
    shaders_cmd->add_option("--out", shader_dir, "folder")->required();

    auto* caps_cmd = app.add_subcommand("caps", "print what the headless context supports");
    bool options_markdown = false;
    auto* options_cmd = tools::add_options_command(app, options_markdown);
    tools::MipmapsOptions mipmaps;
    auto* mipmaps_cmd = tools::add_mipmaps_command(app, mipmaps);
    // export, truth, bench: measuring the trade (tools/penumbra/measure_commands.h).
    const auto measure = tools::add_measure_commands(app);

#ifdef PENUMBRA_HAVE_TRUTH
    tools::GradeOptions grade;
    auto* grade_cmd = tools::add_grade_command(app, grade);
    auto* sweep_cmd = app.add_subcommand(
        "bias-sweep", "acne and peter-panning against bias, elevation, encoding and precision (results/precision)");
    tools::BiasSweepOptions sweep;
    sweep_cmd->add_option("--out-dir", sweep.out_dir,
                          "folder for the CSV, the table and the charts (default results/precision; with --quick "
                          "out/precision-quick)");
    sweep_cmd->add_flag("--quick", sweep.quick, "3 elevations and 5 biases, for CI");
    sweep_cmd->add_option("--size", sweep.size, "image width = height (default 256)")->check(CLI::Range(16, 4096));
    sweep_cmd->add_option("--map-size", sweep.map_size, "shadow map size (default 1024)")->check(CLI::Range(16, 8192));
#endif

    // --egl-device N on every command that opens a context.
    const tools::EglDeviceOption egl_device(app, {"shaders", "export", "options"});

    // The first word must be a subcommand: CLI11 would call an unknown one a missing one.
    std::string subcommands;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        subcommands += (subcommands.empty() ? "" : ", ") + sub->get_name();
        if (argc > 1 && sub->check_name(argv[1])) known = true;
    }
    if (argc > 1 && !known && argv[1][0] != '-') {
        std::fprintf(stderr, "penumbra: error: unknown subcommand '%s' (expected one of %s; see penumbra --help)\n",
                     scene::printable(argv[1]).c_str(), subcommands.c_str());
        return 2;
    }

    // An option without its value is named, where CLI11 would blame the word after it.
    if (const std::string missing = tools::missing_value(app, argc, argv); !missing.empty()) {
        std::fprintf(stderr, "penumbra: error: %s (see penumbra --help)\n", tools::one_line(missing).c_str());
        return 2;
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::RequiredError& e) {
        if (argc < 2 || argv[1][0] == '-')  // no subcommand at all (CLI11: "A subcommand is required")
            std::fprintf(stderr, "penumbra: error: a subcommand is required: one of %s (see penumbra --help)\n",
                         subcommands.c_str());
        else
            std::fprintf(stderr, "penumbra: error: %s (see penumbra --help)\n", tools::one_line(e.what()).c_str());
        return 2;
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "penumbra: error: %s (see penumbra --help)\n", tools::one_line(e.what()).c_str());
        return 2;
    }

    // A chosen EGL device (or PENUMBRA_EGL_DEVICE's) is checked before any work: a bad one is bad input.
    if (const std::string problem = egl_device.apply(); !problem.empty()) {
        std::fprintf(stderr, "penumbra: error: %s\n", tools::one_line(problem).c_str());
        return 2;
    }

    try {
        if (*render_cmd) return run_render(render_options.parse(), verbose, still, render_allow, render_snippets);
        if (*plan_cmd) return run_plan(plan_options.parse(), plan_json, plan_allow, plan_snippets);
        if (*gallery_cmd) return run_gallery(gallery_dir, gallery_options.parse(), gallery_allow);
        if (*shaders_cmd) return run_shaders(shader_dir);
        if (*caps_cmd) return run_caps();
        if (*options_cmd) {
            std::fputs(tools::options_text(options_markdown).c_str(), stdout);
            return 0;
        }
        if (*mipmaps_cmd) return tools::run_mipmaps(mipmaps);
        if (const int rc = tools::run_measure_commands(*measure); rc >= 0) return rc;
#ifdef PENUMBRA_HAVE_TRUTH
        if (*sweep_cmd) {
            // As with bench --quick: CI's small sweep never overwrites the committed results/precision.
            if (sweep.quick && sweep_cmd->count("--out-dir") == 0) sweep.out_dir = "out/precision-quick";
            return tools::run_bias_sweep(sweep);
        }
        if (*grade_cmd) return tools::run_grade(grade);
#endif
    } catch (const Failure& f) {
        std::fprintf(stderr, "penumbra: error: %s\n", tools::one_line(f.message).c_str());
        return f.code;
    } catch (const gl::Error& e) {
        std::fprintf(stderr, "penumbra: error: GL: %s\n", tools::one_line(e.what()).c_str());
        return 1;
    } catch (const memory::OverBudget& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
        return 2;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "penumbra: error: out of memory\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", tools::one_line(e.what()).c_str());
        return 1;
    } catch (...) {
        std::fprintf(stderr, "penumbra: error: an unexpected failure\n");
        return 1;
    }
    return 0;
}

}  // namespace
