// The course's exercises over the library: the four of worksheet W09 (02561), shadow volumes and soft shadows,
// shared by the browser pages (course_web.cpp) and the desktop app (course_desktop.cpp):
//   W09P1   jumping teapot on a marble table top, planar projected shadows (stencil), buttons to
//           switch the light's circulation and the teapot's jump on and off;
//   W09P2a  the scene from the light: its own view and projection fitted tightly around the
//           scene, perspective for the point light, orthographic for a directional light;
//   W09P2b  the scene rendered into a framebuffer object (or into the window and copied out with
//           glCopyTexImage2D: rtt=copy), and that texture on the ground quad;
//   W09P2c  shadow mapping: depth encoding, 4x4 PCF, bias (fixed, the encoding's default or auto),
//           precision (highp or emulated mediump), map size, and the shadow map shown scaled for
//           viewing in a corner;
//   volumes shadow volumes counted in the stencil buffer: depth-pass, depth-fail or auto, the
//           volumes drawn over the image, the stencil count in false colour, and the eye moved
//           into the teapot's shadow (where depth-pass fails);
//   soft    soft shadows from a light with a size: the radius, hard / PCF 4x4 / PCSS / Heckbert-Herf
//           (light samples averaged, converging while the scene stands still), each technique, and
//           a 256-sample reference to flip to.
//   stencil, multipass  stencil effects; post-processing and deferred shading;
//   cascades cascaded shadow maps over a kilometre of terrain (scenes/terrain_scene.h) under a low
//           sun: the number of cascades, the split, the snap, the blend, the cascades view, and a
//           camera that flies (fly(), camera=x,y,z,yaw,pitch in the URL);
//   bulb    a point light's cube of six shadow maps in a room (scenes/room_scene.h): the cube or one
//           map, the map size, the filter, the cube's faces tinted, and the same fly camera, kept
//           in the room.
// Each frame is one or two plans whose inputs carry what an exercise changes (a view from the
// light, a texture on the ground, a region of the window); the scene itself is never edited.
// No GL here: the renderer and the gl layer do the drawing; the platform owns the context.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exercise_list.h"
#include "fly_camera.h"
#include "gl/caps.h"
#include "gl/timer.h"
#include "plan/frames/area_light.h"
#include "plan/plan.h"
#include "render/renderer.h"
#include "plan/settings.h"
#include "scenes/course_scene.h"

namespace penumbra::examples {

class CourseApp {
public:
    explicit CourseApp(Exercise e);
    ~CourseApp();
    CourseApp(const CourseApp&) = delete;
    CourseApp& operator=(const CourseApp&) = delete;

    Exercise exercise() const { return exercise_; }
    // Switches to another exercise: the options the old one started with go back to their
    // defaults, the new one's are set (ExerciseInfo::defaults).
    void set_exercise(Exercise e);

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
    const render::Settings& settings() const { return settings_; }
    const Toggles& toggles() const { return toggles_; }
    bool eye_in_shadow() const { return eye_in_shadow_; }
    // The settings the next frame is drawn with: the exercise's technique (unless it offers a
    // control for it), the soft exercise's reference.
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

    // Time: the light's and the jump's clocks advance by dt when their motion is on and time is
    // not paused. set_time puts both clocks at t.
    void advance(double dt);
    void set_time(double t);
    void set_paused(bool paused) { paused_ = paused; }
    bool paused() const { return paused_; }
    double light_time() const { return light_time_; }
    double jump_time() const { return jump_time_; }

