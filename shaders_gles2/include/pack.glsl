// Bit-shift packing of a depth in [0,1] into four unorm8 channels, most significant in red.
// Byte i is floor(fract(d * 256^i) * 256), written as byte/255 so that the unorm8 conversion
// (round(c * 255)) stores the byte exactly. Under float32 every step is exact, so the round trip
// is exact to 2^-24; src/shadow/encoding.cpp mirrors this on the CPU for the tests.

#ifndef PACK_GLSL
#define PACK_GLSL 1  // included by shadow.glsl and gbuffer.glsl, both in lit.frag

// PACK_FLOOR: the start-up probe found that this context truncates float -> unorm8 instead of
// rounding; aim at the middle of each byte so the intended byte is stored either way.
#ifdef PACK_FLOOR
const float UNORM_OFFSET = 0.5;
#else
const float UNORM_OFFSET = 0.0;
#endif

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

// r8: the depth in red, aimed at the middle of the byte when the context truncates.
vec4 packDepthR8(float depth) {
    return vec4(MP(MP(depth) + UNORM_OFFSET / 255.0), 0.0, 0.0, 1.0);
}
#endif  // PACK_GLSL
