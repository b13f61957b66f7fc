// The test without the bias.
float shadowTest(float zLight, float depth, float bias) {
    return zLight > depth ? 0.0 : 1.0;
}
