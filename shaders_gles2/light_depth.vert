#version 100
// A full-screen triangle that shows the shadow map (the sheet's "scaled for visualization"); with
// AT_FAR_PLANE on the far plane (depth 1: the mirror's depth cleared through the stencil).
attribute vec3 a_position;
varying vec2 v_uv;

void main() {
    v_uv = a_position.xy * 0.5 + 0.5;
#ifdef AT_FAR_PLANE
    gl_Position = vec4(a_position.xy, 1.0, 1.0);
#else
    gl_Position = vec4(a_position.xy, 0.0, 1.0);
#endif
}
