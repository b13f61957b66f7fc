// The app that hosts the course's exercises (examples/exercises/*.cpp, one module each: list.h),
// shared by the browser pages (course_web.cpp) and the desktop app (course_desktop.cpp): the
// options as the URL, the controls and the keys set them, the clocks (clock.h), the GL context's
// life, the fly camera of an exercise with a scene of its own (fly_camera.h), the frame's timing
// (frame_timing.h), and each frame: the settings that follow from the option table and the
// exercise's controls, then the exercise's own draw(), through the Host interface
// (exercise_list.h). It knows no exercise by name. Each frame is one or two plans whose inputs carry
// what an exercise changes (a view from the light, a texture on the ground, a region of the
// window); the scene itself is never edited. No GL here: the renderer and the gl layer do the
// drawing; the platform owns the context.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "clock.h"
#include "exercise_list.h"
#include "fly_camera.h"
#include "frame_timing.h"
#include "gl/caps.h"
#include "gl/timer.h"
#include "plan/budget.h"
#include "plan/frames/area_light.h"
#include "plan/plan.h"
#include "plan/settings.h"
#include "render/error_target.h"
#include "render/lab.h"
#include "render/renderer.h"
#include "scenes/course_scene.h"

namespace penumbra::examples {

// The light samples of a plan (Heckbert-Herf), or null: the one place a plan's statistics are read.
const render::AreaStats* area_stats(const render::FramePlan& plan);

class CourseApp final : private Host {
public:
    // The exercise of that name (exercise_list()); std::invalid_argument for a name not listed.
    // With `defer_marble` the course scene's table has a placeholder texture until complete_scene()
    // (the pages: their first frame comes before the marble's noise is made), and an exercise with
    // a scene of its own starts without the course scene.
    explicit CourseApp(std::string_view exercise, bool defer_marble = false);
    // Makes what the constructor deferred (the marble, or the whole course scene), for the frames
    // from the next one on.
    // Returns true when it made something; false when the scene was already complete.
    bool complete_scene();
    bool scene_complete() const;
    ~CourseApp();
    CourseApp(const CourseApp&) = delete;
    CourseApp& operator=(const CourseApp&) = delete;

    const Exercise& exercise() const { return *exercise_; }
    // Switches to another exercise: the options the old one started with go back to their
    // defaults, the new one's are set (Exercise::defaults). std::invalid_argument for a name not listed.
    void set_exercise(std::string_view name);

    // One option by its URL / command-line name: a technique setting (render's option table), a
    // toggle (exercise_list.h), camera=X,Y,Z,YAW,PITCH (the fly camera of an exercise with a scene
    // of its own: metres and degrees), time=T (both clocks to T, paused) or eye=scene|in-shadow (the
    // camera moved into the teapot's shadow each frame, after the light has moved). Returns "" or one line naming
    // the problem; nothing changes on a problem. Where the exercise's control offers a list (a
    // select, radios, a checkbox), a value off the list is refused, or, for a number (the map
    // size), the nearest listed one the context can render is used and note() says so.
    std::string set_option(std::string_view name, std::string_view value);
    // What the last set_option changed in the value it was given ("map-size=3000 is not one of
    // this page's sizes (256, 512, 1024, 2048); using 2048"), or "" when it took it as it was.
    const std::string& note() const { return note_; }
    // The options this exercise shows, plus any other setting that differs from its default, as
    // name/value pairs that set_option reads back; time=T only while paused.
    std::vector<std::pair<std::string, std::string>> options() const;
    std::string query() const;  // options() as "name=value&name=value" (query.h's encoding: "1e%2B06")
    const render::Settings& settings() const override { return settings_; }
    const Toggles& toggles() const override { return toggles_; }
    bool eye_in_shadow() const { return eye_in_shadow_; }
    // The settings the next frame is drawn with: each technique setting the exercise offers no
    // control for takes its value (Exercise::frame) or, where another exercise holds it here_only(),
    // the option's default; then the exercise's own last word (Exercise::settings).
    render::Settings frame_settings() const;
    // Heckbert-Herf's light samples in the last frame (soft shadows), when it had them.
    const std::optional<render::AreaStats>& area() const { return area_; }
    // One option's value as options() writes it ("" for a name it does not know).
    std::string value_of(std::string_view name) const;
    // The bias in use (with bias=auto its constant part, the slope term is added per fragment),
    // and the chosen encoding's default (the sheet's 0.005 / 0.0015).
    float bias() const;
    float sheet_bias() const;

