#include "gl/device.h"

#include <algorithm>
#include <stdexcept>

#include "gl/check.h"
#include "gl/gl_headers.h"

namespace penumbra::gl {

namespace {

GLenum to_gl(Compare c) {
    switch (c) {
        case Compare::Never: return GL_NEVER;
        case Compare::Less: return GL_LESS;
        case Compare::LEqual: return GL_LEQUAL;
        case Compare::Equal: return GL_EQUAL;
        case Compare::GEqual: return GL_GEQUAL;
        case Compare::Greater: return GL_GREATER;
        case Compare::NotEqual: return GL_NOTEQUAL;
        case Compare::Always: return GL_ALWAYS;
    }
    return GL_ALWAYS;
}

GLenum to_gl(StencilOp op) {
    switch (op) {
        case StencilOp::Keep: return GL_KEEP;
        case StencilOp::Zero: return GL_ZERO;
        case StencilOp::Replace: return GL_REPLACE;
        case StencilOp::Incr: return GL_INCR;
        case StencilOp::Decr: return GL_DECR;
        case StencilOp::IncrWrap: return GL_INCR_WRAP;
        case StencilOp::DecrWrap: return GL_DECR_WRAP;
    }
    return GL_KEEP;
}

void set_enabled(GLenum cap, bool on) {
    if (on)
        glEnable(cap);
    else
        glDisable(cap);
}

constexpr GLsizei kStride = 8 * sizeof(float);  // position 3, normal 3, uv 2

}  // namespace

Device::Device() {
    // A triangle twice the size of the viewport covers it with no diagonal seam.
    const float tri[] = {-1.0f, -1.0f, 0, 0, 0, 0, 0, 0, 3.0f, -1.0f, 0, 0, 0, 0, 0, 0, -1.0f, 3.0f, 0, 0, 0, 0, 0, 0};
    fullscreen_ = Buffer(BufferKind::Vertex, tri, sizeof tri, "fullscreen triangle");
    invalidate();
}

void Device::invalidate() {
    // Put GL in a known state equal to a default PipelineState, then cache that.
    state_ = PipelineState{};
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDisable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilMask(0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDisable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, 0.0f);
    glDisable(GL_SCISSOR_TEST);
    scissor_ = false;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    program_ = 0;
    glUseProgram(0);
    check_made("Device::invalidate", __FILE__, __LINE__);
}

MeshBuffers Device::upload_mesh(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                const std::vector<glm::vec2>& uvs, const std::vector<std::uint32_t>& indices,
                                bool allow_u32, const char* label) {
    if (normals.size() != positions.size() || (!uvs.empty() && uvs.size() != positions.size()))
        throw Error(std::string(label) + ": attribute counts differ");
    std::vector<float> interleaved;
    interleaved.reserve(positions.size() * 8);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec2 uv = uvs.empty() ? glm::vec2(0.0f) : uvs[i];
        interleaved.insert(interleaved.end(), {positions[i].x, positions[i].y, positions[i].z, normals[i].x,
                                               normals[i].y, normals[i].z, uv.x, uv.y});
    }
    MeshBuffers m;
    m.has_uv = !uvs.empty();
    m.vertices = Buffer(BufferKind::Vertex, interleaved.data(), interleaved.size() * sizeof(float), label);
    m.index_count = static_cast<std::int32_t>(indices.size());
    if (positions.size() <= 65536) {
        std::vector<std::uint16_t> small(indices.begin(), indices.end());
        m.indices = Buffer(BufferKind::Index, small.data(), small.size() * sizeof(std::uint16_t), label);
    } else {
        if (!allow_u32)
            throw Error(std::string(label) + ": " + std::to_string(positions.size()) +
                        " vertices need 32-bit indices, and this context lacks OES_element_index_uint");
        m.index_u32 = true;
        m.indices = Buffer(BufferKind::Index, indices.data(), indices.size() * sizeof(std::uint32_t), label);
    }
    return m;
}

