// The course exercises in the browser: one WebGL 1 module for the exercise pages (web/*.html), which
// pass --exercise. The page's JavaScript (web/penumbra-page.js) drives it through the exported
// C functions below: options from the URL and the controls, the state for the readouts, and a
// small test hook (fixed time, synchronous frames, pixel readback, glGetError).
//
// No emscripten header here: the platform layer owns the canvas, the loop and the context's life;
// the exports are listed at link time (web/CMakeLists.txt).
#include <cstdint>
#include <cstdio>
#include <exception>
#include <malloc.h>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "exercises.h"
#include "query.h"
#include "gl/check.h"
#include "plan/json.h"
#include "platform/platform.h"
#include "render/lab.h"
#include "plan/snippets.h"
#include "shadow/encoding.h"

using namespace penumbra;

namespace {

// Everything the browser's frames use lives here: main() returns while the page runs on.
struct WebApp {
    std::unique_ptr<platform::Platform> platform;
    std::unique_ptr<examples::CourseApp> app;
    std::string status = "starting";
    std::string last_error;  // of the last failing call or frame
    std::string reported;    // the last frame error printed (each distinct one is printed once)
    double last_t = -1.0;
    long callbacks = 0;  // of frame(): the browser's animation frames so far
    bool restored = false;      // the context was restored and "restored" is still said
    double restored_at = -1.0;  // the first frame's time after the restore
    int width = 0, height = 0;
    bool lost = false;
    std::vector<std::uint8_t> pixels;
    std::string text;  // the last string handed to JavaScript
    render::LabVerdict lab_verdict;  // the shader lab's last check (its images: penumbra_lab_image)
};
WebApp* g = nullptr;
constexpr double kRestoredSeconds = 3.0;  // how long the status says the context was restored

// Draws one frame; a failure is shown in the status line and printed once to stderr (the page
// routes stderr to console.error).
bool draw_frame() {
    if (!g || !g->app || !g->app->has_gl() || g->lost || g->width <= 0) return false;
    try {
        g->app->draw(g->width, g->height);
        if (!g->reported.empty()) {
            g->reported.clear();
            g->status = "running";
        }
        return true;
    } catch (const std::exception& e) {
        g->last_error = e.what();
        g->status = std::string("error: ") + e.what();
        if (g->reported != g->last_error) {
            g->reported = g->last_error;
            std::fprintf(stderr, "penumbra: %s\n", e.what());
        }
        return false;
    }
}

bool frame(const platform::FrameInfo& f) {
    // "restored" is said for a few seconds of frames, then the status is "running" again (unless a
    // frame's error has replaced it).
    if (g->restored) {
        if (g->restored_at < 0.0) g->restored_at = f.time_s;
        if (f.time_s - g->restored_at > kRestoredSeconds) {
            if (g->reported.empty()) g->status = "running";
            g->restored = false;
        }
    }
    if (g->last_t >= 0.0) g->app->advance(f.time_s - g->last_t);
    g->last_t = f.time_s;
    g->width = f.width;
    g->height = f.height;
    // The marble (deferred by main()) once the first frame is on screen: in the second callback,
    // not the first one, whose frame the browser shows only when it returns. That frame is the
    // scene lit and unshadowed (CourseApp::draw); the exercise's own frame comes with the marble.
    if (g->callbacks++ > 0) g->app->complete_scene();
    draw_frame();
    return true;
}

void on_context(platform::ContextEvent e) {
    if (e == platform::ContextEvent::Lost) {
        g->lost = true;
        g->restored = false;
        g->app->drop_gl();
        g->status = "WebGL context lost: waiting for the browser to restore it";
        std::printf("penumbra: %s\n", g->status.c_str());
        return;
    }
    // A restored context is empty: errors left from the loss are drained, then the renderer, its
    // shaders, meshes, textures, the shadow map and the FBO are all made again.
    while (gl::take_error() != 0) {
    }
    try {
        g->app->create_gl(*g->platform);
        g->lost = false;
        g->restored = true;
        g->restored_at = -1.0;
        g->status = "WebGL context restored: renderer and GL objects made again (generation " +
                    std::to_string(g->app->gl_generation()) + ")";
    } catch (const std::exception& ex) {
        g->status = std::string("WebGL context restored, but making the GL objects failed: ") + ex.what();
        std::fprintf(stderr, "penumbra: %s\n", g->status.c_str());
    }
    std::printf("penumbra: %s\n", g->status.c_str());
}

const char* hand(std::string s) {
    g->text = std::move(s);
    return g->text.c_str();
}

// A snippets file's problems as JSON: [{"line":N,"message":"..."}, ...].
std::string problems_json(const std::vector<render::SnippetProblem>& problems) {
    std::string j = "[";
    for (std::size_t i = 0; i < problems.size(); ++i)
        j += std::string(i ? "," : "") + "{\"line\":" + std::to_string(problems[i].line) +
             ",\"message\":" + render::json_quote(problems[i].message) + "}";
    return j + "]";
}

}  // namespace

