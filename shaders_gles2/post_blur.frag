#version 100
// --post blur and shadow-blur: one direction of a separable Gaussian. BLUR_SUM(F) is generated
// (plan/variants.cpp): the sum of F(offset, weight) over the taps -BLUR_RADIUS..BLUR_RADIUS with
// weights exp(-x^2 / (2 sigma^2)), sigma = BLUR_RADIUS / 3, summing to 1. The texture is sampled at
// texel centres (the target is the source's size), so linear sampling adds nothing between taps;
// the edge is clamped.
#include "precision.glsl"

uniform sampler2D u_image;
uniform vec2 u_step;  // one texel along the direction: (1 / width, 0) or (0, 1 / height)
varying vec2 v_uv;

#ifndef BLUR_SUM
// The file as written (no generated sum): the centre tap alone.
#define BLUR_SUM(F) F(0.0, 1.0)
#endif

vec4 tap(float offset, float weight) { return texture2D(u_image, v_uv + u_step * offset) * weight; }

void main() {
    gl_FragColor = BLUR_SUM(tap);
}
