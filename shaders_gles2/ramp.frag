#version 100
// Precision test pattern: pixel i (row-major from the bottom left, i < u_count) holds the depth
// (256 i + (157 i mod 256)) / 2^24, packed as the light's pass packs it (ENC_R8 or bit-shift RGBA):
// a ramp over [0,1) whose low bits take every value, and whose every step is exact in float32
// (whole numbers below 2^24 and scales by powers of two; no division, whose rounding GLSL leaves
// to the implementation), so the CPU mirror knows the very depth each pixel packed. The pixels
// after the ramp hold u_specials (e.g. 0, 1, 1 - 2^-24). Read back and unpacked on the CPU, it
// shows what the encoding keeps of every depth.
#include "precision.glsl"
#include "pack.glsl"

uniform float u_width;      // the target's width in pixels
uniform float u_count;      // how many ramp values
uniform vec4 u_specials;

void main() {
    float index = floor(gl_FragCoord.x) + floor(gl_FragCoord.y) * u_width;
    float spread = index * 157.0;                                     // < 2^24: exact
    float low = spread - 256.0 * floor(spread * 0.00390625);          // 157 i mod 256
    float d = (index * 256.0 + low) * 5.9604644775390625e-08;         // * 2^-24
    if (index >= u_count) {
        float k = index - u_count;
        d = k < 0.5 ? u_specials.x : k < 1.5 ? u_specials.y : k < 2.5 ? u_specials.z : u_specials.w;
    }
#ifdef ENC_R8
    gl_FragColor = packDepthR8(d);
#else
    gl_FragColor = packDepth(d);
#endif
}
