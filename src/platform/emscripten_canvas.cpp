// A WebGL 1 context on a canvas (Emscripten). The browser owns the loop: run() registers the frame
// callback with requestAnimationFrame and returns. Context loss (WEBGL_lose_context, a GPU reset)
// stops the frames until the browser restores the context; both are reported to the app, which
// must make every GL object again on the restored (empty) context.
#include <emscripten.h>
#include <emscripten/html5.h>

#include <cstring>
#include <string>

#define GL_GLEXT_PROTOTYPES 1  // the extensions' entry points, which Emscripten links (proc_address)
#include <GLES2/gl2.h>
#include <GLES2/gl2ext.h>

#include "platform/platform.h"

// EXT_disjoint_timer_query's object, where Emscripten's query functions look for it (see
// WebCanvas::enable_timer_query), on the current context.
// clang-format off
EM_JS(void, penumbra_fetch_timer_query, (), {
    if (typeof GLctx !== 'undefined' && GLctx)
        GLctx.disjointTimerQueryExt = GLctx.getExtension('EXT_disjoint_timer_query') || null;
})
// Whether the canvas fetched that object for Emscripten's query functions.
EM_JS(int, penumbra_timer_query_fetched, (), {
    return (typeof GLctx !== 'undefined' && GLctx && GLctx.disjointTimerQueryExt) ? 1 : 0;
})
// clang-format on

namespace penumbra::platform {

namespace {

// WebGL extensions are off until asked for; the library uses these where the browser has them.
// After a restore they are off again and are asked for again.
// The half-float ones give the post passes' targets (plan/post.h) where all three are there;
// WEBGL_draw_buffers the deferred G-buffer's three attachments in one pass (plan/frames/deferred.h);
// OES_standard_derivatives the light's horizon from each triangle's own normal (lit.frag).
// EXT_disjoint_timer_query is enabled apart (enable_timer_query): Emscripten needs its object.
constexpr const char* kExtensions[] = {"WEBGL_depth_texture", "OES_element_index_uint", "OES_texture_half_float",
                                       "OES_texture_half_float_linear", "EXT_color_buffer_half_float",
                                       "WEBGL_draw_buffers", "OES_standard_derivatives"};

class WebCanvas final : public Platform {
public:
    ~WebCanvas() override {
        emscripten_cancel_main_loop();
        if (context_ > 0) emscripten_webgl_destroy_context(context_);
    }

    bool init(const CanvasOptions& o, std::string& error) {
        selector_ = o.selector;
        EmscriptenWebGLContextAttributes a;
        emscripten_webgl_init_context_attributes(&a);
        a.majorVersion = 1;
        a.minorVersion = 0;
        a.alpha = EM_FALSE;
        a.depth = EM_TRUE;
        a.stencil = EM_TRUE;     // planar shadows (W09P1) count in the stencil buffer
        a.antialias = EM_FALSE;  // the same pixels as the headless and desktop builds
        a.premultipliedAlpha = EM_TRUE;
        a.preserveDrawingBuffer = o.preserve_drawing_buffer ? EM_TRUE : EM_FALSE;
        a.enableExtensionsByDefault = EM_FALSE;
        context_ = emscripten_webgl_create_context(selector_.c_str(), &a);
        if (context_ <= 0) {
            error = "WebGL 1: no context on " + selector_ + " (emscripten_webgl_create_context returned " +
                    std::to_string(context_) + ")";
            return false;
        }
        if (emscripten_webgl_make_context_current(context_) != EMSCRIPTEN_RESULT_SUCCESS) {
            error = "WebGL 1: emscripten_webgl_make_context_current failed";
            return false;
        }
        enable_extensions();
        emscripten_set_webglcontextlost_callback(selector_.c_str(), this, EM_FALSE, &WebCanvas::lost);
        emscripten_set_webglcontextrestored_callback(selector_.c_str(), this, EM_FALSE, &WebCanvas::restored);
        start_ms_ = emscripten_get_now();
        return true;
    }

