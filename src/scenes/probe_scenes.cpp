#include "scenes/probe_scenes.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/primitives.h"

namespace penumbra::scene {

glm::vec3 light_direction_at(float elevation_deg, float azimuth_deg) {
    const float e = glm::radians(elevation_deg), a = glm::radians(azimuth_deg);
    // From the scene towards the light, then reversed: light travels down.
    const glm::vec3 to_light(std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a));
    return -glm::normalize(to_light);
}

namespace {
Object make_object(const char* name, int mesh, int material, const glm::mat4& world) {
    Object o;
    o.name = name;
    o.mesh = mesh;
    o.material = material;
    o.world = world;
    return o;
}
}  // namespace

Scene make_box_on_plane(float elevation_deg, float azimuth_deg, float scale) {
    Scene s;
    s.meshes = {make_quad(10.0f), make_box(glm::vec3(0.5f, 0.3f, 0.5f))};
    Material ground, box;
    ground.base_color = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    box.base_color = glm::vec4(0.7f, 0.4f, 0.3f, 1.0f);
    s.materials = {ground, box};
    const glm::mat4 S = glm::scale(glm::mat4(1.0f), glm::vec3(scale));
    s.objects = {make_object("ground", 0, 0, S),
                 make_object("box", 1, 1, S * glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.3f, 0.0f)))};
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = 0;
    s.light.type = LightType::Directional;
    s.light.direction = light_direction_at(elevation_deg, azimuth_deg);
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 5.0f, 5.0f) * scale, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(50.0f);
    s.camera.znear = 0.1f * scale;
    s.camera.zfar = 40.0f * scale;
    return s;
}

Scene make_sphere_over_plane(float scale, float znear, float zfar) {
    Scene s;
    s.meshes = {make_quad(10.0f), make_sphere(1.0f, 64, 32)};
    s.materials.resize(1);
    const glm::mat4 S = glm::scale(glm::mat4(1.0f), glm::vec3(scale));
    s.objects = {make_object("ground", 0, 0, S),
                 make_object("sphere", 1, 0, S * glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 0.0f)))};
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = 0;
    s.light.type = LightType::Directional;
    s.light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 7.0f, 7.0f) * scale, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(50.0f);
    s.camera.znear = znear > 0.0f ? znear : 0.5f * scale;
    s.camera.zfar = zfar > 0.0f ? zfar : 40.0f * scale;
    return s;
}

void place_light(Scene& s, const glm::vec3& centre, float distance, float elevation_deg, float azimuth_deg) {
    const glm::vec3 dir = light_direction_at(elevation_deg, azimuth_deg);
    s.light.direction = dir;
    s.light.position = centre - dir * distance;
}

}  // namespace penumbra::scene
