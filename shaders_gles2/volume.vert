#version 100
// Shadow volumes (and any triangles made per frame): homogeneous world points, w = 0 at infinity,
// through the camera's view-projection (an infinite far plane, so nothing at infinity is clipped).
attribute vec4 a_position;
uniform mat4 u_mvp;

void main() {
    gl_Position = u_mvp * a_position;
}