    // The GL side's life. create_gl: the context is current and new (first made, or restored
    // after a loss): make the renderer and every GL object. drop_gl: the context is gone; forget
    // what was made on it.
    void create_gl(const platform::Platform& context);
    void drop_gl();
    bool has_gl() const { return renderer_ != nullptr; }
    const gl::Caps* caps() const;
    std::size_t gl_generation() const { return generation_; }  // how many times create_gl ran

    // Time (clock.h): the light's and the jump's clocks advance by dt when their motion is on and
    // time is not paused. set_time puts both clocks at t.
    void advance(double dt) { clock_.advance(dt, toggles_.light, toggles_.jump); }
    void set_time(double t) { clock_.set(t); }
    void set_paused(bool paused) { clock_.paused = paused; }
    bool paused() const { return clock_.paused; }
    double light_time() const { return clock_.light; }
    double jump_time() const { return clock_.jump; }

    // Draws one frame of the current exercise into the default framebuffer (width x height) and
    // waits for it (a one-pixel readback) so the frame's time is measured. Throws gl::Error on a
    // GL failure and std::invalid_argument when the settings cannot render on this context.
    void draw(int width, int height);
    // The default framebuffer's pixels, RGBA8, top row first.
    std::vector<std::uint8_t> read_pixels(int width, int height);
    // Median ms/frame over the last 60 frames (draw + wait), 0 before the first.
    double median_ms() const { return timing_.median_ms(); }
    // budget-ms=N (render's --budget-ms, plan/budget.h): the frames' map size, encoding and filter
    // chosen from these frames' times; 0 (the default) off. The controller is made at the first
    // frame on a context (its caps) and again after a context restore or another exercise. Null
    // while off, before that frame, or where the exercise's technique has no map.
    const render::BudgetController* budget() const { return budget_ ? &*budget_ : nullptr; }
    // The error the model (plan/error_model.h) predicts against the hard truth for the budget's
    // choice on these frames (%); < 0 while off, before it is measured, or where it cannot be
    // predicted (a soft filter, no resolution match). Measured on a frame drawn offscreen beside
    // the window's (render/frame_edges.h) when the choice changes and every kErrorEvery frames.
    double budget_predicted_error() const { return budget_ ? budget_error_ : -1.0; }
    static constexpr int kErrorEvery = 120;
    // max-error=P (render's --max-error, render/error_target.h): the smallest map (encoding and
    // filter with it) the model predicts within P % of the hard truth on these frames; 0 (the
    // default) off. One of max-error and budget-ms: setting either on sets the other off. The
    // choice is made after the first frame on a context (which draws with the settings alone),
    // again every kErrorEvery frames while the frame moves (not while it is still: paused, or its
    // motions off, and the camera and window as they were), and after a change of option,
    // exercise or context; each time the frame is drawn twice more offscreen, after its time is
    // taken.
    // Hysteresis: a rung still predicted within P is left for a cheaper one only when that one is
    // predicted within kErrorKeep x P. Null while off, before the first choice, or where none can be
    // made (error_target_refusal() says why).
    const render::ErrorChoice* error_choice() const { return error_choice_ ? &*error_choice_ : nullptr; }
    double max_error() const { return max_error_; }
    const std::string& error_target_refusal() const { return error_refusal_; }
    double error_choice_ms() const { return error_ms_; }  // the last choice's wall time (its two frames, plans)
    long error_choices() const { return error_choices_; }  // choices made since max-error was set (-v)
    static constexpr double kErrorKeep = 0.8;
    // GPU time per pass (gl/timer.h, where the context has EXT_disjoint_timer_query): off until
    // switched on; on, each frame's plans are timed as one frame (a second plan's passes named
    // "texture: camera", "map view: light-depth view"), read back without waiting a few frames later, and
    // the last kGpuWindow frames kept. It stays on across a context restore.
    void set_gpu_timing(bool on) {
        gpu_timing_ = on;
        if (renderer_) renderer_->gpu_timer().enable(on);
    }
    bool gpu_timing() const { return gpu_timing_; }
    bool gpu_timer_available() const;
    // Each pass's median over the kept frames, and their totals' (frames 0: none read yet).
    gl::GpuSummary gpu_summary() const { return timing_.gpu_summary(); }
    // Frames dropped for GL_GPU_DISJOINT_EXT on this context.
    int gpu_discarded() const;
    static constexpr std::size_t kGpuWindow = FrameTiming::kGpuWindow;
    long frames_drawn() const { return timing_.frames(); }
    // The passes of the last frame (each plan's), for --verbose and the pages.
    std::string last_plan() const;
    // The last frame's shadow-map tiles, a line a pass: each cascade's and each cube face's
    // ("cascade 1: ...", "face +x: ..."; a pass kept from the frame before says "reused: ..."),
    // "" where it has none: the pages' readout (#cascade-plan). The plans are kept only while
    // keep_plans is on (off until switched on).
    void set_keep_plans(bool on) { keep_plans_ = on; }
    std::string tile_lines() const;
    // What the last frame had to change in the options for the window it was drawn in ("" when
    // nothing): W09P2b's rtt=copy texture larger than the window.
    const std::string& frame_note() const { return frame_note_; }

