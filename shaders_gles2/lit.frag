#version 100
// Camera pass: Phong lighting from one light, scaled by the light's visibility. Variants:
// SHADOW_MAP (with ENC_*, FILTER_*, and BIAS_AUTO with LIGHT_PERSPECTIVE or not; EMULATE_MEDIUMP;
// CASCADES N: N maps in one atlas, the one for the fragment's view depth looked up; CUBE: a point
// light's six faces in one atlas, the one in the fragment's direction looked up; AOV_CASCADES:
// the image tinted by that cascade's or face's colour), IN_SHADOW (planar shadow region: visibility 0),
// AREA_LOOKUP (Heckbert-Herf: the visibility averaged over light samples, from a target; --post
// shadow-blur: the visibility AOV blurred, from a target; with AREA_INTERLEAVE K, the counts of the
// (K + 1) x (K + 1) neighbourhood, a tent whose weights give each of the K x K pixel classes 1),
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
// side of the opening's plane, u_clip_plane < 0, discarded),
// POINT_LIGHTS K (--lights: K point lights from u_point_lights added, points.glsl), POINTS_ONLY
// (only those: forward's later batches, deferred's per-light squares, blended additively),
// GBUFFER_WRITE (--shading deferred's geometry pass: the surface into the G-buffer, gbuffer.glsl:
// all three targets with GBUFFER_MRT through gl_FragData, else the one GBUFFER_TARGET 0/1/2 names;
// RECEIVES: the object receives shadows), GBUFFER_READ (the lighting passes, with screen.vert: the
// surface read back from the G-buffer at the pixel instead of the varyings and the material),
// LIGHT_HORIZON (a light with a size, or one sample of it: the visibility times the part of the
// light above the receiver's horizon; GEOMETRIC_HORIZON: that horizon from the triangle's own
// normal, by dFdx/dFdy).
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

#ifdef GBUFFER_READ
#include "gbuffer.glsl"
uniform sampler2D u_gbuffer_color;
uniform sampler2D u_gbuffer_normal;
uniform sampler2D u_gbuffer_depth;
uniform vec4 u_screen;  // xy: the viewport's lower-left corner; zw: 1 / its size
varying vec4 v_near;
varying vec4 v_far;
#else
varying vec3 v_world;
varying vec3 v_normal;
varying vec2 v_uv;
#endif
#ifdef GBUFFER_WRITE
#include "gbuffer.glsl"
uniform vec4 u_depth_map;  // the ray position s = dot(xyz, world) + w: 0 on the near plane, 1 on the far
#ifndef GBUFFER_TARGET
#define GBUFFER_TARGET 0
#endif
#endif
#ifdef POINT_LIGHTS
#include "points.glsl"
#endif

#ifdef SHADOW_MAP
#include "shadow.glsl"
#if defined(CASCADES) && !defined(GBUFFER_READ)
varying vec4 v_cascade_eye;  // lit.vert: the light's eye space (xyz), the camera's view depth (w)
#elif defined(CASCADES) || defined(CUBE)
#elif defined(GBUFFER_READ)
uniform mat4 u_light_matrix;
#else
varying vec4 v_shadow_coord;
#endif
#endif
#ifdef AREA_LOOKUP
// Heckbert-Herf: the counts of lit light samples (area_add.frag), one channel per sample mod 4.
uniform sampler2D u_area;
uniform vec4 u_area_window;  // xy: the viewport's lower-left corner; zw: 1 / its size
uniform vec4 u_area_weights;  // what each channel counts: 255 / the samples in (area), (1, 0, 0, 0) (shadow-blur)
#ifdef AREA_INTERLEAVE
// Interleaved light samples: each pixel class (x mod K, y mod K) counted its own share of them.
// Offsets -K/2..K/2 on each axis, the two ends (the same class) weighted 1/2: every class weighs
// 1, so the sum is the lit counts of all the samples drawn (u_area_weights: 255 / their number),
// centred on the pixel.
vec4 areaCounts(vec2 pixel) {
    vec4 sum = vec4(0.0);
    for (int j = 0; j <= AREA_INTERLEAVE; ++j) {
        float wy = j == 0 || j == AREA_INTERLEAVE ? 0.5 : 1.0;
        for (int i = 0; i <= AREA_INTERLEAVE; ++i) {
            float w = (i == 0 || i == AREA_INTERLEAVE ? 0.5 : 1.0) * wy;
            vec2 offset = vec2(float(i - AREA_INTERLEAVE / 2), float(j - AREA_INTERLEAVE / 2));
            sum += w * texture2D(u_area, (pixel + offset) * u_area_window.zw);
        }
    }
    return sum;
}
#endif
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
#ifdef LIGHT_HORIZON
// A light with a size (PCSS), or one point of it (a Heckbert-Herf sample): the part of the light
// above the receiver's horizon. The light is a disc of radius u_light_size facing the point (a
// sphere light; a sun: tan of its angular radius at distance 1), as the area-light truth traces
// it; the receiver's tangent plane cuts it at t = D (n.l) / (R sqrt(1 - (n.l)^2)) radii from its
// centre, leaving the share (acos(-t) + t sqrt(1 - t^2)) / pi of its area above. R = 0 (a
// sample): lit only where n.l > 0. Where a light grazes a surface this is what the shadow map
// cannot say: the surface does not shadow itself in the map, but half the light is behind it.
uniform float u_light_size;
float lightHorizon(vec3 n, vec3 l, float distance) {
    float c = dot(n, l);
    if (u_light_size <= 0.0) return c > 0.0 ? 1.0 : 0.0;
    float s = sqrt(max(1.0 - c * c, 1e-8));
    float t = clamp(c * distance / (s * u_light_size), -1.0, 1.0);
    return (acos(-t) + t * sqrt(1.0 - t * t)) / 3.14159265;
}
#endif
#if defined(REFLECTED) || defined(CLIPPED)
uniform vec4 u_clip_plane;  // world (n, d): kept where n.p + d >= 0 (the mirror's camera side, the portal's far side)
#endif
#ifdef REFLECTED
uniform float u_reflectivity;
#endif

