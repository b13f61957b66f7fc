#version 100
// penumbra mipmaps: one mip level from the level above (render/mipmaps.h). The target is half the
// source's size, so this pixel covers 2x2 texels of the source and v_uv is their shared corner; the
// four are read at their centres with nearest sampling (exact bytes, no filtering hardware in the
// sum). Box: their mean, rounded as the CPU rounds it. MIP_NORMAL (a normal map, xyz = n * 0.5 + 0.5): the mean of the four
// decoded normals renormalised to unit length, so the coarse levels keep their lighting instead of
// shortening towards the flat normal; alpha is their mean either way.
// MIP_READ: a level read back by drawing, where it cannot be attached to a framebuffer (WebGL 1):
// the whole chain sampled nearest-mipmap-nearest into a target of that level's size, where one
// pixel spans one texel of the level, so the level of detail is the level's own.
#include "precision.glsl"

uniform sampler2D u_image;  // the level above
uniform vec2 u_texel;       // one texel of it: (1 / width, 1 / height)
varying vec2 v_uv;

// A texel's channels as bytes 0..255; a byte as a colour that a context that rounds and one that
// truncates both store as that byte (pack.glsl's UNORM_OFFSET).
vec4 byte_of(vec4 v) { return floor(v * 255.0 + 0.5); }
vec4 stored(vec4 b) { return (b + 0.25) / 255.0; }

void main() {
#ifdef MIP_READ
    gl_FragColor = texture2D(u_image, v_uv);
#else
    vec2 h = 0.5 * u_texel;
    // The four texels as whole bytes (exact in any float precision up to 4 x 255), so that the
    // rounding below is the CPU reference's, ties included.
    vec4 sum = byte_of(texture2D(u_image, v_uv + vec2(-h.x, -h.y))) + byte_of(texture2D(u_image, v_uv + vec2(h.x, -h.y))) +
               byte_of(texture2D(u_image, v_uv + vec2(-h.x, h.y))) + byte_of(texture2D(u_image, v_uv + vec2(h.x, h.y)));
    vec4 mean = floor((sum + 2.0) * 0.25);  // the rounded mean, ties up
#ifdef MIP_NORMAL
    vec3 n = sum.xyz * (2.0 / (4.0 * 255.0)) - 1.0;
    float len = length(n);
    // Four normals that cancel (a sharp ridge seen from above) have no direction: up.
    n = len > 1.0e-4 ? n / len : vec3(0.0, 0.0, 1.0);
    gl_FragColor = stored(vec4(floor((n * 0.5 + 0.5) * 255.0 + 0.5), mean.w));
#else
    gl_FragColor = stored(mean);
#endif
#endif
}
