// GL error reporting: errors name the GL call (or the pass) and the source line.
// Per-call checks are compiled in for Debug builds (or PENUMBRA_GL_CHECKS=1); the renderer also
// calls check_errors() after every pass in every build, which costs one glGetError per pass.
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
