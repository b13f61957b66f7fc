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

// The share of clip space's square [-1, 1]^2 covered by the convex hull of `points` through `vp`
// (points at or behind its eye plane left out, the rest held to the square: a part is clipped to
// the window already, so only rounding lies outside). Monotone chain over `scratch`, so the many
// small parts of a large scene cost no allocation each.
double part_share(const glm::mat4& vp, const std::vector<glm::vec3>& points, std::vector<glm::vec2>& scratch) {
    scratch.clear();
    for (const glm::vec3& p : points) {
        const glm::vec4 c = vp * glm::vec4(p, 1.0f);
        if (!(c.w > 0.0f)) continue;
        const glm::vec2 q = glm::vec2(c) / c.w;
        if (std::isfinite(q.x) && std::isfinite(q.y)) scratch.push_back(glm::clamp(q, glm::vec2(-1.0f), glm::vec2(1.0f)));
    }
    if (scratch.size() < 3) return 0.0;
    std::sort(scratch.begin(), scratch.end(), [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    const auto cross = [](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
        return static_cast<double>(a.x - o.x) * (b.y - o.y) - static_cast<double>(a.y - o.y) * (b.x - o.x);
    };
    // Lower then upper chain into the back of `scratch`, past the sorted points.
    const size_t n = scratch.size();
    scratch.resize(3 * n);
    size_t k = n;
    for (size_t i = 0; i < n; ++i) {
        while (k >= n + 2 && cross(scratch[k - 2], scratch[k - 1], scratch[i]) <= 0.0) --k;
        scratch[k++] = scratch[i];
    }
    for (size_t i = n - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(scratch[k - 2], scratch[k - 1], scratch[i]) <= 0.0) --k;
        scratch[k++] = scratch[i];
    }
    double twice = 0.0;
    for (size_t i = n; i + 1 < k; ++i)
        twice += static_cast<double>(scratch[i].x) * scratch[i + 1].y - static_cast<double>(scratch[i + 1].x) * scratch[i].y;
    return std::min(std::fabs(twice) / 8.0, 1.0);
}

}  // namespace

Demand receiver_demand(const scene::Light& light, const std::vector<scene::Bounds>& receivers, const glm::mat4& camera_view_proj,
                       int width, int height, const glm::mat4& map_view_proj) {
    const std::array<HalfSpace, 6> window = clip_volume_half_spaces(map_view_proj);
    std::vector<char> whole;
    const std::vector<std::vector<glm::vec3>> seen =
        visible_points_each(light, receivers, camera_view_proj, whole, {window.begin(), window.end()});
    constexpr int n = kDenseTiles;
    struct Tile {
        double pixels = 0.0, share = 0.0;
        std::vector<scene::Bounds> across;  // receivers whose part spans this tile and others
    };
    std::vector<Tile> tiles(static_cast<size_t>(n * n));
    const double image = static_cast<double>(width) * static_cast<double>(height);
    std::vector<glm::vec2> scratch;
    const auto tile_of = [](float v) { return std::clamp(static_cast<int>((v + 1.0f) * 0.5f * static_cast<float>(n)), 0, n - 1); };
    for (size_t k = 0; k < seen.size(); ++k) {
        if (seen[k].empty()) continue;
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
        const int x0 = tile_of(lo.x), x1 = tile_of(hi.x), y0 = tile_of(lo.y), y1 = tile_of(hi.y);
        if (x0 == x1 && y0 == y1) {  // inside one tile: its part as it is
            Tile& t = tiles[static_cast<size_t>(y0 * n + x0)];
            t.pixels += part_share(camera_view_proj, seen[k], scratch) * image;
            t.share += part_share(map_view_proj, seen[k], scratch);
            continue;
        }
        for (int ty = y0; ty <= y1; ++ty)
            for (int tx = x0; tx <= x1; ++tx) tiles[static_cast<size_t>(ty * n + tx)].across.push_back(receivers[k]);
    }
    Demand d;
    struct Need {
        double wanted, pixels;
    };
    std::vector<Need> needs;
    for (int ty = 0; ty < n; ++ty)
        for (int tx = 0; tx < n; ++tx) {
            Tile& t = tiles[static_cast<size_t>(ty * n + tx)];
            if (!t.across.empty()) {
                // Those across tiles clipped again by this one's frustum (most span two to four).
                const auto at = [](int i) { return -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(n); };
                const std::array<HalfSpace, 6> planes =
                    clip_volume_half_spaces(tile_view_proj(map_view_proj, at(tx), at(tx + 1), at(ty), at(ty + 1)));
                for (const std::vector<glm::vec3>& part :
                     visible_points_each(light, t.across, camera_view_proj, whole, {planes.begin(), planes.end()})) {
                    t.pixels += part_share(camera_view_proj, part, scratch) * image;
                    t.share += part_share(map_view_proj, part, scratch);
                }
            }
            d.pixels += t.pixels;
            d.share += t.share;
            if (t.pixels >= 1.0 && t.share > 0.0) needs.push_back({kDenseTexelsPerPixel * std::sqrt(t.pixels / t.share), t.pixels});
        }
    if (needs.empty()) return d;
    std::sort(needs.begin(), needs.end(), [](const Need& a, const Need& b) { return a.wanted < b.wanted; });
    double total = 0.0, served = 0.0;
    for (const Need& need : needs) total += need.pixels;
    for (const Need& need : needs) {
        served += need.pixels;
        d.dense = need.wanted;
        if (served >= kDenseShare * total) break;
    }
    return d;
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
                  "auto %d%s: the receivers in view cover %.0f pixels and %.1f%% of %s, part by part; %g texels a pixel want %.0f on "
                  "average; %g a pixel over %.0f%% of them, tile by tile, want %.0f%s",
                  m.size, bound, static_cast<double>(pixels), 100.0 * static_cast<double>(use) / std::max(maps, 1),
                  maps > 1 ? "each face on average" : "the map", static_cast<double>(kTexelsPerPixel), average,
                  static_cast<double>(kDenseTexelsPerPixel), 100.0 * kDenseShare, dense,
                  scaled ? " (the image counted as 512 pixels a side)" : "");
    m.why = b;
    return m;
}

}  // namespace penumbra::shadow
