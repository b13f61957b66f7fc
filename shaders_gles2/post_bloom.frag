#version 100
// --post bloom: the image plus the mean of its bright part blurred at half and at quarter size (sampled linearly:
// the small targets are stretched over the image).
#include "precision.glsl"

uniform sampler2D u_image;
uniform sampler2D u_bloom_half;
uniform sampler2D u_bloom_quarter;
varying vec2 v_uv;

void main() {
    vec3 bloom = texture2D(u_bloom_half, v_uv).rgb + texture2D(u_bloom_quarter, v_uv).rgb;
    gl_FragColor = vec4(texture2D(u_image, v_uv).rgb + 0.5 * bloom, 1.0);
}
