// --lights N: point lights beside the scene's light, each with a range, unshadowed. Where they
// stand and how bright they are is a function of the scene and N alone, so the forward and the
// deferred frame (plan/frames/deferred.h), the bench and the tests all light the same scene.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::render {

struct PointLight {
    glm::vec3 position{0.0f};
    float range = 1.0f;  // no light at this distance and beyond
    glm::vec3 color{1.0f};
};

// N lights on a Vogel disc over the receivers, a little above the top of the widest (the table):
// hues around the colour wheel, the range shrinking as N grows (1/sqrt N of the disc's radius,
// between 0.15 and 0.5 of it) and the colour dimmed where many overlap, so that 256 lights do
// not wash the image out.
std::vector<PointLight> point_lights(const scene::Scene& scene, int n);

// What one light adds to a surface: Lambert's diffuse times a falloff (1 - (d/range)^2)^2 that
// reaches 0 at the range (points.glsl computes the same).
glm::vec3 point_light_term(const PointLight& l, const glm::vec3& world, const glm::vec3& normal, const glm::vec3& base);

// Forward shading lights them in batches of this many per pass (a uniform array of 2 vec4 each).
inline constexpr int kLightsPerPass = 16;

}  // namespace penumbra::render
