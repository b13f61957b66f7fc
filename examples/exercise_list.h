// The course exercises as modules: each exercise is one file under examples/exercises/ (its page's
// text, its controls, the options it starts with, its keys and its frame) and one line in the list
// (examples/exercises/list.h). This header is what a module declares (Exercise) and what its frame
// may use of the app that hosts it (Host: CourseApp, on the desktop and on the pages), the
// options only the exercises have (the light's and the teapot's motion, the light's projection,
// what the off-screen buffer shows, the shadow map's view), declared with the option table's types
// (plan/options.h), and the registry. A control may also name a job option the exercises take
// (time, eye: CourseApp::set_option). No GL here: the pages are generated from this list at build
// time (web/CMakeLists.txt, catalog_main.cpp), and course_desktop.cpp and exercises.cpp read it at
// run time.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fly_camera.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scene/scene.h"

namespace penumbra::gl {
struct Caps;
}
namespace penumbra::scene {
struct CourseScene;
}
namespace penumbra::render {
class Module;
struct FrameShape;
struct MapLayout;
}

namespace penumbra::examples {

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
    // The setting holds only in the exercises that offer a control for it: the others draw with
    // its default (or their own value, Exercise::frame) whatever it was set to (here_only()).
    bool here_only = false;
};
// The control, its setting held only where it is offered (Control::here_only).
inline Control here_only(Control c) {
    c.here_only = true;
    return c;
}

// A desktop key bound to an option: pressing it steps the option to its next value (Shift: the
// previous one) among the values the exercise's control offers, or all of them. An exercise's own
// bindings (Exercise::keys) hold in it alone and come before the shared ones there (the cascades
// and bulb exercises reuse letters whose options they have no use for); `only` names it.
struct KeyBinding {
    int key;
    std::string_view option;
    std::string_view help;
    std::string_view only = {};
};

// What an exercise's frame may use of the app that hosts it (CourseApp): the window, the settings
// as set, the toggles, the context's limits and the scenes, and the renderer (each render() one
// plan of the frame, timed with the frame's others).
class Host {
public:
    virtual int width() const = 0;
    virtual int height() const = 0;
    virtual const render::Settings& settings() const = 0;  // as set (the frame's are draw()'s argument)
    virtual const Toggles& toggles() const = 0;
    virtual const gl::Caps& gl_caps() const = 0;
    virtual const scene::CourseScene& course() const = 0;
    // One plan over the course scene; `label` names a second plan's passes in the GPU times ("texture").
    virtual void render(const render::Settings& s, const render::FrameInputs& in, const char* label = "") = 0;
    // One plan over the exercise's own scene (Exercise::make_scene), from its fly camera once moved.
    virtual void render_own_scene(const render::Settings& s, const render::FrameInputs& in) = 0;
    // The inputs that show the course scene from the light: its view and projection fitted tightly
    // around what the scene's camera sees in `camera` (its output) and, with `ortho`, a directional
    // light along the point light's line of sight.
    virtual render::FrameInputs light_view(render::Output output, bool ortho, const render::Output& camera) const = 0;
    // What this frame had to change in the options for the window (CourseApp::frame_note()).
    virtual void note_frame(std::string note) = 0;

protected:
    ~Host() = default;
};

using OptionValues = std::vector<std::pair<std::string_view, std::string_view>>;

// budget-ms and max-error's code: the hooks it gives the exercises' host (exercises.h,
// examples/exercise_budget.cpp). The catalogue (catalog_main.cpp) has no host and never draws;
// there the name is weak and null.
struct CourseTrade;
#ifdef PENUMBRA_CATALOG_ONLY
__attribute__((weak))
#endif
const CourseTrade& course_trade();

