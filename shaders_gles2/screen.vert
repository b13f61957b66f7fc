#version 100
// --shading deferred: a full-screen triangle (the main light, the G-buffer's views) or a point
// light's square (a_position.xy in NDC), with the pixel's ray: its points on the near and far
// planes, homogeneous (u_inv_view_proj), interpolated linearly and divided per pixel (the map from
// NDC to them is projective, so this is exact).
attribute vec4 a_position;
uniform mat4 u_inv_view_proj;
varying vec4 v_near;
varying vec4 v_far;

void main() {
    v_near = u_inv_view_proj * vec4(a_position.xy, -1.0, 1.0);
    v_far = u_inv_view_proj * vec4(a_position.xy, 1.0, 1.0);
    gl_Position = vec4(a_position.xy, 0.0, 1.0);
}
