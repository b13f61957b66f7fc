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
    const std::vector<glm::vec4> window_planes(window.begin(), window.end());
    std::vector<char> whole;
    const std::vector<std::vector<glm::vec3>> seen = visible_points_each(light, receivers, camera_view_proj, whole, window_planes);
    const ClipPlanes planes = visible_clip_planes(light, camera_view_proj, window_planes);
    constexpr int n = kDenseTiles;
    struct Tile {
        double pixels = 0.0, share = 0.0;
    };
    std::vector<Tile> tiles(static_cast<size_t>(n * n));
    const double image = static_cast<double>(width) * static_cast<double>(height);
    std::vector<glm::vec2> scratch;
    const auto tile_of = [](float v) { return std::clamp(static_cast<int>((v + 1.0f) * 0.5f * static_cast<float>(n)), 0, n - 1); };
    const auto at = [](int i) { return -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(n); };
    // The map's x >= a (axis 0) or y >= a (axis 1) as a half-space of world space (w > 0 in the
    // window): row `axis` - a row 3 of the matrix.
    const auto beyond = [&map_view_proj](int axis, float a) {
        const glm::vec4 r(map_view_proj[0][axis] - a * map_view_proj[0][3], map_view_proj[1][axis] - a * map_view_proj[1][3],
                          map_view_proj[2][axis] - a * map_view_proj[2][3], map_view_proj[3][axis] - a * map_view_proj[3][3]);
        const ClipPlanes unit = clip_planes({r});
        return unit.unit.empty() ? HalfSpace(0.0f, 0.0f, 0.0f, 1.0f) : unit.unit[0];
    };
    std::vector<glm::vec3> points;
    std::vector<int> tile_index;
    // The planes between tiles and a receiver's sections by them, reused from receiver to receiver
    // (only those between the tiles a receiver spans are made and read).
    std::vector<HalfSpace> xs(static_cast<size_t>(n + 1)), ys(static_cast<size_t>(n + 1));
    std::vector<std::vector<glm::vec3>> x_sections(static_cast<size_t>(n + 1)), y_sections(static_cast<size_t>(n + 1));
    for (size_t k = 0; k < seen.size(); ++k) {
        if (seen[k].empty()) continue;
        glm::vec2 lo(1.0f), hi(-1.0f);
        tile_index.assign(seen[k].size(), -1);
        for (size_t v = 0; v < seen[k].size(); ++v) {
            const glm::vec4 c = map_view_proj * glm::vec4(seen[k][v], 1.0f);
            if (!(c.w > 0.0f)) continue;
            const glm::vec2 q = glm::clamp(glm::vec2(c) / c.w, glm::vec2(-1.0f), glm::vec2(1.0f));
            if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
            tile_index[v] = tile_of(q.y) * n + tile_of(q.x);
        }
        if (lo.x > hi.x || lo.y > hi.y) continue;
        const int x0 = tile_of(lo.x), x1 = tile_of(hi.x), y0 = tile_of(lo.y), y1 = tile_of(hi.y);
        if (x0 == x1 && y0 == y1) {  // inside one tile: its part as it is
            Tile& t = tiles[static_cast<size_t>(y0 * n + x0)];
            t.pixels += part_share(camera_view_proj, seen[k], scratch) * image;
            t.share += part_share(map_view_proj, seen[k], scratch);
            continue;
        }
        // A part across tiles, cut by each: the part within a tile has for vertices the part's own
        // vertices in it and those of the part's sections by the planes between tiles, each
        // section cut to the tile's side. So the sections are made once a plane (x0 < i <= x1,
        // y0 < j <= y1), not the part clipped again by each tile's frustum.
        for (int i = x0; i <= x1 + 1; ++i) xs[static_cast<size_t>(i)] = beyond(0, at(i));
        for (int j = y0; j <= y1 + 1; ++j) ys[static_cast<size_t>(j)] = beyond(1, at(j));
        for (int i = x0 + 1; i <= x1; ++i)
            x_sections[static_cast<size_t>(i)] = clip_box_section(receivers[k], planes, xs[static_cast<size_t>(i)]);
        for (int j = y0 + 1; j <= y1; ++j)
            y_sections[static_cast<size_t>(j)] = clip_box_section(receivers[k], planes, ys[static_cast<size_t>(j)]);
        // A section's piece on one tile's side: between the two planes across it.
        const auto side = [&points](std::vector<glm::vec3> piece, const HalfSpace& from, const HalfSpace& to) {
            if (!piece.empty()) piece = clip_polygon(piece, from);
            if (!piece.empty()) piece = clip_polygon(piece, -to);
            points.insert(points.end(), piece.begin(), piece.end());
        };
        for (int ty = y0; ty <= y1; ++ty)
            for (int tx = x0; tx <= x1; ++tx) {
                points.clear();
                const int index = ty * n + tx;
                for (size_t v = 0; v < seen[k].size(); ++v)
                    if (tile_index[v] == index) points.push_back(seen[k][v]);
                const size_t x = static_cast<size_t>(tx), y = static_cast<size_t>(ty);
                if (tx > x0) side(x_sections[x], ys[y], ys[y + 1]);
                if (tx < x1) side(x_sections[x + 1], ys[y], ys[y + 1]);
                if (ty > y0) side(y_sections[y], xs[x], xs[x + 1]);
                if (ty < y1) side(y_sections[y + 1], xs[x], xs[x + 1]);
                Tile& t = tiles[static_cast<size_t>(index)];
                t.pixels += part_share(camera_view_proj, points, scratch) * image;
                t.share += part_share(map_view_proj, points, scratch);
            }
    }
    Demand d;
    struct Need {
        double wanted, pixels;
    };
    std::vector<Need> needs;
    for (const Tile& t : tiles) {
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

int map_size_step(double wanted, int smallest, SizeSteps steps) {
    int n = smallest;
    while (n < wanted && n < (1 << 30)) n *= 2;
    if (steps == SizeSteps::PowersOfTwo || n == smallest) return n;
    // n is the power of two at or above the want; the want lies in (n / 2, n].
    const int step = std::max(n / 16, 1);
    return std::min(n, static_cast<int>(std::ceil(wanted / step)) * step);
}

MatchedSize matched_map_size(float pixels, float use, int maps, int smallest, int largest, double dense, bool scaled,
                             SizeSteps steps) {
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
    m.size = std::min(map_size_step(std::min(wanted, static_cast<double>(largest)), smallest, steps), largest);
    const char* bound = m.size == largest && wanted > largest ? ", the largest allowed" : m.size == smallest && wanted < smallest ? ", the smallest allowed" : "";
    std::snprintf(b, sizeof b,
                  "auto %d%s: the receivers in view cover %.0f pixels and %.1f%% of %s, part by part; %g texels a pixel want %.0f on "
                  "average; %g a pixel over %.0f%% of them, tile by tile, want %.0f%s",
                  m.size, bound, static_cast<double>(pixels), 100.0 * static_cast<double>(use) / std::max(maps, 1),
                  maps > 1 ? "each face on average" : "the map", static_cast<double>(kTexelsPerPixel), average,
                  static_cast<double>(kDenseTexelsPerPixel), 100.0 * kDenseShare, dense,
                  scaled ? " (the image counted as 512 pixels a side)" : "");
    m.why = b;
    if (steps == SizeSteps::Eighths) m.why += "; rounded up by eighths of an octave";
    return m;
}

}  // namespace penumbra::shadow
