#include "exercises.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <stdexcept>

#include "platform/platform.h"
#include "scene/primitives.h"
#include "shadow/encoding.h"
#include "shadow/light_frustum.h"

namespace penumbra::examples {

namespace {

constexpr float kTableSize = 4.0f;          // the course scene's table top (scene/course_scene.cpp)
constexpr std::size_t kTimingWindow = 60;   // frames in the ms/frame median
constexpr int kMapSizes[] = {256, 512, 1024, 2048, 4096};

bool parse_on_off(std::string_view v, bool& out) {
    if (v == "on") {
        out = true;
        return true;
    }
    if (v == "off") {
        out = false;
        return true;
    }
    return false;
}

const char* on_off(bool v) { return v ? "on" : "off"; }

// The options each exercise shows (in its controls, its URL and its keys).
std::vector<std::string> shown_options(Exercise e) {
    switch (e) {
        case Exercise::W09P1: return {"light", "jump"};
        case Exercise::W09P2a: return {"light", "jump", "projection"};
        case Exercise::W09P2b: return {"light", "jump", "fbo-view", "map-size"};
        case Exercise::W09P2c:
            return {"light", "jump", "encoding", "filter", "bias", "precision", "map-size", "aov", "map-view"};
    }
    return {};
}

// Settings the pages never take: the exercise picks the scene and the technique, the canvas or the
// window its size, and nothing is written to a file.
bool page_refuses(std::string_view name) {
    return name == "scene" || name == "technique" || name == "out" || name == "frames" || name == "size";
}

std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// The settings printer writes a float bias with 17 digits (0.0030000000260770321); a URL wants the
// shortest text that reads back as the same float (0.003).
std::string shortest_float(const std::string& v) {
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0') return v;  // "default", "auto", ...
    const float f = static_cast<float>(d);
    for (int precision = 1; precision <= 9; ++precision) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.*g", precision, static_cast<double>(f));
        if (static_cast<float>(std::strtod(buf, nullptr)) == f) return buf;
    }
    return v;
}

}  // namespace

std::string_view to_string(Exercise e) {
    switch (e) {
        case Exercise::W09P1: return "w09p1";
        case Exercise::W09P2a: return "w09p2a";
        case Exercise::W09P2b: return "w09p2b";
        case Exercise::W09P2c: return "w09p2c";
    }
    return "?";
}

std::string_view title(Exercise e) {
    switch (e) {
        case Exercise::W09P1: return "W09P1: jumping teapot on a marble table top";
        case Exercise::W09P2a: return "W09P2a: the view from the light";
        case Exercise::W09P2b: return "W09P2b: drawing to an off-screen buffer";
        case Exercise::W09P2c: return "W09P2c: shadow mapping in the fragment shader";
    }
    return "?";
}

bool parse_exercise(std::string_view name, Exercise& out) {
    for (Exercise e : kAllExercises)
        if (to_string(e) == name) {
            out = e;
            return true;
        }
    return false;
}

struct CourseApp::Fbo {
    int size = 0;
    gl::Texture color;
    gl::Renderbuffer depth;
    gl::Framebuffer fb;
};

