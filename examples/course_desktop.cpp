// penumbra-desktop: the course exercises (W09P1, W09P2a, W09P2b, W09P2c, volumes, soft, stencil,
// multipass, cascades, bulb) in a desktop window (GLFW, GLES 2 through EGL), with keys for the
// same controls the web pages have; the cascades and bulb exercises fly their camera over the
// terrain and in the room by keys (W S forward and back, Q E turning, R F looking up and down, O
// the scene's camera).
//
//   penumbra-desktop [--exercise NAME] [--size WxH] [--frames N] [--screenshot FILE.png]
//                    [--resize WxH] [--no-vsync] [-v] [--time T] [--keys KEYS] [--print-title]
//                    [--snippets FILE] [any option the pages take]
//
// The options the pages take (the exercises' toggles and the technique settings) come from the
// option tables (examples/exercise_list.h, plan/options.h), as does --help. --frames N stops
// after N frames (for unattended runs), --screenshot writes the last frame as a PNG (top row
// first), --resize asks the window for a new size halfway through, --time fixes both clocks
// (paused), --keys presses keys one a frame from the second (unattended runs, tests), --print-title
// prints the window's title whenever its controls change and at the end. --snippets FILE draws
// with the shader lab's functions from FILE (docs/snippets.md), read again whenever it is saved:
// what does not compile is printed at its lines and the last good functions stay (at first, the
// sheet's answer). Bad input gets one line and exit status 2; a GL failure exit status 1.
//
// The window title is the exercise and its controls' state as the page shows it and keeps in its
// URL (CourseApp::options(): the same names and values), then the ms/frame:
//   "W09P2c | light=on jump=on encoding=rgba filter=hard ... | 2.10 ms/frame"
// It changes at the frame after a key changes a control; the ms every half second.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "exercises.h"
#include "file_watch.h"
#include "gl/check.h"
#include "platform/platform.h"
#include "render/lab.h"
#include "measure/image_io.h"
#include "scene/memory_budget.h"

using namespace penumbra;

