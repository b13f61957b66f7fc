#include "gl/objects.h"

#include <algorithm>
#include <map>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gl/check.h"
#include "gl/entry_points.h"
#include "gl/gl_headers.h"
#include "gl/uniforms.h"

namespace penumbra::gl {

void BufferDeleter::operator()(std::uint32_t id) const { glDeleteBuffers(1, &id); }
void TextureDeleter::operator()(std::uint32_t id) const { glDeleteTextures(1, &id); }
void RenderbufferDeleter::operator()(std::uint32_t id) const { glDeleteRenderbuffers(1, &id); }
void FramebufferDeleter::operator()(std::uint32_t id) const { glDeleteFramebuffers(1, &id); }
void ProgramDeleter::operator()(std::uint32_t id) const { glDeleteProgram(id); }

namespace {
template <typename T>
GLsizei isize(T v) { return static_cast<GLsizei>(v); }
}  // namespace

// ---- Buffer ---------------------------------------------------------------------------------

Buffer::Buffer(BufferKind kind, const void* data, std::size_t bytes, const char* label, bool dynamic)
    : kind_(kind), bytes_(bytes) {
    GLuint id = 0;
    glGenBuffers(1, &id);
    h_ = Handle<BufferDeleter>(id);
    const GLenum target = kind == BufferKind::Vertex ? GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER;
    PENUMBRA_GL(glBindBuffer(target, id));
    PENUMBRA_GL(glBufferData(target, static_cast<GLsizeiptr>(bytes), data, dynamic ? GL_DYNAMIC_DRAW : GL_STATIC_DRAW));
    check_made(label, __FILE__, __LINE__);
}

void Buffer::update(const void* data, std::size_t bytes) {
    if (bytes > bytes_) throw Error("Buffer::update: " + std::to_string(bytes) + " bytes into a buffer of " + std::to_string(bytes_));
    const GLenum target = kind_ == BufferKind::Vertex ? GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER;
    PENUMBRA_GL(glBindBuffer(target, id()));
    PENUMBRA_GL(glBufferSubData(target, 0, static_cast<GLsizeiptr>(bytes), data));
}

// ---- Texture --------------------------------------------------------------------------------

Texture::Texture(const TextureDesc& d) : width_(d.width), height_(d.height), format_(d.format), cube_(d.cube) {
    if (d.width <= 0 || d.height <= 0) throw Error(std::string(d.label) + ": texture size must be positive");
    if (d.cube && (d.width != d.height || d.format != TextureFormat::RGBA8 || d.rgba))
        throw Error(std::string(d.label) + ": a cube map here has square RGBA8 faces and no initial pixels");
    GLuint id = 0;
    glGenTextures(1, &id);
    h_ = Handle<TextureDeleter>(id);
    const GLenum target = bind_target();
    PENUMBRA_GL(glBindTexture(target, id));
    if (d.cube) {
        for (GLenum face = 0; face < 6; ++face)
            PENUMBRA_GL(glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, d.width, d.height, 0, GL_RGBA,
                                     GL_UNSIGNED_BYTE, nullptr));
    } else if (d.format == TextureFormat::Depth) {
        PENUMBRA_GL(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, d.width, d.height, 0, GL_DEPTH_COMPONENT,
                                 GL_UNSIGNED_INT, nullptr));
    } else if (d.format == TextureFormat::RGBA16F) {
        if (d.rgba) throw Error(std::string(d.label) + ": a half-float texture takes no initial RGBA8 pixels");
        PENUMBRA_GL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, d.width, d.height, 0, GL_RGBA, GL_HALF_FLOAT_OES, nullptr));
    } else {
        // Rows of 4 bytes are always aligned; the default unpack alignment of 4 is right.
        PENUMBRA_GL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, d.width, d.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, d.rgba));
    }
    if (d.sampling == Sampling::LinearMipmap || d.sampling == Sampling::NearestMipmap)
        PENUMBRA_GL(glGenerateMipmap(target));
    set_sampling(d.sampling);
    const GLint wrap = d.wrap == Wrap::Repeat && !d.cube ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    PENUMBRA_GL(glTexParameteri(target, GL_TEXTURE_WRAP_S, wrap));
    PENUMBRA_GL(glTexParameteri(target, GL_TEXTURE_WRAP_T, wrap));
    check_made(d.label, __FILE__, __LINE__);
}

unsigned int Texture::bind_target() const { return cube_ ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D; }