    // The fly camera of an exercise with a scene of its own (flies(), fly_camera.h): moves `forward`
    // metres along the view, `right` metres to the side and `up` metres upwards, then turns by `yaw`
    // degrees (to the right) and `pitch` degrees (up), kept within the scene's bounds (the terrain:
    // 0.3 m above the ground, within 2 km of the centre; the room: 0.2 m inside it). Returns false
    // (and changes nothing) in the exercises with the course scene.
    bool fly(double forward, double right, double up, double yaw, double pitch);
    // Back to the scene's own camera (the glTF's).
    void reset_camera();
    // Whether the camera has left the scene's own (the URL then keeps camera=...).
    bool camera_moved() const;
    const FlyCamera& camera() const;
    // The metres a button or key press moves the fly camera (0 without one).
    double fly_step() const;
    // The scene the current exercise draws.
    const scene::Scene& scene() const;
    // The course scene for a frame with settings `s`: its portal (--effects portal, the stencil
    // exercise's) is made the first time a frame asks for it, not with the scene: every other
    // page would build the other scene for nothing (about 15 ms of the first frame in the
    // browser, docs/payload.md). Adding it changes the scene, so the renderer uploads it again.
    const scene::Scene& course_scene_for(const render::Settings& s);

    // The shader lab (docs/snippets.md): on, the frames are drawn with Settings::lab
    // (render::lab_settings of the exercise's) and the snippets set here, where the exercise's
    // settings fit the lab (lab_refusal() == ""); elsewhere it has no effect.
    std::string lab_refusal() const;  // "" or why the lab cannot run here
    bool lab_available() const { return lab_refusal().empty(); }
    void set_lab(bool on) { lab_ = on; }
    bool lab() const { return lab_; }
    // Checks and compiles `text` (render::set_snippets) for the current frame's settings: the
    // problems, else the frames use it from now on. On a problem the last good text stays.
    std::vector<render::SnippetProblem> set_snippets(std::string_view text);
    const std::string& snippets() const { return snippets_; }  // the last good text ("" = the sheet's answer)
    // The verdict on `text` (render::lab_check) with the current frame's settings at time `t`
    // (both clocks' place; the clocks themselves do not move), drawn offscreen at width x height;
    // `text` becomes the snippets when it compiles.
    render::LabVerdict lab_check(std::string_view text, int width, int height, double t);

    // Desktop keys: the help text, and one key's action. Returns a line saying what changed,
    // or "" when the key means nothing here.
    static std::string key_help();
    std::string on_key(int key, bool shift);

private:
    // Host: what the exercise's draw() uses.
    int width() const override { return width_; }
    int height() const override { return height_; }
    const gl::Caps& gl_caps() const override { return renderer_->caps(); }
    const scene::CourseScene& course() const override { return made_course(); }
    void render(const render::Settings& s, const render::FrameInputs& in, const char* label = "") override;
    void render_own_scene(const render::Settings& s, const render::FrameInputs& in) override;
    render::FrameInputs light_view(render::Output output, bool ortho, const render::Output& camera) const override;
    void note_frame(std::string note) override { frame_note_ = std::move(note); }

