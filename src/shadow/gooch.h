// Gooch et al.'s soft shadow (seed 001, "Gooch's method"): the receiving plane moved towards and
// away from the light. The casters are flattened from the light onto K planes parallel to the
// ground at offsets o_i (symmetric about 0), each projection is moved back onto the real ground
// along the plane's normal, and the K shadows are averaged. Moving a plane by o scales the shadow
// about the light's foot point (point light) or slides it along the light's tilt (directional
// light), by o / (H - h) of the caster's lateral distance from the foot, so the spread is radial
// (along the light's tilt) and the penumbra it makes is always too big: the whole shadow, umbra
// included, moves, and contact points slide too. No GL here: the matrices, offsets and weights.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace penumbra::shadow {

// The matrix that flattens geometry from `light` ((p, 1) point, (-direction, 0) directional) onto
// the plane parallel to `ground` ((n, d), n.x + d = 0) at signed distance `offset` along n, then
// moves the result back onto the ground along -n. offset 0: exactly planar_projection(ground, light).
glm::mat4 gooch_projection(const glm::vec4& ground, const glm::vec4& light, float offset);

// K offsets spread * (2 i / (K - 1) - 1), i = 0..K-1: symmetric about 0, from -spread to +spread
// (K = 1: {0}). With spread 0 every entry is exactly 0.
std::vector<float> gooch_offsets(int k, float spread);

// How far the outermost planes are moved (the spread), from the light's radius: chosen so that the
// outermost projection's shift of the shadow of the casters' centre `caster` equals the half-width
// of the penumbra a light of that radius throws from the caster's height h onto the ground:
//   point light at height H over the ground, radius R:  half-width R h / (H - h);
//   directional light, angular radius a:                half-width h tan a.
// The shift of that shadow point by a plane at offset o is o tan t, t the angle of the ray through
// the caster from the ground's normal (t = lateral distance from the light's foot / (H - h) for a
// point light), so spread = half-width / tan t. tan t is taken as at least kGoochMinTilt (a light
// straight over the caster moves nothing sideways: the spread would be infinite), and a point
// light's planes are kept below it (spread <= H / 2). Radius 0 (or no caster over the ground): 0.
inline constexpr float kGoochMinTilt = 0.25f;
float gooch_spread(const glm::vec4& ground, const glm::vec4& light, float radius, const glm::vec3& caster);

// The K weights as whole bytes (of 255) that sum to exactly 255: plane i adds
// round((i + 1) 255 / K) - round(i 255 / K). A pixel lit by all planes ends at exactly 255 in an
// 8-bit target (the hard shadow's lit value); one lit by m planes is within m/2 of a byte of
// 255 m / K.
std::vector<int> gooch_weight_bytes(int k);

// K points of a Vogel (golden-angle) spiral in the unit disc, for the texture variant's taps
// (point i at radius sqrt((i + 0.5) / K)); K = 1: the centre.
std::vector<glm::vec2> gooch_disc(int k);

}  // namespace penumbra::shadow
