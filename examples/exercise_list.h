// The course exercises, in one place: each exercise's name, title, text, technique and the
// controls its page, its URL and the desktop app offer; the options only the exercises have (the
// light's and the teapot's motion, the light's projection, what the off-screen buffer shows, the
// shadow map's view), declared with the option table's types (plan/options.h). A control may
// also name a job option the exercises take (time, eye: CourseApp::set_option). No GL here: the
// pages are generated from this list at build time (web/CMakeLists.txt, catalog_main.cpp), and
// course_desktop.cpp and exercises.cpp read it at run time.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "plan/options.h"

namespace penumbra::examples {

enum class Exercise { W09P1, W09P2a, W09P2b, W09P2c, Volumes, Soft, Stencil, Multipass, Cascades, Bulb };

// The scene an exercise draws: the course scene (the teapot on the table), or one built in code
// from a test file's recipe, in which the camera flies: the kilometre of terrain
// (scenes/terrain_scene.h, tests/data/terrain_km.gltf) or the bulb room (scenes/room_scene.h,
// tests/data/bulb_room.gltf).
enum class ExerciseScene { Course, Terrain, Room };

// What the controls set besides render::Settings.
struct Toggles {
    bool light = true;      // light=on|off: the light circles the table
    bool jump = true;       // jump=on|off: the teapot jumps
    bool ortho = false;     // projection=persp|ortho (W09P2a): ortho makes the light directional
    bool fbo_light = true;  // fbo-view=light|camera (W09P2b): what is rendered into the FBO
    bool rtt_copy = false;  // rtt=fbo|copy (W09P2b): into the FBO, or into the window then glCopyTexImage2D
    bool map_view = true;   // map-view=on|off (W09P2c): the shadow map in the top right corner
    bool reference = false; // reference=on|off (soft): Heckbert-Herf with kReferenceSamples, converging
};
// The soft exercise's reference: Heckbert-Herf with this many light samples, this many added per
// still frame, whatever the method chosen.
inline constexpr int kReferenceSamples = 256;
inline constexpr int kReferencePerFrame = 8;
const std::vector<render::Option<Toggles>>& toggle_table();

// How a page shows an option.
enum class ControlKind {
    Toggle,    // a button that switches on/off
    Radio,     // one radio button per choice
    Select,    // a drop-down list of the choices (or the presets of an integer or a text option)
    Checkbox,  // ticked: values[0], unticked: values[1]
    Number,    // a number-or-word option: a radio per word, one for a number, and the number box
    Slider,    // a number: a slider over [min, max] of the control (within the option's range) and a number box
};

struct Control {
    std::string_view option;  // a render option (a technique option, or the job's eye) or a toggle
    std::string_view group;   // the fieldset it sits in
    ControlKind kind = ControlKind::Select;
    // Select: the choices offered (empty: all); Checkbox: on, off; Slider: the steps a desktop key
    // goes through (the slider and its box take any value in range).
    std::vector<std::string_view> values = {};
    std::string_view label = {};                // instead of the option's own label
    std::string_view hint = {};                 // a short note beside it
    double min = 0.0, max = 0.0;                // Slider: its range (the number box takes the option's)
};

struct ExerciseInfo {
    Exercise id;
    std::string_view name;    // "w09p1": the page (w09p1.html) and --exercise
    std::string_view title;   // "W09P1: Jumping teapot on a marble table top"
    std::string_view text;    // the page's paragraph under the title
    std::string_view brief;   // one line for the index page
    std::string_view canvas;  // the canvas's accessible label
    std::string_view look_for;  // one line under the title: what to try and what to look for
    render::Technique technique;  // its technique (the default, where a control offers the technique)
    std::vector<Control> controls;
    // Options this exercise starts with instead of the defaults (name, value), set when it is
    // chosen and put back to the defaults when another is.
    std::vector<std::pair<std::string_view, std::string_view>> defaults = {};
    // Its scene (ExerciseScene). In a scene of its own the camera flies: the page offers mouse and
    // keys to move it (CourseApp::fly), and camera=... keeps it in the URL.
    ExerciseScene scene = ExerciseScene::Course;
};
// Whether the exercise's camera flies (a scene of its own).
inline bool flies(const ExerciseInfo& x) { return x.scene != ExerciseScene::Course; }
// Whether the exercise offers a control for the option.
bool offers(const ExerciseInfo& x, std::string_view option);

const std::vector<ExerciseInfo>& exercise_list();
const ExerciseInfo& exercise_info(Exercise e);
bool parse_exercise(std::string_view name, Exercise& out);
std::string exercise_names();  // "w09p1, w09p2a, w09p2b, w09p2c, volumes, soft, stencil, multipass, cascades, bulb"
// The first exercises have the digit keys 1-8 on the desktop (9 and 0 are controls); Tab steps
// through all of them.
inline constexpr int kExerciseDigitKeys = 8;

// A desktop key bound to an option: pressing it steps the option to its next value (Shift: the
// previous one) among the values `exercise`'s control offers, or all of them. A binding with
// `only` set holds in that exercise alone and comes before the others there (the cascades and
// bulb exercises reuse letters whose options they have no use for).
struct KeyBinding {
    int key;
    std::string_view option;
    std::string_view help;
    std::optional<Exercise> only = std::nullopt;
};
const std::vector<KeyBinding>& key_bindings();

}  // namespace penumbra::examples
