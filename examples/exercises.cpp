#include "plan/frames/area_light.h"
#include "exercises.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "platform/platform.h"
#include "query.h"
#include "scene/eye.h"
#include "scene/primitives.h"
#include "scenes/room_scene.h"
#include "scenes/terrain_scene.h"
#include "shadow/encoding.h"

namespace penumbra::examples {

namespace {

constexpr float kTableSize = 4.0f;         // the course scene's table top (scenes/course_scene.cpp)
constexpr std::size_t kTimingWindow = 60;  // frames in the ms/frame median
constexpr const char* kFboTexture = "w09p2b";

// The job options the exercises take: time (both clocks, paused) and the eye.
bool exercise_job_option(std::string_view name) { return name == "time" || name == "eye"; }

// Settings the pages and the desktop never take: the exercise picks the scene and the technique
// (unless it offers a control for it), the canvas or the window its size, and nothing is written
// to a file.
bool set_by_the_exercise(Exercise e, std::string_view name) {
    const auto* o = render::find_option(render::option_table(), name);
    if (name == "technique") return !offers(exercise_info(e), name);
    return o && o->info.part == render::OptionPart::Job && !exercise_job_option(name);
}

std::string without_dashes(std::string err) { return err.rfind("--", 0) == 0 ? err.substr(2) : err; }

// The value a technique option holds, as a URL shows it (as render::to_pairs(s) has it, for one name).
std::string setting_value(const render::Settings& s, std::string_view name) {
    const auto* o = render::find_option(render::option_table(), name);
    if (!o || o->info.part != render::OptionPart::Technique) return {};
    render::Options opts;
    opts.settings = s;
    return o->print(opts);
}

}  // namespace

CourseApp::CourseApp(Exercise e) : exercise_(e), course_(scene::make_course_scene()) {
    scene_camera_ = course_.scene.camera;
    own_scene();
    apply_defaults(e);
    // W09P2b's ground: the table quad again with uvs 0..1, so the FBO's picture lies on the table
    // once, and a white material whose texture (a 1x1 placeholder) the FBO's texture replaces.
    scene::Scene& s = course_.scene;
    fbo_mesh_ = static_cast<int>(s.meshes.size());
    scene::Mesh quad = scene::make_quad(kTableSize, 1.0f);
    quad.name = "table (W09P2b)";
    // GL stores a rendered texture bottom row first: flip v so the picture stands upright to the
    // camera, its top towards the back of the table.
    for (auto& uv : quad.uvs) uv.y = 1.0f - uv.y;
    s.meshes.push_back(std::move(quad));
    fbo_image_ = static_cast<int>(s.images.size());
    s.images.push_back(scene::Image{1, 1, {255, 255, 255, 255}});
    scene::Material m;
    m.name = "off-screen buffer";
    m.base_color = glm::vec4(1.0f);
    m.base_color_texture = fbo_image_;
    m.specular = 0.1f;
    m.shininess = 16.0f;
    fbo_material_ = static_cast<int>(s.materials.size());
    s.materials.push_back(m);
}

CourseApp::~CourseApp() = default;

CourseApp::OwnScene* CourseApp::own_scene() {
    const ExerciseScene which = exercise_info(exercise_).scene;
    if (which == ExerciseScene::Course) return nullptr;
    OwnScene& o = which == ExerciseScene::Terrain ? terrain_ : room_;
    if (!o.scene) {
        o.scene = std::make_unique<scene::Scene>(which == ExerciseScene::Terrain ? scene::make_terrain_km_scene()
                                                                                  : scene::make_bulb_room_scene());
        o.camera = o.scene->camera;
        o.fly = o.start = fly_from_view(o.camera.view);
        o.moved = false;
    }
    return &o;
}

const CourseApp::OwnScene* CourseApp::own_scene() const {
    const ExerciseScene which = exercise_info(exercise_).scene;
    const OwnScene* o = which == ExerciseScene::Terrain ? &terrain_ : which == ExerciseScene::Room ? &room_ : nullptr;
    return o && o->scene ? o : nullptr;
}

// The bounds of the current exercise's fly camera.
static const FlyBounds& bounds_of(Exercise e) {
    return exercise_info(e).scene == ExerciseScene::Terrain ? terrain_fly_bounds() : room_fly_bounds();
}

const scene::Scene& CourseApp::scene() const {
    const OwnScene* o = own_scene();
    return o ? *o->scene : course_.scene;
}

bool CourseApp::fly(double forward, double right, double up, double yaw, double pitch) {
    OwnScene* o = own_scene();
    if (!o || !fly_move(o->fly, bounds_of(exercise_), forward, right, up, yaw, pitch)) return false;
    o->moved = true;
    return true;
}

void CourseApp::reset_camera() {
    if (OwnScene* o = own_scene()) {
        o->fly = o->start;
        o->moved = false;
    }
}

bool CourseApp::camera_moved() const {
    const OwnScene* o = own_scene();
    return o && o->moved;
}

const FlyCamera& CourseApp::camera() const {
    static const FlyCamera none;
    const OwnScene* o = own_scene();
    return o ? o->fly : none;
}

double CourseApp::fly_step() const { return own_scene() ? bounds_of(exercise_).step : 0.0; }

void CourseApp::apply_defaults(Exercise e) {
    for (const auto& [name, value] : exercise_info(e).defaults)
        if (const std::string err = set_option(name, value); !err.empty())
            throw std::logic_error("exercise " + std::string(exercise_info(e).name) + ": default " + err);
}

void CourseApp::set_exercise(Exercise e) {
    if (e == exercise_) return;
    // What the old exercise started with goes back to the defaults; the new one's are set.
    for (const auto& d : exercise_info(exercise_).defaults) {
        const std::string_view name = d.first;
        std::string v;
        if (const auto* t = render::find_option(toggle_table(), name)) v = t->print(Toggles{});
        else if (const auto* o = render::find_option(render::option_table(), name)) v = o->print(render::Options{});
        set_option(name, v);
    }
    exercise_ = e;
    own_scene();
    apply_defaults(e);
}

// ---- options --------------------------------------------------------------------------------

namespace {

// The values the exercise's control for a technique option offers: a select's or radios' list, a
// checkbox's two; empty where the control takes any value the option takes (a number box, a
// slider) or the exercise has no control for it (a setting kept from a URL).
std::vector<std::string> offered_values(Exercise e, const render::OptionInfo& info) {
    for (const Control& c : exercise_info(e).controls) {
        if (c.option != info.name) continue;
        if (c.kind == ControlKind::Checkbox && c.values.empty()) return {"on", "off"};
        if (c.kind != ControlKind::Select && c.kind != ControlKind::Radio && c.kind != ControlKind::Checkbox) return {};
        if (!c.values.empty()) return {c.values.begin(), c.values.end()};
        std::vector<std::string> out;
        for (const auto& ch : info.choices.empty() ? info.presets : info.choices) out.emplace_back(ch.value);
        return out;
    }
    return {};
}

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

}  // namespace

std::string CourseApp::keep_to_the_list(render::Settings& t, std::string_view name) {
    const auto* o = render::find_option(render::option_table(), name);
    if (!o) return {};
    std::vector<std::string> offered = offered_values(exercise_, o->info);
    if (offered.empty()) return {};
    const std::string v = setting_value(t, name);
    const auto offers = [&v](const std::vector<std::string>& values) {
        return std::find(values.begin(), values.end(), v) != values.end();
    };
    if (o->info.type != render::OptionType::Integer) {
        if (offers(offered)) return {};
        return std::string(name) + "=" + v + " is not offered here (" + joined(offered) + ")";
    }
    // A number: the listed one nearest on a log scale (sizes and sample counts go in powers of two;
    // +1 for a count that may be 0) among those the context can render.
    const std::vector<std::string> listed = offered;
    if (name == "map-size" && renderer_) {
        const int most = renderer_->caps().max_target_size();
        offered.erase(std::remove_if(offered.begin(), offered.end(), [&](const std::string& x) { return std::stoi(x) > most; }),
                      offered.end());
        if (offered.empty()) offered = {listed.front()};
    }
    if (offers(offered)) return {};
    const double want = std::stod(v);
    const auto distance = [&](const std::string& x) { return std::fabs(std::log((std::stod(x) + 1.0) / (want + 1.0))); };
    std::string best = offered.front();
    for (const auto& x : offered)
        if (distance(x) < distance(best)) best = x;
    if (const std::string err = render::parse_option(t, name, best); !err.empty()) return without_dashes(err);
    if (offers(listed))
        note_ = std::string(name) + "=" + v + " is more than this GL context renders; using " + best;
    else
        note_ = std::string(name) + "=" + v + " is not one of the values offered (" + joined(listed) + "); using " + best;
    return {};
}

std::string CourseApp::set_option(std::string_view name, std::string_view value) {
    note_.clear();
    if (render::find_option(toggle_table(), name))
        return without_dashes(render::set_option(toggle_table(), toggles_, name, value));
    if (name == "time") {
        render::Options t;
        if (std::string err = render::parse_option(t, name, value); !err.empty()) return without_dashes(err);
        set_time(t.job.time);
        paused_ = true;
        return {};
    }
    if (name == "eye") {
        render::Options t;
        if (std::string err = render::parse_option(t, name, value); !err.empty()) return without_dashes(err);
        eye_in_shadow_ = t.job.eye_in_shadow;
        return {};
    }
    if (name == "camera") {
        OwnScene* o = own_scene();
        if (!o)
            return "camera: only the exercises with a scene of their own (" + std::string(exercise_info(Exercise::Cascades).name) +
                   ", " + std::string(exercise_info(Exercise::Bulb).name) + ") fly their camera";
        if (std::string err = parse_fly(value, bounds_of(exercise_), o->fly); !err.empty()) return err;
        o->moved = true;
        return {};
    }
    if (set_by_the_exercise(exercise_, name))
        return std::string(name) + ": set by the exercise (or the canvas, the window), not an option here";
    render::Settings t = settings_;
    if (std::string err = render::parse_option(t, name, value); !err.empty()) return without_dashes(err);
    if (std::string err = keep_to_the_list(t, name); !err.empty()) return err;
    if (exercise_ == Exercise::Soft) {
        // The soft exercise's methods exclude each other: a filter other than hard takes one light
        // sample, more than one light sample the hard filter (the last one set wins).
        if (name == "filter" && t.filter != shadow::Filter::Hard) t.area_samples = 1;
        if (name == "area-samples" && t.area_samples > 1) t.filter = shadow::Filter::Hard;
    }
    if (t.encoding == shadow::Encoding::DepthTex && renderer_ && !renderer_->caps().depth_texture)
        return "encoding: depthtex needs WEBGL_depth_texture / OES_depth_texture, which this context lacks";
    settings_ = t;
    return {};
}

std::vector<std::pair<std::string, std::string>> CourseApp::options() const {
    std::vector<std::string> shown;
    for (const Control& c : exercise_info(exercise_).controls)
        if (std::find(shown.begin(), shown.end(), c.option) == shown.end()) shown.emplace_back(c.option);
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& n : shown) out.emplace_back(n, value_of(n));
    // Any other setting that differs from its default keeps its value across a reload.
    static const auto defaults = render::to_pairs(render::Settings{});
    const auto pairs = render::to_pairs(settings_);
    for (size_t i = 0; i < pairs.size(); ++i) {
        const auto& [k, v] = pairs[i];
        if (set_by_the_exercise(exercise_, k) || std::find(shown.begin(), shown.end(), k) != shown.end()) continue;
        if (v != defaults[i].second) out.emplace_back(k, v);
    }
    if (eye_in_shadow_ && std::find(shown.begin(), shown.end(), "eye") == shown.end()) out.emplace_back("eye", value_of("eye"));
    if (camera_moved()) out.emplace_back("camera", fly_value(camera()));
    if (paused_ && light_time_ == jump_time_) out.emplace_back("time", format_number(light_time_));
    return out;
}

