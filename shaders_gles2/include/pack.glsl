// Bit-shift packing of a depth in [0,1] into four unorm8 channels, most significant in red.
// Byte i is floor(fract(d * 256^i) * 256), written as (byte + 0.25)/255 so that every conversion
// GLES allows stores the byte itself (UNORM_OFFSET below). Under float32 every step is exact (a
// scale by a power of two, fract and floor lose nothing), so the bytes are the same on every
// context and the round trip is exact to 2^-24; src/shadow/encoding.cpp mirrors this on the CPU.

#ifndef PACK_GLSL
#define PACK_GLSL 1  // included by shadow.glsl and gbuffer.glsl, both in lit.frag

// A byte b written as (b + UNORM_OFFSET)/255 reaches the store as b + 0.25 (give or take float32's
// 1e-5 of a step): the nearest integer (GLES 2.0 2.1.2 asks for round(c * 255)), truncation, and
// "either of the two closest" (ES 3.0 2.1.6.2) all give b, and so does a store that converts
// with an error of up to a quarter step (the H100 log suggests NVIDIA's is 0.06 off at the ties).
// Written as b/255 instead, a context that truncates may store b - 1 where b/255 * 255 lands below b.
const float UNORM_OFFSET = 0.25;

#ifdef LAB
// The shader lab (docs/snippets.md): the sheet's packDepth, unpackDepth, shadowTest and
// offset_lookup, as a student wrote them or the sheet's answer, inserted by the shader library at
// the marker below (render::snippet_block). texmapscale is the sheet's name for u_texmapscale.
uniform vec2 u_texmapscale;  // 1/width, 1/height of the shadow map: one texel in texture space
#define texmapscale u_texmapscale
// @snippets
#else

#ifdef EMULATE_MEDIUMP
const float MAX_PACKED_DEPTH = 0.99951171875;  // 1 - 2^-11: the largest half below 1
#else
const float MAX_PACKED_DEPTH = 0.99999994;     // 1 - 2^-24: 1.0 itself would wrap to 0
#endif

vec4 packDepth(float depth) {
    float d = clamp(MP(depth), 0.0, MAX_PACKED_DEPTH);
    vec4 digits = floor(MP(fract(MP(d * vec4(1.0, 256.0, 65536.0, 16777216.0)))) * 256.0);
    return MP((digits + UNORM_OFFSET) / 255.0);
}

float unpackDepth(vec4 rgba) {
    return MP(dot(MP(rgba), MP(vec4(255.0 / 256.0, 255.0 / 65536.0, 255.0 / 16777216.0, 255.0 / 4294967296.0))));
}

// r8: the depth in red, rounded to its byte here rather than by the store (whose rounding near
// the ties differs between contexts), then written as that byte.
vec4 packDepthR8(float depth) {
    float byte = floor(MP(depth) * 255.0 + 0.5);
    return vec4(MP((byte + UNORM_OFFSET) / 255.0), 0.0, 0.0, 1.0);
}
#endif  // LAB
#endif  // PACK_GLSL
