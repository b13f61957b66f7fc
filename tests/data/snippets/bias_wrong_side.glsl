// The bias added to the wrong side of the comparison.
float shadowTest(float zLight, float depth, float bias) {
    return zLight + bias > depth ? 0.0 : 1.0;
}
