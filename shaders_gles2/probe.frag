#version 100
// A constant colour: the start-up probe's, so the renderer can read back how this context turns a
// float into a unorm8 byte (0.6/255 becomes 1 when it rounds, 0 when it truncates); shadow volumes
// shown translucent; the stencil count's false colours; Gooch's casters into its shadow texture
// (ALPHA_TEST: a cut-out's kept part only).
#include "precision.glsl"
#include "alpha.glsl"

uniform vec4 u_value;
#ifdef ALPHA_TEST
varying vec2 v_uv;
#endif

void main() {
#ifdef ALPHA_TEST
    if (materialAlpha(v_uv) < u_alpha_cutoff) discard;
#endif
    gl_FragColor = u_value;
}
