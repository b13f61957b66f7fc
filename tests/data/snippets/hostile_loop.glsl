// A loop that never ends.
float shadowTest(float zLight, float depth, float bias) {
    float lit = 1.0;
    for (int i = 0; i < 10; i += 0) {
        lit *= 0.5;
    }
    return lit;
}
