// A missing semicolon on line 4.
float shadowTest(float zLight, float depth, float bias) {
    float visible = 1.0;
    if (zLight > depth + bias) visible = 0.0
    return visible;
}
