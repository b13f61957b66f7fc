#version 100
// Precision test pattern: pixel i (row-major from the bottom left) holds the depth i / (count - 1)
// packed as the light's pass packs it (ENC_R8 or bit-shift RGBA); the pixels after the ramp hold
// u_specials (e.g. 0, 1, 1 - 2^-24). Read back and unpacked on the CPU, it shows what the
// encoding keeps of every depth.
#include "precision.glsl"
#include "pack.glsl"

uniform float u_width;      // the target's width in pixels
uniform float u_count;      // how many ramp values
uniform vec4 u_specials;

void main() {
    float index = floor(gl_FragCoord.x) + floor(gl_FragCoord.y) * u_width;
    float d = index / (u_count - 1.0);
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
