// Small scenes with known answers, for the precision and bias measurements and the extreme-case
// tests: a box standing on a plane under a directional light at a chosen elevation, a sphere
// floating over a plane, and a way to put the course scene's light at a chosen elevation.
#pragma once

#include "scene/scene.h"

namespace penumbra::scene {

// The direction a light at `elevation_deg` above the horizon (azimuth measured from +x towards +z)
// shines along (unit, pointing down towards the scene).
glm::vec3 light_direction_at(float elevation_deg, float azimuth_deg);

// A 10 x 10 ground quad ("ground") at y = 0 with a 1 x 0.6 x 1 box standing on it at the centre,
// lit by a directional light at the given elevation, seen from above at 45 degrees. `scale`
// multiplies every length (camera included), for the scale extremes.
Scene make_box_on_plane(float elevation_deg, float azimuth_deg = 30.0f, float scale = 1.0f);

// A sphere of radius `scale` centred 2 * scale above a 10 * scale ground quad, with a directional
// light straight down; camera near/far can be overridden (0 keeps the defaults).
Scene make_sphere_over_plane(float scale = 1.0f, float znear = 0.0f, float zfar = 0.0f);

// Moves a point or spot light to `distance` from `centre` at the given elevation and azimuth,
// keeping it aimed at the centre; a directional light takes the direction.
void place_light(Scene& scene, const glm::vec3& centre, float distance, float elevation_deg, float azimuth_deg);

}  // namespace penumbra::scene
