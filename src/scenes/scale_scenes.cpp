#include "scenes/scale_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/primitives.h"
#include "scenes/probe_scenes.h"

namespace penumbra::scene {

namespace {

// A 32-bit LCG (Numerical Recipes' constants): the same scene on every platform.
struct Lcg {
    std::uint32_t state;
    float uniform(float lo, float hi) {
        state = 1664525u * state + 1013904223u;
        return lo + (hi - lo) * static_cast<float>(static_cast<double>(state) / 4294967296.0);
    }
};

// A square pyramid 0.2 wide and 0.35 tall standing on y = 0, flat-shaded, wound outwards: closed
// and convex, so it never needs to shadow itself in a map.
Mesh pyramid() {
    const float s = 0.1f, h = 0.35f;
    const glm::vec3 b0(-s, 0, -s), b1(s, 0, -s), b2(s, 0, s), b3(-s, 0, s), apex(0, h, 0);
    const glm::vec3 faces[6][3] = {{b3, b2, apex}, {b2, b1, apex}, {b1, b0, apex}, {b0, b3, apex}, {b0, b1, b2}, {b0, b2, b3}};
    Mesh m;
    m.name = "pyramid";
    for (const auto& f : faces) {
        const glm::vec3 n = glm::normalize(glm::cross(f[1] - f[0], f[2] - f[0]));
        for (const glm::vec3& p : f) {
            m.indices.push_back(static_cast<std::uint32_t>(m.positions.size()));
            m.positions.push_back(p);
            m.normals.push_back(n);
        }
    }
    seal(m);
    return m;
}

bool read_count(const std::string& text, int& count) {
    if (text.empty() || text.size() > 9) return false;
    for (char ch : text)
        if (ch < '0' || ch > '9') return false;
    count = std::stoi(text);
    return true;
}

}  // namespace

bool is_scale_name(const std::string& name) { return name.rfind("pile:", 0) == 0 || name.rfind("forest:", 0) == 0; }

bool parse_scale_name(const std::string& name, ScaleSpec& spec, std::string& error) {
    const size_t colon = name.find(':');
    spec.layout = name.substr(0, colon) == "pile" ? ScaleLayout::Pile : ScaleLayout::Forest;
    const std::string rest = name.substr(colon + 1);
    const size_t second = rest.find(':');
    const std::string count = rest.substr(0, second);
    const std::string light = second == std::string::npos ? "point" : rest.substr(second + 1);
    if (!read_count(count, spec.count) || spec.count < 1 || spec.count > kMaxScaleCount) {
        error = "--scene " + name + ": the count '" + count + "' is not a whole number from 1 to " +
                std::to_string(kMaxScaleCount);
        return false;
    }
    if (light == "point") spec.light = LightType::Point;
    else if (light == "spot") spec.light = LightType::Spot;
    else if (light == "sun") spec.light = LightType::Directional;
    else {
        error = "--scene " + name + ": the light '" + light + "' is not one of point, spot, sun";
        return false;
    }
    return true;
}

std::string scale_name(const ScaleSpec& spec) {
    std::string out = (spec.layout == ScaleLayout::Pile ? "pile:" : "forest:") + std::to_string(spec.count);
    if (spec.light == LightType::Spot) out += ":spot";
    if (spec.light == LightType::Directional) out += ":sun";
    return out;
}

Scene make_scale_scene(const ScaleSpec& spec) {
    const bool pile = spec.layout == ScaleLayout::Pile;
    const int n = std::max(spec.count, 1);
    // The forest's grid: `side` columns 0.3 apart; the pile's strip 3 x 0.3.
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    const float extent = pile ? 3.0f : 0.3f * static_cast<float>(side);

    Scene s;
    s.meshes = {make_quad(extent + 2.0f, 1.0f), pyramid()};
    Material ground, stone;
    ground.name = "ground";
    ground.base_color = glm::vec4(0.75f, 0.75f, 0.7f, 1.0f);
    stone.name = "stone";
    stone.base_color = glm::vec4(0.6f, 0.45f, 0.35f, 1.0f);
    s.materials = {ground, stone};
    Object g;
    g.name = "ground";
    g.mesh = 0;
    g.material = 0;
    s.objects.reserve(static_cast<size_t>(n) + 1);
    s.objects.push_back(g);
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = 0;

    Lcg rng{12345u};
    for (int i = 0; i < n; ++i) {
        glm::vec3 at;
        if (pile) {
            at = glm::vec3(rng.uniform(-1.5f, 1.5f), rng.uniform(0.0f, 0.3f), rng.uniform(-0.15f, 0.15f));
        } else {
            const float first = -0.5f * 0.3f * static_cast<float>(side - 1);
            at = glm::vec3(first + 0.3f * static_cast<float>(i % side), 0.0f, first + 0.3f * static_cast<float>(i / side));
        }
        const float turn = rng.uniform(0.0f, 1.5707964f);
        Object o;
        o.name = "pyramid " + std::to_string(i);
        o.mesh = 1;
        o.material = 1;
        o.world = glm::rotate(glm::translate(glm::mat4(1.0f), at), turn, glm::vec3(0.0f, 1.0f, 0.0f));
        s.objects.push_back(std::move(o));
    }

    // The pile: seen whole from the front, a little above, lit from the front right. The forest:
    // seen from its edge, looking in over the trees, the nearest rows close and the far ones
    // towards the horizon, lit from above its middle.
    const float half = 0.5f * extent;
    const glm::vec3 eye = pile ? glm::vec3(0.0f, 1.3f, 2.9f) : glm::vec3(0.0f, 2.0f, half + 2.0f);
    const glm::vec3 look = pile ? glm::vec3(0.0f, 0.15f, 0.0f) : glm::vec3(0.0f, 0.0f, half - 6.0f);
    s.camera.view = glm::lookAt(eye, look, glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(50.0f);
    s.camera.znear = pile ? 0.05f : 0.1f;
    s.camera.zfar = pile ? 20.0f : 2.0f * extent + 10.0f;

    s.light.type = spec.light;
    s.light.position = pile ? glm::vec3(2.6f, 1.5f, 0.8f) : glm::vec3(0.3f * half, 0.2f * half + 3.0f, half + 4.0f);
    const glm::vec3 aim = pile ? glm::vec3(0.0f, 0.15f, 0.0f) : glm::vec3(0.0f);
    if (spec.light == LightType::Directional) {
        s.light.direction = light_direction_at(35.0f, 30.0f);
    } else {
        s.light.direction = glm::normalize(aim - s.light.position);
        s.light.spot_outer_cone = glm::radians(60.0f);
        s.light.spot_inner_cone = glm::radians(50.0f);
    }
    return s;
}

}  // namespace penumbra::scene
