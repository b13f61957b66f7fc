// The only layer that knows where it runs. Everything above sees a current GLES2 context and a
// frame callback. Headless EGL (surfaceless Mesa) is here now; a GLFW window and an Emscripten
// canvas implement the same interface: a browser cannot block in a loop, so the platform owns
// the loop and calls back once per frame.
#pragma once

#include <functional>
#include <memory>
#include <string>

namespace penumbra::platform {

struct FrameInfo {
    double time_s = 0.0;   // seconds since the loop started (the tool passes its own t instead)
    int width = 0;         // drawable size in pixels; 0 for headless (draw into your own FBO)
    int height = 0;
    long frame_index = 0;
};

// Return false to stop the loop.
using FrameCallback = std::function<bool(const FrameInfo&)>;

class Platform {
public:
    virtual ~Platform() = default;
    // One line: API, version, renderer.
    virtual std::string description() const = 0;
    // True for a window or a canvas: draw to framebuffer 0 and it is shown. False headless.
    virtual bool has_default_framebuffer() const = 0;
    // Runs frames until the callback returns false (a browser returns at once and keeps calling).
    virtual void run(const FrameCallback& frame) = 0;
};

// A GLES 2 context on EGL's surfaceless platform (no X server, no GPU needed), made current on
// this thread. Returns null and sets `error` to one line naming the failing EGL call when it fails.
std::unique_ptr<Platform> create_headless(std::string& error);

}  // namespace penumbra::platform
