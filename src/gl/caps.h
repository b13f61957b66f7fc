// What the current context can do, probed once after it is made current: extensions, shader
// precision formats, size limits. Fallbacks are chosen from this, never by trial and error.
#pragma once

#include <algorithm>
#include <array>
#include <set>
#include <string>

#include "gl/state.h"
#include "platform/platform.h"

namespace penumbra::gl {

// glGetShaderPrecisionFormat: range as log2 of the magnitude, precision in bits.
struct PrecisionFormat {
    int range_min = 0;
    int range_max = 0;
    int precision = 0;
};

// Which API the context speaks, as the platform layer reports it (Platform::api()): WebGL 1
// differs from GLES 2 in a few places (DEPTH_STENCIL renderbuffers and their attachment point are
// core in WebGL 1).
using Api = platform::Api;

struct Caps {
    Api api = Api::GLES2;
    std::string vendor, renderer, version, glsl_version;
    std::set<std::string> extensions;

    bool depth_texture = false;         // OES_depth_texture / WEBGL_depth_texture
    bool packed_depth_stencil = false;  // OES_packed_depth_stencil (DEPTH24_STENCIL8); WebGL 1: DEPTH_STENCIL
    bool depth24 = false;               // OES_depth24 renderbuffers
    bool element_index_uint = false;    // OES_element_index_uint
    bool fragment_highp = false;        // highp float in fragment shaders (optional in ES 2.0)
    // Multipass: half-float colour targets (OES_texture_half_float to sample them,
    // OES_texture_half_float_linear to filter them, EXT_color_buffer_half_float to render into
    // them; all three, or the post passes stay RGBA8),
    // several colour attachments (EXT_draw_buffers / WEBGL_draw_buffers), rendering into a
    // texture's mip levels other than 0 (OES_fbo_render_mipmap; WebGL 1 cannot).
    bool half_float_target = false;
    bool draw_buffers = false;
    bool render_mipmap = false;
    // dFdx, dFdy in fragment shaders (OES_standard_derivatives): the light's horizon from each
    // triangle's own normal (plan/variants.h, LitFeatures::derivatives).
    bool standard_derivatives = false;
    // GPU time per pass (gl/timer.h): EXT_disjoint_timer_query with its entry points and a
    // TIME_ELAPSED counter of timer_bits > 0 bits (a context may report 0: no timer). Web: not
    // yet (gl/caps.cpp says why).
    bool timer_query = false;
    int timer_bits = 0;
    // How the context turns float colours into unorm8: the bytes it stored for 0.6/255,
    // 128.6/255 and 254.6/255 (1, 129, 255 when it rounds; 0, 128, 254 when it truncates;
    // GLES 3.0 2.1.6.2 allows either of the two closest), found by the renderer's probe
    // (Renderer::unorm_report), not by probe_caps; -1 until it runs. Informative only: the
    // packing shaders write bytes that any of these stores keeps (pack.glsl's UNORM_OFFSET).
    std::array<int, 3> unorm_probe{-1, -1, -1};
    bool unorm_rounds() const { return unorm_probe == std::array<int, 3>{1, 129, 255}; }
    bool unorm_floors() const { return unorm_probe == std::array<int, 3>{0, 128, 254}; }

    // The stencil bits a frame's uses share (render::StencilUse): the packed depth-stencil
    // renderbuffer's 8 (DEPTH24_STENCIL8, WebGL's DEPTH_STENCIL), which the desktop's window asks
    // for too (GLFW_STENCIL_BITS 8). Tests set fewer to see a plan refused.
    int stencil_bits = 8;

    int max_texture_size = 0;
    int max_cube_map_size = 0;  // GL_MAX_CUBE_MAP_TEXTURE_SIZE (0: not queried)
    int max_renderbuffer_size = 0;
    int max_viewport_width = 0;
    int max_viewport_height = 0;

    PrecisionFormat vertex_highp_float, fragment_highp_float, fragment_mediump_float, fragment_lowp_float;

    bool has(const std::string& extension) const { return extensions.count(extension) > 0; }
    // The largest square render target this context can hold (texture and renderbuffer).
    int max_target_size() const {
        return std::min({max_texture_size, max_renderbuffer_size, max_viewport_width, max_viewport_height});
    }
    // The depth renderbuffer of a render target: 24 bits where the context has them.
    RenderbufferFormat depth_format() const {
        return depth24 ? RenderbufferFormat::Depth24 : RenderbufferFormat::Depth16;
    }
    // A packed depth + stencil renderbuffer, in this API's spelling.
    RenderbufferFormat depth_stencil_format() const {
        return api == Api::WebGL1 ? RenderbufferFormat::DepthStencil : RenderbufferFormat::Depth24Stencil8;
    }
    // A few lines for --verbose and logs.
    std::string summary() const;
};

// Probe the context that is current on this thread, which `context` made (its API, and where its
// extension entry points are: gl/entry_points.h).
Caps probe_caps(const platform::Platform& context);

}  // namespace penumbra::gl