    std::string description() const override { return "WebGL 1 canvas " + selector_ + " (Emscripten)"; }
    Api api() const override { return Api::WebGL1; }
    // Emscripten (3.1.6) links the extensions' entry points and routes them to the extension's
    // object: the timer's to GLctx.disjointTimerQueryExt, which its library fetches only for a
    // context made with every extension enabled; this canvas enables them one by one and fetches
    // that object itself (enable_timer_query). Without it glGenQueriesEXT would throw: no timer.
    Proc proc_address(const char* name) const override {
        struct Entry {
            const char* name;
            Proc proc;
            bool timer;
        };
        static const Entry entries[] = {
            {"glDrawBuffersEXT", reinterpret_cast<Proc>(&glDrawBuffersEXT), false},
            {"glGenQueriesEXT", reinterpret_cast<Proc>(&glGenQueriesEXT), true},
            {"glDeleteQueriesEXT", reinterpret_cast<Proc>(&glDeleteQueriesEXT), true},
            {"glBeginQueryEXT", reinterpret_cast<Proc>(&glBeginQueryEXT), true},
            {"glEndQueryEXT", reinterpret_cast<Proc>(&glEndQueryEXT), true},
            {"glGetQueryivEXT", reinterpret_cast<Proc>(&glGetQueryivEXT), true},
            {"glGetQueryObjectuivEXT", reinterpret_cast<Proc>(&glGetQueryObjectuivEXT), true},
            {"glGetQueryObjectui64vEXT", reinterpret_cast<Proc>(&glGetQueryObjectui64vEXT), true}};
        for (const Entry& e : entries)
            if (std::strcmp(e.name, name) == 0) return e.timer && penumbra_timer_query_fetched() == 0 ? nullptr : e.proc;
        return nullptr;
    }
    bool has_default_framebuffer() const override { return true; }

    void run(const FrameCallback& frame) override {
        frame_ = frame;
        // 0 fps: requestAnimationFrame; false: main() returns (the runtime stays alive).
        emscripten_set_main_loop_arg(&WebCanvas::tick, this, 0, EM_FALSE);
    }

    void on_context(ContextCallback callback) override { context_cb_ = std::move(callback); }

    bool set_size(int width, int height) override {
        if (width <= 0 || height <= 0) return false;
        return emscripten_set_canvas_element_size(selector_.c_str(), width, height) == EMSCRIPTEN_RESULT_SUCCESS;
    }

private:
    void enable_extensions() {
        for (const char* e : kExtensions) emscripten_webgl_enable_extension(context_, e);
        enable_timer_query();
    }

    // EXT_disjoint_timer_query (gl/timer.h: each pass's GPU time). Emscripten 3.1.6 routes
    // glGenQueriesEXT, glBeginQueryEXT and the others to GLctx.disjointTimerQueryExt, which its
    // library sets only for a context made with every extension enabled: the canvas sets it here
    // (null where the browser has no such extension; probe_caps then says no timer). After a restore
    // the old extension object is dead, and the new one is fetched again.
    static void enable_timer_query() { penumbra_fetch_timer_query(); }

    static void tick(void* user) {
        auto* self = static_cast<WebCanvas*>(user);
        if (self->lost_ || emscripten_is_webgl_context_lost(self->context_)) return;  // wait for the restore
        int w = 0, h = 0;
        emscripten_get_canvas_element_size(self->selector_.c_str(), &w, &h);
        const FrameInfo info{(emscripten_get_now() - self->start_ms_) / 1000.0, w, h, self->frame_index_++};
        if (!self->frame_(info)) emscripten_cancel_main_loop();
    }

    static EM_BOOL lost(int, const void*, void* user) {
        auto* self = static_cast<WebCanvas*>(user);
        self->lost_ = true;
        if (self->context_cb_) self->context_cb_(ContextEvent::Lost);
        return EM_TRUE;  // preventDefault: tells the browser the page can restore the context
    }

    static EM_BOOL restored(int, const void*, void* user) {
        auto* self = static_cast<WebCanvas*>(user);
        emscripten_webgl_make_context_current(self->context_);
        self->enable_extensions();
        self->lost_ = false;
        if (self->context_cb_) self->context_cb_(ContextEvent::Restored);
        return EM_TRUE;
    }

    std::string selector_;
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_ = 0;
    FrameCallback frame_;
    ContextCallback context_cb_;
    double start_ms_ = 0.0;
    long frame_index_ = 0;
    bool lost_ = false;
};

}  // namespace

std::unique_ptr<Platform> create_web_canvas(const CanvasOptions& options, std::string& error) {
    auto p = std::make_unique<WebCanvas>();
    if (!p->init(options, error)) return nullptr;
    return p;
}

}  // namespace penumbra::platform
