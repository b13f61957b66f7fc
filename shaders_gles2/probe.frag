#version 100
// A constant colour: the start-up probe's, so the renderer can read back how this context turns a
// float into a unorm8 byte (0.6/255 becomes 1 when it rounds, 0 when it truncates); shadow volumes
// shown translucent; the stencil count's false colours.
#include "precision.glsl"

uniform vec4 u_value;

void main() {
    gl_FragColor = u_value;
}
