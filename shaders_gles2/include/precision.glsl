// Fragment precision: highp where the context has it in fragment shaders (GL_FRAGMENT_PRECISION_HIGH),
// because the depth comparison and the bit-shift packing need every bit of a float32; mediump
// (about 10 bits) otherwise, which is the precision the sheet's 0.0015 bias is derived for.
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
// Samplers default to lowp in fragment shaders, and texture2D returns the sampler's precision:
// Mesa's llvmpipe really does return those texels at half precision (a packed depth read back
// 4.6e-4 short of what was stored), so the shadow map is sampled at highp too.
precision highp sampler2D;
precision highp samplerCube;  // the same for a cube map (--cube-layout cubemap)
#else
precision mediump float;
#endif

// EMULATE_MEDIUMP: what a phone's fp16 mediump does to the depth path, made visible on a desktop
// whose mediump is float32 (llvmpipe, SwiftShader). MP(x) rounds where the sheet's code keeps a
// value in mediump: gl_FragCoord.z, the packing steps, the unpacked depth, the shadow coordinate
// and the comparison. Round to 11 significant bits (10 stored + the implicit one), ties away from
// zero; flush below 2^-14 (the smallest normal half) to 0; clamp at 65504. shadow::round_mediump
// does the same on the CPU for the unit tests.
#ifdef EMULATE_MEDIUMP
float mp(float x) {
    float a = abs(x);
    if (a < 6.103515625e-05) return 0.0;
    float e = floor(log2(a));
    // log2 may land a hair off at exact powers of two: correct the exponent so 2^e <= a < 2^(e+1).
    if (exp2(e + 1.0) <= a) e += 1.0;
    if (exp2(e) > a) e -= 1.0;
    float scale = exp2(10.0 - e);
    return sign(x) * min(floor(a * scale + 0.5) / scale, 65504.0);
}
vec2 mp(vec2 v) { return vec2(mp(v.x), mp(v.y)); }
vec3 mp(vec3 v) { return vec3(mp(v.x), mp(v.y), mp(v.z)); }
vec4 mp(vec4 v) { return vec4(mp(v.x), mp(v.y), mp(v.z), mp(v.w)); }
#define MP(x) mp(x)
#else
#define MP(x) (x)
#endif
