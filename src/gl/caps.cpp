#include "gl/caps.h"

#include <algorithm>
#include <sstream>
#include <type_traits>

#include "gl/check.h"
#include "gl/entry_points.h"
#include "gl/gl_headers.h"


namespace penumbra::gl {

namespace {

std::string get_string(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

int get_int(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

PrecisionFormat precision(GLenum shader, GLenum type) {
    GLint range[2] = {0, 0};
    GLint bits = 0;
    glGetShaderPrecisionFormat(shader, type, range, &bits);
    return {range[0], range[1], bits};
}

// EXT_disjoint_timer_query's entry points (every one, or the timer is off) and the bits of its
// TIME_ELAPSED counter.
void probe_timer(Caps& c, const platform::Platform& context, bool listed) {
    EntryPoints& e = entry_points();
    const auto load = [&](auto& fn, const char* name) {
        fn = listed ? reinterpret_cast<std::remove_reference_t<decltype(fn)>>(context.proc_address(name)) : nullptr;
        return fn != nullptr;
    };
    bool all = load(e.gen_queries, "glGenQueriesEXT");
    all = load(e.delete_queries, "glDeleteQueriesEXT") && all;
    all = load(e.begin_query, "glBeginQueryEXT") && all;
    all = load(e.end_query, "glEndQueryEXT") && all;
    all = load(e.get_query_iv, "glGetQueryivEXT") && all;
    all = load(e.get_query_object_uiv, "glGetQueryObjectuivEXT") && all;
    all = load(e.get_query_object_ui64v, "glGetQueryObjectui64vEXT") && all;
    listed = listed && all;
    c.timer_bits = 0;
    if (listed) {
        GLint bits = 0;
        e.get_query_iv(GL_TIME_ELAPSED_EXT, GL_QUERY_COUNTER_BITS_EXT, &bits);
        c.timer_bits = bits;
    }
    c.timer_query = listed && c.timer_bits > 0;
}

}  // namespace

EntryPoints& entry_points() {
    static EntryPoints e;
    return e;
}

Caps probe_caps(const platform::Platform& context) {
    Caps c;
    const Api api = c.api = context.api();
    c.vendor = get_string(GL_VENDOR);
    c.renderer = get_string(GL_RENDERER);
    c.version = get_string(GL_VERSION);
    c.glsl_version = get_string(GL_SHADING_LANGUAGE_VERSION);
    const std::string ext = get_string(GL_EXTENSIONS);
    for (size_t at = 0; at < ext.size();) {
        const size_t end = std::min(ext.find(' ', at), ext.size());
        if (end > at) c.extensions.insert(ext.substr(at, end - at));
        at = end + 1;
    }

    c.depth_texture = c.has("GL_OES_depth_texture") || c.has("GL_WEBGL_depth_texture") ||
                      c.has("WEBGL_depth_texture");
    // WebGL 1 has DEPTH_STENCIL renderbuffers and the DEPTH_STENCIL_ATTACHMENT point in core.
    c.packed_depth_stencil = api == Api::WebGL1 || c.has("GL_OES_packed_depth_stencil");
    c.depth24 = c.has("GL_OES_depth24");
    c.element_index_uint = c.has("GL_OES_element_index_uint") || c.has("OES_element_index_uint");
    const auto either = [&](const char* name) { return c.has(std::string("GL_") + name) || c.has(name); };
    c.half_float_target = either("OES_texture_half_float") && either("OES_texture_half_float_linear") &&
                          either("EXT_color_buffer_half_float");
    c.draw_buffers = either("EXT_draw_buffers") || either("WEBGL_draw_buffers");
    entry_points().draw_buffers =
        c.draw_buffers ? reinterpret_cast<PFNGLDRAWBUFFERSEXTPROC>(context.proc_address("glDrawBuffersEXT")) : nullptr;
    c.draw_buffers = entry_points().draw_buffers != nullptr;
    c.render_mipmap = c.has("GL_OES_fbo_render_mipmap");
    c.standard_derivatives = either("OES_standard_derivatives");
    probe_timer(c, context, either("EXT_disjoint_timer_query"));

    c.max_texture_size = get_int(GL_MAX_TEXTURE_SIZE);
    c.max_cube_map_size = get_int(GL_MAX_CUBE_MAP_TEXTURE_SIZE);
    c.max_renderbuffer_size = get_int(GL_MAX_RENDERBUFFER_SIZE);
    GLint dims[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
    c.max_viewport_width = dims[0];
    c.max_viewport_height = dims[1];

    c.vertex_highp_float = precision(GL_VERTEX_SHADER, GL_HIGH_FLOAT);
    c.fragment_highp_float = precision(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT);
    c.fragment_mediump_float = precision(GL_FRAGMENT_SHADER, GL_MEDIUM_FLOAT);
    c.fragment_lowp_float = precision(GL_FRAGMENT_SHADER, GL_LOW_FLOAT);
    c.fragment_highp = c.fragment_highp_float.precision > 0;
    check_errors("probe_caps", __FILE__, __LINE__);
    return c;
}

std::string Caps::summary() const {
    std::ostringstream s;
    s << (api == Api::WebGL1 ? "WebGL 1: " : "GLES 2: ") << version << " (" << renderer << ", " << vendor << ")\n"
      << "GLSL: " << glsl_version << "\n"
      << "max texture " << max_texture_size << ", renderbuffer " << max_renderbuffer_size << ", viewport "
      << max_viewport_width << "x" << max_viewport_height << "\n"
      << "fragment float precision bits: highp " << fragment_highp_float.precision << ", mediump "
      << fragment_mediump_float.precision << ", lowp " << fragment_lowp_float.precision << "\n"
      << "depth texture " << (depth_texture ? "yes" : "no") << ", packed depth-stencil "
      << (packed_depth_stencil ? "yes" : "no") << ", depth24 " << (depth24 ? "yes" : "no")
      << ", uint indices " << (element_index_uint ? "yes" : "no") << "\n"
      << "half-float targets " << (half_float_target ? "yes" : "no") << ", draw buffers "
      << (draw_buffers ? "yes" : "no") << ", render into mip levels " << (render_mipmap ? "yes" : "no")
      << ", derivatives " << (standard_derivatives ? "yes" : "no")
      << ", GPU timer " << (timer_query ? "yes (" + std::to_string(timer_bits) + " bits)" : std::string("no"));
    return s.str();
}

}  // namespace penumbra::gl