    // Draws one frame of the current exercise into the default framebuffer (width x height) and
    // waits for it (a one-pixel readback) so the frame's time is measured. Throws gl::Error on a
    // GL failure and std::invalid_argument when the settings cannot render on this context.
    void draw(int width, int height);
    // The default framebuffer's pixels, RGBA8, top row first.
    std::vector<std::uint8_t> read_pixels(int width, int height);
    // Median ms/frame over the last 60 frames (draw + wait), 0 before the first.
    double median_ms() const;
    // GPU time per pass (gl/timer.h, where the context has EXT_disjoint_timer_query): off until
    // switched on; on, each frame's plans are timed as one frame (a second plan's passes named
    // "texture: camera", "map view: light-depth view"), read back without waiting a few frames later, and
    // the last kGpuWindow frames kept. It stays on across a context restore.
    void set_gpu_timing(bool on);
    bool gpu_timing() const { return gpu_timing_; }
    bool gpu_timer_available() const { return renderer_ && renderer_->caps().timer_query; }
    // Each pass's median over the kept frames, and their totals' (frames 0: none read yet).
    gl::GpuSummary gpu_summary() const;
    // Frames dropped for GL_GPU_DISJOINT_EXT on this context.
    int gpu_discarded() const { return renderer_ ? renderer_->gpu_timer().discarded() : 0; }
    static constexpr std::size_t kGpuWindow = 30;
    long frames_drawn() const { return frames_drawn_; }
    // The passes of the last frame (each plan's), for --verbose and the pages.
    std::string last_plan() const;
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

    // Desktop keys: the help text, and one key's action. Returns a line saying what changed,
    // or "" when the key means nothing here.
    static std::string key_help();
    std::string on_key(int key, bool shift);

private:
    // set_option's rule for the values a control lists (see there): "" or the refusal.
    std::string keep_to_the_list(render::Settings& t, std::string_view name);
    // `label`: a second plan's, put before its passes' names in the GPU times ("texture").
    void render(render::Settings s, const render::FrameInputs& in, const char* label = "");
    void render(const scene::Scene& sc, const render::Settings& s, const render::FrameInputs& in,
                const char* label = "");
    // A scene built in code with its fly camera: made the first time an exercise needs it.
    struct OwnScene {
        std::unique_ptr<scene::Scene> scene;
        scene::Camera camera;     // its own camera
        FlyCamera fly, start;     // the fly camera, and where the scene's camera stands
        bool moved = false;       // the fly camera has left the scene's
    };
    // The current exercise's own scene (made if needed), or null with the course scene.
    OwnScene* own_scene();
    const OwnScene* own_scene() const;
    // The inputs that show the scene from the light: its view and projection fitted tightly around
    // what the scene's camera sees in `camera` (its output) and, with `ortho`, a directional light
    // along the point light's line of sight.
    render::FrameInputs light_view(render::Output output, bool ortho, const render::Output& camera) const;
    // The values key `option` steps through on this exercise.
    std::vector<std::string> key_values(std::string_view option) const;
    void apply_defaults(Exercise e);

    Exercise exercise_;
    render::Settings settings_;
    Toggles toggles_;
    scene::CourseScene course_;
    scene::Camera scene_camera_;  // the course scene's own camera (eye=scene)
    OwnScene terrain_;  // the cascades exercise's
    OwnScene room_;     // the bulb exercise's
    bool eye_in_shadow_ = false;  // eye=in-shadow: scene::place_eye_in_shadow each frame
    int fbo_mesh_ = -1;      // the table quad with uvs 0..1 (the FBO image once over the table)
    int fbo_material_ = -1;  // white, textured with the placeholder image the FBO replaces
    int fbo_image_ = -1;
    std::unique_ptr<render::Renderer> renderer_;
    std::size_t generation_ = 0;
    double light_time_ = 0.0;
    double jump_time_ = 0.0;
    bool paused_ = false;
    std::vector<double> ms_;  // ring of the last frame times
    bool gpu_timing_ = false;
    std::deque<gl::GpuFrame> gpu_frames_;  // the last kGpuWindow frames' GPU times
    long frames_drawn_ = 0;
    std::string note_;  // of the last set_option
    std::string plan_text_;  // this frame's passes, for --verbose
    std::string frame_note_;  // the last frame's (frame_note())
    std::optional<render::AreaStats> area_;  // the last frame's light samples
};

}  // namespace penumbra::examples
