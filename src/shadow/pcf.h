// Percentage-closer filter kernels, in texels; the shader scales them by texmapscale = 1/size.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shadow/encoding.h"

namespace penumbra::shadow {

// Hard: {(0,0)}; PCF2x2: the 4 offsets (+-0.5, +-0.5); PCF4x4: the 16 offsets in {-1.5,-0.5,0.5,1.5}^2.
std::vector<glm::vec2> pcf_offsets(Filter filter);

}  // namespace penumbra::shadow
