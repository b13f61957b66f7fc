// Resolution matching: see resolution.h.
#include "shadow/resolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "shadow/convex.h"
#include "shadow/light_frustum.h"

namespace penumbra::shadow {

namespace {

// The clip space of the part [x0, x1] x [y0, y1] (NDC) of `vp`'s window, as a matrix of its own:
// its clip volume is that tile's frustum.
glm::mat4 tile_view_proj(const glm::mat4& vp, float x0, float x1, float y0, float y1) {
    glm::mat4 s(1.0f);
    s[0][0] = 2.0f / (x1 - x0);
    s[3][0] = -(x1 + x0) / (x1 - x0);
    s[1][1] = 2.0f / (y1 - y0);
    s[3][1] = -(y1 + y0) / (y1 - y0);
    return s * vp;
}

}  // namespace

double dense_wanted(const scene::Light& light, const std::vector<scene::Bounds>& receivers, const glm::mat4& camera_view_proj,
                    int width, int height, const glm::mat4& map_view_proj) {
    const std::array<HalfSpace, 6> window = clip_volume_half_spaces(map_view_proj);
    std::vector<char> whole;
    const std::vector<std::vector<glm::vec3>> seen =
        visible_points_each(light, receivers, camera_view_proj, whole, {window.begin(), window.end()});
    // Each receiver in the tiles its part in view spans (the bounding rectangle of its points in
    // the map): most span one to four, so the tiles clip about as much as the window did.
    constexpr int n = kDenseTiles;
    std::vector<std::vector<scene::Bounds>> in_tile(static_cast<size_t>(n * n));
    for (size_t k = 0; k < seen.size(); ++k) {
        glm::vec2 lo(1.0f), hi(-1.0f);
        for (const glm::vec3& p : seen[k]) {
            const glm::vec4 c = map_view_proj * glm::vec4(p, 1.0f);
            if (!(c.w > 0.0f)) continue;
            const glm::vec2 q = glm::clamp(glm::vec2(c) / c.w, glm::vec2(-1.0f), glm::vec2(1.0f));
            if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
        if (lo.x > hi.x || lo.y > hi.y) continue;
        const auto tile = [](float v) { return std::clamp(static_cast<int>((v + 1.0f) * 0.5f * static_cast<float>(n)), 0, n - 1); };
        for (int ty = tile(lo.y); ty <= tile(hi.y); ++ty)
            for (int tx = tile(lo.x); tx <= tile(hi.x); ++tx) in_tile[static_cast<size_t>(ty * n + tx)].push_back(receivers[k]);
    }
    struct Need {
        double wanted;
        double pixels;
    };
    std::vector<Need> needs;
    double total = 0.0;
    for (int ty = 0; ty < n; ++ty)
        for (int tx = 0; tx < n; ++tx) {
            const std::vector<scene::Bounds>& boxes = in_tile[static_cast<size_t>(ty * n + tx)];
            if (boxes.empty()) continue;
            const auto at = [](int i) { return -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(n); };
            const glm::mat4 t = tile_view_proj(map_view_proj, at(tx), at(tx + 1), at(ty), at(ty + 1));
            const std::array<HalfSpace, 6> planes = clip_volume_half_spaces(t);
            std::vector<glm::vec3> points;
            for (std::vector<glm::vec3>& part :
                 visible_points_each(light, boxes, camera_view_proj, whole, {planes.begin(), planes.end()}))
                points.insert(points.end(), part.begin(), part.end());
            const double pixels = screen_pixels(points, camera_view_proj, width, height);
            const double share = hull_share(map_view_proj, points);
            if (!(pixels >= 1.0) || !(share > 0.0)) continue;
            needs.push_back({kDenseTexelsPerPixel * std::sqrt(pixels / share), pixels});
            total += pixels;
        }
    if (needs.empty()) return 0.0;
    std::sort(needs.begin(), needs.end(), [](const Need& a, const Need& b) { return a.wanted < b.wanted; });
    double served = 0.0;
    for (const Need& need : needs) {
        served += need.pixels;
        if (served >= kDenseShare * total) return need.wanted;
    }
    return needs.back().wanted;
}

float screen_pixels(const std::vector<glm::vec3>& points, const glm::mat4& camera_view_proj, int width, int height) {
    return hull_share(camera_view_proj, points) * static_cast<float>(width) * static_cast<float>(height);
}

MatchedImage matched_image(int width, int height) {
    MatchedImage m{width, height, false};
    const double side = std::sqrt(static_cast<double>(width) * static_cast<double>(height));
    if (side > 0.0 && side < kMatchedSide) {
        const double k = kMatchedSide / side;
        m.width = static_cast<int>(std::lround(width * k));
        m.height = static_cast<int>(std::lround(height * k));
        m.scaled = true;
    }
    return m;
}

MatchedSize matched_map_size(float pixels, float use, int maps, int smallest, int largest, double dense, bool scaled) {
    MatchedSize m;
    // Powers of two only: `largest` down to one (a cube's atlas bound, 4096 / 3, is 1365).
    int p = smallest;
    while (p * 2 <= largest) p *= 2;
    largest = p;
    char b[1600];
    if (!(pixels >= 1.0f) || !(use > 0.0f)) {
        // Nothing of the receivers in view: the smallest map holds what little there is.
        m.size = smallest;
        std::snprintf(b, sizeof b, "auto %d: no receiver in view", m.size);
        m.why = b;
        return m;
    }
    // Each of `maps` tiles of n texels: n^2 * use texels over the receivers' pixels.
    const double average = kTexelsPerPixel * std::sqrt(static_cast<double>(pixels) / static_cast<double>(use));
    const double wanted = std::max(average, dense);
    m.wanted = static_cast<int>(std::min(wanted, 1e9));
    int n = smallest;
    while (n < largest && n < wanted) n *= 2;
    m.size = std::min(n, largest);
    const char* bound = m.size == largest && wanted > largest ? ", the largest allowed" : m.size == smallest && wanted < smallest ? ", the smallest allowed" : "";
    std::snprintf(b, sizeof b,
                  "auto %d%s: the receivers in view cover %.0f pixels and %.1f%% of %s; %g texels a pixel want %.0f on "
                  "average; %g a pixel over %.0f%% of them, tile by tile, want %.0f%s",
                  m.size, bound, static_cast<double>(pixels), 100.0 * static_cast<double>(use) / std::max(maps, 1),
                  maps > 1 ? "each face on average" : "the map", static_cast<double>(kTexelsPerPixel), average,
                  static_cast<double>(kDenseTexelsPerPixel), 100.0 * kDenseShare, dense,
                  scaled ? " (the image counted as 512 pixels a side)" : "");
    m.why = b;
    return m;
}

}  // namespace penumbra::shadow
