// Lights with a size (scene::Light::radius), sampled: the points Heckbert and Herf's method renders
// a hard shadow from and averages (seed 001, "Soft shadows"). A sphere light of radius R seen from
// the scene is a disc of radius R facing it; a sun of angular radius theta is a cone of directions.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::shadow {

// Point k (0-based) of a light sampled over its disc: the Halton (2, 3) point k + 1 mapped onto the
// unit disc by Shirley's concentric map, so every prefix of the sequence is spread evenly over the
// disc (a progressive render that stops after any k samples is still stratified) and the same k
// gives the same point in every frame. Returned in [-1, 1]^2, inside the unit disc.
glm::vec2 area_sample_point(int k);

// The light moved to sample k: a point or spot light's position moved by radius * (x a + y b) over
// the disc perpendicular to `axis` (unit: from the light towards what it lights); a directional
// light's direction tilted by up to its angular radius. A light of radius 0 is returned unchanged.
scene::Light area_light_sample(const scene::Light& light, int k, const glm::vec3& axis);

// The halton radical inverse of i in base b (b = 2 and 3 above).
float radical_inverse(int i, int base);

}  // namespace penumbra::shadow