namespace {

struct Args {
    std::string exercise = "w09p1";
    int width = 512, height = 512;
    long frames = 0;  // 0: until the window is closed
    std::string screenshot;
    int resize_w = 0, resize_h = 0;
    bool vsync = true;
    bool verbose = false;
    std::string keys;  // --keys: pressed one a frame from the second
    bool print_title = false;
    std::string snippets;  // --snippets FILE
    std::vector<std::pair<std::string, std::string>> options;  // for CourseApp::set_option
};

[[noreturn]] void usage_error(const std::string& message) {
    std::fprintf(stderr, "penumbra-desktop: error: %s (see penumbra-desktop --help)\n", message.c_str());
    std::exit(2);
}

// The short name of an exercise: its title up to the colon ("W09P2c", "Soft shadows").
std::string short_name(const examples::Exercise& e) {
    const std::string_view t = e.title;
    return std::string(t.substr(0, t.find(':')));
}

// The title's controls part: the exercise and its options as the page's URL has them.
std::string title_controls(const examples::CourseApp& app) {
    std::string t = short_name(app.exercise()) + " |";
    for (const auto& [name, value] : app.options()) t += " " + name + "=" + value;
    return t;
}

// A --keys character as a key press: letters as typed (upper case: with Shift), digits and
// [ ] - = , . and space as themselves. 0 for any other character.
platform::KeyEvent key_of(char c) {
    if (c >= 'a' && c <= 'z') return {c - 'a' + 'A', false};
    if (c >= 'A' && c <= 'Z') return {c, true};
    if ((c >= '0' && c <= '9') || c == '[' || c == ']' || c == '-' || c == '=' || c == ',' || c == '.' || c == ' ') return {c, false};
    return {0, false};
}

void print_help() {
    std::string options;
    const auto line = [&](const std::string& name, const std::string& values, std::string_view help) {
        std::string head = "  --" + name + " " + values;
        if (head.size() < 34) head.resize(34, ' ');
        else head += "\n" + std::string(34, ' ');
        options += head + std::string(help) + "\n";
    };
    for (const auto& o : examples::toggle_table()) line(std::string(o.info.name), render::accepted_values(o.info), o.info.help);
    for (const auto& o : render::option_table())
        if (o.info.part == render::OptionPart::Technique && o.info.name != "technique")
            line(std::string(o.info.name), o.info.type == render::OptionType::Choice ? render::accepted_values(o.info) : "V",
                 o.info.help);
    const render::OptionInfo& technique = render::option_info("technique");  // the soft exercise's control
    line(std::string(technique.name), render::accepted_values(technique), "soft: " + std::string(technique.help));
    const render::OptionInfo& eye = render::option_info("eye");  // a job option the exercises take
    line(std::string(eye.name), render::accepted_values(eye), eye.help);
    const render::OptionInfo& budget = render::option_info("budget-ms");  // render's --budget-ms, with --no-vsync
    line(std::string(budget.name), "MS", std::string(budget.help) + " (with --no-vsync: vsync paces the frames)");
    const render::OptionInfo& max_error = render::option_info("max-error");
    line(std::string(max_error.name), "P",
         "0: off; else the smallest map the model predicts within P % of the hard truth on these frames, chosen again "
         "every " + std::to_string(examples::CourseApp::kErrorEvery) + " frames; one of it and budget-ms");
    line("camera", "X,Y,Z,YAW,PITCH",
         "cascades, bulb: where the fly camera stands (metres) and looks (degrees: yaw right of north, pitch up)");
    std::printf(
        "penumbra-desktop: the course exercises (W09, shadow volumes, soft shadows, stencil, multipass, cascades, bulb) in a window "
        "(GLFW, GLES 2 through EGL)\n\n"
        "  --exercise E        %s (default w09p1)\n"
        "  --size WxH          window size (default 512x512)\n"
        "  --frames N          stop after N frames\n"
        "  --screenshot F.png  write the last frame (with --frames)\n"
        "  --resize WxH        resize the window halfway through --frames\n"
        "  --no-vsync          draw as fast as possible\n"
        "  -v, --verbose       print each frame's passes at the end\n"
        "  --time T            both clocks at T seconds, paused\n"
        "  --keys KEYS         press these keys, one a frame from the second (letters as typed:\n"
        "                      upper case with Shift; digits, [ ] - = , . and space)\n"
        "  --print-title       print the window title when its controls change, and at the end\n"
        "  --snippets FILE     the shader lab: packDepth, unpackDepth, shadowTest, offset_lookup from FILE\n"
        "                      (docs/snippets.md), read again when it is saved (w09p2c)\n\n"
        "as the web pages' controls and URL:\n%s\n%s",
        examples::exercise_names().c_str(), options.c_str(), examples::CourseApp::key_help().c_str());
}

Args parse_args(int argc, char** argv) {
    Args a;
    render::Options job;  // --size, --resize and --frames are checked as the option table checks them
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            print_help();
            std::exit(0);
        }
        if (arg == "-v" || arg == "--verbose") {
            a.verbose = true;
            continue;
        }
        if (arg == "--no-vsync") {
            a.vsync = false;
            continue;
        }
        if (arg == "--print-title") {
            a.print_title = true;
            continue;
        }
        if (arg.rfind("--", 0) != 0) usage_error("unexpected argument '" + arg + "'");
        if (i + 1 >= argc) usage_error(arg + ": needs a value (it is the last argument)");
        const std::string name = arg.substr(2), value = argv[++i];
        // "--scene --time 0.5": the value missing is --scene's ("-0.5" is a value).
        if (value.size() > 2 && value[0] == '-' && value[1] == '-' && std::isalpha(static_cast<unsigned char>(value[2])))
            usage_error(arg + ": needs a value (got the option " + value + " instead)");
        if (name == "exercise") {
            if (!examples::find_exercise(value))
                usage_error("--exercise: unknown value '" + value + "' (" + examples::exercise_names() + ")");
            a.exercise = value;
        } else if (name == "size" || name == "resize") {
            if (const std::string err = render::parse_option(job, "size", value); !err.empty())
                usage_error("--" + name + err.substr(6));
            (name == "size" ? a.width : a.resize_w) = job.job.width;
            (name == "size" ? a.height : a.resize_h) = job.job.height;
        } else if (name == "frames") {
            if (const std::string err = render::parse_option(job, "frames", value); !err.empty()) usage_error(err);
            a.frames = job.job.frames;
        } else if (name == "screenshot") {
            if (value.size() < 5 || value.substr(value.size() - 4) != ".png")
                usage_error("--screenshot " + value + ": the file name must end in .png");
            a.screenshot = value;
        } else if (name == "keys") {
            for (const char c : value)
                if (!key_of(c).key) {
                    char shown[8];
                    if (c > ' ' && c < 127) std::snprintf(shown, sizeof shown, "'%c'", c);
                    else std::snprintf(shown, sizeof shown, "\\x%02X", static_cast<unsigned char>(c));
                    usage_error("--keys: " + std::string(shown) + " is not a key here (letters, digits, [ ] - = , . and space)");
                }
            a.keys = value;
        } else if (name == "snippets") {
            a.snippets = value;
        } else {
            a.options.emplace_back(name, value);
        }
    }
    if (!a.screenshot.empty() && a.frames == 0) usage_error("--screenshot needs --frames N");
    return a;
}