CourseApp::CourseApp(Exercise e) : exercise_(e), course_(scene::make_course_scene()) {
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

// ---- options --------------------------------------------------------------------------------

std::string CourseApp::set_option(std::string_view name, std::string_view value) {
    const std::string quoted = "'" + std::string(value) + "'";
    if (name == "light" || name == "jump" || name == "map-view") {
        bool v = false;
        if (!parse_on_off(value, v)) return std::string(name) + ": expected on or off, got " + quoted;
        (name == "light" ? toggles_.light : name == "jump" ? toggles_.jump : toggles_.map_view) = v;
        return {};
    }
    if (name == "projection") {
        if (value != "persp" && value != "ortho") return "projection: expected persp or ortho, got " + quoted;
        toggles_.ortho = value == "ortho";
        return {};
    }
    if (name == "fbo-view") {
        if (value != "light" && value != "camera") return "fbo-view: expected light or camera, got " + quoted;
        toggles_.fbo_light = value == "light";
        return {};
    }
    if (name == "time") {
        render::Settings t = settings_;
        if (std::string err = render::parse_option(t, name, value); !err.empty()) return err.substr(2);
        set_time(t.time);
        paused_ = true;
        return {};
    }
    if (page_refuses(name))
        return std::string(name) + ": set by the exercise (or the canvas, the window), not an option here";
    render::Settings t = settings_;
    std::string err = render::parse_option(t, name, value);
    if (!err.empty()) return err.rfind("--", 0) == 0 ? err.substr(2) : err;
    if (t.encoding == shadow::Encoding::DepthTex && renderer_ && !renderer_->caps().depth_texture)
        return "encoding: depthtex needs WEBGL_depth_texture / OES_depth_texture, which this context lacks";
    settings_ = t;
    return {};
}

std::vector<std::pair<std::string, std::string>> CourseApp::options() const {
    const std::vector<std::string> shown = shown_options(exercise_);
    const auto pairs = render::to_pairs(settings_);
    const auto defaults = render::to_pairs(render::Settings{});
    const auto setting = [&](const std::string& n) {
        for (const auto& [k, v] : pairs)
            if (k == n) return k == "bias" ? shortest_float(v) : v;
        return std::string();
    };
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& n : shown) {
        if (n == "light") out.emplace_back(n, on_off(toggles_.light));
        else if (n == "jump") out.emplace_back(n, on_off(toggles_.jump));
        else if (n == "map-view") out.emplace_back(n, on_off(toggles_.map_view));
        else if (n == "projection") out.emplace_back(n, toggles_.ortho ? "ortho" : "persp");
        else if (n == "fbo-view") out.emplace_back(n, toggles_.fbo_light ? "light" : "camera");
        else out.emplace_back(n, setting(n));
    }
    // Any other setting that differs from its default keeps its value across a reload.
    for (size_t i = 0; i < pairs.size() && i < defaults.size(); ++i) {
        const auto& [k, v] = pairs[i];
        if (page_refuses(k) || k == "time") continue;
        if (std::find(shown.begin(), shown.end(), k) != shown.end()) continue;
        if (v != defaults[i].second) out.emplace_back(k, k == "bias" ? shortest_float(v) : v);
    }
    if (paused_ && light_time_ == jump_time_) out.emplace_back("time", format_number(light_time_));
    return out;
}

std::string CourseApp::query() const {
    std::string q;
    for (const auto& [k, v] : options()) q += (q.empty() ? "" : "&") + k + "=" + v;
    return q;
}

float CourseApp::bias() const { return settings_.effective_bias(); }
float CourseApp::default_bias() const { return shadow::default_bias(settings_.encoding); }

// ---- GL lifetime ----------------------------------------------------------------------------

void CourseApp::create_gl() {
    fbo_.reset();
    renderer_.reset();
    renderer_ = std::make_unique<render::Renderer>(gl::probe_caps());
    renderer_->load(course_.scene);
    ++generation_;
    if (settings_.encoding == shadow::Encoding::DepthTex && !renderer_->caps().depth_texture)
        settings_.encoding = shadow::Encoding::RGBA;
}

void CourseApp::drop_gl() {
    // The objects died with the context; deleting their names on a lost context does nothing.
    fbo_.reset();
    renderer_.reset();
}

const gl::Caps* CourseApp::caps() const { return renderer_ ? &renderer_->caps() : nullptr; }

// ---- time -----------------------------------------------------------------------------------

void CourseApp::advance(double dt) {
    if (paused_ || !(dt > 0.0)) return;
    dt = std::min(dt, 0.25);  // a tab in the background must not make the teapot leap
    if (toggles_.light) light_time_ += dt;
    if (toggles_.jump) jump_time_ += dt;
}

