// A sampler of its own.
uniform sampler2D other;
vec4 offset_lookup(sampler2D map, vec3 shadowCoord, vec2 offset) {
    return texture2D(other, shadowCoord.xy);
}
