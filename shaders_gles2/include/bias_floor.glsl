// The floor of |n.r| / |r| in the auto bias's slope for the hard lookup, from one texel in NDC
// (u_bias_kernel.x): 0.05 (a slope of at most 20) up to a 2048 map, then lower with the texel, to
// 0.025 from 4096 on, so that the capped bias stays the 2048 map's (shadow.glsl, docs/precision.md).
#ifndef SHADOW_HARD_FLOOR
#define SHADOW_HARD_FLOOR(texel) (0.05 * clamp(1024.0 * (texel), 0.5, 1.0))
#endif
