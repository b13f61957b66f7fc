// The 4x4 lookup with the offset in texels added to texture coordinates.
vec4 offset_lookup(sampler2D map, vec3 shadowCoord, vec2 offset) {
    return texture2D(map, shadowCoord.xy + offset);
}
