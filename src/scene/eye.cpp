// Where the eye is (scene/eye.h): the camera moved into the shadow of the largest caster. In
// penumbra_core (no file formats), so the exercise pages can place it too.
#include "scene/eye.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {

bool place_eye_in_shadow(Scene& scene) {
    int best = -1;
    float size = 0.0f;
    Bounds box;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (!o.casts_shadow || static_cast<int>(i) == scene.ground_object) continue;
        const Bounds b = object_bounds(scene, o);
        if (b.empty()) continue;
        const float d = glm::length(b.max - b.min);
        if (d > size && std::isfinite(d)) best = static_cast<int>(i), size = d, box = b;
    }
    if (best < 0) return false;
    const Light& l = scene.light;
    const glm::vec3 c = box.center();
    glm::vec3 dir = l.type == LightType::Directional ? l.direction : c - l.position;
    if (!(glm::length(dir) > 0.0f)) return false;
    dir = glm::normalize(dir);
    const float r = 0.5f * size;
    float along = 1.15f * r;  // just beyond the caster's bounding sphere
    glm::vec3 up(0.0f, 1.0f, 0.0f);
    if (scene.ground_plane) {
        const glm::vec3 n = glm::normalize(glm::vec3(*scene.ground_plane));
        up = n;
        // Not below the ground: at most 80% of the way from the centre to where the ray meets it,
        // and no nearer the ground than 2% of the caster's size.
        const float height = glm::dot(n, c) + scene.ground_plane->w / glm::length(glm::vec3(*scene.ground_plane));
        const float fall = -glm::dot(n, dir);
        if (fall > 1e-4f && height > 0.0f) along = std::min(along, std::max(0.0f, (height - 0.02f * size) / fall));
    }
    const glm::vec3 eye = c + dir * along;
    // Look across the shadow (60 degrees off the direction away from the light, so both the shadow
    // and the lit ground beside it are in view) and down towards the ground.
    glm::vec3 ahead = dir - up * glm::dot(dir, up);
    if (!(glm::length(ahead) > 1e-4f)) ahead = glm::abs(up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    ahead = glm::normalize(ahead);
    const glm::vec3 side = glm::cross(up, ahead);
    const glm::vec3 across = 0.5f * ahead + 0.866f * side;
    const glm::vec3 target = eye + across * r * 2.0f - up * r * 0.8f;
    scene.camera.view = glm::lookAt(eye, target, up);
    scene.camera.znear = std::min(scene.camera.znear, 0.02f * r);
    return true;
}

}  // namespace penumbra::scene
