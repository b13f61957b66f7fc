#version 100
// The shadow map's depth as grey, scaled for viewing: with LINEARIZE (a perspective light) the
// window depth is turned back into distance along the light's axis and spread over [near, far],
// so the nearest surface is black and the farthest white; an orthographic depth is linear already.
#include "precision.glsl"
#include "shadow.glsl"

uniform vec2 u_near_far;
varying vec2 v_uv;

void main() {
    float d = shadowDepth(v_uv);
#ifdef LINEARIZE
    float n = u_near_far.x;
    float f = u_near_far.y;
    float z = 2.0 * n * f / (f + n - (2.0 * d - 1.0) * (f - n));
    d = clamp((z - n) / (f - n), 0.0, 1.0);
#endif
    gl_FragColor = vec4(vec3(d), 1.0);
}