std::string CourseApp::value_of(std::string_view name) const {
    if (const auto* t = render::find_option(toggle_table(), name)) return t->print(toggles_);
    if (name == "camera") return fly_value(camera());
    if (name == "eye") {
        render::Options o;
        o.job.eye_in_shadow = eye_in_shadow_;
        return render::find_option(render::option_table(), name)->print(o);
    }
    return setting_value(settings_, name);
}

std::string CourseApp::query() const {
    std::string q;
    for (const auto& [k, v] : options())
        q += (q.empty() ? "" : "&") + encode_query_component(k) + "=" + encode_query_component(v);
    return q;
}

float CourseApp::bias() const { return settings_.effective_bias(); }
float CourseApp::sheet_bias() const { return shadow::sheet_bias(settings_.encoding); }

// ---- GL lifetime ----------------------------------------------------------------------------

void CourseApp::create_gl(const platform::Platform& context) {
    renderer_.reset();
    renderer_ = std::make_unique<render::Renderer>(gl::probe_caps(context));
    renderer_->load(scene());
    ++generation_;
    ms_.clear();  // frame times of the old context say nothing about this one
    gpu_frames_.clear();
    renderer_->gpu_timer().enable(gpu_timing_);
    if (settings_.encoding == shadow::Encoding::DepthTex && !renderer_->caps().depth_texture)
        settings_.encoding = shadow::Encoding::RGBA;
}

