// Gooch's soft shadow: the offset planes' matrices, their spread from the light's radius, the
// averaging weights. See gooch.h.
#include "shadow/gooch.h"

#include <algorithm>
#include <cmath>

#include "shadow/planar.h"

namespace penumbra::shadow {

namespace {

// The ground with a unit normal (the same plane).
glm::vec4 unit_plane(const glm::vec4& p) {
    const float l = glm::length(glm::vec3(p));
    return l > 0.0f ? p / l : p;
}

}  // namespace

glm::mat4 gooch_projection(const glm::vec4& ground, const glm::vec4& light, float offset) {
    if (offset == 0.0f) return planar_projection(ground, light);
    const glm::vec4 g = unit_plane(ground);
    const glm::vec3 n(g);
    // The plane n.x + d = offset, i.e. (n, d - offset); then x -> x - offset n, which in
    // homogeneous coordinates subtracts offset n w from xyz (a translation matrix).
    const glm::mat4 flat = planar_projection(glm::vec4(n, g.w - offset), light);
    glm::mat4 back(1.0f);
    back[3] = glm::vec4(-offset * n, 1.0f);
    return back * flat;
}

std::vector<float> gooch_offsets(int k, float spread) {
    k = std::max(k, 1);
    std::vector<float> out(static_cast<size_t>(k), 0.0f);
    if (k == 1 || spread == 0.0f) return out;
    for (int i = 0; i < k; ++i) {
        // i and k-1-i get exactly opposite values: the middle's j is computed from both ends alike.
        const int j = 2 * i - (k - 1);  // -(k-1) .. k-1, odd steps of 2
        out[static_cast<size_t>(i)] = spread * static_cast<float>(j) / static_cast<float>(k - 1);
    }
    return out;
}

float gooch_spread(const glm::vec4& ground, const glm::vec4& light, float radius, const glm::vec3& caster) {
    if (!(radius > 0.0f)) return 0.0f;
    const glm::vec4 g = unit_plane(ground);
    const glm::vec3 n(g);
    float h = glm::dot(n, caster) + g.w;  // the caster's height over the ground
    float sign = 1.0f;
    if (light.w != 0.0f) {
        const glm::vec3 p = glm::vec3(light) / light.w;
        const float H = glm::dot(n, p) + g.w;
        if (H < 0.0f) sign = -1.0f;  // the light under the plane: heights measured on its side
        h *= sign;
        const float hl = H * sign;
        if (!(h > 0.0f) || !(h < hl)) return 0.0f;
        const glm::vec3 lateral = (caster - p) - glm::dot(caster - p, n) * n;
        const float tilt = std::max(glm::length(lateral) / (hl - h), kGoochMinTilt);
        const float half_width = radius * h / (hl - h);
        return std::min(half_width / tilt, 0.5f * hl);
    }
    const glm::vec3 towards = glm::normalize(glm::vec3(light));  // towards the light
    const float up = glm::dot(towards, n);
    if (up < 0.0f) sign = -1.0f;
    h *= sign;
    if (!(h > 0.0f) || up == 0.0f) return 0.0f;
    const float tilt = std::max(glm::length(towards - up * n) / std::fabs(up), kGoochMinTilt);
    const float half_width = h * std::tan(std::min(radius, 1.5f));
    return half_width / tilt;
}

std::vector<int> gooch_weight_bytes(int k) {
    k = std::max(k, 1);
    std::vector<int> out;
    const auto at = [k](int i) { return static_cast<int>(std::lround(255.0 * i / k)); };
    for (int i = 0; i < k; ++i) out.push_back(at(i + 1) - at(i));
    return out;
}

std::vector<glm::vec2> gooch_disc(int k) {
    k = std::max(k, 1);
    std::vector<glm::vec2> out;
    if (k == 1) return {glm::vec2(0.0f)};
    const double golden = 2.39996322972865332;
    for (int i = 0; i < k; ++i) {
        // The angle reduced to one turn in double, its sine and cosine in float: the points are
        // floats, and the pages' modules then hold no double-precision trigonometry.
        const double turns = golden * i / 6.283185307179586;
        const float r = static_cast<float>(std::sqrt((i + 0.5) / k));
        const float a = static_cast<float>(6.283185307179586 * (turns - std::floor(turns)));
        out.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    return out;
}

}  // namespace penumbra::shadow
