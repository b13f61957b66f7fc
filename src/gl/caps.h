// What the current context can do, probed once after it is made current: extensions, shader
// precision formats, size limits. Fallbacks are chosen from this, never by trial and error.
#pragma once

#include <set>
#include <string>

namespace penumbra::gl {

// glGetShaderPrecisionFormat: range as log2 of the magnitude, precision in bits.
struct PrecisionFormat {
    int range_min = 0;
    int range_max = 0;
    int precision = 0;
};

struct Caps {
    std::string vendor, renderer, version, glsl_version;
    std::set<std::string> extensions;

    bool depth_texture = false;         // OES_depth_texture / WEBGL_depth_texture
    bool packed_depth_stencil = false;  // OES_packed_depth_stencil (DEPTH24_STENCIL8); WebGL 1: DEPTH_STENCIL
    bool depth24 = false;               // OES_depth24 renderbuffers
    bool element_index_uint = false;    // OES_element_index_uint
    bool fragment_highp = false;        // highp float in fragment shaders (optional in ES 2.0)

    int max_texture_size = 0;
    int max_renderbuffer_size = 0;
    int max_viewport_width = 0;
    int max_viewport_height = 0;

    PrecisionFormat vertex_highp_float, fragment_highp_float, fragment_mediump_float, fragment_lowp_float;

    bool has(const std::string& extension) const { return extensions.count(extension) > 0; }
    // The largest square render target this context can hold (texture and renderbuffer).
    int max_target_size() const;
    // A few lines for --verbose and logs.
    std::string summary() const;
};

// Probe the context that is current on this thread.
Caps probe_caps();

}  // namespace penumbra::gl
