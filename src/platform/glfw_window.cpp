// A desktop window through GLFW with a GLES 2 context created by EGL (GLFW_EGL_CONTEXT_API), the
// same API the headless and the browser builds use. Under Xvfb (no GPU) Mesa renders on llvmpipe.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <string>

#include "platform/platform.h"

namespace penumbra::platform {

namespace {

std::string g_glfw_error;  // the last GLFW error, for the one-line failure message

void on_glfw_error(int code, const char* description) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%05X", static_cast<unsigned>(code));
    g_glfw_error = std::string(description ? description : "?") + " (" + buf + ")";
}

int translate_key(int key) {
    switch (key) {
        case GLFW_KEY_ESCAPE: return keys::Escape;
        case GLFW_KEY_LEFT: return keys::Left;
        case GLFW_KEY_RIGHT: return keys::Right;
        case GLFW_KEY_UP: return keys::Up;
        case GLFW_KEY_DOWN: return keys::Down;
        case GLFW_KEY_TAB: return keys::Tab;
        case GLFW_KEY_F1: return keys::F1;
        default: break;
    }
    // GLFW's printable keys are their US-layout ASCII codes (letters upper case).
    if (key >= GLFW_KEY_SPACE && key <= GLFW_KEY_GRAVE_ACCENT) return key;
    return 0;
}

class GlfwWindow final : public Platform {
public:
    ~GlfwWindow() override {
        if (window_) glfwDestroyWindow(window_);
        if (initialised_) glfwTerminate();
    }

    bool init(const WindowOptions& o, std::string& error) {
        glfwSetErrorCallback(on_glfw_error);
        if (!glfwInit()) return fail(error, "glfwInit");
        initialised_ = true;
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
        glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
        glfwWindowHint(GLFW_RED_BITS, 8);
        glfwWindowHint(GLFW_GREEN_BITS, 8);
        glfwWindowHint(GLFW_BLUE_BITS, 8);
        glfwWindowHint(GLFW_DEPTH_BITS, 24);
        glfwWindowHint(GLFW_STENCIL_BITS, 8);  // planar shadows (W09P1) count in the stencil buffer
        glfwWindowHint(GLFW_SAMPLES, 0);       // the same pixels as the headless and browser builds
        glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
        window_ = glfwCreateWindow(o.width, o.height, o.title.c_str(), nullptr, nullptr);
        if (!window_) return fail(error, "glfwCreateWindow (GLES 2 through EGL)");
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(o.swap_interval);
        glfwSetWindowUserPointer(window_, this);
        glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
            auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w));
            if (action != GLFW_PRESS || !self->key_) return;
            const int k = translate_key(key);
            if (k) self->key_(KeyEvent{k, (mods & GLFW_MOD_SHIFT) != 0});
        });
        description_ = "GLFW " + std::string(glfwGetVersionString()) + " window, GLES 2 through EGL";
        return true;
    }

    std::string description() const override { return description_; }
    Api api() const override { return Api::GLES2; }
    Proc proc_address(const char* name) const override { return glfwGetProcAddress(name); }
    bool has_default_framebuffer() const override { return true; }

    void run(const FrameCallback& frame) override {
        const double start = glfwGetTime();
        for (long i = 0; !glfwWindowShouldClose(window_);) {
            glfwPollEvents();
            int w = 0, h = 0;
            glfwGetFramebufferSize(window_, &w, &h);
            if (w <= 0 || h <= 0) {  // minimised: nothing to draw into
                glfwWaitEventsTimeout(0.1);
                continue;
            }
            if (!frame(FrameInfo{glfwGetTime() - start, w, h, i++})) break;
            glfwSwapBuffers(window_);
        }
    }

    void on_key(KeyCallback callback) override { key_ = std::move(callback); }

    bool set_size(int width, int height) override {
        if (width <= 0 || height <= 0) return false;
        glfwSetWindowSize(window_, width, height);
        // Let the window system answer before the next frame asks for the size.
        for (int i = 0; i < 50; ++i) {
            glfwPollEvents();
            int w = 0, h = 0;
            glfwGetFramebufferSize(window_, &w, &h);
            if (w == width && h == height) break;
            glfwWaitEventsTimeout(0.01);
        }
        return true;
    }

    void set_title(const std::string& title) override { glfwSetWindowTitle(window_, title.c_str()); }

private:
    bool fail(std::string& error, const char* what) {
        error = std::string("GLFW window: ") + what + " failed" + (g_glfw_error.empty() ? "" : ": " + g_glfw_error);
        return false;
    }

    bool initialised_ = false;
    GLFWwindow* window_ = nullptr;
    KeyCallback key_;
    std::string description_;
};

}  // namespace

std::unique_ptr<Platform> create_glfw_window(const WindowOptions& options, std::string& error) {
    auto p = std::make_unique<GlfwWindow>();
    if (!p->init(options, error)) return nullptr;
    return p;
}

}  // namespace penumbra::platform
