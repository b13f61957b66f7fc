// --shading deferred: the G-buffer's three RGBA8 targets, written by the geometry pass (lit.frag
// with GBUFFER_WRITE) and read by the lighting passes (GBUFFER_READ) and the views (gbuffer_view.frag).
//   colour: rgb the base colour (the material's times its texture), a the specular strength (to 1)
//   normal: the world normal, octahedral, x and y in 16 bits each (x high, x low, y high, y low)
//   depth:  rgb where the surface lies on the pixel's ray between the near and far planes (0..1,
//           24 bits, linear in the camera's depth), a 128 if it receives shadows + shininess / 2
// Cleared to all ones: a depth of 255, 255, 255 is no surface (a surface's is at most 255, 255, 254).
// Bytes are written as (byte + UNORM_OFFSET) / 255 (pack.glsl: the same byte whether the context
// rounds or truncates) and read back as whole bytes; render/deferred.cpp's CPU mirror is the tests' reference.
#include "pack.glsl"

vec4 gbufferOut(vec4 bytes) { return (bytes + UNORM_OFFSET) / 255.0; }
vec4 gbufferBytes(vec4 texel) { return floor(texel * 255.0 + 0.5); }

vec2 signNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

// The octahedral map of a unit vector to [0,1]^2 (the lower half folded over the diagonals).
vec2 octEncode(vec3 n) {
    vec3 a = n / (abs(n.x) + abs(n.y) + abs(n.z));
    vec2 e = a.xy;
    if (a.z < 0.0) e = (1.0 - abs(e.yx)) * signNotZero(e);
    return e * 0.5 + 0.5;
}
vec3 octDecode(vec2 e) {
    vec2 f = e * 2.0 - 1.0;
    vec3 n = vec3(f, 1.0 - abs(f.x) - abs(f.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(f.yx)) * signNotZero(f);
    return normalize(n);
}
// v in [0,1] as 16 bits: (high byte, low byte).
vec2 split16(float v) {
    float q = floor(clamp(v, 0.0, 1.0) * 65535.0 + 0.5);
    float hi = floor(q / 256.0);
    return vec2(hi, q - hi * 256.0);
}

vec4 gbufferColorBytes(vec3 base, float specular) { return vec4(floor(clamp(vec4(base, specular), 0.0, 1.0) * 255.0 + 0.5)); }
vec4 gbufferNormalBytes(vec3 n) {
    vec2 e = octEncode(n);
    return vec4(split16(e.x), split16(e.y));
}
vec4 gbufferDepthBytes(float s, float shininess, bool receives) {
    float q = floor(clamp(s, 0.0, 1.0) * 16777214.0 + 0.5);
    float hi = floor(q / 65536.0);
    float rest = q - hi * 65536.0;
    float mid = floor(rest / 256.0);
    float a = min(floor(max(shininess, 0.0) * 0.5 + 0.5), 127.0) + (receives ? 128.0 : 0.0);
    return vec4(hi, mid, rest - mid * 256.0, a);
}

vec3 gbufferNormal(vec4 bytes) { return octDecode(vec2(bytes.x * 256.0 + bytes.y, bytes.z * 256.0 + bytes.w) / 65535.0); }
bool gbufferEmpty(vec4 depthBytes) { return depthBytes.x + depthBytes.y + depthBytes.z >= 765.0; }
float gbufferDepth(vec4 depthBytes) { return (depthBytes.x * 65536.0 + depthBytes.y * 256.0 + depthBytes.z) / 16777214.0; }
float gbufferShininess(vec4 depthBytes) { return mod(depthBytes.w, 128.0) * 2.0; }
bool gbufferReceives(vec4 depthBytes) { return depthBytes.w >= 128.0; }
