// Shadow-map lookup for the camera pass. The encoding (ENC_R8, ENC_RGBA, else a depth texture)
// and the filter (FILTER_PCF4X4, FILTER_PCF2X2, else hard) are chosen by #define when the variant
// is compiled, so no shader branches on settings at run time.
#include "pack.glsl"

uniform sampler2D u_shadow_map;
uniform vec2 u_texmapscale;  // 1/width, 1/height of the shadow map: one texel in texture space
uniform float u_bias;        // the fragment is in shadow if z_l > depth + bias

float shadowDepth(vec2 uv) {
#ifdef ENC_RGBA
    return unpackDepth(texture2D(u_shadow_map, uv));
#else
    // ENC_R8 writes depth to red; a depth texture also returns it in red.
    return texture2D(u_shadow_map, uv).r;
#endif
}

float litAt(vec2 uv, float z) {
    return z > shadowDepth(uv) + u_bias ? 0.0 : 1.0;
}

// 1.0 where the light reaches, 0.0 in shadow, PCF fractions in between. Points outside the
// light's frustum are lit: the map says nothing about them.
float shadowVisibility(vec4 shadowCoord) {
    if (shadowCoord.w <= 0.0) return 1.0;
    vec3 c = shadowCoord.xyz / shadowCoord.w;
    if (c.x < 0.0 || c.x > 1.0 || c.y < 0.0 || c.y > 1.0 || c.z < 0.0 || c.z > 1.0) return 1.0;
#if defined(FILTER_PCF4X4)
    // 16 taps at -1.5, -0.5, 0.5, 1.5 texels: a 4x4 block of the map (Bunnell & Pellacini).
    float sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            vec2 offset = vec2(float(i) - 1.5, float(j) - 1.5);
            sum += litAt(c.xy + offset * u_texmapscale, c.z);
        }
    }
    return sum / 16.0;
#elif defined(FILTER_PCF2X2)
    float sum = litAt(c.xy + vec2(-0.5, -0.5) * u_texmapscale, c.z);
    sum += litAt(c.xy + vec2(0.5, -0.5) * u_texmapscale, c.z);
    sum += litAt(c.xy + vec2(-0.5, 0.5) * u_texmapscale, c.z);
    sum += litAt(c.xy + vec2(0.5, 0.5) * u_texmapscale, c.z);
    return sum * 0.25;
#else
    return litAt(c.xy, c.z);
#endif
}
