#version 100
// Positions only: the light's pass (u_mvp = P_l V_l M) and the planar stencil pass
// (u_mvp = P V S M, S flattening onto the ground from the light). ALPHA_TEST: the texture
// coordinate too, for the cut-out's discard (alpha.glsl); the projection keeps it.
attribute vec3 a_position;
uniform mat4 u_mvp;
#ifdef ALPHA_TEST
attribute vec2 a_uv;
varying vec2 v_uv;
#endif

void main() {
#ifdef ALPHA_TEST
    v_uv = a_uv;
#endif
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