void CourseApp::set_time(double t) { light_time_ = jump_time_ = t; }

// ---- drawing --------------------------------------------------------------------------------

void CourseApp::render_checked(const scene::Scene& scene, const render::Settings& s, const gl::Target& target) {
    if (const std::string problem = renderer_->check(scene, s); !problem.empty()) {
        throw std::runtime_error(problem.rfind("--", 0) == 0 ? problem.substr(2) : problem);
    }
    plan_text_ += renderer_->render(scene, s, &target).describe();
}

void CourseApp::render_light_view(const render::Settings& s, const gl::Target& target, bool ortho) {
    scene::Scene& sc = course_.scene;
    // The light's frustum around what casts and receives shadows, as the shadow pass fits it.
    scene::Bounds bounds;
    for (const auto& o : sc.objects)
        if (o.mesh >= 0 && (o.casts_shadow || o.receives_shadow)) bounds.add(scene::object_bounds(sc, o));
    scene::Light light = sc.light;
    if (ortho) {
        // A directional light along the point light's line of sight to the scene.
        light.type = scene::LightType::Directional;
        light.direction = glm::normalize(bounds.center() - light.position);
    }
    const shadow::LightFrustum f = shadow::fit_light_frustum(light, scene::corners(bounds), bounds.center());
    const scene::Camera camera = sc.camera;
    const scene::Light saved_light = sc.light;
    sc.light = light;
    sc.camera.view = f.view;
    sc.camera.projection = f.proj;
    try {
        render_checked(sc, s, target);
    } catch (...) {
        sc.camera = camera;
        sc.light = saved_light;
        throw;
    }
    sc.camera = camera;
    sc.light = saved_light;
}

void CourseApp::draw_w09p1(const gl::Target& window) {
    render::Settings s = settings_;
    s.technique = render::Technique::Planar;
    s.aov = render::Aov::Color;
    render_checked(course_.scene, s, window);
}

void CourseApp::draw_w09p2a(const gl::Target& window) {
    render::Settings s = settings_;
    s.technique = render::Technique::None;  // seen from the light, nothing is in shadow
    s.aov = render::Aov::Color;
    render_light_view(s, window, toggles_.ortho);
}

void CourseApp::ensure_fbo(int size) {
    if (fbo_ && fbo_->size == size) return;
    fbo_.reset();
    auto f = std::make_unique<Fbo>();
    f->size = size;
    gl::TextureDesc d;
    d.width = d.height = size;
    d.sampling = gl::Sampling::Linear;
    // WebGL 1 repeats only power-of-two textures; the uvs stay in 0..1 anyway.
    d.wrap = (size & (size - 1)) == 0 ? gl::Wrap::Repeat : gl::Wrap::Clamp;
    d.label = "W09P2b colour texture";
    f->color = gl::Texture(d);
    f->depth = gl::Renderbuffer(renderer_->caps().depth24 ? gl::RenderbufferFormat::Depth24
                                                          : gl::RenderbufferFormat::Depth16,
                                size, size, "W09P2b depth");
    gl::FramebufferDesc fd;
    fd.color = &f->color;
    fd.depth = &f->depth;
    fd.label = "W09P2b framebuffer";
    f->fb = gl::Framebuffer(fd);
    fbo_ = std::move(f);
}

