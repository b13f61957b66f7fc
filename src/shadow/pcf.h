// Percentage-closer filter kernels, in texels: the one definition of each filter's taps. The
// shader generator writes them into the lookup (plan/variants.cpp: PCF_SUM) and the CPU mirror
// below averages the same taps, so the two cannot drift apart.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "shadow/encoding.h"

namespace penumbra::shadow {

// Hard: {(0,0)}; PCF2x2: the 4 offsets (+-0.5, +-0.5); PCF4x4: the 16 offsets in {-1.5,-0.5,0.5,1.5}^2.
// Rows (y) outer, columns (x) inner, bottom-left first.
std::vector<glm::vec2> pcf_offsets(Filter filter);

// --bias auto's reach of the kernel in texels per axis: the largest tap offset, plus half a texel
// to the nearest texel centre, plus half a texel of margin. Without the margin the bias equals the
// worst-case depth step exactly and the comparison's own rounding decides, which shows as acne
// (measured on the course table).
float kernel_reach_texels(Filter filter);

// The early exit (PcfKernel::EarlyExit) looks at the kernel's 4 corner taps first, the offsets of
// pcf_offsets at its reach on both axes (+-1.5, +-1.5 for PCF 4x4), and returns their common
// answer when they agree; only where they disagree are the other taps read and all averaged as the
// full kernel averages them. It applies to kernels with taps other than their corners: PCF 4x4.
// Hard has one tap and PCF 2x2's four taps are its corners, so both are the full kernel either way
// (and their shader variants are the same).
bool pcf_early_exit_applies(Filter filter);

// PCSS's taps: n points of a Vogel (sunflower) disc of radius 1, point i at radius
// sqrt((i + 0.5) / n) and angle i * the golden angle + rotation. The shader turns the disc by a
// per-pixel angle (interleaved gradient noise) and scales it per fragment; the same formula here.
inline constexpr float kGoldenAngle = 2.3999632f;
std::vector<glm::vec2> vogel_disc(int n, float rotation = 0.0f);

// PCSS's two radii for a receiver at light-eye depth receiver_depth (along the light's axis):
// where its blockers can be (the cone from the receiver to the light's disc, at the light's near
// plane) and the penumbra's half-width for blockers at blocker_depth (the same cone at that
// depth), both in the map's units before the texture scale: tangent units for a perspective
// light (light_size = its radius in world units), world units for an orthographic one
// (light_size = tan of its angular radius). The shader computes the same (shadow.glsl).
struct PcssRadii {
    float search = 0.0f;
    float penumbra = 0.0f;
};
PcssRadii pcss_radii(float light_size, bool perspective, float receiver_depth, float blocker_depth, float near);

// The same cone in the map's window depth (the shader's pcssConeDepth): a point `rho` from the
// receiver's ray (the units of pcss_radii) is inside the cone at window depths up to
// at_ray - per_unit * rho. `near`, `far`: the light's planes (eye depths).
struct PcssConeDepth {
    float at_ray = 0.0f;
    float per_unit = 0.0f;
    float deepest(float rho) const { return at_ray - per_unit * rho; }
};
PcssConeDepth pcss_cone_depth(float light_size, bool perspective, float receiver_depth, float near, float far);

// One blocker the search found: its window depth and its distance from the receiver's ray.
struct PcssBlocker {
    float depth = 0.0f;
    float rho = 0.0f;
};
// The window depth that sizes the penumbra (--pcss-blockers): layered, the mean depth of the
// blockers inside the cone (those that can hide part of the light from this receiver; if none
// is, the least depth of all: the widest penumbra, so that the filter reaches furthest for a
// caster the taps missed); mean, of all of them (Fernando 2005). No blockers: -1 (the receiver is
// lit). The shader's search adds a tap on the receiver's own ray, at rho 0, always inside.
float pcss_blocker_depth(const std::vector<PcssBlocker>& blockers, const PcssConeDepth& cone, bool layered);

bool pcf_is_corner(Filter filter, glm::vec2 offset);

// The CPU mirror of the shader's lookup: the fraction of taps where the receiver at depth z is lit
// (z <= stored depth + bias), each tap at uv + offset * texel. `stored_depth` reads the map. With
// PcfKernel::EarlyExit, 0 or 1 when the corner taps agree, as the shader returns it.
float pcf_visibility(Filter filter, PcfKernel kernel, glm::vec2 uv, float z, float bias, glm::vec2 texel,
                     const std::function<float(glm::vec2)>& stored_depth);

}  // namespace penumbra::shadow
