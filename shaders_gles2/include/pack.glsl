// Bit-shift packing of a depth in [0,1] into four unorm8 channels, most significant in red.
// Byte i is floor(fract(d * 256^i) * 256), written as byte/255 so that the unorm8 conversion
// (round(c * 255)) stores the byte exactly. Under float32 every step is exact, so the round trip
// is exact to 2^-24; src/shadow/encoding.cpp mirrors this on the CPU for the tests.
vec4 packDepth(float depth) {
    // 1.0 would wrap to 0.0 (fract(1.0) == 0.0): keep it one quantum below.
    float d = clamp(depth, 0.0, 0.99999994);
    vec4 digits = floor(fract(d * vec4(1.0, 256.0, 65536.0, 16777216.0)) * 256.0);
    return digits / 255.0;
}

float unpackDepth(vec4 rgba) {
    return dot(rgba, vec4(255.0 / 256.0, 255.0 / 65536.0, 255.0 / 16777216.0, 255.0 / 4294967296.0));
}
