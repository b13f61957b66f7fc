// Move-only owners of GL objects. Each is made from a small descriptor, deletes its object when it
// goes out of scope, and never copies. Creation failures throw gl::Error naming what failed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/check.h"
#include "gl/state.h"

namespace penumbra::gl {

// Shared move-only handle logic: `id` is 0 when empty; Deleter frees a non-zero id.
template <typename Deleter>
class Handle {
public:
    Handle() = default;
    explicit Handle(std::uint32_t id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0u)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0u);
        }
        return *this;
    }
    std::uint32_t id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    std::uint32_t release() { return std::exchange(id_, 0u); }
    void reset() {
        if (id_) Deleter{}(id_);
        id_ = 0;
    }

private:
    std::uint32_t id_ = 0;
};

struct BufferDeleter { void operator()(std::uint32_t id) const; };
struct TextureDeleter { void operator()(std::uint32_t id) const; };
struct RenderbufferDeleter { void operator()(std::uint32_t id) const; };
struct FramebufferDeleter { void operator()(std::uint32_t id) const; };
struct ProgramDeleter { void operator()(std::uint32_t id) const; };

enum class BufferKind { Vertex, Index };

class Buffer {
public:
    Buffer() = default;
    // `dynamic`: refilled often (GL_DYNAMIC_DRAW) with update().
    Buffer(BufferKind kind, const void* data, std::size_t bytes, const char* label, bool dynamic = false);
    // Replaces the first `bytes` (at most bytes()) of its contents.
    void update(const void* data, std::size_t bytes);
    std::uint32_t id() const { return h_.id(); }
    BufferKind kind() const { return kind_; }
    std::size_t bytes() const { return bytes_; }

private:
    Handle<BufferDeleter> h_;
    BufferKind kind_ = BufferKind::Vertex;
    std::size_t bytes_ = 0;
};

struct TextureDesc {
    int width = 0;
    int height = 0;
    TextureFormat format = TextureFormat::RGBA8;
    Sampling sampling = Sampling::Nearest;
    Wrap wrap = Wrap::Clamp;
    const std::uint8_t* rgba = nullptr;  // initial RGBA8 pixels (rows bottom first), or none
    // A cube map (GL_TEXTURE_CUBE_MAP): six square faces of width x width, RGBA8, no initial
    // pixels (rendered into: FramebufferDesc::color_face), read with textureCube.
    bool cube = false;
    const char* label = "texture";
};

