#version 100
// The light's view: the depth of the nearest surface, written the way the encoding stores it.
#include "precision.glsl"
#include "pack.glsl"
#include "alpha.glsl"
#ifdef ALPHA_TEST
varying vec2 v_uv;
#endif

void main() {
#ifdef ALPHA_TEST
    // A cut-out (glTF MASK) casts only where it is kept: the gaps of a fence leave no depth.
    if (materialAlpha(v_uv) < u_alpha_cutoff) discard;
#endif
#if defined(LAB)
    // The shader lab: the sheet's packing, as written (plan/snippets.h).
    gl_FragColor = packDepth(gl_FragCoord.z);
#elif defined(ENC_R8)
    // 8 bits in red: the sheet's first shadow map.
    gl_FragColor = packDepthR8(gl_FragCoord.z);
#elif defined(ENC_RGBA)
    gl_FragColor = packDepth(gl_FragCoord.z);
#else
    // Depth texture (or a stencil-only pass): the depth attachment keeps gl_FragCoord.z and the
    // colour written here goes nowhere.
    gl_FragColor = vec4(1.0);
#endif
}
