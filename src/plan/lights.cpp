#include "plan/lights.h"

#include <algorithm>
#include <cmath>

#include "plan/plan.h"

namespace penumbra::render {

namespace {

// Hue h (0..1) at saturation 0.85 and value 1.
glm::vec3 hue(float h) {
    const glm::vec3 k = glm::abs(glm::fract(glm::vec3(h) + glm::vec3(1.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f);
    return glm::mix(glm::vec3(1.0f), glm::clamp(k - 1.0f, 0.0f, 1.0f), 0.85f);
}

}  // namespace

std::vector<PointLight> point_lights(const scene::Scene& scene, int n) {
    std::vector<PointLight> out;
    if (n <= 0) return out;
    // The disc: over all receivers, at the top of the widest (the table's top).
    scene::Bounds receivers, widest;
    float widest_area = -1.0f;
    for (const scene::Bounds& b : shadow_bounds(scene).receivers) {
        receivers.add(b);
        const float area = (b.max.x - b.min.x) * (b.max.z - b.min.z);
        if (area > widest_area) {
            widest_area = area;
            widest = b;
        }
    }
    if (receivers.empty()) receivers = widest = scene_bounds(scene);
    if (receivers.empty()) receivers = widest = scene::Bounds::around(glm::vec3(-1.0f), glm::vec3(1.0f));
    const glm::vec3 c = receivers.center();
    const float radius = std::max(0.5f * std::max(receivers.max.x - receivers.min.x, receivers.max.z - receivers.min.z), 1e-3f);
    const float count = static_cast<float>(n);
    const float range = radius * std::clamp(1.0f / std::sqrt(count), 0.15f, 0.5f);
    // How many lights reach a point of the disc on average, and the colour scaled to keep that
    // near two full lights.
    const float overlap = count * range * range / (0.81f * radius * radius);
    const float strength = 0.8f * std::min(1.0f, 2.0f / std::max(overlap, 1e-3f));
    const float golden = 2.39996323f;  // the golden angle
    for (int i = 0; i < n; ++i) {
        const float fi = static_cast<float>(i);
        const float r = 0.9f * radius * std::sqrt((fi + 0.5f) / count);
        PointLight l;
        l.position = glm::vec3(c.x + r * std::cos(fi * golden), widest.max.y + 0.35f * range,
                               c.z + r * std::sin(fi * golden));
        l.range = range;
        l.color = hue(std::fmod(fi * 0.618034f, 1.0f)) * strength;
        out.push_back(l);
    }
    return out;
}

glm::vec3 point_light_term(const PointLight& l, const glm::vec3& world, const glm::vec3& normal, const glm::vec3& base) {
    const glm::vec3 d = l.position - world;
    const float q = glm::dot(d, d) / (l.range * l.range);
    const float falloff = std::max(1.0f - q, 0.0f);
    const float lambert = std::max(glm::dot(normal, glm::normalize(d)), 0.0f);
    return base * l.color * (lambert * falloff * falloff);
}

}  // namespace penumbra::render