class Texture {
public:
    Texture() = default;
    explicit Texture(const TextureDesc& desc);
    std::uint32_t id() const { return h_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    TextureFormat format() const { return format_; }
    bool cube() const { return cube_; }
    unsigned int bind_target() const;  // GL_TEXTURE_2D or GL_TEXTURE_CUBE_MAP
    std::size_t bytes() const;  // estimated GPU memory of level 0 (all six faces of a cube)

    // Mip levels (RGBA8 textures): level `level` (>= 1) defined as width x height RGBA8 pixels
    // (rows bottom first), or undefined contents with null; and glGenerateMipmap over level 0.
    // Each binds the texture on the active unit (tell the Device: forget_textures()).
    void set_level(int level, int width, int height, const std::uint8_t* rgba);
    void generate_mipmap();
    // How it is sampled from now on (NearestMipmap, LinearMipmap: every level must be defined).
    void set_sampling(Sampling sampling);
    // glCopyTexImage2D: level `level` becomes the width x height region of the bound framebuffer
    // whose lower-left corner is (x, y): RGBA, or RGB (a framebuffer without alpha, e.g. a window's,
    // can only give that). Any level, in GLES 2 and WebGL 1 alike; level 0 takes the region's size.
    void copy_framebuffer(int level, int x, int y, int width, int height, bool alpha);

private:
    Handle<TextureDeleter> h_;
    int width_ = 0, height_ = 0;
    TextureFormat format_ = TextureFormat::RGBA8;
    bool cube_ = false;
};

class Renderbuffer {
public:
    Renderbuffer() = default;
    Renderbuffer(RenderbufferFormat format, int width, int height, const char* label);
    std::uint32_t id() const { return h_.id(); }
    RenderbufferFormat format() const { return format_; }
    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t bytes() const;

private:
    Handle<RenderbufferDeleter> h_;
    RenderbufferFormat format_ = RenderbufferFormat::Depth16;
    int width_ = 0, height_ = 0;
};

// A framebuffer object with its attachments; completeness is checked where it is made and a
// failure names the status (GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT, ...), says what it means and
// lists what was attached (framebuffer_status_meaning).
// Colour attachments beyond the first: EXT_draw_buffers / WEBGL_draw_buffers (Caps::draw_buffers).
inline constexpr int kMaxExtraColors = 3;

struct FramebufferDesc {
    const Texture* color = nullptr;
    // The level of `color` rendered into: 0, or any other with OES_fbo_render_mipmap
    // (Caps::render_mipmap; GLES 2 and WebGL 1 render into level 0 only).
    int color_level = 0;
    // `color` is a cube map: the face rendered into, 0..5 (+x, -x, +y, -y, +z, -z).
    int color_face = 0;
    // COLOR_ATTACHMENT1.. in order (null: none): with any, the framebuffer's draw buffers are all
    // of its colour attachments, gl_FragData[i] into attachment i.
    const Texture* more_colors[kMaxExtraColors] = {nullptr, nullptr, nullptr};
    const Texture* depth_texture = nullptr;
    const Renderbuffer* depth = nullptr;  // depth or packed depth-stencil
    const Renderbuffer* stencil = nullptr;
    const char* label = "framebuffer";
};

// What an incomplete framebuffer's status means, in the course notes' failure classes: an
// attachment that cannot be rendered, none at all, sizes that differ, a combination the
// implementation does not support. Empty for GL_FRAMEBUFFER_COMPLETE and unknown values.
std::string framebuffer_status_meaning(unsigned int status);

class Framebuffer {
public:
    Framebuffer() = default;
    explicit Framebuffer(const FramebufferDesc& desc);
    std::uint32_t id() const { return h_.id(); }

private:
    Handle<FramebufferDeleter> h_;
};

// Fixed attribute locations, bound before linking, shared by every program and mesh layout.
enum Attribute : std::uint32_t { kPosition = 0, kNormal = 1, kUV = 2 };

// Debug builds (and PENUMBRA_GL_CHECKS) refuse to set a uniform the program does not declare.
inline constexpr bool kStrictUniforms = kCheckEachCall;

// A linked program. Compile and link logs go into the thrown error with the label.
class Program {
public:
    Program() = default;
    Program(const std::string& vertex_source, const std::string& fragment_source, const std::string& label);
    std::uint32_t id() const { return h_.id(); }
    const std::string& label() const { return label_; }

    // Uniform setters for the bound program. A uniform the source declares but the compiler
    // optimised out is ignored; one the source does not declare (in the variant's active #ifdef
    // blocks, see gl/uniforms.h) throws gl::Error in debug builds, naming it and the program.
    void set(const char* name, int v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::mat3& v) const;
    void set(const char* name, const glm::mat4& v) const;
    // Declared in the source's active blocks (whether or not the compiler kept it); debug builds
    // only (release builds do not scan the source and answer false).
    // An array's element ("u_point_lights[3]") is declared with its array.
    bool declares(const std::string& name) const { return declared_.count(name.substr(0, name.find('['))) > 0; }

private:
    int location(const char* name) const;
    Handle<ProgramDeleter> h_;
    std::string label_;
    std::set<std::string> declared_;
    mutable std::unordered_map<std::string, int> locations_;
};

// Many programs linked to see whether they link (the every-variant test): each distinct shader
// source compiled once, a batch's compiles and links all issued before any status is read (so
// that a context with GL_KHR_parallel_shader_compile works on them at once), each program deleted
// once its status is read, each shader once no later program uses it. The programs bind the
// attributes as Program does. Returns, for each program, "" or the error Program would throw
// ("LABEL: fragment shader failed to compile: LOG", "LABEL: program failed to link: LOG").
struct ProgramSources {
    std::string vertex, fragment, label;
};
std::vector<std::string> check_programs(const std::vector<ProgramSources>& programs, std::size_t batch = 64);

}  // namespace penumbra::gl