// One exercise: its page, its controls, its keys and its frame.
struct Exercise {
    std::string_view name;    // "w09p1": the page (w09p1.html) and --exercise
    std::string_view title;   // "W09P1: Jumping teapot on a marble table top"
    std::string_view text;    // the page's paragraph under the title
    std::string_view brief;   // one line for the index page
    std::string_view canvas;  // the canvas's accessible label
    std::string_view look_for;  // one line under the title: what to try and what to look for
    std::vector<Control> controls;
    // Options this exercise starts with instead of the defaults (name, value), set when it is
    // chosen and put back to the defaults when another is.
    OptionValues defaults = {};
    // Settings its frames are drawn with where it offers no control for them ({"technique",
    // "planar"}); a setting another exercise holds here_only() takes its default instead.
    OptionValues frame = {};
    // Its own desktop keys, before the shared ones (key_bindings()).
    std::vector<KeyBinding> keys = {};
    // A scene of its own, made the first time it is needed, in which the camera flies within
    // `fly_bounds` (the page offers mouse and keys to move it: CourseApp::fly; camera=... keeps it
    // in the URL). Null: the course scene.
    scene::Scene (*make_scene)() = nullptr;
    const FlyBounds& (*fly_bounds)() = nullptr;
    // Adds what its frames need to the course scene (a mesh, a material), once, before the GL
    // objects are made.
    void (*extend_course)(scene::Scene& course) = nullptr;
    // After set_option stored `name` in `t` (the settings it is about to keep): its own rules.
    void (*on_set)(render::Settings& t, std::string_view name) = nullptr;
    // The last word over its frame's settings (after `frame` and the defaults).
    void (*settings)(const Toggles& toggles, render::Settings& s) = nullptr;
    // Its frame: `s` the frame's settings, `in` the inputs that draw the course scene's camera into
    // the whole window. Each host.render() is one plan of the frame.
    void (*draw)(Host& host, render::Settings s, render::FrameInputs in) = nullptr;
    // The technique and effect modules its frames can use (render::planar_module, ...): a browser
    // page's module links only these (plan/techniques/technique.h). unit.ExerciseList checks that
    // they cover every technique and effect its controls and frame can reach.
    std::vector<const render::Module& (*)()> modules = {};
    // The frame shapes beside the forward one its frames can take (render::area_light_shape,
    // deferred_shape, shadow_blur_shape: plan/frames/frame.h), checked the same way.
    std::vector<const render::FrameShape& (*)()> frames = {};
    // The shadow map's layouts beside one map its frames can take (render::cascades_layout,
    // cube_layout: plan/techniques/technique.h), checked the same way; without one, its frames
    // plan one map where they would have taken it, with a note.
    std::vector<const render::MapLayout& (*)()> layouts = {};
    // The shader lab's splice (render::snippet_block) where the exercise's page has the lab's panel
    // (web/pages.py's LAB_EXERCISES): only then does a page's module link the lab's GLSL scan.
    std::string (*lab)(std::string_view text, shadow::Encoding e) = nullptr;
    // budget-ms and max-error's code (course_trade) where the exercise offers their control: only
    // then does a page's module link it; elsewhere a page refuses them by name. The desktop app
    // has it for every exercise.
    const CourseTrade& (*trade)() = nullptr;
    // The course's portal scene (scene::make_course_portal) where the exercise's frames take the
    // portal effect (render::portal_module among `modules`), and the eye moved into a shadow
    // (scene::place_eye_in_shadow) where it offers `eye`: only then does a page's module link them.
    scene::Portal (*portal)() = nullptr;
    bool (*eye_in_shadow)(scene::Scene& scene) = nullptr;
};
// Whether the exercise's camera flies (a scene of its own).
inline bool flies(const Exercise& x) { return x.make_scene != nullptr; }
// Whether the exercise offers a control for the option.
bool offers(const Exercise& x, std::string_view option);

// ---- the registry (examples/exercises/list.h) ---------------------------------------------------
const std::vector<Exercise>& exercise_list();
// The exercises the list is made of (exercise_registry.cpp): every one of list.h, or in a browser
// page's module (built with PENUMBRA_PAGE=name) that page's alone.
std::vector<Exercise> exercise_registry();
// The exercise of that name, or null.
const Exercise* find_exercise(std::string_view name);
std::string exercise_names();  // "w09p1, w09p2a, w09p2b, w09p2c, volumes, soft, stencil, multipass, cascades, bulb"
// The first exercises have the digit keys 1-8 on the desktop (9 and 0 are controls); Tab steps
// through all of them.
inline constexpr int kExerciseDigitKeys = 8;
// The shared keys, then each exercise's own (with `only` its name).
const std::vector<KeyBinding>& key_bindings();
// Whether some exercise holds the setting only where it is offered (Control::here_only). A fixed
// list (here_only_options()), the same in a page that has one exercise: unit.ExerciseList checks it
// against every exercise's controls.
bool held_here_only(std::string_view option);
const std::vector<std::string_view>& here_only_options();

}  // namespace penumbra::examples