void CourseApp::draw_w09p2b(const gl::Target& window) {
    const int size = std::clamp(settings_.map_size, 1, renderer_->caps().max_target_size());
    ensure_fbo(size);
    render::Settings s = settings_;
    s.technique = render::Technique::None;
    s.aov = render::Aov::Color;
    // 1. The scene into the framebuffer object (the ground with its marble).
    renderer_->set_image_override(fbo_image_, nullptr);
    const gl::Target into{&fbo_->fb, size, size};
    if (toggles_.fbo_light)
        render_light_view(s, into, false);
    else
        render_checked(course_.scene, s, into);
    // 2. The scene from the camera, the ground quad textured with what the FBO holds.
    scene::Object& table = course_.scene.objects[static_cast<size_t>(course_.table)];
    const int mesh = table.mesh, material = table.material;
    table.mesh = fbo_mesh_;
    table.material = fbo_material_;
    renderer_->set_image_override(fbo_image_, &fbo_->color);
    try {
        render_checked(course_.scene, s, window);
    } catch (...) {
        table.mesh = mesh;
        table.material = material;
        renderer_->set_image_override(fbo_image_, nullptr);
        throw;
    }
    table.mesh = mesh;
    table.material = material;
    renderer_->set_image_override(fbo_image_, nullptr);
}

void CourseApp::draw_w09p2c(const gl::Target& window) {
    render::Settings s = settings_;
    s.technique = render::Technique::ShadowMap;
    render_checked(course_.scene, s, window);
    if (!toggles_.map_view) return;
    // The shadow map scaled for viewing, a quarter of the smaller side, in the top right corner.
    const int side = std::max(16, std::min(window.width, window.height) / 4);
    const int margin = std::max(2, side / 16);
    if (side + margin > window.width || side + margin > window.height) return;
    gl::Target pip{nullptr, side, side, window.width - side - margin, window.height - side - margin, true};
    s.aov = render::Aov::LightDepth;
    render_checked(course_.scene, s, pip);
}

void CourseApp::draw(int width, int height) {
    if (!renderer_) throw std::runtime_error("no GL context");
    const auto start = std::chrono::steady_clock::now();
    scene::animate_course(course_, light_time_, jump_time_);
    const gl::Target window{nullptr, width, height};
    plan_text_.clear();
    settings_.width = width;
    settings_.height = height;
    switch (exercise_) {
        case Exercise::W09P1: draw_w09p1(window); break;
        case Exercise::W09P2a: draw_w09p2a(window); break;
        case Exercise::W09P2b: draw_w09p2b(window); break;
        case Exercise::W09P2c: draw_w09p2c(window); break;
    }
    // Wait for the frame before the clock stops. glFinish would do on the desktop, but WebGL's
    // finish() returns at once in Chromium (it only flushes); reading one pixel back waits for the
    // rendering everywhere.
    renderer_->read_target(gl::Target{nullptr, 1, 1});
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (ms_.size() < kTimingWindow)
        ms_.push_back(ms);
    else
        ms_[static_cast<size_t>(frames_drawn_) % kTimingWindow] = ms;
    ++frames_drawn_;
}

std::vector<std::uint8_t> CourseApp::read_pixels(int width, int height) {
    if (!renderer_) throw std::runtime_error("no GL context");
    return renderer_->read_target(gl::Target{nullptr, width, height});
}

