// Two of the four: the unpacking right (a loop), the test without its bias.
float unpackDepth(const in vec4 rgbaDepth) {
    float depth = 0.0;
    float scale = 1.0;
    for (int i = 0; i < 4; ++i) {
        depth += rgbaDepth[i] * scale;
        scale /= 256.0;
    }
    return depth;
}

float shadowTest(float zLight, float depth, float bias) {
    return zLight > depth ? 0.0 : 1.0;
}
