// --lights: a point light of range r (plan/lights.h): Lambert's diffuse times (1 - (d/r)^2)^2,
// which reaches 0 at the range. u_point_lights holds two vec4 per light: (position, range), (colour, 0).
#ifndef POINT_LIGHTS
#define POINT_LIGHTS 1
#endif
uniform vec4 u_point_lights[2 * POINT_LIGHTS];

vec3 pointLight(vec4 positionRange, vec3 color, vec3 world, vec3 n, vec3 base) {
    vec3 d = positionRange.xyz - world;
    float falloff = max(1.0 - dot(d, d) / (positionRange.w * positionRange.w), 0.0);
    return base * color * (max(dot(n, normalize(d)), 0.0) * falloff * falloff);
}

vec3 pointLights(vec3 world, vec3 n, vec3 base) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < POINT_LIGHTS; ++i) sum += pointLight(u_point_lights[2 * i], u_point_lights[2 * i + 1].rgb, world, n, base);
    return sum;
}
