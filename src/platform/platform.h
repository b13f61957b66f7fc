// The only layer that knows where it runs. Everything above sees a current GLES2 context and a
// frame callback. Headless EGL (surfaceless Mesa) is here now; a GLFW window and an Emscripten
// canvas implement the same interface: a browser cannot block in a loop, so the platform owns
// the loop and calls back once per frame.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace penumbra::platform {

struct FrameInfo {
    double time_s = 0.0;   // seconds since the loop started (the tool passes its own t instead)
    int width = 0;         // drawable size in pixels; 0 for headless (draw into your own FBO)
    int height = 0;
    long frame_index = 0;
};

// Return false to stop the loop.
using FrameCallback = std::function<bool(const FrameInfo&)>;

// A key press: printable keys as their US-layout ASCII character (letters upper case, digits,
// '[', ']', '-', '=', ...), the others as the Key values below.
struct KeyEvent {
    int key = 0;
    bool shift = false;
};
namespace keys {
inline constexpr int Escape = 256;
inline constexpr int Left = 257;
inline constexpr int Right = 258;
inline constexpr int Up = 259;
inline constexpr int Down = 260;
inline constexpr int Tab = 261;
inline constexpr int F1 = 262;
}  // namespace keys
using KeyCallback = std::function<void(const KeyEvent&)>;

enum class ContextEvent { Lost, Restored };

// The API of the context a platform makes: GLES 2 (EGL: headless, GLFW) or WebGL 1 (a canvas).
enum class Api { GLES2, WebGL1 };
using ContextCallback = std::function<void(ContextEvent)>;

class Platform {
public:
    virtual ~Platform() = default;
    // One line: API, version, renderer.
    virtual std::string description() const = 0;
    // More lines naming the implementation, for `penumbra caps` (headless EGL: its vendor, version,
    // client APIs and the display's device); empty where there is nothing more.
    virtual std::string details() const { return {}; }
    // Which API the context speaks (the gl layer's capability probe needs it).
    virtual Api api() const = 0;
    // An extension's entry point in this context ("glDrawBuffersEXT"), or null: the gl layer looks
    // them up here when it probes the context (EGL's or GLFW's lookup; Emscripten links them).
    using Proc = void (*)();
    virtual Proc proc_address(const char* name) const {
        (void)name;
        return nullptr;
    }
    // True for a window or a canvas: draw to framebuffer 0 and it is shown. False headless.
    virtual bool has_default_framebuffer() const = 0;
    // Runs frames until the callback returns false (a browser returns at once and keeps calling).
    virtual void run(const FrameCallback& frame) = 0;

    // ---- windows and canvases: input, size and the context's life (headless: none of it) ----
    // Called for each key pressed (not for repeats).
    virtual void on_key(KeyCallback callback) { (void)callback; }
    // Called when the context is lost and again when it is restored (WebGL). Between the two,
    // no frame is run; on Restored the context is current again, empty: every GL object made
    // before the loss is gone and must be made again.
    virtual void on_context(ContextCallback callback) { (void)callback; }
    // Asks for a drawable of this size (a window is resized, a canvas gets new width/height);
    // later frames report the size really obtained. False where the size cannot be set.
    virtual bool set_size(int width, int height) {
        (void)width;
        (void)height;
        return false;
    }
    // Sets the window's title (no-op elsewhere).
    virtual void set_title(const std::string& title) { (void)title; }
};

// A GLES 2 context on EGL's surfaceless platform (no X server, no GPU needed), made current on
// this thread; or, when an EGL device is chosen (below), on that device through
// EGL_PLATFORM_DEVICE_EXT. Returns null and sets `error` to one line naming the failing EGL call
// (or the bad choice) when it fails.
std::unique_ptr<Platform> create_headless(std::string& error);

// The EGL devices (EGL_EXT_device_enumeration) in eglQueryDevicesEXT's order, each with a name
// (its DRM node, renderer, CUDA index or "software" where EGL says); `error` is set, and the list
// empty, where EGL cannot enumerate them.
struct EglDevice {
    int index = 0;
    std::string name;
};
std::vector<EglDevice> egl_devices(std::string& error);
// Chooses the device create_headless uses from now on: `value` is an index into egl_devices(),
// given by `source` ("--egl-device", "PENUMBRA_EGL_DEVICE"; named in the message). Returns "" or
// one line naming the problem (not an index, or out of range: how many devices there are); the
// default is kept then. Until it is called, create_headless reads PENUMBRA_EGL_DEVICE (when set
// and not empty) the first time; unset, the default: the surfaceless Mesa platform.
std::string choose_egl_device(const std::string& value, const std::string& source);
// The index in use, or -1 for the default.
int chosen_egl_device();

// A desktop window (GLFW) with a GLES 2 context made through EGL, a depth and a stencil buffer,
// made current on this thread; run() polls events, calls back and swaps until the callback
// returns false or the window is closed. Native builds only (src/platform/glfw_window.cpp).
struct WindowOptions {
    int width = 512;
    int height = 512;
    std::string title = "penumbra";
    int swap_interval = 1;  // 1: wait for vsync; 0: as fast as it goes
};
std::unique_ptr<Platform> create_glfw_window(const WindowOptions& options, std::string& error);

// A WebGL 1 context on a canvas (Emscripten), with depth and stencil, no antialiasing, made
// current; run() hands the frame callback to the browser's requestAnimationFrame loop and returns
// at once (what the callback uses must outlive main). Context loss and restore are reported
// through on_context. Browser builds only (src/platform/emscripten_canvas.cpp).
struct CanvasOptions {
    std::string selector = "#canvas";
    // Keep the drawing buffer after it is shown, so a test can read back the last frame at any time.
    bool preserve_drawing_buffer = true;
};
std::unique_ptr<Platform> create_web_canvas(const CanvasOptions& options, std::string& error);

}  // namespace penumbra::platform
