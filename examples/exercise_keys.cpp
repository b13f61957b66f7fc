// CourseApp's desktop keys: the help text and what each key does (exercise_list.h's bindings, the
// fly camera of the cascades and bulb exercises, and the keys handled here).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "exercises.h"
#include "platform/platform.h"
#include "query.h"

namespace penumbra::examples {

// ---- keys -----------------------------------------------------------------------------------

std::string CourseApp::key_help() {
    // A line a key: the key, the option it changes (the page's control, the URL's name), what it does.
    std::string out = "keys (key, the option it changes as in the page's URL and the title, what it does):\n";
    const auto line = [&](const std::string& key, std::string_view option, std::string_view help) {
        std::string l = "  " + key;
        l.resize(14, ' ');
        l += option;
        if (l.size() < 31) l.resize(31, ' ');
        else l += ' ';
        out += l + std::string(help) + "\n";
    };
    for (size_t i = 0; i < exercise_list().size(); ++i)
        line(i < static_cast<size_t>(kExerciseDigitKeys) ? std::to_string(i + 1) : "Tab",
             "exercise " + std::string(exercise_list()[i].name), exercise_list()[i].title);
    line("Tab", "exercise", "the next exercise (Shift+Tab: the previous)");
    for (const KeyBinding& k : key_bindings()) line(std::string(1, static_cast<char>(k.key)), k.option, k.help);
    // The fly camera of the cascades and bulb exercises (before the bindings of those letters there).
    line("W S Up Dn", "camera", "cascades, bulb: fly forward / back 2 m, in the room 0.25 m (Shift: 10 times)");
    line("Q E Lt Rt", "camera", "cascades, bulb: turn left / right 5 degrees (Shift: 20)");
    line("R F", "camera", "cascades, bulb: look up / down 3 degrees");
    line("O", "camera", "cascades, bulb: back to the scene's camera");
    // The keys on_key handles itself.
    line("[ ]", "bias", "W09P2c: bias down / up (x1.5)");
    line("B", "bias", "W09P2c: bias=sheet (the sheet's constant for the encoding)");
    line("U", "bias", "W09P2c: bias=auto (the packing's precision + a receiver-slope term per fragment)");
    line("- =", "light-radius", "soft: light radius down / up (0.05)");
    line("Space", "time", "pause / resume both clocks (paused: time=T in the title and the URL)");
    line("P", "", "print the settings: the URL query and the penumbra render command of this frame");
    line("H, F1", "", "this list");
    line("Esc", "", "quit");
    return out;
}

std::vector<std::string> CourseApp::key_values(std::string_view option) const {
    for (const Control& c : exercise_->controls)
        if (c.option == option && !c.values.empty()) return {c.values.begin(), c.values.end()};
    std::vector<std::string> out;
    const render::OptionInfo* info = nullptr;
    if (const auto* t = render::find_option(toggle_table(), option)) info = &t->info;
    else info = &render::option_info(option);
    const bool presets = info->choices.empty() || info->type == render::OptionType::Integer;  // --map-size auto
    for (const render::Choice& c : presets ? info->presets : info->choices) out.emplace_back(c.value);
    return out;
}

std::string CourseApp::on_key(int key, bool shift) {
    const auto set = [this](std::string_view name, const std::string& value) {
        const std::string err = set_option(name, value);
        return err.empty() ? std::string(name) + " = " + value : err;
    };
    const int exercises = static_cast<int>(exercise_list().size());
    if (key >= '1' && key < '1' + std::min(exercises, kExerciseDigitKeys)) {
        set_exercise(exercise_list()[static_cast<size_t>(key - '1')].name);
        return std::string(exercise_->title);
    }
    if (key == platform::keys::Tab) {
        const int i = static_cast<int>(exercise_ - exercise_list().data());
        set_exercise(exercise_list()[static_cast<size_t>(((shift ? i - 1 : i + 1) % exercises + exercises) % exercises)].name);
        return std::string(exercise_->title);
    }
    if (flies(*exercise_)) {  // the fly camera
        const double step = fly_step() * (shift ? 10.0 : 1.0), turn = shift ? 20.0 : 5.0;
        bool moved = true;
        switch (key) {
            case 'W':
            case platform::keys::Up: fly(step, 0, 0, 0, 0); break;
            case 'S':
            case platform::keys::Down: fly(-step, 0, 0, 0, 0); break;
            case 'Q':
            case platform::keys::Left: fly(0, 0, 0, -turn, 0); break;
            case 'E':
            case platform::keys::Right: fly(0, 0, 0, turn, 0); break;
            case 'R': fly(0, 0, 0, 0, 3.0); break;
            case 'F': fly(0, 0, 0, 0, -3.0); break;
            case 'O': reset_camera(); break;
            default: moved = false;
        }
        if (moved) return camera_moved() ? "camera = " + fly_value(camera()) : std::string("camera = the scene's");
    }
    // The bindings of this exercise alone first, then the others.
    std::vector<const KeyBinding*> bindings;
    for (const KeyBinding& k : key_bindings())
        if (k.only == exercise_->name) bindings.push_back(&k);
    for (const KeyBinding& k : key_bindings())
        if (k.only.empty()) bindings.push_back(&k);
    for (const KeyBinding* kb : bindings) {
        const KeyBinding& k = *kb;
        if (k.key != key) continue;
        // The next value among those offered (Shift: the previous), skipping what the context refuses.
        const std::vector<std::string> values = key_values(k.option);
        const std::string current = value_of(k.option);
        const int n = static_cast<int>(values.size());
        int i = static_cast<int>(std::find(values.begin(), values.end(), current) - values.begin());
        if (i == n) {  // not among them (a map size off the list): step to the nearest ones
            int above = 0;
            if (k.option == "map-size")
                while (above < n && values[static_cast<size_t>(above)] != "auto" &&
                       std::stoi(values[static_cast<size_t>(above)]) < settings_.map_size)
                    ++above;
            i = shift ? above : above - 1;
        }
        for (int step = 0; step < n; ++step) {
            i = ((shift ? i - 1 : i + 1) % n + n) % n;
            // Without a context that has it (or any context yet), no depth texture.
            const bool depth_texture = renderer_ && renderer_->caps().depth_texture;
            if (k.option == "encoding" && values[static_cast<size_t>(i)] == "depthtex" && !depth_texture) continue;
            std::string line = set(k.option, values[static_cast<size_t>(i)]);
            if (line.find(" = ") == std::string::npos) continue;
            if (k.option == "encoding") {
                char buf[64];
                std::snprintf(buf, sizeof buf, " (bias %.4g, default %.4g)", static_cast<double>(bias()),
                              static_cast<double>(sheet_bias()));
                line += buf;
            }
            return line;
        }
        return k.option == "encoding" ? std::string("encoding: no other encoding on this context") : std::string();
    }
    switch (key) {
        case ' ':
            clock_.paused = !clock_.paused;
            return clock_.paused ? "paused" : "running";
        case '[':
        case ']': {
            // From auto, step from the encoding's default (auto's constant alone is far smaller).
            const double from = static_cast<double>(settings_.bias_auto ? sheet_bias() : bias());
            const double b = from * (key == ']' ? 1.5 : 1.0 / 1.5);
            return set("bias", format_number(std::clamp(b, 1e-6, 1.0)));
        }
        case 'B': return set("bias", "sheet") + " (" + format_number(static_cast<double>(sheet_bias())) + ")";
        case 'U': return set("bias", "auto") + " (" + format_number(static_cast<double>(bias())) + " + slope)";
        case '=':
        case '-': {  // the light's radius, in steps of 0.05 (from the scene's, 0 for the course scene)
            const double r = static_cast<double>(settings_.light_radius.value_or(made_course().scene.light.radius));
            return set("light-radius", format_number(std::max(0.0, std::round((r + (key == '=' ? 0.05 : -0.05)) * 100.0) / 100.0)));
        }
        case 'P': {
            render::Options o;
            o.settings = frame_settings();
            o.job.time = clock_.light;
            return "?" + query() + "\npenumbra render " + render::to_args(o);
        }
        case 'H':
        case platform::keys::F1: return key_help();
        default: return {};
    }
}

}  // namespace penumbra::examples
