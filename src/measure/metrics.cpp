#include "measure/metrics.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace penumbra::measure {

Score score(const std::vector<std::uint8_t>& rendered, const std::vector<std::uint8_t>& truth_lit,
            const std::vector<std::uint8_t>& valid, const std::vector<float>* soft) {
    const size_t n = rendered.size();
    if (truth_lit.size() != n || valid.size() != n)
        throw std::invalid_argument("metrics: the rendered image, the truth and the mask differ in size");
    const bool with_soft = soft && !soft->empty();
    if (with_soft && soft->size() != n) throw std::invalid_argument("metrics: the area-light truth differs in size");
    Score s;
    double abs_sum = 0.0, soft_sum = 0.0, penumbra_sum = 0.0;
    for (size_t i = 0; i < n; ++i) {
        if (!valid[i]) continue;
        ++s.valid;
        const bool dark = rendered[i] < kDarkBelow;
        const bool lit = truth_lit[i] != 0;
        if (!lit) ++s.truth_shadowed;
        if (dark && lit) ++s.false_shadow;
        if (!dark && !lit) ++s.false_lit;
        const double v = rendered[i] / 255.0;
        abs_sum += std::fabs(v - (lit ? 1.0 : 0.0));
        if (with_soft) {
            const float t = (*soft)[i];
            const double d = std::fabs(v - static_cast<double>(t));
            soft_sum += d;
            if (t > 0.0f && t < 1.0f) {
                ++s.penumbra;
                penumbra_sum += d;
            }
        }
    }
    if (s.valid > 0) {
        const double total = static_cast<double>(s.valid);
        s.false_shadow_pct = 100.0 * static_cast<double>(s.false_shadow) / total;
        s.false_lit_pct = 100.0 * static_cast<double>(s.false_lit) / total;
        s.error_pct = s.false_shadow_pct + s.false_lit_pct;
        s.mae_pct = 100.0 * abs_sum / total;
        if (with_soft) s.mae_soft_pct = 100.0 * soft_sum / total;
    } else if (with_soft) {
        s.mae_soft_pct = 0.0;
    }
    if (with_soft)
        s.mae_penumbra_pct = s.penumbra > 0 ? 100.0 * penumbra_sum / static_cast<double>(s.penumbra) : 0.0;
    return s;
}

std::vector<BandScore> score_by_band(const std::vector<std::uint8_t>& rendered, const std::vector<std::uint8_t>& truth_lit,
                                     const std::vector<std::uint8_t>& valid, const std::vector<float>& depth,
                                     const std::vector<double>& edges) {
    if (depth.size() != rendered.size()) throw std::invalid_argument("metrics: the depths differ in size from the image");
    if (edges.size() < 2 || !std::is_sorted(edges.begin(), edges.end()))
        throw std::invalid_argument("metrics: band edges must be at least two, ascending");
    std::vector<BandScore> out;
    for (size_t b = 0; b + 1 < edges.size(); ++b) {
        std::vector<std::uint8_t> in(valid.size(), 0);
        for (size_t i = 0; i < valid.size() && i < depth.size(); ++i) {
            const double d = static_cast<double>(depth[i]);
            in[i] = valid[i] && d >= edges[b] && d < edges[b + 1] ? 1 : 0;
        }
        out.push_back({edges[b], edges[b + 1], score(rendered, truth_lit, in)});
    }
    return out;
}

double flip_pct(const std::vector<std::uint8_t>& lit_a, const std::vector<std::uint8_t>& lit_b,
                const std::vector<std::uint8_t>& valid_a, const std::vector<std::uint8_t>& valid_b) {
    const size_t n = lit_a.size();
    if (lit_b.size() != n || valid_a.size() != n || valid_b.size() != n)
        throw std::invalid_argument("metrics: the two frames differ in size");
    size_t both = 0, flips = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!valid_a[i] || !valid_b[i]) continue;
        ++both;
        flips += (lit_a[i] != 0) != (lit_b[i] != 0);
    }
    return both ? 100.0 * static_cast<double>(flips) / static_cast<double>(both) : 0.0;
}

std::vector<std::uint8_t> lit_flags(const std::vector<std::uint8_t>& rendered) {
    std::vector<std::uint8_t> out(rendered.size());
    for (size_t i = 0; i < rendered.size(); ++i) out[i] = rendered[i] >= kDarkBelow ? 1 : 0;
    return out;
}

std::vector<std::uint8_t> classify(const std::vector<std::uint8_t>& rendered, const std::vector<std::uint8_t>& truth_lit,
                                   const std::vector<std::uint8_t>& valid) {
    const size_t n = rendered.size();
    if (truth_lit.size() != n || valid.size() != n)
        throw std::invalid_argument("metrics: the rendered image, the truth and the mask differ in size");
    std::vector<std::uint8_t> out(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (!valid[i]) {
            out[i] = 3;
            continue;
        }
        const bool dark = rendered[i] < kDarkBelow;
        const bool lit = truth_lit[i] != 0;
        out[i] = dark && lit ? 1 : (!dark && !lit ? 2 : 0);
    }
    return out;
}

std::vector<std::size_t> pareto_front(const std::vector<Point2>& points, double min_gain) {
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), size_t{0});
    // By cost, then error: a point is on the front when its error is below every cheaper point's.
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
        if (points[a].error != points[b].error) return points[a].error < points[b].error;
        return a < b;
    });
    std::vector<std::size_t> front;
    double best = INFINITY;
    for (size_t i : order) {
        if (!std::isfinite(points[i].cost) || !std::isfinite(points[i].error)) continue;
        if (points[i].error < best - min_gain) {
            front.push_back(i);
            best = points[i].error;
        }
    }
    return front;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace penumbra::measure