// The objects died with the context; deleting their names on a lost context does nothing.
void CourseApp::drop_gl() { renderer_.reset(); }

const gl::Caps* CourseApp::caps() const { return renderer_ ? &renderer_->caps() : nullptr; }

// ---- time -----------------------------------------------------------------------------------

void CourseApp::advance(double dt) {
    if (paused_ || !(dt > 0.0)) return;
    dt = std::min(dt, 0.25);  // a tab in the background must not make the teapot leap
    if (toggles_.light) light_time_ += dt;
    if (toggles_.jump) jump_time_ += dt;
    // Switched off in mid-air, the teapot comes down and rests on the table.
    else jump_time_ = std::min(jump_time_ + dt, scene::course_teapot_landing(jump_time_));
}

void CourseApp::set_time(double t) { light_time_ = jump_time_ = t; }

// ---- drawing --------------------------------------------------------------------------------

void CourseApp::render(render::Settings s, const render::FrameInputs& in, const char* label) {
    render(course_.scene, s, in, label);
}

void CourseApp::render(const scene::Scene& sc, const render::Settings& s, const render::FrameInputs& in,
                       const char* label) {
    renderer_->gpu_timer().set_prefix(*label ? std::string(label) + ": " : std::string());
    const render::FramePlan& p = renderer_->render(sc, s, in);
    plan_text_ += p.describe();
    if (const render::AreaStats* a = render::area_of(p); a && !area_) area_ = *a;
}