void Texture::set_sampling(Sampling sampling) {
    GLint min_filter = GL_NEAREST, mag_filter = GL_NEAREST;
    switch (sampling) {
        case Sampling::Nearest: break;
        case Sampling::Linear: min_filter = mag_filter = GL_LINEAR; break;
        case Sampling::LinearMipmap: min_filter = GL_LINEAR_MIPMAP_LINEAR, mag_filter = GL_LINEAR; break;
        case Sampling::NearestMipmap: min_filter = GL_NEAREST_MIPMAP_NEAREST; break;
    }
    PENUMBRA_GL(glBindTexture(bind_target(), id()));
    PENUMBRA_GL(glTexParameteri(bind_target(), GL_TEXTURE_MIN_FILTER, min_filter));
    PENUMBRA_GL(glTexParameteri(bind_target(), GL_TEXTURE_MAG_FILTER, mag_filter));
}

void Texture::set_level(int level, int width, int height, const std::uint8_t* rgba) {
    if (format_ != TextureFormat::RGBA8) throw Error("Texture::set_level: only RGBA8 textures have levels set here");
    PENUMBRA_GL(glBindTexture(GL_TEXTURE_2D, id()));
    PENUMBRA_GL(glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba));
    check_made("Texture::set_level", __FILE__, __LINE__);
}

void Texture::generate_mipmap() {
    PENUMBRA_GL(glBindTexture(GL_TEXTURE_2D, id()));
    PENUMBRA_GL(glGenerateMipmap(GL_TEXTURE_2D));
    check_made("glGenerateMipmap", __FILE__, __LINE__);
}

void Texture::copy_framebuffer(int level, int x, int y, int width, int height, bool alpha) {
    PENUMBRA_GL(glBindTexture(GL_TEXTURE_2D, id()));
    PENUMBRA_GL(glCopyTexImage2D(GL_TEXTURE_2D, level, alpha ? GL_RGBA : GL_RGB, x, y, width, height, 0));
    check_made("glCopyTexImage2D", __FILE__, __LINE__);
    if (level == 0) {
        width_ = width;
        height_ = height;
    }
}

std::size_t Texture::bytes() const {
    return (cube_ ? 6u : 1u) * static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) *
           static_cast<std::size_t>(bytes_per_pixel(format_));
}

// ---- Renderbuffer ---------------------------------------------------------------------------

Renderbuffer::Renderbuffer(RenderbufferFormat format, int width, int height, const char* label)
    : format_(format), width_(width), height_(height) {
    GLenum internal = GL_DEPTH_COMPONENT16;
    switch (format) {
        case RenderbufferFormat::Depth16: internal = GL_DEPTH_COMPONENT16; break;
        case RenderbufferFormat::Depth24: internal = GL_DEPTH_COMPONENT24_OES; break;
        case RenderbufferFormat::Depth24Stencil8: internal = GL_DEPTH24_STENCIL8_OES; break;
        case RenderbufferFormat::DepthStencil: internal = GL_DEPTH_STENCIL_OES; break;  // WebGL 1's DEPTH_STENCIL
        case RenderbufferFormat::Stencil8: internal = GL_STENCIL_INDEX8; break;
    }
    GLuint id = 0;
    glGenRenderbuffers(1, &id);
    h_ = Handle<RenderbufferDeleter>(id);
    PENUMBRA_GL(glBindRenderbuffer(GL_RENDERBUFFER, id));
    PENUMBRA_GL(glRenderbufferStorage(GL_RENDERBUFFER, internal, width, height));
    check_made(label, __FILE__, __LINE__);
}

std::size_t Renderbuffer::bytes() const {
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) *
           static_cast<std::size_t>(bytes_per_pixel(format_));
}

// ---- Framebuffer ----------------------------------------------------------------------------

std::string framebuffer_status_meaning(unsigned int status) {
    switch (status) {
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "an attachment cannot be rendered to: its format is not renderable at that attachment point (a "
                   "depth texture as colour, a colour format the context cannot draw into) or its image has no size";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "nothing is attached: a framebuffer needs at least one image";
        case GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS:
            return "the attachments differ in size: GLES2 and WebGL 1 need every image of one framebuffer to have the "
                   "same width and height";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "this implementation does not support this combination of formats (separate depth and stencil "
                   "buffers are the usual one: attach a packed depth-stencil instead)";
        default: return "";
    }
}