extern "C" {

// Sets one option (URL or control): returns 1, or 0 with penumbra_last_error() saying why.
int penumbra_set_option(const char* name, const char* value) {
    if (!g || !g->app) return 0;
    const std::string err = g->app->set_option(name, value);
    if (!err.empty()) {
        g->last_error = err;
        return 0;
    }
    return 1;
}

// Applies the page's URL query ("?a=b&c=d", examples/query.h: decoded and checked in C++, each pair
// through set_option): returns the notes, one a line ("" when every pair was taken).
const char* penumbra_set_query(const char* query) {
    if (!g || !g->app) return hand("");
    // Refused pairs come back from apply_query; a value taken but changed (a map size off the list)
    // leaves the app's note, said too.
    std::vector<std::string> changed;
    std::string notes;
    for (const auto& n : examples::apply_query(query ? query : "", [&](std::string_view name, std::string_view value) {
             std::string err = g->app->set_option(name, value);
             if (err.empty() && !g->app->note().empty()) changed.push_back(g->app->note());
             return err;
         }))
        notes += (notes.empty() ? "" : "\n") + n;
    for (const auto& n : changed) notes += (notes.empty() ? "" : "\n") + n;
    return hand(notes);
}

const char* penumbra_last_error() { return hand(g ? g->last_error : ""); }
const char* penumbra_query() { return hand(g && g->app ? g->app->query() : ""); }

// Everything the page shows, as JSON.
const char* penumbra_state() {
    if (!g || !g->app) return hand("{}");
    using render::json_bool;
    using render::json_number;
    using render::json_quote;
    const auto& a = *g->app;
    const auto& s = a.settings();
    std::string j = "{";
    j += "\"exercise\":" + json_quote(a.exercise().name);
    j += ",\"title\":" + json_quote(a.exercise().title);
    j += ",\"query\":" + json_quote(a.query());
    j += ",\"options\":{";
    bool first = true;
    for (const auto& [k, v] : a.options()) {
        j += (first ? "" : ",") + json_quote(k) + ":" + json_quote(v);
        first = false;
    }
    j += "}";
    j += ",\"bias\":" + json_number(static_cast<double>(a.bias()));
    j += ",\"sheetBias\":" + json_number(static_cast<double>(a.sheet_bias()));
    // bias=auto's constant part for the chosen encoding and precision (the page's bias control says it).
    j += ",\"autoBias\":" + json_number(static_cast<double>(shadow::auto_bias_constant(s.encoding, s.precision)));
    // A number where the size is fixed, "auto" where the plan matches it to the screen.
    j += ",\"mapSize\":" + (s.map_size == render::Settings::kAutoMapSize ? std::string("\"auto\"") : std::to_string(s.map_size));
    // Heckbert-Herf's light samples in the last frame: how many are in the average, of how many.
    if (const auto& area = a.area())
        j += ",\"area\":{\"done\":" + std::to_string(area->done) + ",\"total\":" + std::to_string(area->total) +
             ",\"added\":" + std::to_string(area->added) + "}";
    else
        j += ",\"area\":null";
    j += ",\"ms\":" + json_number(a.median_ms());
    // budget-ms: what the controller chose and why (null while off or before its first frame).
    if (const render::BudgetController* b = a.budget())
        j += ",\"budget\":{\"mapSize\":" + std::to_string(b->settings().map_size) + ",\"encoding\":" +
             json_quote(std::string(shadow::to_string(b->settings().encoding))) + ",\"filter\":" +
             json_quote(std::string(shadow::to_string(b->settings().filter))) + ",\"why\":" + json_quote(b->why()) +
             ",\"predictedErrorPct\":" + (a.budget_predicted_error() >= 0.0 ? json_number(a.budget_predicted_error()) : "null") + "}";
    else
        j += ",\"budget\":null";
    // max-error: the rung chosen and why, or why none can be (null while off or before the first choice).
    if (const render::ErrorChoice* c = a.error_choice())
        j += ",\"errorTarget\":{\"mapSize\":" + std::to_string(c->settings().map_size) + ",\"predictedErrorPct\":" +
             json_number(c->rung().predicted_pct) + ",\"why\":" + json_quote(c->why) + "}";
    else if (a.max_error() > 0.0 && !a.error_target_refusal().empty())
        j += ",\"errorTarget\":{\"mapSize\":null,\"why\":" + json_quote(a.error_target_refusal()) + "}";
    else
        j += ",\"errorTarget\":null";
    // Each pass's GPU time (EXT_disjoint_timer_query), median of the last frames the timer read
    // back: null where the context has no timer.
    if (a.gpu_timer_available()) {
        const gl::GpuSummary gs = a.gpu_summary();
        j += ",\"gpu\":{\"frames\":" + std::to_string(gs.frames) + ",\"discarded\":" +
             std::to_string(a.gpu_discarded()) + ",\"total\":" + json_number(gs.total_ms) + ",\"passes\":[";
        for (size_t i = 0; i < gs.passes.size(); ++i)
            j += std::string(i ? "," : "") + "{\"name\":" + json_quote(gs.passes[i].name) +
                 ",\"ms\":" + json_number(gs.passes[i].ms) + ",\"frames\":" + std::to_string(gs.passes[i].frames) + "}";
        j += "]}";
    } else {
        j += ",\"gpu\":null";
    }
    j += ",\"frames\":" + std::to_string(a.frames_drawn());
    j += ",\"lightTime\":" + json_number(a.light_time());
    j += ",\"jumpTime\":" + json_number(a.jump_time());
    j += ",\"paused\":" + json_bool(a.paused());
    j += ",\"lost\":" + json_bool(g->lost);
    j += ",\"generation\":" + std::to_string(a.gl_generation());
    const gl::Caps* caps = a.caps();
    j += ",\"depthTexture\":" + json_bool(caps && caps->depth_texture);
    j += ",\"derivatives\":" + json_bool(caps && caps->standard_derivatives);
    j += ",\"maxMapSize\":" + std::to_string(caps ? caps->max_target_size() : 0);
    j += ",\"renderer\":" + json_quote(caps ? caps->renderer : "");
    j += ",\"status\":" + json_quote(g->status);
    // What the last option set changed in its value ("" when it took it as it was).
    j += ",\"note\":" + json_quote(a.note());
    // What the last frame had to change for the canvas (W09P2b's copy larger than it).
    j += ",\"frameNote\":" + json_quote(a.frame_note());
    j += ",\"width\":" + std::to_string(g->width) + ",\"height\":" + std::to_string(g->height);
    // The fly camera of an exercise with a scene of its own (null elsewhere): metres and degrees,
    // whether it moved, and the metres a press moves.
    if (examples::flies(a.exercise())) {
        const auto& c = a.camera();
        j += ",\"camera\":{\"x\":" + json_number(static_cast<double>(c.eye.x)) +
             ",\"y\":" + json_number(static_cast<double>(c.eye.y)) + ",\"z\":" + json_number(static_cast<double>(c.eye.z)) +
             ",\"yaw\":" + json_number(static_cast<double>(c.yaw)) + ",\"pitch\":" + json_number(static_cast<double>(c.pitch)) +
             ",\"moved\":" + json_bool(a.camera_moved()) + ",\"step\":" + json_number(a.fly_step()) + "}";
    } else {
        j += ",\"camera\":null";
    }
    j += "}";
    return hand(j);
}

// The fly camera (the cascades and bulb exercises): metres forward, right and up, then degrees of yaw (right)
// and pitch (up). 1, or 0 where the exercise has no fly camera.
int penumbra_fly(double forward, double right, double up, double yaw, double pitch) {
    return g && g->app && g->app->fly(forward, right, up, yaw, pitch) ? 1 : 0;
}
// Back to the scene's own camera.
void penumbra_reset_camera() {
    if (g && g->app) g->app->reset_camera();
}

// ---- the test hook -----------------------------------------------------------------------------
void penumbra_set_time(double t) {
    if (g && g->app) g->app->set_time(t);
}
void penumbra_pause(int paused) {
    if (g && g->app) g->app->set_paused(paused != 0);
}
long penumbra_frame_count() { return g && g->app ? g->app->frames_drawn() : 0; }
// 1 once the scene is whole (the marble made after the first frame, main()), else 0.
int penumbra_scene_complete() { return g && g->app && g->app->scene_complete() ? 1 : 0; }
// Draws one frame now, outside the animation loop (at the current, e.g. fixed, time). Not timed
// on the GPU: a test draws many such frames in one JavaScript task, and WebGL makes no query's
// result available before the task returns (the ring of pending frames would fill).
int penumbra_render_now(int width, int height) {
    if (!g || !g->app) return 0;
    if (width > 0 && height > 0) {
        g->width = width;
        g->height = height;
    }
    const bool timing = g->app->gpu_timing();
    g->app->set_gpu_timing(false);
    g->app->complete_scene();  // a frame drawn on demand is the whole scene's
    const bool drawn = draw_frame();
    g->app->set_gpu_timing(timing);
    return drawn ? 1 : 0;
}
// The canvas's pixels (RGBA8, top row first, width x height of the last frame); null on failure.
const std::uint8_t* penumbra_read_pixels() {
    if (!g || !g->app || !g->app->has_gl() || g->lost) return nullptr;
    try {
        g->pixels = g->app->read_pixels(g->width, g->height);
    } catch (const std::exception& e) {
        g->last_error = e.what();
        return nullptr;
    }
    return g->pixels.data();
}
int penumbra_width() { return g ? g->width : 0; }
int penumbra_height() { return g ? g->height : 0; }
// The oldest pending GL error (0: none), through Emscripten's glGetError.
unsigned penumbra_gl_error() { return g && !g->lost ? gl::take_error() : 0u; }
const char* penumbra_plan() { return hand(g && g->app ? g->app->last_plan() : ""); }
// The last frame's shadow-map tile lines (CourseApp::tile_lines): the page's #cascade-plan.
const char* penumbra_tile_lines() { return hand(g && g->app ? g->app->tile_lines() : ""); }
// The wasm heap's bytes in use (malloc's allocated blocks; Module.HEAP8.length is the whole heap):
// the soak (tests/web/soak.mjs) watches it for leaks.
unsigned long penumbra_heap_used() { return static_cast<unsigned long>(mallinfo().uordblks); }

// ---- the shader lab (docs/pages.md, docs/snippets.md: web/lab/lab.js) ------------------------------
// Whether the frame's settings fit the lab, and if not why (render::lab_refusal); whether it is on;
// the encoding whose answer it checks against and the constant bias it draws with.
const char* penumbra_lab_state() {
    if (!g || !g->app) return hand("{}");
    using render::json_bool;
    using render::json_quote;
    const render::Settings s = g->app->frame_settings();
    const render::Settings lab = render::lab_settings(s);
    std::string j = "{\"available\":" + json_bool(g->app->lab_available());
    j += ",\"refusal\":" + json_quote(g->app->lab_refusal());
    j += ",\"on\":" + json_bool(g->app->lab());
    j += ",\"encoding\":" + json_quote(shadow::to_string(s.encoding));
    j += ",\"bias\":" + render::json_number(static_cast<double>(lab.effective_bias()));
    j += "}";
    return hand(j);
}
// Frames drawn with the lab's snippets (1) or the renderer's own code (0).
void penumbra_lab_enable(int on) {
    if (g && g->app) g->app->set_lab(on != 0);
}
// The student's text into the renderer's programs: {"ok":true,"problems":[]}, or ok false and the
// problems at the student's lines (the last good snippets stay, so does the frame).
const char* penumbra_lab_set(const char* text) {
    if (!g || !g->app) return hand("{\"ok\":false,\"problems\":[{\"line\":0,\"message\":\"the module is not running\"}]}");
    std::vector<render::SnippetProblem> problems;
    try {
        problems = g->app->set_snippets(text ? text : "");
    } catch (const std::exception& e) {
        problems.push_back({0, e.what()});
    }
    return hand("{\"ok\":" + render::json_bool(problems.empty()) + ",\"problems\":" + problems_json(problems) + "}");
}
// The text the panel offers: 0 the starter skeleton, 1 the sheet's answer for the encoding in use.
const char* penumbra_lab_text(int which) {
    if (which == 1 && g && g->app) return hand(render::sheet_answer(g->app->frame_settings().encoding));
    return hand(render::snippet_skeleton());
}
// The classic mistakes for the encoding in use: [{"name","hint","text"}, ...].
const char* penumbra_lab_mistakes() {
    if (!g || !g->app) return hand("[]");
    std::string j = "[";
    bool first = true;
    for (const auto& m : render::snippet_mistakes(g->app->frame_settings().encoding)) {
        j += std::string(first ? "" : ",") + "{\"name\":" + render::json_quote(m.name) +
             ",\"hint\":" + render::json_quote(m.hint) + ",\"text\":" + render::json_quote(m.text) + "}";
        first = false;
    }
    return hand(j + "]");
}
// The verdict on `text` with the scene at time t (the clocks do not move) at width x height: JSON
// with compiles, problems, width, height, differingPct, mistake, matchPct, verdict (error,
// no-function, matches, mistake, differs), functions, matches and hint; the three visibility
// images (RGBA8, top row first) from penumbra_lab_image.
const char* penumbra_lab_check(const char* text, int width, int height, double t) {
    if (!g || !g->app || !g->app->has_gl() || g->lost) return hand("{\"compiles\":false,\"problems\":[{\"line\":0,\"message\":\"no WebGL context\"}]}");
    auto& a = *g->app;
    try {
        g->lab_verdict = a.lab_check(text ? text : "", width, height, t);
    } catch (const std::exception& e) {
        g->lab_verdict = render::LabVerdict{};
        g->lab_verdict.problems.push_back({0, e.what()});
    }
    const auto& v = g->lab_verdict;
    using render::json_bool;
    using render::json_number;
    using render::json_quote;
    std::string j = "{\"compiles\":" + json_bool(v.compiles) + ",\"problems\":" + problems_json(v.problems);
    j += ",\"width\":" + std::to_string(v.width) + ",\"height\":" + std::to_string(v.height);
    j += ",\"differingPct\":" + json_number(v.differing_pct) + ",\"mistake\":" + json_quote(v.mistake);
    // The share of differing pixels up to which a frame still matches the sheet's answer's (render/lab.h).
    j += ",\"matchPct\":" + json_number(render::kLabMatchPct);
    // The verdict as render::lab_verdict decides it (a file writing none of the functions is no match).
    j += ",\"verdict\":" + json_quote(std::string(render::lab_outcome_name(v.outcome)));
    j += ",\"functions\":" + json_quote(render::snippet_names(v.defines));
    j += ",\"matches\":" + json_bool(v.matches());
    j += ",\"hint\":" + json_quote(v.hint) + "}";
    return hand(j);
}
// The last check's images: 0 the student's visibility, 1 the sheet's answer's, 2 the difference;
// null when it has none (it did not compile).
const std::uint8_t* penumbra_lab_image(int which) {
    if (!g) return nullptr;
    const auto& v = g->lab_verdict;
    const std::vector<std::uint8_t>& img = which == 0 ? v.student : which == 1 ? v.reference : v.difference;
    return img.size() == static_cast<std::size_t>(v.width) * static_cast<std::size_t>(v.height) * 4 && !img.empty()
               ? img.data()
               : nullptr;
}

}  // extern "C"

