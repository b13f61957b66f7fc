// Whether every entry of a matrix is finite (no NaN, no infinity): what the extremes and the
// light-frustum tests ask of every matrix a fit makes.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace penumbra::test {

inline bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace penumbra::test
