// Bit-shift packing read back with its weights in the wrong order: alpha weighs the most.
float unpackDepth(const in vec4 rgbaDepth) {
    return dot(rgbaDepth, vec4(1.0 / 16777216.0, 1.0 / 65536.0, 1.0 / 256.0, 1.0));
}
