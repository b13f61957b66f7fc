// Lights with a size (scene::Light::radius), sampled: the points Heckbert and Herf's method renders
// a hard shadow from and averages (seed 001, "Soft shadows"). A sphere light of radius R seen from
// the scene is a disc of radius R facing it; a sun of angular radius theta is a cone of directions.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::shadow {

// Point k (0-based) of the n a light is sampled with, over its disc: a rank-1 lattice spiral, the
// i-th point at radius sqrt((i + 1/2) / n) and angle 2 pi (i g / n mod 1). Heckbert-Herf counts
// the points on the lit side of each caster's edge, so what matters is how evenly the points split
// under a line across the disc, and g is chosen for n by exactly that (area_light.cpp): 64 points
// split it with a mean error of 1.01 % of the disc against 1.57 % for the first 64 Halton (2, 3)
// points this used before (docs/soft.md). The index i is taken in bit-reversed order of k, so a
// block of n / 4 or n / 16 consecutive k (an interleaved pixel class's share, --area-interleave,
// or a progressive render's first frames) is the residue class of i mod 4 or 16, a lattice of its
// own, and spread over the whole disc too. The same (k, n) gives the same point in every frame.
// Returned inside the unit disc; n = 1 is the centre.
glm::vec2 area_sample_point(int k, int n);

// The light moved to sample k of n: a point or spot light's position moved by radius * (x a + y b) over
// the disc perpendicular to `axis` (unit: from the light towards what it lights); a directional
// light's direction tilted by up to its angular radius. A light of radius 0 is returned unchanged.
scene::Light area_light_sample(const scene::Light& light, int k, int n, const glm::vec3& axis);

}  // namespace penumbra::shadow
