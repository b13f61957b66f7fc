#version 100
// Camera pass: Phong lighting from one light, scaled by the light's visibility. Variants:
// SHADOW_MAP (with ENC_*, FILTER_*, and BIAS_AUTO with LIGHT_PERSPECTIVE or not; EMULATE_MEDIUMP), IN_SHADOW (planar shadow region: visibility 0),
// AREA_LOOKUP (Heckbert-Herf: the visibility averaged over light samples, from a target; --post
// shadow-blur: the visibility AOV blurred, from a target),
// GOOCH_TEXTURE (Gooch's shadow texture, black casters on white, sampled linearly at GOOCH_TAPS
// offsets over the penumbra's width at this receiver's distance from the light), LIGHT_AMBIENT /
// LIGHT_DIRECT (only that term: Gooch's planes add the direct light once per plane that lights the
// pixel, scaled by u_light_weight), TEXTURED (base colour texture), LIGHT_SPOT (cone falloff), AOV_VISIBILITY (write visibility
// as grey instead of colour), ALPHA_TEST (glTF MASK: alpha below u_alpha_cutoff discarded, before
// any output, so the visibility AOV sees through the gaps too), ALPHA_BLEND (glTF BLEND: the alpha
// written for the blend), DOUBLE_SIDED (a back face is lit with its normal turned to the viewer),
// REFLECTED (--effects mirror: the scene seen in the mirror through the reflected camera; what lies
// behind the mirror's plane, u_clip_plane < 0, discarded: GLES2 has no user clip planes; the colour
// premultiplied by u_reflectivity, its alpha, for the blend over the mirror's own colour),
// CLIPPED (--effects portal: the other scene seen through the opening; what lies on the camera's
// side of the opening's plane, u_clip_plane < 0, discarded).
#include "precision.glsl"

uniform vec4 u_base_color;
uniform vec4 u_light;  // xyz = position when w = 1; direction towards the light when w = 0
uniform vec3 u_light_color;
uniform vec3 u_camera_pos;
uniform float u_ambient;
uniform float u_specular;
uniform float u_shininess;

#ifdef TEXTURED
uniform sampler2D u_base_texture;
#endif
#ifdef ALPHA_TEST
uniform float u_alpha_cutoff;
#endif
#ifdef LIGHT_SPOT
uniform vec3 u_spot_direction;  // where the light travels
uniform vec2 u_spot_cos;        // cos(outer cone), cos(inner cone)
#endif

varying vec3 v_world;
varying vec3 v_normal;
varying vec2 v_uv;

#ifdef SHADOW_MAP
#include "shadow.glsl"
varying vec4 v_shadow_coord;
#endif
#ifdef AREA_LOOKUP
// Heckbert-Herf: the counts of lit light samples (area_add.frag), one channel per sample mod 4.
uniform sampler2D u_area;
uniform vec4 u_area_window;  // xy: the viewport's lower-left corner; zw: 1 / its size
uniform vec4 u_area_weights;  // what each channel counts: 255 / the samples in (area), (1, 0, 0, 0) (shadow-blur)
#endif

#ifdef GOOCH_TEXTURE
uniform sampler2D u_gooch;
uniform vec2 u_gooch_scale;   // texture units per unit of tangent (perspective) or world (orthographic), x and y
uniform vec3 u_gooch_spread;  // the taps' radius at light distance d: max(x d + y + z / d, 0) (times the scale)
varying vec4 v_gooch_coord;
varying float v_gooch_depth;
vec2 g_gooch_uv;
vec2 g_gooch_radius;
float goochTap(vec2 offset) { return texture2D(u_gooch, g_gooch_uv + offset * g_gooch_radius).r; }
#endif
#if defined(LIGHT_DIRECT)
uniform float u_light_weight;
#endif
#if defined(REFLECTED) || defined(CLIPPED)
uniform vec4 u_clip_plane;  // world (n, d): kept where n.p + d >= 0 (the mirror's camera side, the portal's far side)
#endif
#ifdef REFLECTED
uniform float u_reflectivity;
#endif

void main() {
#if defined(REFLECTED) || defined(CLIPPED)
    if (dot(u_clip_plane, vec4(v_world, 1.0)) < 0.0) discard;
#endif
#if defined(ALPHA_TEST) || defined(ALPHA_BLEND)
    float alpha = u_base_color.a;
#ifdef TEXTURED
    alpha *= texture2D(u_base_texture, v_uv).a;
#endif
#ifdef ALPHA_TEST
    if (alpha < u_alpha_cutoff) discard;
#endif
#endif
    vec3 n = normalize(v_normal);
#ifdef DOUBLE_SIDED
    if (!gl_FrontFacing) n = -n;
#endif
    vec3 l = normalize(u_light.xyz - v_world * u_light.w);
    float visibility = 1.0;
#if defined(SHADOW_MAP)
    visibility = shadowVisibility(v_shadow_coord, n);
#elif defined(IN_SHADOW)
    visibility = 0.0;
#elif defined(AREA_LOOKUP)
    vec4 counts = texture2D(u_area, (gl_FragCoord.xy - u_area_window.xy) * u_area_window.zw);
    visibility = min(dot(counts, u_area_weights), 1.0);
#elif defined(GOOCH_TEXTURE)
    // Behind the light or outside its frustum: lit.
    if (v_gooch_coord.w > 0.0) {
        g_gooch_uv = v_gooch_coord.xy / v_gooch_coord.w;
        if (all(greaterThanEqual(g_gooch_uv, vec2(0.0))) && all(lessThanEqual(g_gooch_uv, vec2(1.0)))) {
            float d = max(v_gooch_depth, 1e-4);
            g_gooch_radius = u_gooch_scale * max(u_gooch_spread.x * d + u_gooch_spread.y + u_gooch_spread.z / d, 0.0);
            visibility = GOOCH_SUM(goochTap) / float(GOOCH_TAPS);
        }
    }
#endif

#if defined(AOV_VISIBILITY) && defined(LIGHT_AMBIENT)
    gl_FragColor = vec4(0.0, 0.0, 0.0, 1.0);
#elif defined(AOV_VISIBILITY) && defined(LIGHT_DIRECT)
    gl_FragColor = vec4(vec3(visibility * u_light_weight), 1.0);
#elif defined(AOV_VISIBILITY)
    gl_FragColor = vec4(vec3(visibility), 1.0);
#else
    vec4 base = u_base_color;
#ifdef TEXTURED
    base *= texture2D(u_base_texture, v_uv);
#endif
    vec3 v = normalize(u_camera_pos - v_world);
    float diffuse = max(dot(n, l), 0.0);
    float specular = 0.0;
    if (diffuse > 0.0) specular = u_specular * pow(max(dot(reflect(-l, n), v), 0.0), u_shininess);
    float cone = 1.0;
#ifdef LIGHT_SPOT
    cone = smoothstep(u_spot_cos.x, u_spot_cos.y, dot(-l, u_spot_direction));
#endif
    vec3 direct = (base.rgb * diffuse + vec3(specular)) * u_light_color * (visibility * cone);
#if defined(LIGHT_AMBIENT)
    gl_FragColor = vec4(base.rgb * u_ambient, 1.0);
#elif defined(LIGHT_DIRECT)
    gl_FragColor = vec4(direct * u_light_weight, 1.0);
#else
    gl_FragColor = vec4(base.rgb * u_ambient + direct, 1.0);
#endif
#ifdef ALPHA_BLEND
    gl_FragColor.a = alpha;
#endif
#ifdef REFLECTED
    gl_FragColor = vec4(gl_FragColor.rgb * u_reflectivity, u_reflectivity);
#endif
#endif
}
