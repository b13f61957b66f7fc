// Only the unpacking: the other three functions are the sheet's answer's.
float unpackDepth(const in vec4 rgbaDepth) {
    float depth = 0.0;
    float scale = 1.0;
    for (int i = 0; i < 4; ++i) {
        depth += rgbaDepth[i] * scale;
        scale /= 256.0;
    }
    return depth;
}
