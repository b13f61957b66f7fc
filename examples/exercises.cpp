#include "exercises.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "platform/platform.h"
#include "query.h"
#include "plan/json.h"
#include "plan/options.h"
#include "plan/techniques/technique.h"
#include "plan/weak_in_pages.h"
#include "scene/eye.h"
#include "scenes/portal_scene.h"
#include "shadow/encoding.h"

// In the browser a page's module has these only where its exercise names them (Exercise::trade,
// portal, eye_in_shadow); null here otherwise.
namespace penumbra::scene {
PENUMBRA_WEAK_IN_PAGES Portal make_course_portal();
PENUMBRA_WEAK_IN_PAGES bool place_eye_in_shadow(Scene& scene);
}  // namespace penumbra::scene

namespace penumbra::examples {

PENUMBRA_WEAK_IN_PAGES const CourseTrade& course_trade();

namespace {

const CourseTrade& (*trade_getter())() { return &course_trade; }
scene::Portal (*portal_getter())() { return &scene::make_course_portal; }
bool (*eye_getter())(scene::Scene&) { return &scene::place_eye_in_shadow; }

// An option set on in a page without its code.
std::string not_in_page(std::string_view option, std::string_view value) {
    return std::string(option) + " " + std::string(value) +
           ": not in this page's code (each page loads only what it offers; an exercise page that offers it has it)";
}

// The job options the exercises take: time (both clocks, paused), the eye, the time budget and the
// error target.
bool exercise_job_option(std::string_view name) {
    return name == "time" || name == "eye" || name == "budget-ms" || name == "max-error";
}

// What setting one of budget-ms and max-error on does to the other, when it was on.
constexpr const char* kOneControl = " off: a time budget or an error target, one at a time";

// Settings the pages and the desktop never take: the exercise picks the scene and the technique
// (unless it offers a control for it), the canvas or the window its size, and nothing is written
// to a file.
bool set_by_the_exercise(const Exercise& x, std::string_view name) {
    const auto* o = render::find_option(render::option_table(), name);
    if (name == "technique") return !offers(x, name);
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

const Exercise& exercise_named(std::string_view name) {
    if (const Exercise* x = find_exercise(name)) return *x;
    throw std::invalid_argument("unknown exercise '" + std::string(name) + "' (" + exercise_names() + ")");
}

}  // namespace

// The one place a plan's light-sample statistics are read (the plan's area, where it has one).
const render::AreaStats* area_stats(const render::FramePlan& plan) { return render::area_of(plan); }

// Without its portal: course_scene_for() adds it for the first frame that asks for it.
CourseApp::CourseApp(std::string_view exercise, bool defer_marble)
    : exercise_(&exercise_named(exercise)), defer_marble_(defer_marble) {
    // A page's first frame of an exercise with its own scene does without the course scene.
    if (!defer_marble || !flies(*exercise_)) made_course();
    own_scene();
    apply_defaults();
}

CourseApp::~CourseApp() = default;

void CourseApp::apply_defaults() {
    for (const auto& [name, value] : exercise_->defaults)
        if (const std::string err = set_option(name, value); !err.empty())
            throw std::logic_error("exercise " + std::string(exercise_->name) + ": default " + err);
}

void CourseApp::set_exercise(std::string_view name) {
    const Exercise& next = exercise_named(name);
    if (&next == exercise_) return;
    // What the old exercise started with goes back to the defaults; the new one's are set.
    for (const auto& d : exercise_->defaults) {
        const std::string_view option = d.first;
        std::string v;
        if (const auto* t = render::find_option(toggle_table(), option)) v = t->print(Toggles{});
        else if (const auto* o = render::find_option(render::option_table(), option)) v = o->print(render::Options{});
        set_option(option, v);
    }
    exercise_ = &next;
    own_scene();
    apply_defaults();
    budget_.reset();  // another scene: its times start afresh
    budget_error_rung_ = -1;
    reset_error_target();
}

// ---- options --------------------------------------------------------------------------------

namespace {

// The values the exercise's control for a technique option offers: a select's or radios' list, a
// checkbox's two; empty where the control takes any value the option takes (a number box, a
// slider) or the exercise has no control for it (a setting kept from a URL).
std::vector<std::string> offered_values(const Exercise& x, const render::OptionInfo& info) {
    for (const Control& c : x.controls) {
        if (c.option != info.name) continue;
        if (c.kind == ControlKind::Checkbox && c.values.empty()) return {"on", "off"};
        if (c.kind != ControlKind::Select && c.kind != ControlKind::Radio && c.kind != ControlKind::Checkbox) return {};
        if (!c.values.empty()) return {c.values.begin(), c.values.end()};
        std::vector<std::string> out;
        // An integer's words (--map-size auto) are among its presets.
        const bool presets = info.choices.empty() || info.type == render::OptionType::Integer;
        for (const auto& ch : presets ? info.presets : info.choices) out.emplace_back(ch.value);
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
    std::vector<std::string> offered = offered_values(*exercise_, o->info);
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
        offered.erase(std::remove_if(offered.begin(), offered.end(), [&](const std::string& x) { return x != "auto" && std::stoi(x) > most; }),
                      offered.end());
        if (offered.empty()) offered = {listed.front()};
    }
    if (offers(offered)) return {};
    const auto number = [](const std::string& x) {
        double d = 0.0;
        render::parse_number(x, d);  // whole numbers: the option's value and the exercise's list
        return d;
    };
    // auto, where a list lacks it (W09P2b's texture sizes): the size it stands for elsewhere.
    const double want = v == "auto" ? static_cast<double>(t.fixed_map_size()) : number(v);
    const auto distance = [&](const std::string& x) { return std::fabs(std::log((number(x) + 1.0) / (want + 1.0))); };
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
        clock_.set(t.job.time);
        clock_.paused = true;
        return {};
    }
    if (name == "eye") {
        render::Options t;
        if (std::string err = render::parse_option(t, name, value); !err.empty()) return without_dashes(err);
        if (t.job.eye_in_shadow && !eye_getter()) return not_in_page(name, value);
        eye_in_shadow_ = t.job.eye_in_shadow;
        return {};
    }
    if (name == "budget-ms") {
        render::Options t;
        if (std::string err = render::parse_option(t, name, value); !err.empty()) return without_dashes(err);
        if (t.job.budget_ms > 0.0 && !trade()) return not_in_page(name, value);
        if (t.job.budget_ms > 0.0)
            if (std::string why = render::budget_refusal(exercise_settings()); !why.empty()) return without_dashes(why);
        budget_ms_ = t.job.budget_ms;
        budget_.reset();  // made at the next frame, on this context
        budget_error_rung_ = -1;
        if (budget_ms_ > 0.0 && max_error_ > 0.0) {
            max_error_ = 0.0;
            note_ = std::string("max-error") + kOneControl;
        }
        reset_error_target();
        return {};
    }
    if (name == "max-error") {
        render::Options t;
        if (std::string err = render::parse_option(t, name, value); !err.empty()) return without_dashes(err);
        if (t.job.max_error > 0.0 && !trade()) return not_in_page(name, value);
        if (t.job.max_error > 0.0)
            if (std::string why = render::max_error_refusal(exercise_settings()); !why.empty()) return without_dashes(why);
        max_error_ = t.job.max_error;
        reset_error_target();
        if (max_error_ > 0.0 && budget_ms_ > 0.0) {
            budget_ms_ = 0.0;
            budget_.reset();
            budget_error_rung_ = -1;
            note_ = std::string("budget-ms") + kOneControl;
        }
        return {};
    }
    if (name == "camera") {
        OwnScene* o = own_scene();
        if (!o) {
            std::string flying;
            for (const Exercise& x : exercise_list())
                if (flies(x)) flying += (flying.empty() ? "" : ", ") + std::string(x.name);
            return "camera: only the exercises with a scene of their own (" + flying + ") fly their camera";
        }
        if (value.empty()) return "camera: needs a value: X,Y,Z,YAW,PITCH (metres, degrees)";
        return o->fly.set(value);
    }
    if (set_by_the_exercise(*exercise_, name))
        return std::string(name) + ": set by the exercise (or the canvas, the window), not an option here";
    render::Settings t = settings_;
    if (std::string err = render::parse_option(t, name, value); !err.empty()) return without_dashes(err);
    if (std::string err = keep_to_the_list(t, name); !err.empty()) return err;
    // A browser page has only its exercise's technique and effect modules (Exercise::modules).
    if (std::string err = render::unlinked_problem(t, name); !err.empty()) return without_dashes(err);
    if (exercise_->on_set) exercise_->on_set(t, name);
    if (t.encoding == shadow::Encoding::DepthTex && renderer_ && !renderer_->caps().depth_texture)
        return "encoding: depthtex needs WEBGL_depth_texture / OES_depth_texture, which this context lacks";
    settings_ = t;
    return {};
}

std::vector<std::pair<std::string, std::string>> CourseApp::options() const {
    std::vector<std::string> shown;
    for (const Control& c : exercise_->controls)
        if (std::find(shown.begin(), shown.end(), c.option) == shown.end()) shown.emplace_back(c.option);
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& n : shown) out.emplace_back(n, value_of(n));
    // Any other setting that differs from its default (the exercise's own where it has one, as
    // W09P2c's light-fit) keeps its value across a reload.
    render::Settings start;
    for (const auto& [name, value] : exercise_->defaults) (void)render::parse_option(start, name, value);
    const auto defaults = render::to_pairs(start);
    const auto pairs = render::to_pairs(settings_);
    for (size_t i = 0; i < pairs.size(); ++i) {
        const auto& [k, v] = pairs[i];
        if (set_by_the_exercise(*exercise_, k) || std::find(shown.begin(), shown.end(), k) != shown.end()) continue;
        if (v != defaults[i].second) out.emplace_back(k, v);
    }
    if (eye_in_shadow_ && std::find(shown.begin(), shown.end(), "eye") == shown.end()) out.emplace_back("eye", value_of("eye"));
    if (camera_moved()) out.emplace_back("camera", fly_value(camera()));
    if (clock_.paused && clock_.together()) out.emplace_back("time", format_number(clock_.light));
    if (budget_ms_ > 0.0 && std::find(shown.begin(), shown.end(), "budget-ms") == shown.end())
        out.emplace_back("budget-ms", value_of("budget-ms"));
    if (max_error_ > 0.0 && std::find(shown.begin(), shown.end(), "max-error") == shown.end())
        out.emplace_back("max-error", value_of("max-error"));
    return out;
}

std::string CourseApp::value_of(std::string_view name) const {
    if (const auto* t = render::find_option(toggle_table(), name)) return t->print(toggles_);
    if (name == "camera") return fly_value(camera());
    if (name == "budget-ms") return format_number(budget_ms_);
    if (name == "max-error") return format_number(max_error_);
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
    timing_.clear();  // frame times of the old context say nothing about this one
    renderer_->gpu_timer().enable(gpu_timing_);
    if (settings_.encoding == shadow::Encoding::DepthTex && !renderer_->caps().depth_texture)
        settings_.encoding = shadow::Encoding::RGBA;
    renderer_->set_snippets(snippets_);  // the lab's: they passed the scan (set_snippets)
}

const CourseTrade* CourseApp::trade() const { return trade_getter() ? &trade_getter()() : nullptr; }

// The objects died with the context; deleting their names on a lost context does nothing.
void CourseApp::drop_gl() {
    renderer_.reset();
    budget_.reset();  // the times measured on the old context say nothing about the next
    budget_error_rung_ = -1;
    reset_error_target();  // its ladder is the old context's
}

const gl::Caps* CourseApp::caps() const { return renderer_ ? &renderer_->caps() : nullptr; }
bool CourseApp::gpu_timer_available() const { return renderer_ && renderer_->caps().timer_query; }
int CourseApp::gpu_discarded() const { return renderer_ ? renderer_->gpu_timer().discarded() : 0; }

// ---- drawing --------------------------------------------------------------------------------

const scene::Scene& CourseApp::course_scene_for(const render::Settings& s) {
    // (A page without the portal's scene refuses the effect: render::unlinked_problem.)
    scene::Scene& course = made_course().scene;
    if (s.has(render::Effect::Portal) && !course.portal)
        if (const auto make = portal_getter()) course.portal = make();
    return course;
}

void CourseApp::render(const render::Settings& s, const render::FrameInputs& in, const char* label) {
    render_plan(course_scene_for(s), s, in, label);
}

void CourseApp::render_own_scene(const render::Settings& s, const render::FrameInputs& in) {
    OwnScene& o = *own_scene();
    // Unmoved, the scene's own camera exactly (the frame `penumbra render --scene
    // tests/data/terrain_km.gltf` or `bulb_room.gltf` draws); moved, the fly camera's.
    o.scene->camera = o.camera;
    o.scene->camera.view = o.fly.view(o.camera.view);
    render_plan(*o.scene, s, in, "");
}

void CourseApp::render_plan(const scene::Scene& sc, const render::Settings& s, const render::FrameInputs& in,
                            const char* label) {
    renderer_->gpu_timer().set_prefix(*label ? std::string(label) + ": " : std::string());
    const render::FramePlan& p = renderer_->render(sc, s, in);
    plan_text_ += p.describe();
    if (keep_plans_) plans_.push_back(p);
    if (const render::AreaStats* a = area_stats(p); a && !area_) area_ = *a;
}

render::Settings CourseApp::frame_settings() const {
    render::Settings s = exercise_settings();
    // The budget's choice before the lab's: the lab keeps its own packing (render::lab_settings).
    if (const CourseTrade* t = trade()) s = (this->*t->apply)(s);
    if (lab_ && !own_scene()) {
        const render::Settings lab = render::lab_settings(s);
        if (render::lab_refusal(lab).empty()) return lab;
    }
    return s;
}

render::Settings CourseApp::exercise_settings() const {
    // Each technique setting the exercise has no control for: its own value, or the default where
    // another exercise holds it only where offered (the multipass exercise's post passes, the
    // cascades', the cube's layout); any other keeps what was set (a URL's, a key's).
    const Exercise& x = *exercise_;
    render::Options o, defaults;
    o.settings = settings_;
    for (const auto& option : render::option_table()) {
        const std::string_view name = option.info.name;
        if (option.info.part != render::OptionPart::Technique || offers(x, name)) continue;
        const auto own = std::find_if(x.frame.begin(), x.frame.end(), [&](const auto& f) { return f.first == name; });
        if (own != x.frame.end()) option.store(o, own->second);
        else if (held_here_only(name)) option.store(o, option.print(defaults));
    }
    if (x.settings) x.settings(toggles_, o.settings);
    return o.settings;
}

// ---- the shader lab -------------------------------------------------------------------------

std::string CourseApp::lab_refusal() const {
    if (own_scene()) return "the shader lab runs on the course scene (w09p2c)";
    return render::lab_refusal(render::lab_settings(exercise_settings()));
}

std::vector<render::SnippetProblem> CourseApp::set_snippets(std::string_view text) {
    if (!renderer_) {
        // No context yet: the scan now, the compiler when the context is made (create_gl).
        auto problems = render::scan_snippets(text).problems;
        if (problems.empty()) snippets_ = std::string(text);
        return problems;
    }
    if (const std::string why = lab_refusal(); !why.empty()) return {{0, why}};
    scene::animate_course(made_course(), clock_.light, clock_.jump);
    const render::Settings s = frame_settings();
    auto problems = render::set_snippets(*renderer_, course_scene_for(s), s, text);
    if (problems.empty()) snippets_ = std::string(text);
    return problems;
}

render::LabVerdict CourseApp::lab_check(std::string_view text, int width, int height, double t) {
    render::LabVerdict v;
    if (!renderer_) {
        v.problems = {{0, "no GL context"}};
        return v;
    }
    if (const std::string why = lab_refusal(); !why.empty()) {
        v.problems = {{0, why}};
        return v;
    }
    scene::CourseScene& course = made_course();
    scene::animate_course(course, t, t);  // the next draw() puts the scene back at the clocks'
    course.scene.camera = scene_camera_;
    const render::Settings s = frame_settings();
    v = render::lab_check(*renderer_, course_scene_for(s), s, text, render::offscreen(width, height));
    if (v.compiles) snippets_ = std::string(text);  // else the renderer kept snippets_ (render::lab_check)
    return v;
}

render::FrameInputs CourseApp::light_view(render::Output output, bool ortho, const render::Output& camera) const {
    const scene::Scene& sc = made_course().scene;
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
    const CourseTrade* trade_code = trade();
    if (trade_code) (this->*trade_code->start)();
    const auto start = std::chrono::steady_clock::now();
    // The course scene where it is made (a page's first frame of the bulb room has none yet).
    if (course_) {
        scene::animate_course(*course_, clock_.light, clock_.jump);
        // The eye: the scene's camera, or (where the light now is) inside the teapot's shadow.
        course_->scene.camera = scene_camera_;
        if (eye_in_shadow_)
            if (const auto place = eye_getter()) place(course_->scene);
    }
    width_ = width;
    height_ = height;
    plan_text_.clear();
    plans_.clear();
    frame_note_.clear();
    area_.reset();
    render::FrameInputs in;
    in.output = render::Output::to_window(width, height);
    // The frame's plans are timed as one GPU frame (a plan that throws leaves it unfinished: the
    // next frame drops it).
    gl::PassTimer& timer = renderer_->gpu_timer();
    timer.begin_group();
    // A page's first frame (main() deferred the marble) is the scene lit and unshadowed, one program:
    // a first frame's time is mostly its programs' (docs/payload.md). The exercise's comes next.
    static const render::Settings first = [] {
        render::Settings f;
        render::parse_option(f, "technique", "none");
        return f;
    }();
    if (scene_complete()) exercise_->draw(*this, frame_settings(), std::move(in));
    else if (own_scene()) render_own_scene(first, in);
    else render_plan(made_course().scene, first, in, "");
    timer.end_group();
    timer.set_prefix("");
    // Wait for the frame before the clock stops. glFinish would do on the desktop, but WebGL's
    // finish() returns at once in Chromium (it only flushes); reading one pixel back waits for the
    // rendering everywhere.
    renderer_->read_window(0, 0, 1, 1);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    timing_.add(ms);
    if (trade_code) (this->*trade_code->after)(ms, width, height);
    // The GPU times that have arrived (a few frames old), without waiting.
    timing_.add_gpu(timer.take(false));
}

std::vector<std::uint8_t> CourseApp::read_pixels(int width, int height) {
    if (!renderer_) throw std::runtime_error("no GL context");
    return renderer_->read_window(0, 0, width, height);
}

std::string CourseApp::last_plan() const { return std::string(exercise_->title) + "\n" + plan_text_; }

std::string CourseApp::tile_lines() const {
    const auto tile = [](const std::string& text) {
        if (text.find("cascade") != std::string::npos || text.find("a cube of") != std::string::npos ||
            text.find("a cube map of") != std::string::npos)
            return true;
        for (size_t at = text.find("face "); at != std::string::npos; at = text.find("face ", at + 1))
            if (at + 6 < text.size() && (text[at + 5] == '+' || text[at + 5] == '-') &&
                std::string_view("xyz").find(text[at + 6]) != std::string_view::npos)
                return true;
        return false;
    };
    std::string lines;
    for (const render::FramePlan& plan : plans_)
        for (const render::Pass& pass : plan.passes) {
            if (!tile(pass.name + ": " + pass.detail)) continue;
            // A pass kept from the frame before says so first; a "reused (...)" in a detail is cut short.
            std::string detail = pass.detail;
            if (pass.skipped) {
                detail = "reused: " + detail;
            } else if (const size_t at = detail.find("reused ("); at != std::string::npos) {
                const size_t end = detail.find(')', at);
                if (end != std::string::npos) detail.replace(at, end + 1 - at, "reused");
            }
            std::string line = pass.name + ": " + detail;
            if (line.rfind("shadow-map", 0) == 0) line.erase(0, line.find_first_not_of(' ', 10));
            lines += (lines.empty() ? "" : "\n") + line;
        }
    return lines;
}

}  // namespace penumbra::examples