#ifdef PCSS_QUAD
// PCSS's filter over pixels as well as taps: a pixel's visibility averaged with its neighbours'
// across the 2x2 quad, read through dFdx and dFdy (OES_standard_derivatives), so three pixels'
// interleaved taps (shadow.glsl) count at the cost of one's. Called where control flow is uniform
// (GLSL ES 1.00 8.8: derivatives are undefined elsewhere). A neighbour's value is v + dFdx(v) from
// the quad's left column, v - dFdx(v) from its right, but only where dFdx was taken in this pixel's
// own row of a quad aligned to even coordinates: the spec lets a context approximate (coarse
// derivatives take one row for the whole quad, as softpipe does), so the probe p.x (1 + p.y), whose
// difference across the pair is 1 + p.y exactly there, tells; elsewhere that neighbour is left
// out. The same for dFdy. Averaging moves a pixel's filter a third of a pixel towards its
// neighbours, which costs more than the noise it removes where the penumbra is narrow on screen,
// so the share fades in as the filter's radius grows from 2 to 10 pixels (docs/soft.md).
float pcssQuadShare(float v) {
    vec2 p = mod(floor(gl_FragCoord.xy), 2.0);
    vec4 dx = dFdx(vec4(v, p.x + p.x * p.y, g_pcss_c));
    vec4 dy = dFdy(vec4(v, p.y + p.x * p.y, g_pcss_c));
    float share = clamp((g_pcss_r / max(max(length(dx.zw), length(dy.zw)), 1e-6) - 2.0) / 8.0, 0.0, 1.0);
    float wx = abs(dx.y - 1.0 - p.y) < 0.5 ? share : 0.0;
    float wy = abs(dy.y - 1.0 - p.x) < 0.5 ? share : 0.0;
    return (v + wx * (v + (1.0 - 2.0 * p.x) * dx.x) + wy * (v + (1.0 - 2.0 * p.y) * dy.x)) / (1.0 + wx + wy);
}
#endif

