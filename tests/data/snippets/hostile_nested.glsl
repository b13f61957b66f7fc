// Calls that multiply: every pixel would run 16 x 16 x 16 steps.
float a(float x) { for (int i = 0; i < 16; ++i) x += 1.0; return x; }
float b(float x) { for (int i = 0; i < 16; ++i) x += a(x); return x; }
float shadowTest(float zLight, float depth, float bias) {
    for (int i = 0; i < 16; ++i) depth += b(depth) * 0.0;
    return zLight > depth + bias ? 0.0 : 1.0;
}
