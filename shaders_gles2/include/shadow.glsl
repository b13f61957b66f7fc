// Shadow-map lookup for the camera pass. The encoding (ENC_R8, ENC_RGBA, else a depth texture),
// the filter's kernel (PCF_TAPS with PCF_SUM, or PCF_EARLY_EXIT's split) and the bias rule
// (BIAS_AUTO or a constant) are chosen by #define when the variant is compiled, so no shader
// branches on settings at run time.
#include "pack.glsl"

#ifdef CUBE_MAP
uniform samplerCube u_shadow_cube;  // --cube-layout cubemap: the cube's faces (CUBE)
#else
uniform sampler2D u_shadow_map;
#endif
#ifndef LAB  // the lab declares it in pack.glsl, before its functions
uniform vec2 u_texmapscale;  // 1/width, 1/height of the shadow map: one texel in texture space
#endif
uniform float u_bias;        // the fragment is in shadow if z_l > depth + bias (auto: the constant part)
#if defined(CASCADES) || defined(CUBE)
// Cascaded shadow maps (CASCADES maps) or a point light's cube (CUBE: six faces), tiles of one
// atlas. A lookup works in the coordinates of the cascade's or face's own map, [0, 1]
// (u_texmapscale: one texel of a tile), and reads the atlas through shadowDepth, clamped to the
// tile's texel centres (each tile acts as a map with clamped edges). The tile is copied here
// before its lookup (cascadeLookup, shadowCube).
vec4 g_shadow_tile;   // xy: the tile's lower-left corner in the atlas, zw: its size (texture units)
#endif
#ifdef CASCADES
vec4 g_cascade_slope;  // the cascade's u_bias_slope
#define SHADOW_SLOPE g_cascade_slope
#elif (defined(BIAS_AUTO) && !defined(BIAS_PER_VERTEX)) || defined(FILTER_PCSS)
uniform vec4 u_bias_slope;      // x, y: tan of the half-angles (perspective) or half-extents
                                // (orthographic); z, w: the light's near and far
#define SHADOW_SLOPE u_bias_slope
#endif

#ifdef CUBE
// A point light's cube: face i looks along +x, -x, +y, -y, +z, -z (shadow::cube_face_rotation).
// Every face has the same perspective projection, a little wider than 90 degrees (the guard band
// that lets a filter near a face's edge read the neighbouring directions' depth).
uniform vec3 u_cube_light;     // the light's position
uniform vec4 u_cube_tile[6];   // each face's tile (g_shadow_tile); zw = 0: the face was not drawn
uniform vec3 u_cube_depth;     // x: 0.5 / the window's half-extent in tangent units; window depth = y - z / depth
int g_cube_face;               // the face of the lookup

// A direction from the light in face g_cube_face's eye space (the face looks down -z).
vec3 cubeFaceEye(vec3 d) {
    if (g_cube_face == 0) return vec3(d.z, d.y, -d.x);
    if (g_cube_face == 1) return vec3(-d.z, d.y, d.x);
    if (g_cube_face == 2) return vec3(-d.x, -d.z, -d.y);
    if (g_cube_face == 3) return vec3(-d.x, d.z, d.y);
    if (g_cube_face == 4) return vec3(-d.x, d.y, -d.z);
    return d;
}
#define SHADOW_ROTATE(v) cubeFaceEye(v)
#define SHADOW_CENTER vec2(0.0)

#ifdef CUBE_MAP
// cubeFaceEye undone: a direction in face g_cube_face's eye space back in the world.
vec3 cubeFaceWorld(vec3 e) {
    if (g_cube_face == 0) return vec3(-e.z, e.y, e.x);
    if (g_cube_face == 1) return vec3(e.z, e.y, -e.x);
    if (g_cube_face == 2) return vec3(-e.x, -e.z, -e.y);
    if (g_cube_face == 3) return vec3(-e.x, e.z, e.y);
    if (g_cube_face == 4) return vec3(-e.x, e.y, -e.z);
    return e;
}
#endif
#endif

