#version 100
// --aov gbuffer-*: what the G-buffer holds, decoded for people. VIEW_COLOR the base colour;
// VIEW_NORMAL n * 0.5 + 0.5; VIEW_POSITION the world position over the shadowed objects' bounds
// (0..1 per axis); VIEW_DEPTH the ray position s mapped by u_view_range (1 - (s - x) * y: near
// white, far black). Where no surface is, the background (the pass's clear) shows.
#include "precision.glsl"
#include "gbuffer.glsl"

uniform sampler2D u_gbuffer_color;
uniform sampler2D u_gbuffer_normal;
uniform sampler2D u_gbuffer_depth;
uniform vec4 u_screen;  // xy: the viewport's lower-left corner; zw: 1 / its size
uniform vec3 u_bounds_min;
uniform vec3 u_bounds_size;
uniform vec2 u_view_range;
varying vec4 v_near;
varying vec4 v_far;

void main() {
    vec2 uv = (gl_FragCoord.xy - u_screen.xy) * u_screen.zw;
    vec4 depth = gbufferBytes(texture2D(u_gbuffer_depth, uv));
    if (gbufferEmpty(depth)) discard;
    float s = gbufferDepth(depth);
#if defined(VIEW_COLOR)
    gl_FragColor = vec4(texture2D(u_gbuffer_color, uv).rgb, 1.0);
#elif defined(VIEW_NORMAL)
    gl_FragColor = vec4(gbufferNormal(gbufferBytes(texture2D(u_gbuffer_normal, uv))) * 0.5 + 0.5, 1.0);
#elif defined(VIEW_POSITION)
    vec3 world = mix(v_near.xyz / v_near.w, v_far.xyz / v_far.w, s);
    gl_FragColor = vec4(clamp((world - u_bounds_min) / u_bounds_size, 0.0, 1.0), 1.0);
#else
    gl_FragColor = vec4(vec3(clamp(1.0 - (s - u_view_range.x) * u_view_range.y, 0.0, 1.0)), 1.0);
#endif
}