void Device::bind_target(const Target& t) {
    PENUMBRA_GL(glBindFramebuffer(GL_FRAMEBUFFER, t.fb ? t.fb->id() : 0u));
    PENUMBRA_GL(glViewport(t.x, t.y, t.width, t.height));
    if (t.clip) {
        if (!scissor_) glEnable(GL_SCISSOR_TEST);
        PENUMBRA_GL(glScissor(t.x, t.y, t.width, t.height));
        scissor_ = true;
    } else if (scissor_) {
        glDisable(GL_SCISSOR_TEST);
        scissor_ = false;
    }
}

void Device::clear(const glm::vec4* color, bool depth, bool stencil) {
    // Clears obey the write masks: open the ones being cleared, and note it in the cache.
    GLbitfield bits = 0;
    if (color) {
        glClearColor(color->r, color->g, color->b, color->a);
        if (!state_.color_write) {
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            state_.color_write = true;
        }
        bits |= GL_COLOR_BUFFER_BIT;
    }
    if (depth) {
        glClearDepthf(1.0f);
        if (!state_.depth_write) {
            glDepthMask(GL_TRUE);
            state_.depth_write = true;
        }
        bits |= GL_DEPTH_BUFFER_BIT;
    }
    if (stencil) {
        glClearStencil(0);
        if (state_.stencil.write_mask != 0xFF) {
            glStencilMask(0xFF);
            state_.stencil.write_mask = 0xFF;
        }
        bits |= GL_STENCIL_BUFFER_BIT;
    }
    PENUMBRA_GL(glClear(bits));
}

void Device::apply(const PipelineState& s) {
    if (s.depth_test != state_.depth_test) set_enabled(GL_DEPTH_TEST, s.depth_test);
    if (s.depth_func != state_.depth_func) glDepthFunc(to_gl(s.depth_func));
    if (s.depth_write != state_.depth_write) glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
    if (s.color_write != state_.color_write) {
        const GLboolean c = s.color_write ? GL_TRUE : GL_FALSE;
        glColorMask(c, c, c, c);
    }
    if (s.cull != state_.cull) {
        set_enabled(GL_CULL_FACE, s.cull != Cull::None);
        if (s.cull != Cull::None) glCullFace(s.cull == Cull::Back ? GL_BACK : GL_FRONT);
    }
    const StencilState& a = s.stencil;
    const StencilState& b = state_.stencil;
    if (a.enabled != b.enabled) set_enabled(GL_STENCIL_TEST, a.enabled);
    if (a.func != b.func || a.ref != b.ref || a.read_mask != b.read_mask) glStencilFunc(to_gl(a.func), a.ref, a.read_mask);
    if (a.write_mask != b.write_mask) glStencilMask(a.write_mask);
    if (a.fail != b.fail || a.depth_fail != b.depth_fail || a.pass != b.pass || a.two_sided != b.two_sided ||
        a.back_fail != b.back_fail || a.back_depth_fail != b.back_depth_fail || a.back_pass != b.back_pass) {
        if (a.two_sided) {
            glStencilOpSeparate(GL_FRONT, to_gl(a.fail), to_gl(a.depth_fail), to_gl(a.pass));
            glStencilOpSeparate(GL_BACK, to_gl(a.back_fail), to_gl(a.back_depth_fail), to_gl(a.back_pass));
        } else {
            glStencilOp(to_gl(a.fail), to_gl(a.depth_fail), to_gl(a.pass));
        }
    }
    if (s.blend != state_.blend) {
        if ((s.blend == Blend::Off) != (state_.blend == Blend::Off)) set_enabled(GL_BLEND, s.blend != Blend::Off);
        if (s.blend == Blend::Add) glBlendFunc(GL_ONE, GL_ONE);
        else if (s.blend == Blend::Alpha) glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        else if (s.blend == Blend::Over) glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
    const bool offset = s.offset_factor != 0.0f || s.offset_units != 0.0f;
    const bool offset_was = state_.offset_factor != 0.0f || state_.offset_units != 0.0f;
    if (offset != offset_was) set_enabled(GL_POLYGON_OFFSET_FILL, offset);
    if (offset && (s.offset_factor != state_.offset_factor || s.offset_units != state_.offset_units))
        glPolygonOffset(s.offset_factor, s.offset_units);
    state_ = s;
    // Per call in checked builds only: in the others the pass's (or the frame's) check finds what
    // these calls left queued, naming the pass.
    if constexpr (kCheckEachCall) check_errors("Device::apply", __FILE__, __LINE__);
}

void Device::use(const Program& program) {
    if (program.id() == program_) return;
    PENUMBRA_GL(glUseProgram(program.id()));
    program_ = program.id();
}

void Device::bind_texture(int unit, const Texture& texture) {
    const auto u = static_cast<size_t>(unit);
    if (u < bound_.size() && bound_[u] == texture.id() && texture.id() != 0) return;
    PENUMBRA_GL(glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit)));
    PENUMBRA_GL(glBindTexture(texture.bind_target(), texture.id()));
    if (u >= bound_.size()) bound_.resize(u + 1, 0);
    bound_[u] = texture.id();
}