#if (defined(BIAS_AUTO) && !defined(BIAS_PER_VERTEX)) || defined(PCSS_LAYERED)
// The light's eye space, for the receiver's plane (the auto bias's slope, PCSS's layered blocker
// search). A cube has its own (cubeFaceEye, centre 0).
#ifndef CUBE
uniform mat3 u_light_rotation;  // world -> light eye space
#define SHADOW_ROTATE(v) (u_light_rotation * (v))
#ifdef LIGHT_PERSPECTIVE
uniform vec2 u_bias_center;     // tan at the middle of the window (an asymmetric frustum; 0 when symmetric)
#define SHADOW_CENTER u_bias_center
#endif
#endif
#ifdef LIGHT_PERSPECTIVE
// The ray from the light through the lookup c, in its eye space (z = -1).
vec3 lightRay(vec3 c) {
    return vec3((2.0 * c.x - 1.0) * SHADOW_SLOPE.x + SHADOW_CENTER.x, (2.0 * c.y - 1.0) * SHADOW_SLOPE.y + SHADOW_CENTER.y, -1.0);
}
#endif
#endif

#ifdef BIAS_PER_VERTEX
// The auto bias's slope term from lit.vert (one map, the forward pass; see there): constant over a
// flat face, so a vertex computes it for the whole face.
varying float v_bias_slope;
float shadowBias(vec3 normal, vec3 c) { return u_bias + v_bias_slope; }
#elif defined(BIAS_AUTO)
// Receiver-plane slope bias, computed from the receiver's normal in the light's eye space: across
// the kernel's reach, how far does the surface move along the light's axis? For a plane with
// normal n hit along the ray r = (c_x + x tan_x, c_y + y tan_y, -1) (perspective; c: the window's
// middle, 0 for a symmetric frustum) the eye depth changes per
// unit of NDC x by z n_x tan_x / |n.r| (y likewise); orthographic: half_w n_x / |n_z|. Converted to
// window depth by d(z_window)/d(z_eye). |n.r| is floored at 0.05 |r| (a surface within 3 degrees
// of edge-on to the light, barely lit anyway), which caps the slope at 20. The hard lookup on a map
// finer than 2048 texels lowers that floor with the texel (to 0.025 from 4096 on), so the capped
// bias stays the 2048 map's: near the terminator of a tessellated surface the facet is steeper than
// its interpolated normal says, and that gap does not shrink with the texel (docs/precision.md: the
// course's acne rose at 4096 without it). PCF and PCSS keep 0.05: their wider reach peter-pans.
uniform vec2 u_bias_kernel;     // x: one texel in NDC (2 / map size); y: the kernel's reach in texels per axis

// reach: how far the kernel reaches, in texels per axis; floorFacing: the floor of |n.r| / |r|.
#include "bias_floor.glsl"
float shadowBiasFloor(vec3 normal, vec3 c, float reach, float floorFacing) {
    vec3 nl = SHADOW_ROTATE(normal);
    float n = SHADOW_SLOPE.z;
    float f = SHADOW_SLOPE.w;
    float across = (abs(nl.x) * SHADOW_SLOPE.x + abs(nl.y) * SHADOW_SLOPE.y) * u_bias_kernel.x * reach;
#ifdef LIGHT_PERSPECTIVE
    vec3 ray = lightRay(c);
    float facing = max(abs(dot(nl, ray)), floorFacing * length(ray));
    float zEye = 2.0 * n * f / (f + n - (2.0 * c.z - 1.0) * (f - n));
    float dz = zEye * across / facing;
    return u_bias + dz * n * f / ((f - n) * zEye * zEye);
#else
    float facing = max(abs(nl.z), floorFacing);
    return u_bias + across / facing / (f - n);
#endif
}
float shadowBiasReach(vec3 normal, vec3 c, float reach) { return shadowBiasFloor(normal, c, reach, 0.05); }
float shadowBias(vec3 normal, vec3 c) { return shadowBiasFloor(normal, c, u_bias_kernel.y, SHADOW_FACING_FLOOR(u_bias_kernel.x)); }
#else
float shadowBiasReach(vec3 normal, vec3 c, float reach) { return u_bias; }
float shadowBias(vec3 normal, vec3 c) { return u_bias; }
#endif

