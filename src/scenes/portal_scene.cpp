#include "scenes/portal_scene.h"

#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/primitives.h"

namespace penumbra::scene {

namespace {

constexpr float kOpening = 1.4f;  // the opening's width and height
constexpr float kBorder = 0.1f;   // the frame's width around it
constexpr float kDepth = 0.08f;   // the frame's thickness
constexpr float kStandsAt = -1.2f;  // z of the opening on the table

// `m` transformed by `t`, appended to `into` (normals by t's rotation: no scaling here).
void append(Mesh& into, const Mesh& m, const glm::mat4& t) {
    const auto base = static_cast<std::uint32_t>(into.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        into.positions.push_back(glm::vec3(t * glm::vec4(m.positions[i], 1.0f)));
        into.normals.push_back(glm::normalize(glm::mat3(t) * m.normals[i]));
    }
    for (std::uint32_t i : m.indices) into.indices.push_back(base + i);
}

// The opening: a square facing +z in the plane z = 0, from y = kBorder up, centred on x = 0.
Mesh opening_mesh() {
    Mesh m;
    m.name = "portal opening";
    const float h = 0.5f * kOpening;
    for (const glm::vec2 p : {glm::vec2(-h, 0.0f), glm::vec2(h, 0.0f), glm::vec2(h, kOpening), glm::vec2(-h, kOpening)}) {
        m.positions.emplace_back(p.x, p.y + kBorder, 0.0f);
        m.normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    seal(m);
    return m;
}

// The frame: four bars around the opening, standing on y = 0.
Mesh frame_mesh() {
    Mesh m;
    m.name = "portal frame";
    const float w = kOpening + 2.0f * kBorder;
    const auto bar = [&](glm::vec3 half, glm::vec3 centre) {
        append(m, make_box(half), glm::translate(glm::mat4(1.0f), centre));
    };
    bar({0.5f * w, 0.5f * kBorder, 0.5f * kDepth}, {0.0f, 0.5f * kBorder, 0.0f});                       // sill
    bar({0.5f * w, 0.5f * kBorder, 0.5f * kDepth}, {0.0f, kOpening + 1.5f * kBorder, 0.0f});            // lintel
    bar({0.5f * kBorder, 0.5f * kOpening, 0.5f * kDepth}, {-0.5f * (kOpening + kBorder), kBorder + 0.5f * kOpening, 0.0f});
    bar({0.5f * kBorder, 0.5f * kOpening, 0.5f * kDepth}, {0.5f * (kOpening + kBorder), kBorder + 0.5f * kOpening, 0.0f});
    seal(m);
    return m;
}

Material colour(const char* name, glm::vec3 rgb, float specular) {
    Material m;
    m.name = name;
    m.base_color = glm::vec4(rgb, 1.0f);
    m.specular = specular;
    m.shininess = 24.0f;
    return m;
}

}  // namespace

Portal make_course_portal() {
    auto beyond = std::make_shared<Scene>();
    Scene& s = *beyond;
    s.meshes.push_back(make_quad(12.0f, 1.0f));                       // 0 the lawn
    s.meshes.push_back(make_sphere(0.35f, 32, 16));                    // 1
    s.meshes.push_back(make_box(glm::vec3(0.28f)));                    // 2
    s.meshes.push_back(make_box(glm::vec3(0.18f, 0.9f, 0.18f)));       // 3 the pillar
    s.meshes.push_back(opening_mesh());                                // 4
    s.meshes.push_back(frame_mesh());                                  // 5
    s.materials = {colour("lawn", {0.36f, 0.55f, 0.30f}, 0.05f), colour("red", {0.80f, 0.22f, 0.18f}, 0.6f),
                   colour("blue", {0.25f, 0.35f, 0.80f}, 0.3f), colour("stone", {0.75f, 0.72f, 0.66f}, 0.2f),
                   colour("frame", {0.42f, 0.27f, 0.14f}, 0.3f)};
    const auto place = [&](const char* name, int mesh, int material, glm::vec3 at) {
        Object o;
        o.name = name;
        o.mesh = mesh;
        o.material = material;
        o.world = glm::translate(glm::mat4(1.0f), at);
        s.objects.push_back(o);
    };
    place("lawn", 0, 0, {0.0f, 0.0f, -6.0f});
    place("sphere", 1, 1, {-0.45f, 0.35f, -2.6f});
    place("box", 2, 2, {0.2f, 0.28f, -2.1f});
    place("pillar", 3, 3, {-0.2f, 0.9f, -4.2f});
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = 0;
    s.light.type = LightType::Directional;
    s.light.direction = glm::normalize(glm::vec3(0.8f, -0.5f, -0.3f));  // from the left, low: long shadows to the right
    s.light.color = glm::vec3(1.0f, 0.86f, 0.66f);

    Portal p;
    p.opening_mesh = 4;
    p.frame_mesh = 5;
    p.frame_material = 4;
    p.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, kStandsAt));
    p.sky = glm::vec3(0.55f, 0.42f, 0.62f);  // a dusk sky, unlike the course's grey
    p.beyond = std::move(beyond);
    return p;
}

}  // namespace penumbra::scene
