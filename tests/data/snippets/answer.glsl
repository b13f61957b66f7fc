// W09P2c, bit-shift packing: what the sheet teaches, written out.
vec4 packDepth(float z) {
    const vec4 bitShift = vec4(1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0);
    const vec4 bitMask = vec4(1.0 / 256.0, 1.0 / 256.0, 1.0 / 256.0, 0.0);
    vec4 rgbaDepth = fract(z * bitShift);
    rgbaDepth -= rgbaDepth.gbaa * bitMask;
    return rgbaDepth;
}

float unpackDepth(const in vec4 rgbaDepth) {
    const vec4 bitShift = vec4(1.0, 1.0 / 256.0, 1.0 / (256.0 * 256.0), 1.0 / (256.0 * 256.0 * 256.0));
    return dot(rgbaDepth, bitShift);
}

float shadowTest(float zLight, float depth, float bias) {
    if (zLight > depth + bias)
        return 0.0;
    return 1.0;
}

vec4 offset_lookup(sampler2D map, vec3 shadowCoord, vec2 offset) {
    return texture2D(map, shadowCoord.xy + offset * texmapscale);
}