#ifdef CUBE_MAP
// A point of face g_cube_face's map read from the cube map by its direction: the faces were drawn
// turned 180 degrees about their axes (shadow::fit_cube), which is how textureCube lays out a face,
// so the direction finds the texel drawn for it. Past the face's edge (a filter's taps) it finds
// the next face's, whose window depth is along that face's axis: the point it holds is turned
// into this face's window depth (along this face's axis, 1 / m of the other's).
float shadowDepth(vec2 uv) {
    vec3 d = cubeFaceWorld(vec3((uv - 0.5) / u_cube_depth.x, -1.0));
#ifdef ENC_RGBA
    float stored = unpackDepth(textureCube(u_shadow_cube, d));
#else
    float stored = textureCube(u_shadow_cube, d).r;
#endif
    vec3 a = abs(d);
    float m = max(a.x, max(a.y, a.z));
    // window depth = y - z / depth: the other face's depth z / (y - stored) is m times this face's.
    return MP(m <= 1.0 ? stored : u_cube_depth.y - m * (u_cube_depth.y - stored));
}
#else
float shadowDepth(vec2 uv) {
#if defined(CASCADES) || defined(CUBE)
    uv = g_shadow_tile.xy + clamp(uv, 0.5 * u_texmapscale, 1.0 - 0.5 * u_texmapscale) * g_shadow_tile.zw;
#endif
#ifdef ENC_RGBA
    return unpackDepth(texture2D(u_shadow_map, uv));
#else
    // ENC_R8 writes depth to red; a depth texture also returns it in red.
    return MP(texture2D(u_shadow_map, uv).r);
#endif
}
#endif

#ifdef LAB
// The shader lab: the sheet's test on the sheet's lookup (plan/snippets.h), one 2D map.
float litAt(vec2 uv, float z, float bias) {
    return shadowTest(z, unpackDepth(offset_lookup(u_shadow_map, vec3(uv, z), vec2(0.0))), bias);
}
#else
float litAt(vec2 uv, float z, float bias) {
    return z > MP(shadowDepth(uv) + bias) ? 0.0 : 1.0;
}
#endif

#ifdef PCF_TAPS
// One tap of the kernel: `offset` in texels from the lookup point.
float litTap(vec2 offset, vec2 uv, float z, float bias) {
#ifdef LAB
    return shadowTest(z, unpackDepth(offset_lookup(u_shadow_map, vec3(uv, z), offset)), bias);
#else
    return litAt(uv + offset * u_texmapscale, z, bias);
#endif
}

// 1.0 where the light reaches, 0.0 in shadow, PCF fractions in between. Points outside the
// light's frustum are lit: the map says nothing about them. normal: the receiver's unit normal in
// world space (for BIAS_AUTO). The kernel's taps (PCF_TAPS, PCF_SUM) are written into the variant
// from shadow::pcf_offsets (plan/variants.cpp): hard is one tap at the lookup point, PCF 2x2 four
// at +-0.5 texel, PCF 4x4 sixteen at +-0.5 and +-1.5 texels (Bunnell & Pellacini).
// PCF_EARLY_EXIT (PCF 4x4 unless --pcf-kernel full): the 4 corner taps (PCF_CORNERS) first; where
// they agree the fragment is taken as wholly lit or wholly shadowed and the other 12 taps
// (PCF_REST) are not needed. Where they disagree the sum is that of the full kernel. Whether the 12
// are then skipped is the driver's business: llvmpipe runs both sides of the branch under a lane
// mask, SwiftShader skips the samples of a 2x2 quad whose corners all agree, a GPU those of a warp
// (docs/pcf_early_exit.md).
float shadowVisibility(vec4 shadowCoord, vec3 normal) {
    if (shadowCoord.w <= 0.0) return 1.0;
    vec3 c = MP(shadowCoord.xyz / shadowCoord.w);
    if (c.x < 0.0 || c.x > 1.0 || c.y < 0.0 || c.y > 1.0 || c.z < 0.0 || c.z > 1.0) return 1.0;
    float bias = shadowBias(normal, c);
#ifdef PCF_EARLY_EXIT
    float corners = PCF_CORNERS(litTap, c.xy, c.z, bias);
    if (corners == 0.0 || corners == 4.0) return corners * 0.25;
    return (corners + PCF_REST(litTap, c.xy, c.z, bias)) / float(PCF_TAPS);
#else
    return PCF_SUM(litTap, c.xy, c.z, bias) / float(PCF_TAPS);
#endif
}
#endif

