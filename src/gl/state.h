// The gl layer's plain values: pipeline state, texture and renderbuffer formats. No GL call is
// made here (state.cpp only compares and prints), so a frame plan that holds these values can be
// built and tested without a context.
#pragma once

#include <cstdint>
#include <string>

namespace penumbra::gl {

enum class Compare { Never, Less, LEqual, Equal, GEqual, Greater, NotEqual, Always };
enum class StencilOp { Keep, Zero, Replace, Incr, Decr, IncrWrap, DecrWrap };
enum class Cull { None, Back, Front };

struct StencilState {
    bool enabled = false;
    Compare func = Compare::Always;
    int ref = 0;
    std::uint32_t read_mask = 0xFF;
    std::uint32_t write_mask = 0xFF;
    StencilOp fail = StencilOp::Keep, depth_fail = StencilOp::Keep, pass = StencilOp::Keep;
    // Two-sided: the back faces' ops (glStencilOpSeparate); the ones above are then the front's.
    bool two_sided = false;
    StencilOp back_fail = StencilOp::Keep, back_depth_fail = StencilOp::Keep, back_pass = StencilOp::Keep;
    bool operator==(const StencilState& o) const;
    bool operator!=(const StencilState& o) const { return !(*this == o); }
};

// The stencil test on, comparing with `ref` by `func`, and `pass` where it and the depth test pass.
inline StencilState stencil_test(Compare func, int ref, StencilOp pass = StencilOp::Keep) {
    StencilState s;
    s.enabled = true;
    s.func = func;
    s.ref = ref;
    s.pass = pass;
    return s;
}

// Two-sided stencil counting (shadow volumes): front faces `front`, back faces `back`, applied where
// the depth test passes (depth-pass) or where it fails (depth-fail); wrapping, so that any order of
// increments and decrements sums right.
inline StencilState stencil_count(bool on_depth_fail) {
    StencilState s;
    s.enabled = true;
    s.func = Compare::Always;
    s.two_sided = true;
    if (on_depth_fail) {
        s.depth_fail = StencilOp::DecrWrap;
        s.back_depth_fail = StencilOp::IncrWrap;
    } else {
        s.pass = StencilOp::IncrWrap;
        s.back_pass = StencilOp::DecrWrap;
    }
    return s;
}

// Blending of a colour over what the target holds: by the source's alpha, added (ONE, ONE:
// Heckbert-Herf's accumulation of light samples), or a premultiplied colour over it (ONE,
// ONE_MINUS_SRC_ALPHA: the mirror's reflection, rgb already scaled by the reflectivity in alpha).
enum class Blend { Off, Alpha, Add, Over };

struct PipelineState {
    bool depth_test = true;
    Compare depth_func = Compare::Less;
    bool depth_write = true;
    bool color_write = true;
    Cull cull = Cull::Back;
    StencilState stencil;
    Blend blend = Blend::Off;
    // glPolygonOffset(factor, units) with GL_POLYGON_OFFSET_FILL where either is non-zero: positive
    // values push the fragments' depth away from the eye.
    float offset_factor = 0.0f, offset_units = 0.0f;
    bool operator==(const PipelineState& o) const;
    bool operator!=(const PipelineState& o) const { return !(*this == o); }
};

// How many GL calls turning state `from` into `to` takes, as gl::Device::apply makes them (one per
// field group that differs; 0 when equal): what a frame plan's state-change count adds up.
int state_calls(const PipelineState& from, const PipelineState& to);

std::string to_string(Compare c);    // "less"
std::string to_string(StencilOp o);  // "replace"
std::string to_string(Cull c);       // "back"
// "depth less, write; colour on; cull back; stencil off" or "...; stencil equal 1 (read ff), pass incr"
std::string to_string(const PipelineState& s);

enum class TextureFormat {
    RGBA8,    // GL_RGBA / GL_UNSIGNED_BYTE
    RGBA16F,  // GL_RGBA / GL_HALF_FLOAT_OES (OES_texture_half_float; a target with EXT_color_buffer_half_float)
    Depth   // GL_DEPTH_COMPONENT / GL_UNSIGNED_INT (OES_depth_texture)
};
// NearestMipmap: the nearest texel of the nearest level (a level read back exactly by drawing).
enum class Sampling { Nearest, Linear, LinearMipmap, NearestMipmap };
enum class Wrap { Clamp, Repeat };

enum class RenderbufferFormat {
    Depth16,
    Depth24,          // OES_depth24
    Depth24Stencil8,  // OES_packed_depth_stencil, attached at DEPTH and STENCIL
    DepthStencil,     // WebGL 1's DEPTH_STENCIL, attached once at DEPTH_STENCIL_ATTACHMENT
    Stencil8
};

std::string to_string(Sampling s);            // "nearest"
std::string to_string(Wrap w);                // "clamp"
std::string to_string(RenderbufferFormat f);  // "depth24"
// Bytes per pixel as the GPU is assumed to store them (estimates for memory figures).
int bytes_per_pixel(TextureFormat f);
int bytes_per_pixel(RenderbufferFormat f);

}  // namespace penumbra::gl
