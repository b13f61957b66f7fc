#version 100
// Camera pass: world-space position and normal for lighting, and with SHADOW_MAP the position
// in the shadow map's texture space, (u_l, v_l, z_l, w) = B P_l V_l p_world (CASCADES: the point in
// the light's eye space and the camera's view depth, the cascade picked per fragment; CUBE: looked
// up per fragment from the world position).
attribute vec3 a_position;
attribute vec3 a_normal;
attribute vec2 a_uv;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;  // inverse transpose of the model matrix's upper 3x3
uniform mat4 u_view_proj;

// The same position in every variant: forward's later light batches draw the surfaces again, depth equal.
invariant gl_Position;

varying vec3 v_world;
varying vec3 v_normal;
varying vec2 v_uv;

#if defined(SHADOW_MAP) && !defined(CASCADES) && !defined(CUBE)
uniform mat4 u_light_matrix;
varying vec4 v_shadow_coord;
#endif
#if defined(SHADOW_MAP) && defined(CASCADES)
// Both are affine in the world position, so interpolating them is exact: the fragment shader is
// spared a matrix per pixel.
uniform mat4 u_cascade_light;   // world -> the light's eye space
uniform vec4 u_cascade_depth;   // camera view depth of a world point p: dot(xyz, p) + w
varying vec4 v_cascade_eye;     // xyz: the light's eye space; w: the camera's view depth
#endif
#ifdef GOOCH_TEXTURE
uniform mat4 u_gooch_matrix;  // world -> the shadow texture's (u, v, z, w)
uniform vec4 u_gooch_depth;   // world -> distance from the light along its view axis
varying vec4 v_gooch_coord;
varying float v_gooch_depth;
#endif

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    v_uv = a_uv;
#if defined(SHADOW_MAP) && !defined(CASCADES) && !defined(CUBE)
    v_shadow_coord = u_light_matrix * world;
#endif
#if defined(SHADOW_MAP) && defined(CASCADES)
    v_cascade_eye = vec4((u_cascade_light * world).xyz, dot(u_cascade_depth, world));
#endif
#ifdef GOOCH_TEXTURE
    v_gooch_coord = u_gooch_matrix * world;
    v_gooch_depth = dot(u_gooch_depth, world);
#endif
    gl_Position = u_view_proj * world;
}