double CourseApp::median_ms() const {
    if (ms_.empty()) return 0.0;
    std::vector<double> v = ms_;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string CourseApp::last_plan() const { return std::string(title(exercise_)) + "\n" + plan_text_; }

// ---- keys -----------------------------------------------------------------------------------

std::string CourseApp::key_help() {
    return "keys:\n"
           "  1 2 3 4   exercise W09P1 (planar shadows), W09P2a (view from the light),\n"
           "            W09P2b (scene into an FBO, on the ground), W09P2c (shadow mapping)\n"
           "  L         light circulation on/off\n"
           "  J         the teapot's jump on/off\n"
           "  Space     pause/resume time\n"
           "  O         W09P2a: light projection perspective (point light) / orthographic (directional)\n"
           "  V         W09P2b: the FBO holds the view from the light / from the camera\n"
           "  E         W09P2c: next depth encoding (r8, rgba, depthtex where the context has it)\n"
           "  F         W09P2c: 4x4 PCF on/off\n"
           "  [ ]       W09P2c: bias down / up (x1.5)\n"
           "  B         W09P2c: bias back to the encoding's default\n"
           "  U         W09P2c: bias auto (the encoding's quantum + a receiver-slope term per fragment)\n"
           "  R         W09P2c: precision highp / emulated mediump (fp16 along the depth path, as on a phone)\n"
           "  M         shadow map size (W09P2b: FBO size) 256..4096, Shift+M backwards\n"
           "  A         W09P2c: view colour / visibility\n"
           "  S         W09P2c: shadow map view on/off\n"
           "  P         print the settings (URL query and penumbra render options)\n"
           "  H, F1     this help\n"
           "  Esc       quit\n";
}

std::string CourseApp::on_key(int key, bool shift) {
    const auto set = [this](const char* name, const std::string& value) {
        const std::string err = set_option(name, value);
        return err.empty() ? std::string(name) + " = " + value : err;
    };
    switch (key) {
        case '1': case '2': case '3': case '4':
            exercise_ = kAllExercises[key - '1'];
            return std::string(title(exercise_));
        case 'L': return set("light", on_off(!toggles_.light));
        case 'J': return set("jump", on_off(!toggles_.jump));
        case ' ':
            paused_ = !paused_;
            return paused_ ? "paused" : "running";
        case 'O': return set("projection", toggles_.ortho ? "persp" : "ortho");
        case 'V': return set("fbo-view", toggles_.fbo_light ? "camera" : "light");
        case 'S': return set("map-view", on_off(!toggles_.map_view));
        case 'E': {
            const bool depth_texture = renderer_ && renderer_->caps().depth_texture;
            shadow::Encoding e = settings_.encoding;
            do {
                e = e == shadow::Encoding::R8 ? shadow::Encoding::RGBA
                    : e == shadow::Encoding::RGBA ? shadow::Encoding::DepthTex
                                                  : shadow::Encoding::R8;
            } while (e == shadow::Encoding::DepthTex && !depth_texture);
            std::string line = set("encoding", std::string(shadow::to_string(e)));
            char buf[64];
            std::snprintf(buf, sizeof buf, " (bias %.4g, default %.4g)", static_cast<double>(bias()),
                          static_cast<double>(default_bias()));
            return line + buf;
        }
        case 'F': return set("filter", settings_.filter == shadow::Filter::Hard ? "pcf4x4" : "hard");
        case '[':
        case ']': {
            // From auto, step from the encoding's default (auto's constant alone is far smaller).
            const double from = static_cast<double>(settings_.bias_auto ? default_bias() : bias());
            const double b = from * (key == ']' ? 1.5 : 1.0 / 1.5);
            return set("bias", format_number(std::clamp(b, 1e-6, 1.0)));
        }
        case 'B': return set("bias", "default") + " (" + format_number(static_cast<double>(default_bias())) + ")";
        case 'U': return set("bias", "auto") + " (" + format_number(static_cast<double>(bias())) + " + slope)";
        case 'R': return set("precision", settings_.precision == shadow::Precision::Highp ? "mediump" : "highp");
        case 'M': {
            const int n = static_cast<int>(std::size(kMapSizes));
            int i = 0;
            while (i < n && kMapSizes[i] < settings_.map_size) ++i;
            if (i < n && kMapSizes[i] == settings_.map_size)
                i = (i + (shift ? n - 1 : 1)) % n;
            else
                i = shift ? (i + n - 1) % n : i % n;
            return set("map-size", std::to_string(kMapSizes[i]));
        }
        case 'A': return set("aov", settings_.aov == render::Aov::Visibility ? "color" : "visibility");
        case 'P': {
            render::Settings s = settings_;
            s.time = light_time_;
            s.technique = exercise_ == Exercise::W09P1   ? render::Technique::Planar
                          : exercise_ == Exercise::W09P2c ? render::Technique::ShadowMap
                                                          : render::Technique::None;
            return "?" + query() + "\npenumbra render " + render::to_args(s);
        }
        case 'H':
        case platform::keys::F1: return key_help();
        default: return {};
    }
}

}  // namespace penumbra::examples
