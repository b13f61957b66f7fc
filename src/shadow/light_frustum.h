// The light's view and projection, fitted tightly around the points that must be in the map
// (exercise W09P2a): perspective for point and spot lights, orthographic for directional ones.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::shadow {

struct LightFrustum {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    float znear = 0.1f;  // distances along the light's view axis (eye space -z)
    float zfar = 1.0f;
    bool perspective = true;
    glm::mat4 view_proj() const { return proj * view; }
};

// Fit the light's frustum around `points` (world space: the corners of every caster's and
// receiver's bounds). A point or spot light looks from its position towards `aim` (the scene's
// centre, as the exercise does); a directional light looks along its direction. The view's up
// vector is chosen so that it is never parallel to the view axis (a light straight overhead).
// Every point lies inside the returned clip volume, with a small margin.
LightFrustum fit_light_frustum(const scene::Light& light, const std::vector<glm::vec3>& points,
                               const glm::vec3& aim);

// Matrix that maps clip space [-1,1] to texture space [0,1] (the sheet's B).
glm::mat4 clip_to_texture();

}  // namespace penumbra::shadow
