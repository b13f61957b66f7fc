#version 100
// --effects outline: the object pushed out along its normals by a width in pixels, the same at any
// depth. The normal is turned into a direction on the screen (the derivative of the projected
// position along it), and the clip-space position moved by the width in NDC times w, so after the
// divide by w the move is u_outline_width pixels wherever the vertex is. Scaling the model instead
// (the notes' way) widens the outline with the object's size and shrinks it with its distance.
// With u_outline_width 0 it is the object itself, computed as lit.vert computes it (the stencil
// mark of the object's pixels).
attribute vec3 a_position;
attribute vec3 a_normal;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;  // inverse transpose of the model matrix's upper 3x3
uniform mat4 u_view_proj;
uniform vec2 u_viewport;       // the target's size in pixels
uniform float u_outline_width; // pixels

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    vec4 clip = u_view_proj * world;
    // d(clip.xy / clip.w) along the normal, up to the positive factor 1 / w^2, in pixels.
    vec4 along = u_view_proj * vec4(u_normal_matrix * a_normal, 0.0);
    vec2 screen = (along.xy * clip.w - clip.xy * along.w) * u_viewport;
    float len = length(screen);
    vec2 dir = len > 0.0 ? screen / len : vec2(0.0);
    clip.xy += dir * (2.0 * u_outline_width / u_viewport) * clip.w;
    gl_Position = clip;
}
