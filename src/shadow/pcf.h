// Percentage-closer filter kernels, in texels: the one definition of each filter's taps. The
// shader generator writes them into the lookup (render/variants.cpp: PCF_SUM) and the CPU mirror
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
bool pcf_is_corner(Filter filter, glm::vec2 offset);

// The CPU mirror of the shader's lookup: the fraction of taps where the receiver at depth z is lit
// (z <= stored depth + bias), each tap at uv + offset * texel. `stored_depth` reads the map. With
// PcfKernel::EarlyExit, 0 or 1 when the corner taps agree, as the shader returns it.
float pcf_visibility(Filter filter, PcfKernel kernel, glm::vec2 uv, float z, float bias, glm::vec2 texel,
                     const std::function<float(glm::vec2)>& stored_depth);

}  // namespace penumbra::shadow