int main(int argc, char** argv) {
    std::string exercise = "w09p1";
    for (int i = 1; i + 1 < argc; ++i)
        if (std::string(argv[i]) == "--exercise") {
            if (examples::find_exercise(argv[i + 1])) exercise = argv[i + 1];
            else std::fprintf(stderr, "penumbra: unknown exercise '%s'\n", argv[i + 1]);
        }
    g = new WebApp;  // lives as long as the page
    // The marble's noise waits for the first frame: it is most of the course scene's making, and the
    // page shows the table in the marble's white until the second frame (docs/payload.md).
    g->app = std::make_unique<examples::CourseApp>(exercise, true);
    g->app->set_gpu_timing(true);  // the readout's GPU time per pass, where the context has a timer
    g->app->set_keep_plans(true);  // penumbra_tile_lines
    std::string error;
    g->platform = platform::create_web_canvas(platform::CanvasOptions{}, error);
    if (!g->platform) {
        g->status = "error: " + error;
        std::fprintf(stderr, "penumbra: %s\n", error.c_str());
        return 1;
    }
    try {
        g->app->create_gl(*g->platform);
    } catch (const std::exception& e) {
        g->status = std::string("error: ") + e.what();
        std::fprintf(stderr, "penumbra: %s\n", e.what());
        return 1;
    }
    g->status = "running";
    g->platform->on_context(on_context);
    g->platform->run(frame);  // returns at once; the browser calls frame() from now on
    return 0;
}
