// Procedural marble for the textured objects: value-noise turbulence bent through a sine,
// computed on the CPU so the project ships no image file. The texture tiles: the noise lattice
// wraps at the image's edge and the vein sine runs a whole number of periods across it.
#include "scene/marble.h"

#include "scene/hash.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace penumbra::scene {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;
constexpr int kOctaves = 5;
constexpr int kBaseCells = 4;  // lattice cells across the image at the lowest octave
constexpr float kWhite[3] = {0.93f, 0.92f, 0.90f};
constexpr float kMeanCloud = 0.98f;  // the cloudiness's mean: 0.94 + 0.08 x a noise of mean 1/2

// Where pixel centre p of a size-pixel image falls on a lattice of n cells (the same along x and y):
// the two lattice points either side (wrapping) and the faded fraction between them. Made once per
// octave rather than per pixel and sample: the marble is made before the pages' first frame.
struct Axis {
    struct Cell {
        int i0 = 0, i1 = 0;
        float t = 0.0f;
    };
    std::vector<Cell> cells;

    Axis(int n, int size) : cells(static_cast<size_t>(size)) {
        const auto fade = [](float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); };
        for (int p = 0; p < size; ++p) {
            const float c = (static_cast<float>(p) + 0.5f) / static_cast<float>(size);
            const float f = c * static_cast<float>(n);
            Cell& cell = cells[static_cast<size_t>(p)];
            cell.i0 = std::min(static_cast<int>(f), n - 1);
            cell.i1 = (cell.i0 + 1) % n;
            cell.t = fade(f - static_cast<float>(cell.i0));
        }
    }
};

// One octave of periodic value noise: a cells x cells lattice of values in [0,1) that wraps,
// so noise(u) with u in [0,1) tiles.
struct Lattice {
    int cells = 0;
    std::vector<float> values;

    Lattice(int n, std::uint32_t seed, std::uint32_t octave) : cells(n), values(static_cast<size_t>(n * n)) {
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const std::uint32_t h = hash32(seed ^ hash32(static_cast<std::uint32_t>(x) ^
                                                             hash32(static_cast<std::uint32_t>(y) ^ hash32(octave))));
                values[static_cast<size_t>(y * n + x)] = static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
            }
    }

    // The sample at pixel (x, y) of the image, through the lattice's per-pixel table (see Axis):
    // bilinear with a quintic fade (C2, so no creases between cells).
    float sample(const Axis& ax, int x, int y) const {
        const Axis::Cell& cx = ax.cells[static_cast<size_t>(x)];
        const Axis::Cell& cy = ax.cells[static_cast<size_t>(y)];
        const float* r0 = &values[static_cast<size_t>(cy.i0 * cells)];
        const float* r1 = &values[static_cast<size_t>(cy.i1 * cells)];
        const float a = r0[cx.i0] + (r0[cx.i1] - r0[cx.i0]) * cx.t;
        const float b = r1[cx.i0] + (r1[cx.i1] - r1[cx.i0]) * cx.t;
        return a + (b - a) * cy.t;
    }
};

std::uint8_t to_byte(float c) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

