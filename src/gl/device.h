// Pipeline state, draw calls and readback over the current context. A pass is data: the render
// layer describes the state it wants (PipelineState) and the Device applies only what changed,
// so GL state is never set twice in a row and no layer above this one calls gl* itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gl/objects.h"
#include "gl/state.h"

namespace penumbra::gl {

// GPU copy of a scene mesh: interleaved position/normal/uv and 16- or 32-bit indices.
struct MeshBuffers {
    Buffer vertices;
    Buffer indices;
    std::int32_t index_count = 0;
    bool index_u32 = false;
    bool has_uv = false;
};

// Where a pass draws: an FBO, or the context's default framebuffer when fb is null.
struct Target {
    const Framebuffer* fb = nullptr;
    int width = 0;
    int height = 0;
    // A region of a larger framebuffer (a picture-in-picture view): the viewport's lower-left
    // corner, and with clip set, clears are kept inside the region too (scissor test).
    int x = 0;
    int y = 0;
    bool clip = false;
};

class Device {
public:
    Device();  // assumes a fresh context: the GL defaults are what it tracks

    // Mesh upload: positions and normals are required, uvs optional (empty), indices 3 per
    // triangle. Needs OES_element_index_uint when there are more than 65536 vertices.
    MeshBuffers upload_mesh(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                            const std::vector<glm::vec2>& uvs, const std::vector<std::uint32_t>& indices,
                            bool allow_u32, const char* label);

    void bind_target(const Target& target);
    void clear(const glm::vec4* color, bool depth, bool stencil);
    void apply(const PipelineState& state);
    void use(const Program& program);
    // Binds unless the unit already holds the texture (since the last forget_textures()).
    void bind_texture(int unit, const Texture& texture);
    // Forget what the units hold: call after textures were deleted or made (a deleted texture's
    // name may come back for a new one), e.g. at the start of a frame after the pool's changes.
    void forget_textures() { bound_.clear(); }
    // Draws all triangles; the vertex shader reads a_position, a_normal and (when the mesh has
    // them) a_uv. uv is set to 0 for meshes without uvs.
    void draw(const MeshBuffers& mesh);
    // Triangles of homogeneous points (x, y, z, w) made on the CPU (shadow volumes), uploaded once
    // into a buffer of their own, then drawn from it in a_position as often as they are still
    // wanted (a still volume: render/renderer.h keeps the buffer per list).
    // `capacity`: bytes to allocate if more than the points take (a buffer refilled later with
    // Buffer::update; GL_DYNAMIC_DRAW then).
    Buffer upload_points(const std::vector<glm::vec4>& triangles, const char* label, std::size_t capacity = 0);
    void draw_points(const Buffer& points, std::size_t count);
    // A single triangle that covers the viewport (positions in clip space in a_position.xy).
    void draw_fullscreen();

    // Reads the bound target's pixels, RGBA8, rows bottom first (GL order).
    std::vector<std::uint8_t> read_rgba(int width, int height);
    // The same from the region whose lower-left corner is (x, y).
    std::vector<std::uint8_t> read_rgba(int x, int y, int width, int height);
    void finish();
    // Forget every cached state (after something outside the Device touched GL, e.g. a context restore).
    void invalidate();

private:
    PipelineState state_;
    bool scissor_ = false;  // a clipped Target is bound
    std::uint32_t program_ = 0;
    std::vector<std::uint32_t> bound_;  // the texture each unit holds, by unit (0: unknown)
    Buffer fullscreen_;
};

}  // namespace penumbra::gl
