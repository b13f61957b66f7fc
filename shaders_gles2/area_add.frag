#version 100
// Heckbert and Herf's accumulation, one light sample at a time: where the sample's visibility image
// (the hard technique's visibility AOV, lit 1, shadowed 0) is lit, add one count (1/255, exact in
// unorm8) to one channel of the accumulation target (blending ONE, ONE). Sample k counts in channel
// k mod 4, so 4 x 255 samples fit in RGBA8 with no rounding; the camera pass divides by their number
// (lit.frag, AREA_LOOKUP). GLES2 has no accumulation buffer and no float target everywhere.
// AREA_INTERLEAVE (--area-interleave K): only the pixels of one class, (x, y) mod K = u_class.xy
// (u_class.z = K), count this sample; the others are discarded.
#include "precision.glsl"

uniform sampler2D u_sample;  // this sample's visibility
uniform vec4 u_channel;      // 1/255 in the channel this sample counts in, 0 elsewhere
varying vec2 v_uv;
#ifdef AREA_INTERLEAVE
uniform vec4 u_class;
#endif

void main() {
#ifdef AREA_INTERLEAVE
    if (any(notEqual(mod(floor(gl_FragCoord.xy), u_class.z), u_class.xy))) discard;
#endif
    gl_FragColor = texture2D(u_sample, v_uv).r >= 0.5 ? u_channel : vec4(0.0);
}
