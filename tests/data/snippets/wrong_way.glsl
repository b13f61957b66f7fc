// The comparison the wrong way round: 1.0 (lit) where the point is behind the stored depth.
float shadowTest(float zLight, float depth, float bias) {
    return zLight - bias > depth ? 1.0 : 0.0;
}