#ifdef FILTER_PCSS
// Percentage-closer soft shadows (Fernando 2005) for a light of a size: (1) the blocker search,
// PCSS_SEARCH_TAPS taps over the part of the map where something between the receiver and the
// light's disc can be (the cone from the receiver to the disc, at the light's near plane);
// (2) the blockers' mean depth gives the penumbra's half-width by similar triangles (the same cone
// at that depth); (3) a PCF of PCSS_FILTER_TAPS taps over that width, its slope bias reaching as
// far. The taps are Vogel discs turned by a per-pixel angle (interleaved gradient noise), so a
// few taps give noise rather than bands. Every encoding: each tap reads shadowDepth(). The CPU
// mirror of the radii: shadow::pcss_radii (shadow/pcf.h).
uniform vec2 u_pcss;  // x: the light's size (perspective: radius in world units; orthographic:
                      // tan of its angular radius); y: the largest radius searched, in texels

// Depth along the light's axis (eye space) of a window depth.
float lightEyeDepth(float z) {
    float n = SHADOW_SLOPE.z;
    float f = SHADOW_SLOPE.w;
#ifdef LIGHT_PERSPECTIVE
    return 2.0 * n * f / (f + n - (2.0 * z - 1.0) * (f - n));
#else
    return n + z * (f - n);
#endif
}

// The radius in texels (per axis) of the cone from a receiver at eye depth zr to the light's
// disc, where it crosses eye depth d.
vec2 coneTexels(float zr, float d) {
#ifdef LIGHT_PERSPECTIVE
    float k = u_pcss.x * max(zr - d, 0.0) / (zr * d);
#else
    float k = u_pcss.x * max(zr - d, 0.0);
#endif
    vec2 r = k / (2.0 * SHADOW_SLOPE.xy) / u_texmapscale;
    return min(r, vec2(u_pcss.y));
}

#ifdef PCSS_LAYERED
// The cone from a receiver at eye depth zr to the light's disc, in window depth: a point rho
// from the receiver's ray (tangent units for a perspective light, world units for an
// orthographic one) is inside it at window depths up to x - y rho. Perspective: the cone's
// radius S (zr - e) / (zr e) >= rho while e <= S zr / (S + rho zr), and window depth
// f / (f - n) (1 - n / e) is then f / (f - n) (1 - n / zr) - f n rho / ((f - n) S). Orthographic:
// S (zr - e) >= rho while e <= zr - rho / S, window depth (e - n) / (f - n).
vec2 pcssConeDepth(float zr) {
    float n = SHADOW_SLOPE.z;
    float f = SHADOW_SLOPE.w;
    float size = max(u_pcss.x, 1e-6);
#ifdef LIGHT_PERSPECTIVE
    return vec2(f / (f - n) * (1.0 - n / zr), f * n / ((f - n) * size));
#else
    return vec2((zr - n) / (f - n), 1.0 / ((f - n) * size));
#endif
}

