#include "gl/check.h"

#include <cstdio>

#include "gl/gl_headers.h"

namespace penumbra::gl {

std::string enum_name(unsigned int value) {
    switch (value) {
        case GL_NO_ERROR: return "GL_NO_ERROR";
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS: return "GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS";
        case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
        case 0x9242: return "CONTEXT_LOST_WEBGL";
        default: break;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%04X", value);
    return buf;
}

void check_errors(const char* where, const char* file, int line) {
    std::string names;
    for (int guard = 0; guard < 16; ++guard) {
        const GLenum e = glGetError();
        if (e == GL_NO_ERROR) break;
        if (!names.empty()) names += ", ";
        names += enum_name(e);
    }
    if (names.empty()) return;
    std::string msg = names + " after " + where;
    if (file) msg += " (" + std::string(file) + ":" + std::to_string(line) + ")";
    throw Error(msg);
}

unsigned int take_error() { return glGetError(); }

}  // namespace penumbra::gl