namespace {

const char* texture_format_name(TextureFormat f) { return f == TextureFormat::Depth ? "depth" : "rgba8"; }

// "colour texture rgba8 64x64, depth renderbuffer depth16 32x32", or "nothing".
std::string attachments(const FramebufferDesc& d) {
    std::string out;
    const auto add = [&](const std::string& s) { out += (out.empty() ? "" : ", ") + s; };
    const auto size = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
    if (d.color)
        add(std::string("colour texture ") + texture_format_name(d.color->format()) + " " +
            size(d.color->width(), d.color->height()) +
            (d.color_level ? " level " + std::to_string(d.color_level) : std::string()));
    for (const Texture* t : d.more_colors)
        if (t) add(std::string("colour texture ") + texture_format_name(t->format()) + " " + size(t->width(), t->height()));
    if (d.depth_texture)
        add(std::string("depth texture ") + texture_format_name(d.depth_texture->format()) + " " +
            size(d.depth_texture->width(), d.depth_texture->height()));
    if (d.depth)
        add(std::string("depth renderbuffer ") + to_string(d.depth->format()) + " " +
            size(d.depth->width(), d.depth->height()));
    if (d.stencil)
        add(std::string("stencil renderbuffer ") + to_string(d.stencil->format()) + " " +
            size(d.stencil->width(), d.stencil->height()));
    return out.empty() ? "nothing" : out;
}

// glDrawBuffersEXT: found through the platform when the caps were probed (entry_points).
void draw_buffers(GLsizei n, const GLenum* buffers, const char* label) {
    const auto fn = entry_points().draw_buffers;
    if (!fn) throw Error(std::string(label) + ": several colour attachments, but no glDrawBuffersEXT on this context");
    fn(n, buffers);
}

}  // namespace

Framebuffer::Framebuffer(const FramebufferDesc& d) {
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    h_ = Handle<FramebufferDeleter>(id);
    PENUMBRA_GL(glBindFramebuffer(GL_FRAMEBUFFER, id));
    if (d.color)
        PENUMBRA_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                           d.color->cube() ? static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + d.color_face)
                                                           : GL_TEXTURE_2D,
                                           d.color->id(), d.color_level));
    GLenum buffers[1 + kMaxExtraColors] = {GL_COLOR_ATTACHMENT0};
    GLsizei count = 1;
    for (const Texture* t : d.more_colors) {
        if (!t) break;
        buffers[count] = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + count);
        PENUMBRA_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[count], GL_TEXTURE_2D, t->id(), 0));
        ++count;
    }
    if (count > 1) draw_buffers(count, buffers, d.label);
    if (d.depth_texture)
        PENUMBRA_GL(
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, d.depth_texture->id(), 0));
    if (d.depth && d.depth->format() == RenderbufferFormat::DepthStencil) {
        // WebGL 1 attaches a DEPTH_STENCIL renderbuffer at DEPTH_STENCIL_ATTACHMENT (0x821A), once.
        PENUMBRA_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, 0x821A, GL_RENDERBUFFER, d.depth->id()));
    } else if (d.depth) {
        PENUMBRA_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, d.depth->id()));
        if (d.depth->format() == RenderbufferFormat::Depth24Stencil8)
            PENUMBRA_GL(
                glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, d.depth->id()));
    }
    if (d.stencil)
        PENUMBRA_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, d.stencil->id()));
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    PENUMBRA_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        const std::string meaning = framebuffer_status_meaning(status);
        throw Error(std::string(d.label) + ": framebuffer incomplete: " + enum_name(status) + (meaning.empty() ? "" : ": " + meaning) +
                    " (attached: " + attachments(d) + ")");
    }
    check_made(d.label, __FILE__, __LINE__);
}

// ---- Program --------------------------------------------------------------------------------

namespace {

// A shader's or a program's info log (glGetShaderiv + glGetShaderInfoLog, or the program's pair).
template <typename GetIv, typename GetLog>
std::string info_log(GLuint id, GetIv get_iv, GetLog get_log) {
    GLint len = 0;
    get_iv(id, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<size_t>(len > 1 ? len : 1), '\0');
    get_log(id, isize(log.size()), nullptr, log.data());
    return log.data();
}

// "" when shader `s` compiled, else "vertex shader failed to compile: LOG".
std::string compile_error(GLenum stage, GLuint s) {
    GLint ok = GL_FALSE;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (ok == GL_TRUE) return "";
    return std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
           " shader failed to compile: " + info_log(s, glGetShaderiv, glGetShaderInfoLog);
}

GLuint compile(GLenum stage, const std::string& source, const std::string& label) {
    const GLuint s = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    if (const std::string error = compile_error(stage, s); !error.empty()) {
        glDeleteShader(s);
        throw Error(label + ": " + error);
    }
    return s;
}

// Every program's attributes at the same locations, bound before linking.
void bind_attributes(GLuint p) {
    glBindAttribLocation(p, kPosition, "a_position");
    glBindAttribLocation(p, kNormal, "a_normal");
    glBindAttribLocation(p, kUV, "a_uv");
}

std::string program_log(GLuint p) { return info_log(p, glGetProgramiv, glGetProgramInfoLog); }

}  // namespace

Program::Program(const std::string& vs, const std::string& fs, const std::string& label) : label_(label) {
    if (kStrictUniforms) {
        declared_ = declared_uniforms(vs);
        declared_.merge(declared_uniforms(fs));
    }
    const GLuint v = compile(GL_VERTEX_SHADER, vs, label);
    GLuint f = 0;
    try {
        f = compile(GL_FRAGMENT_SHADER, fs, label);
    } catch (...) {
        glDeleteShader(v);
        throw;
    }
    const GLuint p = glCreateProgram();
    h_ = Handle<ProgramDeleter>(p);
    glAttachShader(p, v);
    glAttachShader(p, f);
    bind_attributes(p);
    glLinkProgram(p);
    // The program keeps its compiled code; the shader objects can go now.
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = GL_FALSE;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) throw Error(label + ": program failed to link: " + program_log(p));
    check_errors(label.c_str(), __FILE__, __LINE__);
}

