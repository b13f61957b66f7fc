// GL error reporting: errors name the GL call (or the pass) and the source line.
// Per-call checks are compiled in for Debug builds (or PENUMBRA_GL_CHECKS=1); the renderer also
// calls check_errors() in every build: after every pass natively (one glGetError per pass), once
// after the frame's last pass in the browser (kErrorQueryWaits). An error stays queued until a
// glGetError reads it, so a later check still catches it; it only names a wider span.
#pragma once

#include <stdexcept>
#include <string>

namespace penumbra::gl {

// Thrown for every GL failure the library detects: compile/link errors, incomplete framebuffers,
// glGetError after a call or a pass, unsupported features.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The name of a GL enum (GL_INVALID_OPERATION, GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT, ...),
// or its hex value when unknown.
std::string enum_name(unsigned int value);

// Throws Error("GL_INVALID_ENUM after <where> (file:line)") if glGetError reports anything;
// drains every pending error.
void check_errors(const char* where, const char* file = nullptr, int line = 0);

// The oldest pending glGetError value (0: none), taken off the queue without throwing; for the
// pages' test hook and for draining what a lost context left behind.
unsigned int take_error();

// Whether a glGetError waits for every command issued before it. In the browser it does: WebGL's
// getError is a synchronous call to the GPU process, which answers once it has run what came
// before (each one a stall in the frame: the pages made 9 or 10 a frame). Natively it reads the
// driver's error flag.
#ifdef __EMSCRIPTEN__
inline constexpr bool kErrorQueryWaits = true;
#else
inline constexpr bool kErrorQueryWaits = false;
#endif

// After making or filling a GL object (a buffer, a texture, a render target), or setting the
// device's whole state (gl::Device::invalidate, when a context is new): natively a
// check_errors() now; in the browser nothing, and the frame's one check names any error with a
// wider span. There each check would wait for the GPU process to run what came before, and a page
// makes its scene's buffers and textures one after the other while it starts: the main thread
// would wait for every upload instead of going on to the first frame (docs/payload.md).
inline void check_made(const char* what, const char* file = nullptr, int line = 0) {
    if constexpr (!kErrorQueryWaits) check_errors(what, file, line);
    else (void)what, (void)file, (void)line;
}

// Checked builds (Debug, or PENUMBRA_GL_CHECKS=1): a glGetError after every GL call (PENUMBRA_GL)
// and state change, and uniforms the program does not declare refused.
#if defined(PENUMBRA_GL_CHECKS) || !defined(NDEBUG)
inline constexpr bool kCheckEachCall = true;
#else
inline constexpr bool kCheckEachCall = false;
#endif

}  // namespace penumbra::gl

#if defined(PENUMBRA_GL_CHECKS) || !defined(NDEBUG)
#define PENUMBRA_GL(call)                                              \
    do {                                                               \
        call;                                                          \
        ::penumbra::gl::check_errors(#call, __FILE__, __LINE__);       \
    } while (0)
#else
#define PENUMBRA_GL(call) call
#endif
