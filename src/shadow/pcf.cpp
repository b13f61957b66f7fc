// Percentage-closer filter kernels: the texel offsets the shadow lookup averages over.
#include "shadow/pcf.h"

namespace penumbra::shadow {

std::vector<glm::vec2> pcf_offsets(Filter filter) {
    // Offsets sit at half-texel positions for the even kernels so the taps are symmetric about
    // the lookup point (sum of offsets = 0) and each lands between texel centres, as in
    // GPU Gems ch. 11. Order: rows (y) outer, columns (x) inner, bottom-left first.
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

}  // namespace penumbra::shadow