// MAX_SHADER_COMPILER_THREADS_KHR is left as it is: its initial value, 0xFFFFFFFF, lets the
// driver use as many threads as it likes (NVIDIA compiles in parallel; llvmpipe one at a time).
std::vector<std::string> check_programs(const std::vector<ProgramSources>& programs, std::size_t batch) {
    // One shader object per distinct (stage, source), and the last program that uses it.
    struct Shader {
        GLuint id = 0;
        std::size_t last_use = 0;
        bool checked = false;
        std::string error;  // "vertex shader failed to compile: LOG"
    };
    std::map<std::pair<GLenum, std::string>, Shader> shaders;
    for (std::size_t i = 0; i < programs.size(); ++i) {
        shaders[{GL_VERTEX_SHADER, programs[i].vertex}].last_use = i;
        shaders[{GL_FRAGMENT_SHADER, programs[i].fragment}].last_use = i;
    }
    const auto shader = [&](GLenum stage, const std::string& source) -> Shader& {
        Shader& sh = shaders[{stage, source}];
        if (sh.id == 0) {  // issued now, its status read after the batch's links are issued
            sh.id = glCreateShader(stage);
            const char* text = source.c_str();
            glShaderSource(sh.id, 1, &text, nullptr);
            glCompileShader(sh.id);
        }
        return sh;
    };
    const auto compiled = [](GLenum stage, Shader& sh) {
        if (!sh.checked) sh.error = compile_error(stage, sh.id);
        sh.checked = true;
        return sh.error.empty();
    };
    std::vector<std::string> errors(programs.size());
    batch = std::max<std::size_t>(batch, 1);
    for (std::size_t first = 0; first < programs.size(); first += batch) {
        const std::size_t end = std::min(first + batch, programs.size());
        std::vector<GLuint> ids;
        for (std::size_t i = first; i < end; ++i) {
            const GLuint p = glCreateProgram();
            glAttachShader(p, shader(GL_VERTEX_SHADER, programs[i].vertex).id);
            glAttachShader(p, shader(GL_FRAGMENT_SHADER, programs[i].fragment).id);
            bind_attributes(p);
            glLinkProgram(p);
            ids.push_back(p);
        }
        for (std::size_t i = first; i < end; ++i) {
            const GLuint p = ids[i - first];
            Shader& v = shaders[{GL_VERTEX_SHADER, programs[i].vertex}];
            Shader& f = shaders[{GL_FRAGMENT_SHADER, programs[i].fragment}];
            const bool v_ok = compiled(GL_VERTEX_SHADER, v), f_ok = compiled(GL_FRAGMENT_SHADER, f);
            GLint ok = GL_FALSE;
            glGetProgramiv(p, GL_LINK_STATUS, &ok);
            if (!v_ok || !f_ok)
                errors[i] = programs[i].label + ": " + (v_ok ? f.error : v.error);
            else if (ok != GL_TRUE)
                errors[i] = programs[i].label + ": program failed to link: " + program_log(p);
            glDeleteProgram(p);
            for (Shader* sh : {&v, &f})
                if (sh->last_use == i && sh->id) {
                    glDeleteShader(sh->id);
                    sh->id = 0;
                }
        }
        check_errors("check_programs", __FILE__, __LINE__);
    }
    return errors;
}

int Program::location(const char* name) const {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    if (kStrictUniforms && !declares(name))
        throw Error(label_ + ": no uniform '" + name + "' in this program (misspelt, or a feature the variant lacks)");
    const int loc = glGetUniformLocation(h_.id(), name);
    locations_.emplace(name, loc);
    return loc;
}

void Program::set(const char* name, int v) const {
    if (const int l = location(name); l >= 0) glUniform1i(l, v);
}
void Program::set(const char* name, float v) const {
    if (const int l = location(name); l >= 0) glUniform1f(l, v);
}
void Program::set(const char* name, const glm::vec2& v) const {
    if (const int l = location(name); l >= 0) glUniform2fv(l, 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec3& v) const {
    if (const int l = location(name); l >= 0) glUniform3fv(l, 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec4& v) const {
    if (const int l = location(name); l >= 0) glUniform4fv(l, 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::mat3& v) const {
    if (const int l = location(name); l >= 0) glUniformMatrix3fv(l, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::mat4& v) const {
    if (const int l = location(name); l >= 0) glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace penumbra::gl
