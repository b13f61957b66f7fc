#version 100
// Positions only: the light's pass (u_mvp = P_l V_l M) and the planar stencil pass
// (u_mvp = P V S M, S flattening onto the ground from the light).
attribute vec3 a_position;
uniform mat4 u_mvp;

void main() {
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