namespace {
void bind_vertex_layout(GLuint vbo, bool uv) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glEnableVertexAttribArray(kPosition);
    glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, kStride, nullptr);
    glEnableVertexAttribArray(kNormal);
    glVertexAttribPointer(kNormal, 3, GL_FLOAT, GL_FALSE, kStride, reinterpret_cast<const void*>(3 * sizeof(float)));
    if (uv) {
        glEnableVertexAttribArray(kUV);
        glVertexAttribPointer(kUV, 2, GL_FLOAT, GL_FALSE, kStride, reinterpret_cast<const void*>(6 * sizeof(float)));
    } else {
        glDisableVertexAttribArray(kUV);
        glVertexAttrib2f(kUV, 0.0f, 0.0f);
    }
}
}  // namespace

void Device::draw(const MeshBuffers& mesh) {
    bind_vertex_layout(mesh.vertices.id(), mesh.has_uv);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.id());
    PENUMBRA_GL(glDrawElements(GL_TRIANGLES, mesh.index_count, mesh.index_u32 ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT,
                               nullptr));
}

Buffer Device::upload_points(const std::vector<glm::vec4>& triangles, const char* label, std::size_t capacity) {
    const std::size_t bytes = triangles.size() * sizeof(glm::vec4);
    if (capacity <= bytes) return Buffer(BufferKind::Vertex, triangles.data(), bytes, label);
    Buffer b(BufferKind::Vertex, nullptr, capacity, label, true);
    b.update(triangles.data(), bytes);
    return b;
}

void Device::draw_points(const Buffer& points, std::size_t count) {
    if (count == 0) return;
    glBindBuffer(GL_ARRAY_BUFFER, points.id());
    glEnableVertexAttribArray(kPosition);
    glVertexAttribPointer(kPosition, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glDisableVertexAttribArray(kNormal);
    glDisableVertexAttribArray(kUV);
    PENUMBRA_GL(glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count)));
}

void Device::draw_fullscreen() {
    bind_vertex_layout(fullscreen_.id(), false);
    PENUMBRA_GL(glDrawArrays(GL_TRIANGLES, 0, 3));
}

std::vector<std::uint8_t> Device::read_rgba(int width, int height) { return read_rgba(0, 0, width, height); }

std::vector<std::uint8_t> Device::read_rgba(int x, int y, int width, int height) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4u);
    PENUMBRA_GL(glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, px.data()));
    check_errors("glReadPixels", __FILE__, __LINE__);
    return px;
}

void Device::finish() { glFinish(); }

}  // namespace penumbra::gl
