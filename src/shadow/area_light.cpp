#include "shadow/area_light.h"

#include <cmath>

namespace penumbra::shadow {

namespace {

constexpr float kPi = 3.14159265358979f;

// Shirley and Chiu's concentric map from the unit square to the unit disc (area-preserving).
glm::vec2 concentric(float u, float v) {
    const float a = 2.0f * u - 1.0f, b = 2.0f * v - 1.0f;
    if (a == 0.0f && b == 0.0f) return glm::vec2(0.0f);
    float r, phi;
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = 0.25f * kPi * (b / a);
    } else {
        r = b;
        phi = 0.5f * kPi - 0.25f * kPi * (a / b);
    }
    return r * glm::vec2(std::cos(phi), std::sin(phi));
}

// Two unit vectors completing `n` to an orthonormal basis.
void basis(const glm::vec3& n, glm::vec3& a, glm::vec3& b) {
    const glm::vec3 helper = std::fabs(n.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    a = glm::normalize(glm::cross(helper, n));
    b = glm::cross(n, a);
}

}  // namespace

float radical_inverse(int i, int base) {
    float inv = 1.0f / static_cast<float>(base), f = inv, r = 0.0f;
    for (int n = i; n > 0; n /= base) {
        r += f * static_cast<float>(n % base);
        f *= inv;
    }
    return r;
}

glm::vec2 area_sample_point(int k) { return concentric(radical_inverse(k + 1, 2), radical_inverse(k + 1, 3)); }

scene::Light area_light_sample(const scene::Light& light, int k, const glm::vec3& axis) {
    if (!(light.radius > 0.0f)) return light;
    scene::Light out = light;
    const glm::vec2 d = area_sample_point(k);
    glm::vec3 a, b;
    if (light.type == scene::LightType::Directional) {
        const glm::vec3 towards = -glm::normalize(light.direction);
        basis(towards, a, b);
        const glm::vec3 tilted = glm::normalize(towards + std::tan(light.radius) * (d.x * a + d.y * b));
        out.direction = -tilted;
    } else {
        const float len = glm::length(axis);
        basis(len > 0.0f ? axis / len : glm::vec3(0.0f, -1.0f, 0.0f), a, b);
        out.position = light.position + light.radius * (d.x * a + d.y * b);
    }
    return out;
}

}  // namespace penumbra::shadow
