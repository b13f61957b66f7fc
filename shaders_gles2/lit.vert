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
#ifdef BIAS_PER_VERTEX
// The auto bias's slope term (shadow.glsl's shadowBiasFloor, there per fragment): across the
// kernel's reach, how far the receiver's plane moves in window depth,
// across * n f / ((f - n) |n.p|), p the point in the light's eye space. |n.p| is the same at every
// point of a plane, so on a flat face the term is the same at its vertices and the interpolation
// is exact; on a curved one it is interpolated between its vertices' normals. |n.p| is floored at
// 0.05 |p| as there (the hard lookup beyond 2048 lower: bias_floor.glsl). Set for one map in the
// forward pass (plan/variants.cpp); cascades, the cube, PCSS and the deferred pass keep it per
// fragment. These uniforms are this stage's alone: the fragment stage does not declare them.
#include "bias_floor.glsl"
uniform mat3 u_light_rotation;  // world -> light eye space
uniform vec4 u_bias_slope;      // x, y: tan of the half-angles (perspective) or half-extents; z, w: near, far
uniform vec2 u_bias_kernel;     // x: one texel in NDC (2 / map size); y: the kernel's reach in texels per axis
#ifdef LIGHT_PERSPECTIVE
uniform vec2 u_bias_center;     // tan at the middle of the window (an asymmetric frustum)
#endif
varying float v_bias_slope;

float biasSlope(vec3 normal, vec4 c) {
    vec3 nl = u_light_rotation * normalize(normal);
    float n = u_bias_slope.z;
    float f = u_bias_slope.w;
    float across = (abs(nl.x) * u_bias_slope.x + abs(nl.y) * u_bias_slope.y) * u_bias_kernel.x * u_bias_kernel.y;
    float floorFacing = SHADOW_FACING_FLOOR(u_bias_kernel.x);
#ifdef LIGHT_PERSPECTIVE
    // The point in the light's eye space from its map coordinates (x, y in [0, w], w the distance
    // along the light's axis): linear, no division, right behind the light too.
    vec3 p = vec3((2.0 * c.x - c.w) * u_bias_slope.x + c.w * u_bias_center.x,
                  (2.0 * c.y - c.w) * u_bias_slope.y + c.w * u_bias_center.y, -c.w);
    return across * n * f / ((f - n) * max(abs(dot(nl, p)), floorFacing * length(p)));
#else
    return across / max(abs(nl.z), floorFacing) / (f - n);
#endif
}
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
#ifdef BIAS_PER_VERTEX
    v_bias_slope = biasSlope(v_normal, v_shadow_coord);
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
