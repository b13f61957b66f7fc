// Shadow-map lookup for the camera pass. The encoding (ENC_R8, ENC_RGBA, else a depth texture),
// the filter's kernel (PCF_TAPS with PCF_SUM, or PCF_EARLY_EXIT's split) and the bias rule
// (BIAS_AUTO or a constant) are chosen by #define when the variant is compiled, so no shader
// branches on settings at run time.
#include "pack.glsl"

uniform sampler2D u_shadow_map;
uniform vec2 u_texmapscale;  // 1/width, 1/height of the shadow map: one texel in texture space
uniform float u_bias;        // the fragment is in shadow if z_l > depth + bias (auto: the constant part)
#if defined(BIAS_AUTO) || defined(FILTER_PCSS)
uniform vec4 u_bias_slope;      // x, y: tan of the half-angles (perspective) or half-extents
                                // (orthographic); z, w: the light's near and far
#endif

#ifdef BIAS_AUTO
// Receiver-plane slope bias, computed from the receiver's normal in the light's eye space: across
// the kernel's reach, how far does the surface move along the light's axis? For a plane with
// normal n hit along the ray r = (c_x + x tan_x, c_y + y tan_y, -1) (perspective; c: the window's
// middle, 0 for a symmetric frustum) the eye depth changes per
// unit of NDC x by z n_x tan_x / |n.r| (y likewise); orthographic: half_w n_x / |n_z|. Converted to
// window depth by d(z_window)/d(z_eye). |n.r| is floored at 0.05 |r| (a surface within 3 degrees
// of edge-on to the light, barely lit anyway), which caps the slope at 20.
uniform mat3 u_light_rotation;  // world -> light eye space
uniform vec2 u_bias_kernel;     // x: one texel in NDC (2 / map size); y: the kernel's reach in texels per axis
#ifdef LIGHT_PERSPECTIVE
uniform vec2 u_bias_center;     // tan at the middle of the window (an asymmetric frustum; 0 when symmetric)
#endif

// reach: how far the kernel reaches, in texels per axis.
float shadowBiasReach(vec3 normal, vec3 c, float reach) {
    vec3 nl = u_light_rotation * normal;
    float n = u_bias_slope.z;
    float f = u_bias_slope.w;
    float across = (abs(nl.x) * u_bias_slope.x + abs(nl.y) * u_bias_slope.y) * u_bias_kernel.x * reach;
#ifdef LIGHT_PERSPECTIVE
    vec3 ray = vec3((2.0 * c.x - 1.0) * u_bias_slope.x + u_bias_center.x, (2.0 * c.y - 1.0) * u_bias_slope.y + u_bias_center.y, -1.0);
    float facing = max(abs(dot(nl, ray)), 0.05 * length(ray));
    float zEye = 2.0 * n * f / (f + n - (2.0 * c.z - 1.0) * (f - n));
    float dz = zEye * across / facing;
    return u_bias + dz * n * f / ((f - n) * zEye * zEye);
#else
    float facing = max(abs(nl.z), 0.05);
    return u_bias + across / facing / (f - n);
#endif
}
float shadowBias(vec3 normal, vec3 c) { return shadowBiasReach(normal, c, u_bias_kernel.y); }
#else
float shadowBiasReach(vec3 normal, vec3 c, float reach) { return u_bias; }
float shadowBias(vec3 normal, vec3 c) { return u_bias; }
#endif

float shadowDepth(vec2 uv) {
#ifdef ENC_RGBA
    return unpackDepth(texture2D(u_shadow_map, uv));
#else
    // ENC_R8 writes depth to red; a depth texture also returns it in red.
    return MP(texture2D(u_shadow_map, uv).r);
#endif
}

float litAt(vec2 uv, float z, float bias) {
    return z > MP(shadowDepth(uv) + bias) ? 0.0 : 1.0;
}

#ifdef PCF_TAPS
// One tap of the kernel: `offset` in texels from the lookup point.
float litTap(vec2 offset, vec2 uv, float z, float bias) {
    return litAt(uv + offset * u_texmapscale, z, bias);
}

// 1.0 where the light reaches, 0.0 in shadow, PCF fractions in between. Points outside the
// light's frustum are lit: the map says nothing about them. normal: the receiver's unit normal in
// world space (for BIAS_AUTO). The kernel's taps (PCF_TAPS, PCF_SUM) are written into the variant
// from shadow::pcf_offsets (render/variants.cpp): hard is one tap at the lookup point, PCF 2x2 four
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
    float n = u_bias_slope.z;
    float f = u_bias_slope.w;
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
    vec2 r = k / (2.0 * u_bias_slope.xy) / u_texmapscale;
    return min(r, vec2(u_pcss.y));
}

// One turn of the golden angle: the step from one Vogel tap to the next.
const vec2 kGolden = vec2(-0.7373688, 0.6754903);
vec2 turnGolden(vec2 d) { return vec2(d.x * kGolden.x - d.y * kGolden.y, d.x * kGolden.y + d.y * kGolden.x); }

float shadowVisibility(vec4 shadowCoord, vec3 normal) {
    if (shadowCoord.w <= 0.0) return 1.0;
    vec3 c = MP(shadowCoord.xyz / shadowCoord.w);
    if (c.x < 0.0 || c.x > 1.0 || c.y < 0.0 || c.y > 1.0 || c.z < 0.0 || c.z > 1.0) return 1.0;
    float zr = lightEyeDepth(c.z);
    float angle = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    vec2 start = vec2(cos(angle), sin(angle));

    // (1) Blockers: taps nearer the light than the receiver (by the bias of a small kernel).
    vec2 search = coneTexels(zr, u_bias_slope.z);
    float bias = shadowBias(normal, c);
    float blockers = 0.0;
    float sum = 0.0;
    vec2 dir = start;
    for (int i = 0; i < PCSS_SEARCH_TAPS; ++i) {
        vec2 o = sqrt((float(i) + 0.5) / float(PCSS_SEARCH_TAPS)) * dir;
        float d = shadowDepth(c.xy + o * search * u_texmapscale);
        if (c.z > MP(d + bias)) {
            blockers += 1.0;
            sum += d;
        }
        dir = turnGolden(dir);
    }
    if (blockers == 0.0) return 1.0;

    // (2) The penumbra's half-width from the blockers' mean depth; (3) the filter over it.
    vec2 width = coneTexels(zr, lightEyeDepth(sum / blockers));
    float filterBias = shadowBiasReach(normal, c, max(width.x, width.y) + 1.0);
    float lit = 0.0;
    dir = start;
    for (int i = 0; i < PCSS_FILTER_TAPS; ++i) {
        vec2 o = sqrt((float(i) + 0.5) / float(PCSS_FILTER_TAPS)) * dir;
        lit += litAt(c.xy + o * width * u_texmapscale, c.z, filterBias);
        dir = turnGolden(dir);
    }
    return lit / float(PCSS_FILTER_TAPS);
}
#endif
