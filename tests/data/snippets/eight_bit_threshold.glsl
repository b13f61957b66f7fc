// Bit-shift packing, but the 8-bit threshold.
float unpackDepth(const in vec4 rgbaDepth) {
    return dot(rgbaDepth, vec4(1.0, 1.0 / 256.0, 1.0 / 65536.0, 1.0 / 16777216.0));
}

float shadowTest(float zLight, float depth, float bias) {
    return zLight > depth + 0.005 ? 0.0 : 1.0;
}
