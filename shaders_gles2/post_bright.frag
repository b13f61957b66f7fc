#version 100
// --post bloom: the bright part of the image, each channel minus u_threshold (at least 0), drawn
// into a target half the size, where each pixel's centre falls between four texels of the source:
// linear sampling averages them (a 2x2 box). With u_threshold 0, the half-size image to a quarter.
#include "precision.glsl"

uniform sampler2D u_image;
uniform float u_threshold;
varying vec2 v_uv;

void main() {
    gl_FragColor = vec4(max(texture2D(u_image, v_uv).rgb - vec3(u_threshold), vec3(0.0)), 1.0);
}
