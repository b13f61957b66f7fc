// The floor of |n.r| / |r| in the auto bias's slope, from one texel in NDC (u_bias_kernel.x): 0.05
// (a slope of at most 20). The hard lookup lowers it with the texel beyond a 2048 map, to 0.025
// from 4096 on, so that the capped bias stays the 2048 map's; PCF and PCSS keep 0.05 (shadow.glsl,
// docs/precision.md). Read by the fragment stage (shadow.glsl) and the vertex stage (lit.vert).
#ifndef SHADOW_FACING_FLOOR
#ifdef FILTER_HARD
#define SHADOW_FACING_FLOOR(texel) (0.05 * clamp(1024.0 * (texel), 0.5, 1.0))
#else
#define SHADOW_FACING_FLOOR(texel) 0.05
#endif
#endif