// The snippets file's text; a file that cannot be read is bad input (exit status 2) at the start,
// and said (the last good text kept) when reloading.
bool read_snippets(const std::string& path, std::string& text) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return false;
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::stringstream s;
    s << in.rdbuf();
    text = s.str();
    return !in.bad();
}

// Compiles the file's text into the app's lab and says what came of it.
void load_snippets(examples::CourseApp& app, const std::string& path, const char* what) {
    std::string text;
    if (!read_snippets(path, text)) {
        std::fprintf(stderr, "penumbra-desktop: snippets: %s: cannot read it; the last good functions stay\n", path.c_str());
        return;
    }
    const auto problems = app.set_snippets(text);
    for (const auto& p : problems)
        std::fprintf(stderr, "penumbra-desktop: snippets: %s%s: %s\n", path.c_str(),
                     p.line > 0 ? (":" + std::to_string(p.line)).c_str() : "", p.message.c_str());
    // A file that writes none of the functions draws the sheet's answer: said, never a match (render/lab.h).
    const std::string none = render::lab_no_function(text);
    if (problems.empty())
        std::printf("snippets: %s %s%s%s\n", path.c_str(), what, none.empty() ? "" : ". ", none.c_str());
    else
        std::printf("snippets: %s does not compile; drawing with %s\n", path.c_str(),
                    app.snippets().empty() ? "the sheet's answer" : "the last good functions");
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    if (std::string error; !memory::budget_from_env(error)) usage_error(error);
    const Args args = parse_args(argc, argv);
    examples::CourseApp app(args.exercise);
    // Every option is checked before a window opens; what the context supports, after.
    // A value off a control's list becomes the nearest listed one: said on stderr, as the page says it.
    const auto note = [&app] {
        if (!app.note().empty()) std::fprintf(stderr, "penumbra-desktop: note: %s\n", app.note().c_str());
    };
    for (const auto& [name, value] : args.options) {
        if (const std::string err = app.set_option(name, value); !err.empty()) usage_error("--" + err);
        if (name != "map-size") note();  // a map size is set again, and said, once the context's limit is known
    }

    if (!args.snippets.empty()) {
        std::string text;
        if (!read_snippets(args.snippets, text)) usage_error("--snippets " + args.snippets + ": cannot read it");
        app.set_lab(true);
        if (!app.lab_available())
            usage_error("--snippets: " + app.lab_refusal() + " (exercise " +
                        args.exercise + "; the lab runs on w09p2c)");
    }

    std::string error;
    platform::WindowOptions wo;
    wo.width = args.width;
    wo.height = args.height;
    wo.title = title_controls(app);
    wo.swap_interval = args.vsync ? 1 : 0;
    auto window = platform::create_glfw_window(wo, error);
    if (!window) {
        std::fprintf(stderr, "penumbra-desktop: error: %s\n", error.c_str());
        return 1;
    }
    int status = 0;
    try {
        app.create_gl(*window);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "penumbra-desktop: error: %s\n", e.what());
        return 1;
    }
    for (const auto& [name, value] : args.options)
        if (name == "encoding" || name == "map-size") {  // depthtex needs OES_depth_texture; a size, the limit
            if (const std::string err = app.set_option(name, value); !err.empty()) usage_error("--" + err);
            note();
        }

    std::printf("%s\n%s\n%s\n%s", window->description().c_str(), app.caps()->summary().c_str(),
                std::string(app.exercise().title).c_str(), examples::CourseApp::key_help().c_str());
    std::fflush(stdout);
    examples::FileWatch watch(args.snippets);
    if (!args.snippets.empty()) load_snippets(app, args.snippets, "compiled");

    bool quit = false;
    const auto on_key = [&](const platform::KeyEvent& k) {
        if (k.key == platform::keys::Escape) {
            quit = true;
            return;
        }
        const std::string message = app.on_key(k.key, k.shift);
        if (!message.empty()) {
            std::printf("%s\n", message.c_str());
            std::fflush(stdout);
        }
    };
    window->on_key(on_key);

    double last_t = -1.0, last_ms_shown = -1.0;
    std::string shown_controls, title;
    int last_w = 0, last_h = 0;
    std::string shown_frame_note;
    window->run([&](const platform::FrameInfo& f) {
        if (f.frame_index >= 1 && f.frame_index <= static_cast<long>(args.keys.size()))  // the first frame as started
            on_key(key_of(args.keys[static_cast<size_t>(f.frame_index - 1)]));
        if (quit) return false;
        if (last_t >= 0.0) app.advance(f.time_s - last_t);
        last_t = f.time_s;
        if (!args.snippets.empty() && watch.changed(f.time_s)) load_snippets(app, args.snippets, "reloaded: compiled");
        if (f.width != last_w || f.height != last_h) {
            if (last_w) std::printf("window resized to %dx%d\n", f.width, f.height);
            last_w = f.width;
            last_h = f.height;
        }
        try {
            app.draw(f.width, f.height);
            // What the frame had to change for this window (W09P2b's copy larger than it): said
            // once each time it changes.
            if (app.frame_note() != shown_frame_note) {
                shown_frame_note = app.frame_note();
                if (!shown_frame_note.empty()) std::fprintf(stderr, "penumbra-desktop: note: %s\n", shown_frame_note.c_str());
            }
        } catch (const gl::Error& e) {
            std::fprintf(stderr, "penumbra-desktop: error: GL: %s\n", e.what());
            status = 1;
            return false;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "penumbra-desktop: error: %s\n", e.what());
            status = 1;
            return false;
        }
        // The title: at once when a control changed, the ms/frame (and the light samples) every half second.
        const std::string controls = title_controls(app);
        if (controls != shown_controls || f.time_s - last_ms_shown >= 0.5) {
            last_ms_shown = f.time_s;
            char figures[128];
            std::snprintf(figures, sizeof figures, " | %.2f ms/frame", app.median_ms());
            title = controls + figures;
            if (const render::BudgetController* b = app.budget()) {  // budget-ms: what it chose
                std::snprintf(figures, sizeof figures, " | budget: %s %s %d", shadow::to_string(b->settings().encoding).data(),
                              shadow::to_string(b->settings().filter).data(), b->settings().map_size);
                title += figures;
                if (app.budget_predicted_error() >= 0.0) {  // the model's, against the truth
                    std::snprintf(figures, sizeof figures, ", predicted error %.3f %%", app.budget_predicted_error());
                    title += figures;
                }
            }
            if (const render::ErrorChoice* c = app.error_choice()) {  // max-error: what it chose
                std::snprintf(figures, sizeof figures, " | max-error: %s, predicted %.3f %%", render::rung_label(c->rung()).c_str(),
                              c->rung().predicted_pct);
                title += figures;
            }
            if (const auto& area = app.area()) {  // Heckbert-Herf's progress (soft shadows)
                std::snprintf(figures, sizeof figures, " | light samples %d of %d", area->done, area->total);
                title += figures;
            }
            window->set_title(title);
            if (args.print_title && controls != shown_controls) {
                std::printf("title: %s\n", title.c_str());
                std::fflush(stdout);
            }
            shown_controls = controls;
        }
        const long n = f.frame_index + 1;
        if (args.resize_w && args.frames && n == std::max(1L, args.frames / 2))
            window->set_size(args.resize_w, args.resize_h);
        if (args.frames && n >= args.frames) {
            if (!args.screenshot.empty()) {
                const auto rgba = app.read_pixels(f.width, f.height);
                const std::string err =
                    measure::write_png(args.screenshot, measure::from_rgba(rgba, f.width, f.height, 3));
                if (!err.empty()) {
                    std::fprintf(stderr, "penumbra-desktop: error: %s\n", err.c_str());
                    status = 1;
                } else {
                    std::printf("wrote %s (%dx%d)\n", args.screenshot.c_str(), f.width, f.height);
                }
            }
            return false;
        }
        return true;
    });
    std::printf("%ld frames, median %.3f ms/frame (draw + wait, last %zu frames); %s\n", app.frames_drawn(),
                app.median_ms(), static_cast<size_t>(std::min(60L, app.frames_drawn())), app.query().c_str());
    if (const auto& area = app.area()) std::printf("light samples %d of %d\n", area->done, area->total);
    if (const render::BudgetController* b = app.budget()) {
        if (args.verbose)
            for (const auto& line : b->log()) std::printf("budget: %s\n", line.c_str());
        std::printf("%s\n", b->why().c_str());
        if (app.budget_predicted_error() >= 0.0)
            std::printf("predicted error %.3f %% of the truth (the frame's shadow edges, plan/error_model.h)\n",
                        app.budget_predicted_error());
    }
    if (const render::ErrorChoice* c = app.error_choice()) {
        if (args.verbose)
            for (const render::ErrorRung& g : c->rungs)
                std::printf("max-error: %s predicted %.3f %%\n", render::rung_label(g).c_str(), g.predicted_pct);
        if (args.verbose)
            std::printf("max-error: %ld choice%s, the last took %.1f ms (two frames offscreen, three plans)\n",
                        app.error_choices(), app.error_choices() == 1 ? "" : "s", app.error_choice_ms());
        std::printf("%s\n", c->why.c_str());
    } else if (app.max_error() > 0.0 && !app.error_target_refusal().empty()) {
        std::printf("%s\n", app.error_target_refusal().c_str());
    }
    if (args.print_title) std::printf("title: %s\n", title.c_str());
    if (args.verbose) std::printf("%s", app.last_plan().c_str());
    return status;
}