// The receiver's plane around the lookup: its window depth per texel of offset along the map's x
// and y, from its normal in the light's eye space (signed, where shadowBiasReach takes the
// absolute slope). Perspective: the plane n.p = k hit along the ray r = (x tan_x + c_x,
// y tan_y + c_y, -1) is at eye depth z = k / (n.r), so dz/dx = -z n_x tan_x / (n.r); orthographic:
// dz/dx = n_x half_w / n_z. |n.r| is floored as there (a surface edge-on to the light).
vec2 receiverSlope(vec3 normal, vec3 c) {
    vec3 nl = SHADOW_ROTATE(normal);
    float n = SHADOW_SLOPE.z;
    float f = SHADOW_SLOPE.w;
    vec2 ndc = 2.0 * u_texmapscale;  // one texel in NDC
#ifdef LIGHT_PERSPECTIVE
    vec3 ray = lightRay(c);
    float nr = dot(nl, ray);
    float floorNr = 0.05 * length(ray);
    nr = nr < 0.0 ? min(nr, -floorNr) : max(nr, floorNr);
    float zEye = lightEyeDepth(c.z);
    return -zEye * nl.xy * SHADOW_SLOPE.xy / nr * ndc * n * f / ((f - n) * zEye * zEye);
#else
    float nz = nl.z < 0.0 ? min(nl.z, -0.05) : max(nl.z, 0.05);
    return nl.xy * SHADOW_SLOPE.xy / nz * ndc / (f - n);
#endif
}
#endif

// One turn of the golden angle: the step from one Vogel tap to the next.
const vec2 kGolden = vec2(-0.7373688, 0.6754903);
vec2 turnGolden(vec2 d) { return vec2(d.x * kGolden.x - d.y * kGolden.y, d.x * kGolden.y + d.y * kGolden.x); }

