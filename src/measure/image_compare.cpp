#include "measure/image_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace penumbra::measure {

namespace {

enum : std::uint8_t { kSame = 0, kExplained = 128, kUnexplained = 255 };

// The largest per-channel difference between pixel p of a and pixel q of b.
int pixel_diff(const Pixels& a, size_t p, const Pixels& b, size_t q) {
    const size_t c = static_cast<size_t>(a.channels);
    int m = 0;
    for (size_t k = 0; k < c; ++k) m = std::max(m, std::abs(int(a.data[p * c + k]) - int(b.data[q * c + k])));
    return m;
}

// Each pixel classified: same within step, off but found within one pixel in the golden, or not.
std::vector<std::uint8_t> classify(const Pixels& actual, const Pixels& golden, int step, int reach) {
    if (actual.width != golden.width || actual.height != golden.height || actual.channels != golden.channels ||
        actual.data.size() != golden.data.size())
        throw std::invalid_argument("compare_images: the images differ in size or channels");
    const int w = actual.width, h = actual.height;
    std::vector<std::uint8_t> cls(static_cast<size_t>(w) * static_cast<size_t>(h), kSame);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t p = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
            if (pixel_diff(actual, p, golden, p) <= step) continue;
            bool found = false;
            for (int dy = -reach; dy <= reach && !found; ++dy)
                for (int dx = -reach; dx <= reach && !found; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const size_t q = static_cast<size_t>(qy) * static_cast<size_t>(w) + static_cast<size_t>(qx);
                    found = pixel_diff(actual, p, golden, q) <= step;
                }
            cls[p] = found ? kExplained : kUnexplained;
        }
    return cls;
}

// The largest 8-connected group of unexplained pixels (a flood fill with an explicit stack).
int largest_cluster(std::vector<std::uint8_t> cls, int w, int h) {
    int best = 0;
    std::vector<size_t> stack;
    for (size_t start = 0; start < cls.size(); ++start) {
        if (cls[start] != kUnexplained) continue;
        int size = 0;
        cls[start] = kSame;
        stack.push_back(start);
        while (!stack.empty()) {
            const size_t p = stack.back();
            stack.pop_back();
            ++size;
            const int x = static_cast<int>(p % static_cast<size_t>(w)), y = static_cast<int>(p / static_cast<size_t>(w));
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const size_t q = static_cast<size_t>(qy) * static_cast<size_t>(w) + static_cast<size_t>(qx);
                    if (cls[q] != kUnexplained) continue;
                    cls[q] = kSame;
                    stack.push_back(q);
                }
        }
        best = std::max(best, size);
    }
    return best;
}

}  // namespace

std::string ImageComparison::summary() const {
    char line[320];
    const double n = std::max(1, pixels);
    std::snprintf(line, sizeof line,
                  "max %d, mean %.4f; %d of %d pixels off by more than the step (%.3f %%), %d of them no 1-pixel "
                  "shift explains (%.4f %%), largest group of those %d",
                  max, mean, off, pixels, 100.0 * off / n, unexplained, 100.0 * unexplained / n, largest_cluster);
    return line;
}

ImageComparison compare_images(const Pixels& actual, const Pixels& golden, const CompareRules& rules) {
    const auto cls = classify(actual, golden, rules.step, rules.reach);
    ImageComparison r;
    double sum = 0.0;
    for (size_t i = 0; i < actual.data.size(); ++i) {
        const int v = std::abs(int(actual.data[i]) - int(golden.data[i]));
        r.max = std::max(r.max, v);
        sum += v;
    }
    r.mean = actual.data.empty() ? 0.0 : sum / static_cast<double>(actual.data.size());
    r.pixels = static_cast<int>(cls.size());
    for (std::uint8_t c : cls) {
        r.off += c != kSame;
        r.unexplained += c == kUnexplained;
    }
    r.largest_cluster = largest_cluster(cls, actual.width, actual.height);
    const double n = std::max(1, r.pixels);
    r.passed = r.off <= rules.max_off_share * n && r.unexplained <= rules.max_unexplained_share * n &&
               r.largest_cluster <= rules.max_cluster;
    return r;
}

Pixels comparison_map(const Pixels& actual, const Pixels& golden, const CompareRules& rules) {
    Pixels m;
    m.width = actual.width;
    m.height = actual.height;
    m.channels = 1;
    m.data = classify(actual, golden, rules.step, rules.reach);
    return m;
}

}  // namespace penumbra::measure