Image make_marble(int size, std::uint32_t seed) {
    Image img;
    if (size <= 0) return img;  // nothing to make; an empty image rather than a crash
    img.width = img.height = size;
    img.rgba.resize(static_cast<size_t>(size) * static_cast<size_t>(size) * 4u);

    // Two independent turbulence fields (one per vein set) from different seed streams; both
    // fields' octave o has the same cells, so one Axis each.
    std::vector<Lattice> lat_a, lat_b;
    std::vector<Axis> axes;
    for (int o = 0; o < kOctaves; ++o) {
        lat_a.emplace_back(kBaseCells << o, seed, static_cast<std::uint32_t>(o));
        lat_b.emplace_back(kBaseCells << o, hash32(seed + 0x9e3779b9U), static_cast<std::uint32_t>(o));
        axes.emplace_back(kBaseCells << o, size);
    }
    // Turbulence: sum of |2n - 1| over octaves with halving amplitude, normalised to [0,1].
    const auto turbulence = [&axes](const std::vector<Lattice>& lat, int x, int y) {
        float sum = 0.0f, amp = 1.0f, norm = 0.0f;
        for (size_t o = 0; o < lat.size(); ++o) {
            sum += amp * std::fabs(2.0f * lat[o].sample(axes[o], x, y) - 1.0f);
            norm += amp;
            amp *= 0.5f;
        }
        return sum / norm;
    };

    const glm::vec3 white(kWhite[0], kWhite[1], kWhite[2]);
    const glm::vec3 vein(0.42f, 0.47f, 0.56f);  // grey-blue
    for (int y = 0; y < size; ++y) {
        const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(size);
        for (int x = 0; x < size; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
            // Whole periods across the image in u and v keep the sines tileable.
            const float ta = turbulence(lat_a, x, y);
            const float tb = turbulence(lat_b, x, y);
            const float sa = std::sin(kTwoPi * (2.0f * u + 1.0f * v) + 5.0f * ta);
            const float sb = std::sin(kTwoPi * (1.0f * u - 3.0f * v) + 4.0f * tb);
            // Veins are where the sine crosses zero; a high power of (1 - |s|) keeps them thin.
            // (Powers by repeated squaring: std::pow per pixel was a third of the run time.)
            const float a1 = 1.0f - std::fabs(sa), a2 = a1 * a1, main_vein = a2 * a2 * a2;            // ^6
            const float b1 = 1.0f - std::fabs(sb), b3 = b1 * b1 * b1, b6 = b3 * b3;
            const float fine_vein = 0.45f * b6 * b6;                                                 // ^12
            const float k = std::min(1.0f, main_vein + fine_vein);
            // A faint cloudiness from the low octaves so the white is not flat.
            const float cloud = 0.94f + 0.08f * lat_b[0].sample(axes[0], x, y);
            const glm::vec3 c = glm::mix(white * cloud, vein, k);
            std::uint8_t* px = &img.rgba[(static_cast<size_t>(y) * static_cast<size_t>(size) + static_cast<size_t>(x)) * 4u];
            px[0] = to_byte(c.r);
            px[1] = to_byte(c.g);
            px[2] = to_byte(c.b);
            px[3] = 255;
        }
    }
    return img;
}

Image marble_placeholder() {
    Image img;
    img.width = img.height = 1;
    img.rgba = {to_byte(kWhite[0] * kMeanCloud), to_byte(kWhite[1] * kMeanCloud), to_byte(kWhite[2] * kMeanCloud), 255};
    return img;
}

Image make_tile_normal_map(int size) {
    Image img;
    img.width = img.height = size;
    img.rgba.resize(static_cast<size_t>(size) * static_cast<size_t>(size) * 4u);
    // Height |sin(8 pi u)| * |sin(8 pi v)| (u, v in 0..1): domes meeting in creases along the grid
    // lines. Its slope along each axis (per unit of the sine's argument, times kSlope) tilts the
    // normal: up to about 50 degrees at a crease.
    constexpr float kTiles = 8.0f, kSlope = 1.2f;
    const float w = kTiles * 0.5f * kTwoPi;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
            const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(size);
            const float su = std::sin(w * u), sv = std::sin(w * v);
            const float cu = std::cos(w * u), cv = std::cos(w * v);
            // d|sin t| / dt = sign(sin t) cos t
            const float du = (su < 0.0f ? -cu : cu) * std::fabs(sv), dv = (sv < 0.0f ? -cv : cv) * std::fabs(su);
            const glm::vec3 n = glm::normalize(glm::vec3(-kSlope * du, -kSlope * dv, 1.0f));
            std::uint8_t* px = &img.rgba[(static_cast<size_t>(y) * static_cast<size_t>(size) + static_cast<size_t>(x)) * 4u];
            px[0] = to_byte(n.x * 0.5f + 0.5f);
            px[1] = to_byte(n.y * 0.5f + 0.5f);
            px[2] = to_byte(n.z * 0.5f + 0.5f);
            px[3] = 255;
        }
    return img;
}

}  // namespace penumbra::scene
