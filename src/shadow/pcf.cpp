// Percentage-closer filter kernels: the texel offsets the shadow lookup averages over.
#include "shadow/pcf.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadow {

std::vector<glm::vec2> pcf_offsets(Filter filter) {
    // Offsets sit at half-texel positions for the even kernels so the taps are symmetric about
    // the lookup point (sum of offsets = 0) and each lands between texel centres, as in
    // GPU Gems ch. 11.
    int n = 1;
    switch (filter) {
        case Filter::Hard: return {glm::vec2(0.0f)};
        case Filter::PCF2x2: n = 2; break;
        case Filter::PCF4x4: n = 4; break;
    }
    std::vector<glm::vec2> out;
    out.reserve(static_cast<size_t>(n * n));
    const float first = -0.5f * static_cast<float>(n - 1);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) out.emplace_back(first + static_cast<float>(x), first + static_cast<float>(y));
    return out;
}

float kernel_reach_texels(Filter filter) {
    float reach = 0.0f;
    for (const glm::vec2& o : pcf_offsets(filter)) reach = std::max({reach, std::fabs(o.x), std::fabs(o.y)});
    return reach + 1.0f;
}

float pcf_visibility(Filter filter, glm::vec2 uv, float z, float bias, glm::vec2 texel,
                     const std::function<float(glm::vec2)>& stored_depth) {
    const auto taps = pcf_offsets(filter);
    float lit = 0.0f;
    for (const glm::vec2& o : taps) lit += z > stored_depth(uv + o * texel) + bias ? 0.0f : 1.0f;
    return lit / static_cast<float>(taps.size());
}

}  // namespace penumbra::shadow
