// Resolution matching: see resolution.h.
#include "shadow/resolution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shadow/light_frustum.h"

namespace penumbra::shadow {

float screen_pixels(const std::vector<glm::vec3>& points, const glm::mat4& camera_view_proj, int width, int height) {
    return hull_share(camera_view_proj, points) * static_cast<float>(width) * static_cast<float>(height);
}

MatchedSize matched_map_size(float pixels, float use, int maps, int smallest, int largest) {
    MatchedSize m;
    // Powers of two only: `largest` down to one (a cube's atlas bound, 4096 / 3, is 1365).
    int p = smallest;
    while (p * 2 <= largest) p *= 2;
    largest = p;
    char b[200];
    if (!(pixels >= 1.0f) || !(use > 0.0f)) {
        // Nothing of the receivers in view: the smallest map holds what little there is.
        m.size = smallest;
        std::snprintf(b, sizeof b, "auto %d: no receiver in view", m.size);
        m.why = b;
        return m;
    }
    // Each of `maps` tiles of n texels: n^2 * use texels over the receivers' pixels.
    const double wanted = kTexelsPerPixel * std::sqrt(static_cast<double>(pixels) / static_cast<double>(use));
    m.wanted = static_cast<int>(std::min(wanted, 1e9));
    int n = smallest;
    while (n < largest && n < wanted) n *= 2;
    m.size = std::min(n, largest);
    const char* bound = m.size == largest && wanted > largest ? ", the largest allowed" : m.size == smallest && wanted < smallest ? ", the smallest allowed" : "";
    std::snprintf(b, sizeof b, "auto %d%s: the receivers in view cover %.0f pixels and %.1f%% of %s; %g texels a pixel want %d",
                  m.size, bound, static_cast<double>(pixels), 100.0 * static_cast<double>(use) / std::max(maps, 1),
                  maps > 1 ? "each face on average" : "the map", static_cast<double>(kTexelsPerPixel), m.wanted);
    m.why = b;
    return m;
}

}  // namespace penumbra::shadow