render::Settings CourseApp::frame_settings() const {
    render::Settings s = settings_;
    if (!offers(exercise_info(exercise_), "technique")) s.technique = exercise_info(exercise_).technique;
    if (!offers(exercise_info(exercise_), "post")) s.post.clear();  // the multipass exercise's alone
    if (!offers(exercise_info(exercise_), "shading")) s.shading = render::Shading::Forward;
    if (!offers(exercise_info(exercise_), "lights")) s.lights = 0;
    // The cascades' settings belong to the cascades and bulb exercises alone (the bulb's cube
    // has no split, snap or blend).
    const render::Settings d;
    if (!offers(exercise_info(exercise_), "cascades")) s.cascades = d.cascades;
    if (!offers(exercise_info(exercise_), "cascade-split")) s.cascade_split = d.cascade_split;
    if (!offers(exercise_info(exercise_), "cascade-snap")) s.cascade_snap = d.cascade_snap;
    if (!offers(exercise_info(exercise_), "cascade-blend")) s.cascade_blend = d.cascade_blend;
    if (!offers(exercise_info(exercise_), "cube-layout")) s.cube_map = d.cube_map;
    if (exercise_ == Exercise::Soft && toggles_.reference) {
        s.filter = shadow::Filter::Hard;
        s.area_samples = kReferenceSamples;
        s.area_per_frame = kReferencePerFrame;
    }
    return s;
}

