// Fragment precision: highp where the context has it in fragment shaders (GL_FRAGMENT_PRECISION_HIGH),
// because the depth comparison and the bit-shift packing need every bit of a float32; mediump
// (about 10 bits) otherwise, which is the precision the sheet's 0.0015 bias is derived for.
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif
