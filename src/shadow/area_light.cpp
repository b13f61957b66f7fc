#include "shadow/area_light.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace penumbra::shadow {

namespace {

constexpr float kPi = 3.14159265358979f;

// Two unit vectors completing `n` to an orthonormal basis.
void basis(const glm::vec3& n, glm::vec3& a, glm::vec3& b) {
    const glm::vec3 helper = std::fabs(n.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    a = glm::normalize(glm::cross(helper, n));
    b = glm::cross(n, a);
}

// The spiral index of sample k of n: k's place in the bit-reversed order of [0, n), so that the
// first n / 4^j samples, and each later block of as many, are a residue class mod 4^j.
int area_sample_index(int k, int n) {
    int bits = 0;
    while ((1 << bits) < n) ++bits;
    // The (k + 1)-th of 0, 1, .. 2^bits - 1 whose bit reversal is below n: at most 2n steps.
    for (int j = 0, seen = 0; j < (1 << bits); ++j) {
        int r = 0;
        for (int b = 0; b < bits; ++b) r |= ((j >> b) & 1) << (bits - 1 - b);
        if (r < n && seen++ == k) return r;
    }
    return k;  // k outside [0, n): the caller's bug; the spiral's own index keeps it defined
}

// Point i of the n points (i / n, i g / n mod 1) taken as (squared radius, turns) on the unit disc.
glm::vec2 lattice_point(int i, int n, int g) {
    const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
    const float v = static_cast<float>((static_cast<long long>(i) * g) % n) / static_cast<float>(n);
    const float phi = 2.0f * kPi * v;
    return std::sqrt(u) * glm::vec2(std::cos(phi), std::sin(phi));
}

// The mean |share of the points on one side of a line - the disc's area there| over 256 fixed
// lines across the unit disc (directions by the golden ratio, offsets evenly spaced): the error
// of a Heckbert-Herf pixel inside a straight edge's penumbra.
double split_error(const glm::vec2* p, int count) {
    constexpr int kLines = 256;
    double sum = 0.0;
    for (int l = 0; l < kLines; ++l) {
        const double turn = 0.6180339887498949 * l - std::floor(0.6180339887498949 * l);
        // The angle in float and its sine and cosine in float, as the points are: the pages'
        // modules then hold no double-precision sine or cosine (docs/payload.md). Every
        // generator chosen for 2 to 1024 samples is the same as with the double's (tried).
        const float angle = static_cast<float>(2.0 * 3.14159265358979 * turn);
        const float c = std::cos(angle), s = std::sin(angle);
        const double d = -1.0 + 2.0 * (l + 0.5) / kLines;
        int above = 0;
        for (int k = 0; k < count; ++k) above += static_cast<double>(p[k].x * c + p[k].y * s) > d ? 1 : 0;
        const double area = (std::acos(d) - d * std::sqrt(1.0 - d * d)) / 3.14159265358979;
        sum += std::fabs(static_cast<double>(above) / count - area);
    }
    return sum / kLines;
}

// The generator g for n points: the one whose points split the fixed lines best, the whole set
// counted fully and its blocks of n / 4 and n / 16 consecutive samples (an interleaved pixel
// class's share, a progressive render's first frames) at 0.3. The blocks are the residue classes
// of i mod 4 and 16 (area_sample_index), lattices of their own with generator g mod (n / 4) and
// g mod (n / 16). A golden-angle spiral's whole set splits as well, but its every 16th point
// bunches within 120 degrees. Candidates: every g below 16 points, else those within n / 16 of
// the golden ratio's n / phi^2 and n / phi, where the best whole sets lie: at n = 1020 about 0.1 s
// once, then cached.
int lattice_generator(int n) {
    static std::mutex mutex;
    static std::unordered_map<int, int> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = cache.find(n); it != cache.end()) return it->second;
    std::vector<int> candidates;
    if (n < 16) {
        for (int g = 1; g < n; ++g) candidates.push_back(g);
    } else {
        for (double centre : {0.3819660112501051 * n, 0.6180339887498949 * n})
            for (int g = static_cast<int>(centre - n / 16.0); g <= static_cast<int>(centre + n / 16.0) + 1; ++g)
                if (g >= 1 && g < n && std::find(candidates.begin(), candidates.end(), g) == candidates.end())
                    candidates.push_back(g);
    }
    int best_g = 1;
    double best = 1e9;
    std::vector<int> order(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) order[static_cast<size_t>(k)] = area_sample_index(k, n);
    std::vector<glm::vec2> p(static_cast<size_t>(n));
    for (int g : candidates) {
        for (size_t k = 0; k < p.size(); ++k) p[k] = lattice_point(order[k], n, g);
        double blocks = 0.0;
        int kinds = 0;
        for (int classes : {4, 16}) {
            if (n % classes != 0 || n / classes < 4) continue;
            const int m = n / classes;
            double e = 0.0;
            for (int j = 0; j < classes; ++j) e += split_error(p.data() + j * m, m);
            blocks += e / classes;
            ++kinds;
        }
        const double score = split_error(p.data(), n) + (kinds > 0 ? 0.3 * blocks / kinds : 0.0);
        if (score < best) {
            best = score;
            best_g = g;
        }
    }
    cache.emplace(n, best_g);
    return best_g;
}

}  // namespace

glm::vec2 area_sample_point(int k, int n) {
    if (n <= 1) return glm::vec2(0.0f);
    return lattice_point(area_sample_index(k, n), n, lattice_generator(n));
}

scene::Light area_light_sample(const scene::Light& light, int k, int n, const glm::vec3& axis) {
    if (!(light.radius > 0.0f)) return light;
    scene::Light out = light;
    const glm::vec2 d = area_sample_point(k, n);
    glm::vec3 a, b;
    if (light.type == scene::LightType::Directional) {
        const glm::vec3 towards = -glm::normalize(light.direction);
        basis(towards, a, b);
        const glm::vec3 tilted = glm::normalize(towards + std::tan(light.radius) * (d.x * a + d.y * b));
        out.direction = -tilted;
    } else {
        const float len = glm::length(axis);
        basis(len > 0.0f ? axis / len : glm::vec3(0.0f, -1.0f, 0.0f), a, b);
        out.position = light.position + light.radius * (d.x * a + d.y * b);
    }
    return out;
}

}  // namespace penumbra::shadow