void main() {
#ifdef GBUFFER_READ
    vec2 gUv = (gl_FragCoord.xy - u_screen.xy) * u_screen.zw;
    vec4 gDepth = gbufferBytes(texture2D(u_gbuffer_depth, gUv));
    if (gbufferEmpty(gDepth)) discard;
    vec3 world = mix(v_near.xyz / v_near.w, v_far.xyz / v_far.w, gbufferDepth(gDepth));
    vec3 n = gbufferNormal(gbufferBytes(texture2D(u_gbuffer_normal, gUv)));
    vec4 gColor = texture2D(u_gbuffer_color, gUv);
    vec4 base = vec4(gColor.rgb, 1.0);
    float specularStrength = gColor.a;
    float shininess = gbufferShininess(gDepth);
    bool receives = gbufferReceives(gDepth);
#else
    vec3 world = v_world;
#if defined(REFLECTED) || defined(CLIPPED)
    if (dot(u_clip_plane, vec4(world, 1.0)) < 0.0) discard;
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
    vec4 base = u_base_color;
#ifdef TEXTURED
    base *= texture2D(u_base_texture, v_uv);
#endif
    float specularStrength = u_specular;
    float shininess = u_shininess;
    bool receives = true;
#endif

#if defined(GBUFFER_WRITE)
    float s = dot(u_depth_map.xyz, world) + u_depth_map.w;
#ifdef RECEIVES
    bool receivesShadows = true;
#else
    bool receivesShadows = false;
#endif
#if defined(GBUFFER_MRT)
    gl_FragData[0] = gbufferOut(gbufferColorBytes(base.rgb, specularStrength));
    gl_FragData[1] = gbufferOut(gbufferNormalBytes(n));
    gl_FragData[2] = gbufferOut(gbufferDepthBytes(s, shininess, receivesShadows));
#elif GBUFFER_TARGET == 0
    gl_FragColor = gbufferOut(gbufferColorBytes(base.rgb, specularStrength));
#elif GBUFFER_TARGET == 1
    gl_FragColor = gbufferOut(gbufferNormalBytes(n));
#else
    gl_FragColor = gbufferOut(gbufferDepthBytes(s, shininess, receivesShadows));
#endif
#elif defined(POINTS_ONLY)
    gl_FragColor = vec4(pointLights(world, n, base.rgb), 1.0);
#else
    vec3 l = normalize(u_light.xyz - world * u_light.w);
    float visibility = 1.0;
#if defined(SHADOW_MAP) && defined(CASCADES)
#ifdef GBUFFER_READ
    if (receives) visibility = shadowCascades((u_cascade_light * vec4(world, 1.0)).xyz, dot(u_cascade_depth, vec4(world, 1.0)), n);
#else
    if (receives) visibility = shadowCascades(v_cascade_eye.xyz, v_cascade_eye.w, n);
#endif
#elif defined(SHADOW_MAP) && defined(CUBE)
    if (receives) visibility = shadowCube(world, n);
#elif defined(SHADOW_MAP) && defined(GBUFFER_READ)
    if (receives) visibility = shadowVisibility(u_light_matrix * vec4(world, 1.0), n);
#elif defined(SHADOW_MAP)
    visibility = shadowVisibility(v_shadow_coord, n);
#elif defined(IN_SHADOW)
    visibility = 0.0;
#elif defined(AREA_LOOKUP)
#ifdef AREA_INTERLEAVE
    vec4 counts = areaCounts(gl_FragCoord.xy - u_area_window.xy);
#else
    vec4 counts = texture2D(u_area, (gl_FragCoord.xy - u_area_window.xy) * u_area_window.zw);
#endif
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
#ifdef PCSS_QUAD
    visibility = pcssQuadShare(visibility);
#endif

#ifdef LIGHT_HORIZON
    vec3 horizonNormal = n;
#ifdef GEOMETRIC_HORIZON
    // The triangle's own plane: world is linear over it, so its differences across the pixel quad
    // span the plane whichever way the context takes them (coarse or fine, GLSL ES 1.00 8.8 with
    // OES_standard_derivatives). Turned to the interpolated normal's side; a degenerate quad keeps n.
    vec3 facet = cross(dFdx(world), dFdy(world));
    if (dot(facet, facet) > 0.0) {
        facet = normalize(facet);
        horizonNormal = dot(facet, n) < 0.0 ? -facet : facet;
    }
#endif
    visibility *= lightHorizon(horizonNormal, l, u_light.w > 0.0 ? length(u_light.xyz - world) : 1.0);
#endif

#if defined(AOV_VISIBILITY) && defined(LIGHT_AMBIENT)
    gl_FragColor = vec4(0.0, 0.0, 0.0, 1.0);
#elif defined(AOV_VISIBILITY) && defined(LIGHT_DIRECT)
    gl_FragColor = vec4(vec3(visibility * u_light_weight), 1.0);
#elif defined(AOV_VISIBILITY)
    gl_FragColor = vec4(vec3(visibility), 1.0);
#else
    vec3 v = normalize(u_camera_pos - world);
    float diffuse = max(dot(n, l), 0.0);
    float specular = 0.0;
    if (diffuse > 0.0) specular = specularStrength * pow(max(dot(reflect(-l, n), v), 0.0), shininess);
    float cone = 1.0;
#ifdef LIGHT_SPOT
    cone = smoothstep(u_spot_cos.x, u_spot_cos.y, dot(-l, u_spot_direction));
#endif
    vec3 direct = (base.rgb * diffuse + vec3(specular)) * u_light_color * (visibility * cone);
#ifdef POINT_LIGHTS
    direct += pointLights(world, n, base.rgb);
#endif
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
    // What an RGBA8 target keeps (GLES 2.0 3.8.2 clamps the colour to [0,1] before blending and
    // storing), made explicit: the mirror's share below is of the colour seen, and Mesa softpipe,
    // which blends over the unclamped colour an earlier pass left in its tile cache, agrees.
    gl_FragColor = clamp(gl_FragColor, 0.0, 1.0);
#ifdef REFLECTED
    gl_FragColor = vec4(gl_FragColor.rgb * u_reflectivity, u_reflectivity);
#endif
#if defined(AOV_CASCADES) && (defined(CASCADES) || defined(CUBE))
    gl_FragColor.rgb = mix(gl_FragColor.rgb, g_cascade_tint, 0.5);
#elif defined(AOV_CASCADES)
    gl_FragColor.rgb = mix(gl_FragColor.rgb, vec3(1.0, 0.2, 0.2), 0.5);
#endif
#endif
#endif
}
