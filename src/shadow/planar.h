// Planar projected shadows (seed 001): the matrix that flattens geometry onto a plane
// from a point light (light.w = 1) or along a direction (light.w = 0).
#pragma once

#include <glm/glm.hpp>

namespace penumbra::shadow {

// plane = (n, d) with n.p + d = 0. light = (p, 1) for a point light, (-direction, 0) for a
// directional light (a homogeneous point at infinity in the direction the light comes from).
// M * x lies on the plane, on the line through the light and x.
glm::mat4 planar_projection(const glm::vec4& plane, const glm::vec4& light);

}  // namespace penumbra::shadow
