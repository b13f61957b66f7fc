// Bit-shift packing, read back from red alone.
float unpackDepth(const in vec4 rgbaDepth) {
    return rgbaDepth.r;
}
