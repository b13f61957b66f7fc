// A bias far beyond the precision.
float shadowTest(float zLight, float depth, float bias) {
    return zLight - 0.05 > depth ? 0.0 : 1.0;
}