#ifdef PCSS_QUAD
// What lit.frag's pcssQuadShare needs from the lookup: the shadow coordinate in texels and the
// filter's radius in texels (0 where no filter ran: outside the map, no blocker, lit).
vec2 g_pcss_c = vec2(0.0);
float g_pcss_r = 0.0;
#endif
float shadowVisibility(vec4 shadowCoord, vec3 normal) {
    if (shadowCoord.w <= 0.0) return 1.0;
    vec3 c = MP(shadowCoord.xyz / shadowCoord.w);
#ifdef PCSS_QUAD
    g_pcss_c = c.xy / u_texmapscale;
#endif
    if (c.x < 0.0 || c.x > 1.0 || c.y < 0.0 || c.y > 1.0 || c.z < 0.0 || c.z > 1.0) return 1.0;
    float zr = lightEyeDepth(c.z);
#ifdef PCSS_QUAD
    // The four pixels of a 2x2 quad (lit.frag's pcssQuadShare) take one angle, turned a quarter
    // turn each, and a quarter of the radial step apart: the filter taps of the three a pixel
    // averages interleave into one disc of 48 rather than three overlapping discs of 16.
    vec2 parity = mod(floor(gl_FragCoord.xy), 2.0);
    float quadClass = parity.x + 2.0 * parity.y;
    vec2 cell = floor(gl_FragCoord.xy * 0.5);
    float radial = (quadClass + 0.5) * 0.25;
#else
    float quadClass = 0.0;
    vec2 cell = gl_FragCoord.xy;
    float radial = 0.5;
#endif
    float angle = 6.2831853 * fract(52.9829189 * fract(dot(cell, vec2(0.06711056, 0.00583715)))) + 1.5707963 * quadClass;
    vec2 start = vec2(cos(angle), sin(angle));

    // (1) Blockers: taps nearer the light than the receiver (by the bias of a small kernel).
    // PCSS_LAYERED (--pcss-blockers layered): nearer than the receiver's plane there (a receiver
    // lit at a grazing angle is not its own blocker), and the blockers that shadow this receiver
    // told from the rest: a blocker at depth d can hide part of the light only if it lies inside
    // the cone from the receiver to the light's disc at d. Their mean depth sizes the filter, so a
    // receiver under stacked casters, or beside a pole's foot, gets the penumbra of the layer over
    // it rather than of all the depths around. With no tap inside (too few taps for a narrow
    // cone), the blocker nearest the light (below).
    vec2 search = coneTexels(zr, SHADOW_SLOPE.z);
    float bias = shadowBias(normal, c);
#ifdef PCSS_LAYERED
    vec2 slope = receiverSlope(normal, c);
    // A tap r (0..1) of the way out holds a blocker inside the cone when its window depth is at
    // most coneDepth.x - coneDepth.y r: the deepest point of the cone at that distance from the
    // ray, linear in it (shadow::pcss_cone_depth), so no division per tap.
    vec2 reach = search * 2.0 * SHADOW_SLOPE.xy * u_texmapscale;  // tangent (perspective) or world units
    vec2 coneDepth = pcssConeDepth(zr) * vec2(1.0, max(reach.x, reach.y));
    float inCone = 0.0;
    float sumIn = 0.0;
#endif
    float blockers = 0.0;
    float sum = 0.0;
#ifdef PCSS_LAYERED
    // The texel on the receiver's own ray to the light's centre: a blocker there is inside the
    // cone whatever its depth. The Vogel taps start about a sixth of the search's radius out, and
    // a thin caster across the ray (a pole, a bar) falls between them.
    float centre = shadowDepth(c.xy);
    float nearest = 1.0;  // the blockers' least window depth
    if (c.z > MP(centre + bias)) {
        inCone = 1.0;
        sumIn = centre;
        blockers = 1.0;
        nearest = centre;
    }
#endif
    vec2 dir = start;
    for (int i = 0; i < PCSS_SEARCH_TAPS; ++i) {
        float r = sqrt((float(i) + 0.5) / float(PCSS_SEARCH_TAPS));
        vec2 o = r * dir;
#ifdef PCSS_LAYERED
        vec2 t = o * search;
        float d = shadowDepth(c.xy + t * u_texmapscale);
        if (c.z + dot(slope, t) > MP(d + bias)) {
            if (d <= coneDepth.x - coneDepth.y * r) {
                inCone += 1.0;
                sumIn += d;
            }
#else
        float d = shadowDepth(c.xy + o * search * u_texmapscale);
        if (c.z > MP(d + bias)) {
#endif
            blockers += 1.0;
            sum += d;
#ifdef PCSS_LAYERED
            nearest = min(nearest, d);
#endif
        }
        dir = turnGolden(dir);
    }
    if (blockers == 0.0) return 1.0;
#ifdef PCSS_LAYERED
    // None inside any cone: the blockers found lie beside it, and a caster inside it was missed
    // between the taps. The nearest to the light has the widest cone, so its penumbra is the
    // widest: the filter then reaches furthest for what the search missed, and counts it soft.
    if (inCone == 0.0) {
        sumIn = nearest;
        inCone = 1.0;
    }
    sum = sumIn;
    blockers = inCone;
#endif

    // (2) The penumbra's half-width from the blockers' mean depth; (3) the filter over it.
    vec2 width = coneTexels(zr, lightEyeDepth(sum / blockers));
#ifdef PCSS_QUAD
    g_pcss_r = max(width.x, width.y);
#endif
    float filterBias = shadowBiasReach(normal, c, max(width.x, width.y) + 1.0);
    float lit = 0.0;
    dir = start;
    for (int i = 0; i < PCSS_FILTER_TAPS; ++i) {
        vec2 o = sqrt((float(i) + radial) / float(PCSS_FILTER_TAPS)) * dir;
        lit += litAt(c.xy + o * width * u_texmapscale, c.z, filterBias);
        dir = turnGolden(dir);
    }
    return lit / float(PCSS_FILTER_TAPS);
}
#endif

#if defined(CASCADES) || defined(CUBE)
vec3 g_cascade_tint;           // --aov cascades: the colour of the cascade(s) or the cube's face used

vec3 cascadeTint(int k) {
    if (k == 0) return vec3(1.0, 0.2, 0.2);
    if (k == 1) return vec3(0.2, 0.9, 0.2);
    if (k == 2) return vec3(0.25, 0.4, 1.0);
    if (k == 3) return vec3(1.0, 0.9, 0.1);
    if (k == 4) return vec3(0.9, 0.3, 0.9);
    return vec3(0.2, 0.9, 0.9);
}
#endif

#ifdef CUBE
// The face a point lies in (its direction's largest component: shadow::cube_face_of), and the
// point in that face's map: a perspective lookup like one map's.
float shadowCube(vec3 world, vec3 normal) {
    vec3 d = world - u_cube_light;
    vec3 a = abs(d);
    g_cube_face = a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0 : 1) : a.y >= a.z ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5);
    g_cascade_tint = cascadeTint(g_cube_face);
    g_shadow_tile = vec4(0.0);
    for (int i = 0; i < 6; ++i)
        if (i == g_cube_face) g_shadow_tile = u_cube_tile[i];
    // A face not drawn sees nothing the camera sees.
    if (g_shadow_tile.z == 0.0) return 1.0;
    vec3 e = cubeFaceEye(d);
    float depth = max(-e.z, 1e-6);
    return shadowVisibility(vec4(0.5 + u_cube_depth.x * e.xy / depth, u_cube_depth.y - u_cube_depth.z / depth, 1.0), normal);
}
#endif