render::FrameInputs CourseApp::light_view(render::Output output, bool ortho, const render::Output& camera) const {
    const scene::Scene& sc = course_.scene;
    scene::Light light = sc.light;
    if (ortho) {
        // A directional light along the point light's line of sight to the scene.
        light.type = scene::LightType::Directional;
        light.direction = glm::normalize(render::shadowed_bounds(sc).center() - light.position);
    }
    render::FrameInputs seen;
    seen.output = camera;
    const shadow::LightFrustum f = render::fit_light_view(sc, light, render::camera_view(sc, seen).view_proj);
    render::FrameInputs in;
    in.output = std::move(output);
    in.view = f.view;
    in.projection = f.proj;
    in.light = light;
    return in;
}

void CourseApp::draw(int width, int height) {
    if (!renderer_) throw std::runtime_error("no GL context");
    const auto start = std::chrono::steady_clock::now();
    scene::animate_course(course_, light_time_, jump_time_);
    // The eye: the scene's camera, or (where the light now is) inside the teapot's shadow.
    course_.scene.camera = scene_camera_;
    if (eye_in_shadow_) scene::place_eye_in_shadow(course_.scene);
    const render::Output window = render::Output::to_window(width, height);
    render::Settings s = frame_settings();
    plan_text_.clear();
    frame_note_.clear();
    area_.reset();
    render::FrameInputs in;
    in.output = window;
    // The frame's plans are timed as one GPU frame (a plan that throws leaves it unfinished: the
    // next frame drops it).
    gl::PassTimer& timer = renderer_->gpu_timer();
    timer.begin_group();
    switch (exercise_) {
        case Exercise::W09P1:
            s.aov = render::Aov::Color;
            render(s, in);
            break;
        case Exercise::W09P2a:  // seen from the light, nothing is in shadow
            s.aov = render::Aov::Color;
            render(s, light_view(window, toggles_.ortho, window));
            break;
        case Exercise::W09P2b: {
            s.aov = render::Aov::Color;
            // 1. The scene into a texture (the ground with its marble), 2. the scene from the
            // camera with that texture where the table's material has its placeholder.
            int size = std::clamp(settings_.map_size, 1, renderer_->caps().max_target_size());
            if (toggles_.rtt_copy) {
                // glCopyTexImage2D copies what the window holds: the texture is no larger than the
                // window. The largest power of two that fits (WebGL 1 repeats only those).
                const int fit = std::min(width, height);
                if (size > fit) {
                    int p = 1;
                    while (p * 2 <= fit) p *= 2;
                    frame_note_ = "rtt=copy: the texture is copied from the window, so it can be no larger than the "
                                  "window's " + std::to_string(fit) + " pixels: " + std::to_string(p) + "x" +
                                  std::to_string(p) + " instead of " + std::to_string(size) + "x" + std::to_string(size);
                    size = p;
                }
            }
            const bool pot = (size & (size - 1)) == 0;  // WebGL 1 repeats only power-of-two textures
            const gl::Wrap wrap = pot ? gl::Wrap::Repeat : gl::Wrap::Clamp;
            const render::Output texture =
                toggles_.rtt_copy ? render::Output::copied_texture(kFboTexture, size, size, gl::Sampling::Linear, wrap)
                                  : render::Output::texture(kFboTexture, size, size, gl::Sampling::Linear, wrap);
            render::Output into_output = texture;
            if (toggles_.rtt_copy) {  // drawn in the window's corner, copied, then drawn over
                into_output = render::Output::window_region(0, 0, size, size);
                into_output.copy_to = kFboTexture;
                into_output.sampling = texture.sampling;
                into_output.wrap = texture.wrap;
            }
            render::FrameInputs into;
            if (toggles_.fbo_light) into = light_view(into_output, false, window);
            else into.output = into_output;
            render(s, into, "texture");
            in.objects.push_back({course_.table, fbo_mesh_, fbo_material_});
            in.images.push_back({fbo_image_, texture});
            render(s, in);
            break;
        }
        case Exercise::W09P2c: {
            if (s.aov == render::Aov::StencilCount) s.aov = render::Aov::Color;  // no volumes here
            render(s, in);
            if (!toggles_.map_view) break;
            // The shadow map scaled for viewing, a quarter of the smaller side, in the top right corner.
            const int side = std::max(16, std::min(width, height) / 4);
            const int margin = std::max(2, side / 16);
            if (side + margin > width || side + margin > height) break;
            s.aov = render::Aov::LightDepth;
            in.output = render::Output::window_region(width - side - margin, height - side - margin, side, side);
            render(s, in, "map view");
            break;
        }
        case Exercise::Volumes:  // colour, visibility or the stencil count; the volumes drawn or not
            if (s.aov == render::Aov::LightDepth) s.aov = render::Aov::Color;  // no shadow map here
            render(s, in);
            break;
        case Exercise::Soft:  // one plan: the light samples accumulate over still frames
            if (s.aov != render::Aov::Visibility) s.aov = render::Aov::Color;
            render(s, in);
            break;
        case Exercise::Stencil:  // the colour image: the effects are drawn on it only
            s.aov = render::Aov::Color;
            render(s, in);
            break;
        case Exercise::Multipass:  // colour, visibility or a G-buffer view, through the post passes
            if (s.aov != render::Aov::Visibility && !render::gbuffer_aov(s.aov)) s.aov = render::Aov::Color;
            render(s, in);
            break;
        case Exercise::Cascades:  // the terrain or the room from the fly camera: colour, visibility or
        case Exercise::Bulb: {    // the cascades (the cube's faces)
            if (s.aov != render::Aov::Visibility && s.aov != render::Aov::Cascades) s.aov = render::Aov::Color;
            OwnScene& o = *own_scene();
            // Unmoved, the scene's own camera exactly (the frame `penumbra render --scene
            // tests/data/terrain_km.gltf` or `bulb_room.gltf` draws); moved, the fly camera's.
            o.scene->camera = o.camera;
            if (o.moved) o.scene->camera.view = fly_view(o.fly);
            render(*o.scene, s, in);
            break;
        }
    }
    timer.end_group();
    timer.set_prefix("");
    // Wait for the frame before the clock stops. glFinish would do on the desktop, but WebGL's
    // finish() returns at once in Chromium (it only flushes); reading one pixel back waits for the
    // rendering everywhere.
    renderer_->read_window(0, 0, 1, 1);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (ms_.size() < kTimingWindow) ms_.push_back(ms);
    else ms_[static_cast<size_t>(frames_drawn_) % kTimingWindow] = ms;
    ++frames_drawn_;
    // The GPU times that have arrived (a few frames old), without waiting.
    for (gl::GpuFrame& f : timer.take(false)) gpu_frames_.push_back(std::move(f));
    while (gpu_frames_.size() > kGpuWindow) gpu_frames_.pop_front();
}

void CourseApp::set_gpu_timing(bool on) {
    gpu_timing_ = on;
    if (renderer_) renderer_->gpu_timer().enable(on);
}

gl::GpuSummary CourseApp::gpu_summary() const {
    return gl::summarize(std::vector<gl::GpuFrame>(gpu_frames_.begin(), gpu_frames_.end()));
}

std::vector<std::uint8_t> CourseApp::read_pixels(int width, int height) {
    if (!renderer_) throw std::runtime_error("no GL context");
    return renderer_->read_window(0, 0, width, height);
}

double CourseApp::median_ms() const {
    if (ms_.empty()) return 0.0;
    std::vector<double> v = ms_;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string CourseApp::last_plan() const { return std::string(exercise_info(exercise_).title) + "\n" + plan_text_; }

}  // namespace penumbra::examples