    // frame_settings() without the lab.
    render::Settings exercise_settings() const;
    void render_plan(const scene::Scene& sc, const render::Settings& s, const render::FrameInputs& in, const char* label);
    // set_option's rule for the values a control lists (see there): "" or the refusal.
    std::string keep_to_the_list(render::Settings& t, std::string_view name);
    // A scene built in code with its fly camera: made the first time an exercise needs it.
    struct OwnScene {
        std::unique_ptr<scene::Scene> scene;
        scene::Camera camera;  // its own camera
        FlyRig fly;
    };
    // The current exercise's own scene (made if needed), or null with the course scene.
    OwnScene* own_scene();
    const OwnScene* own_scene() const;
    // The values key `option` steps through on this exercise.
    std::vector<std::string> key_values(std::string_view option) const;
    void apply_defaults();

    const Exercise* exercise_ = nullptr;
    render::Settings settings_;
    Toggles toggles_;
    // The course scene, made on first use (made_course()): a page whose exercise has a scene of its
    // own (the bulb room, the terrain) draws that scene's first frame before the teapot is
    // tessellated and welded, and makes the course with the marble in complete_scene().
    scene::CourseScene& made_course() const;
    mutable std::optional<scene::CourseScene> course_;
    mutable scene::Camera scene_camera_;  // the course scene's own camera (eye=scene)
    bool defer_marble_ = false;
    std::map<std::string_view, OwnScene> own_;  // by exercise name
    bool eye_in_shadow_ = false;  // eye=in-shadow: scene::place_eye_in_shadow each frame
    std::unique_ptr<render::Renderer> renderer_;
    std::size_t generation_ = 0;
    CourseClock clock_;
    FrameTiming timing_;
    bool gpu_timing_ = false;
    int width_ = 0, height_ = 0;  // of the frame being drawn
    std::string note_;  // of the last set_option
    std::string plan_text_;  // this frame's passes, for --verbose
    bool keep_plans_ = false;
    std::vector<render::FramePlan> plans_;  // this frame's, with keep_plans
    std::string frame_note_;  // the last frame's (frame_note())
    std::optional<render::AreaStats> area_;  // the last frame's light samples
    bool lab_ = false;
    std::string snippets_;
    double budget_ms_ = 0.0;
    std::optional<render::BudgetController> budget_;
    double budget_error_ = -1.0;  // budget_predicted_error()
    int budget_error_rung_ = -1;  // the rung it was measured for
    long budget_error_age_ = 0;   // frames since
    // What a frame's shadow edges depend on besides the settings: the clocks, the fly camera and
    // the window. A prediction is made again only when it differs (a still frame's is the same).
    struct EdgesFrame {
        double light = -1.0, jump = -1.0;
        int width = 0, height = 0;
        FlyCamera camera;
        bool operator==(const EdgesFrame& o) const {
            return light == o.light && jump == o.jump && width == o.width && height == o.height && camera.eye == o.camera.eye &&
                   camera.yaw == o.camera.yaw && camera.pitch == o.camera.pitch;
        }
    };
    EdgesFrame edges_frame(int width, int height) const;
    EdgesFrame budget_error_frame_;  // the frame it was measured on
    void predict_budget_error(int width, int height);
    double max_error_ = 0.0;
    std::optional<render::BudgetController> error_ladder_;  // the rungs max-error chooses from
    std::optional<render::ErrorChoice> error_choice_;
    std::string error_refusal_;
    long error_age_ = 0;  // frames since the choice
    EdgesFrame error_frame_;  // the frame it was made on
    long error_choices_ = 0;
    double error_ms_ = 0.0;
    // (Here, not with the error target's code: every page calls it.)
    void reset_error_target() {
        error_ladder_.reset();
        error_choice_.reset();
        error_refusal_.clear();
        error_age_ = 0;
        error_choices_ = 0;
    }
    void choose_for_error(int width, int height);
    // budget-ms and max-error's code (exercise_budget.cpp), reached through trade(): null in a
    // page whose exercise does not name it (Exercise::trade).
    friend const CourseTrade& course_trade();
    const CourseTrade* trade() const;
    void start_trade();                                 // before a frame: the budget's controller
    render::Settings traded(render::Settings s) const;  // the frame's settings with their choice
    void after_trade(double ms, int width, int height);  // after the frame's time: what they measure
};

// The hooks course_trade() gives CourseApp.
struct CourseTrade {
    void (CourseApp::*start)();
    render::Settings (CourseApp::*apply)(render::Settings s) const;
    void (CourseApp::*after)(double ms, int width, int height);
};

}  // namespace penumbra::examples