#ifdef CASCADES
// Every cascade looks along the light with the same axes: one matrix takes a world point into the
// light's eye space, and each cascade's map is that scaled and offset per axis (its orthographic
// window and depth range, then clip to texture space).
uniform mat4 u_cascade_light;             // world -> the light's eye space
uniform vec3 u_cascade_scale[CASCADES];   // light eye space -> the cascade's own map, (u, v, z) in [0, 1] inside
uniform vec3 u_cascade_offset[CASCADES];
uniform vec4 u_cascade_tile[CASCADES];    // its tile (g_cascade_tile)
uniform vec4 u_cascade_slope[CASCADES];   // its half-extents, near and far (u_bias_slope)
uniform vec4 u_cascade_end;    // each cascade's far end in camera view depth (x: the first's)
uniform vec4 u_cascade_band;   // the band before each far end blended into the next cascade (0: none)
uniform vec4 u_cascade_depth;  // camera view depth of a world point p: dot(xyz, p) + w

// Cascade k's visibility. A uniform array is indexed by a loop index only (GLSL ES 1.00,
// appendix A: fragment shaders need constant-index-expressions).
float cascadeLookup(int k, vec3 eye, vec3 normal) {
    vec4 coord = vec4(0.0, 0.0, 0.0, -1.0);
    for (int i = 0; i < CASCADES; ++i) {
        if (i == k) {
            coord = vec4(eye * u_cascade_scale[i] + u_cascade_offset[i], 1.0);
            g_shadow_tile = u_cascade_tile[i];
            g_cascade_slope = u_cascade_slope[i];
        }
    }
    return shadowVisibility(coord, normal);
}

// The first cascade whose slice reaches the point's view depth (the last beyond them all); in the
// band before its far end, blended linearly into the next one's.
// eye: the point in the light's eye space (u_cascade_light); depth: its camera view depth
// (u_cascade_depth), both from the vertex shader (v_cascade_eye) or a G-buffer's point.
float shadowCascades(vec3 eye, float depth, vec3 normal) {
    int k = CASCADES - 1;
    float t = 0.0;
    for (int i = CASCADES - 1; i >= 0; --i) {
        if (depth <= u_cascade_end[i]) {
            k = i;
            float band = u_cascade_band[i];
            t = band > 0.0 ? clamp((depth - u_cascade_end[i]) / band + 1.0, 0.0, 1.0) : 0.0;
        }
    }
    g_cascade_tint = cascadeTint(k);
    float visibility = cascadeLookup(k, eye, normal);
    if (t > 0.0) {
        visibility = mix(visibility, cascadeLookup(k + 1, eye, normal), t);
        g_cascade_tint = mix(g_cascade_tint, cascadeTint(k + 1), t);
    }
    return visibility;
}
#endif
