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
        case Filter::Hard:
        case Filter::PCSS: return {glm::vec2(0.0f)};  // PCSS's taps: vogel_disc, scaled per fragment
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

namespace {
// The largest tap offset on either axis, in texels.
float largest_offset(Filter filter) {
    float reach = 0.0f;
    for (const glm::vec2& o : pcf_offsets(filter)) reach = std::max({reach, std::fabs(o.x), std::fabs(o.y)});
    return reach;
}
}  // namespace

float kernel_reach_texels(Filter filter) { return largest_offset(filter) + 1.0f; }

bool pcf_early_exit_applies(Filter filter) { return pcf_offsets(filter).size() > 4; }

std::vector<glm::vec2> vogel_disc(int n, float rotation) {
    std::vector<glm::vec2> out;
    for (int i = 0; i < n; ++i) {
        const float r = std::sqrt((static_cast<float>(i) + 0.5f) / static_cast<float>(n));
        const float a = static_cast<float>(i) * kGoldenAngle + rotation;
        out.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    return out;
}

PcssRadii pcss_radii(float light_size, bool perspective, float receiver_depth, float blocker_depth, float near) {
    // The cone from the receiver to the light's disc, where it crosses depth d: its radius in
    // world units is size (zr - d) / zr; seen from the light's centre (a perspective map) that is
    // size (zr - d) / (zr d) in tangent units. An orthographic (sun) map: tan(angular radius) (zr - d).
    const auto cone = [&](float d) {
        const float zr = receiver_depth;
        if (!(zr > d)) return 0.0f;
        return perspective ? light_size * (zr - d) / (zr * d) : light_size * (zr - d);
    };
    return {cone(near), cone(blocker_depth)};
}

PcssConeDepth pcss_cone_depth(float light_size, bool perspective, float receiver_depth, float near, float far) {
    // Perspective: the cone's radius S (zr - e) / (zr e) reaches rho while e <= S zr / (S + rho zr),
    // whose window depth f / (f - n) (1 - n / e) is f / (f - n) (1 - n / zr) - f n rho / ((f - n) S).
    // Orthographic: S (zr - e) >= rho while e <= zr - rho / S; window depth (e - n) / (f - n).
    const float n = near, f = far, zr = receiver_depth, size = std::max(light_size, 1e-6f);
    if (perspective) return {f / (f - n) * (1.0f - n / zr), f * n / ((f - n) * size)};
    return {(zr - n) / (f - n), 1.0f / ((f - n) * size)};
}

float pcss_blocker_depth(const std::vector<PcssBlocker>& blockers, const PcssConeDepth& cone, bool layered) {
    if (blockers.empty()) return -1.0f;
    float all = 0.0f, inside = 0.0f, nearest = blockers.front().depth;
    int n_inside = 0;
    for (const PcssBlocker& b : blockers) {
        all += b.depth;
        nearest = std::min(nearest, b.depth);
        if (b.depth <= cone.deepest(b.rho)) {
            inside += b.depth;
            ++n_inside;
        }
    }
    if (!layered) return all / static_cast<float>(blockers.size());
    return n_inside > 0 ? inside / static_cast<float>(n_inside) : nearest;
}

bool pcf_is_corner(Filter filter, glm::vec2 offset) {
    const float reach = largest_offset(filter);
    return std::fabs(offset.x) == reach && std::fabs(offset.y) == reach;
}

float pcf_visibility(Filter filter, PcfKernel kernel, glm::vec2 uv, float z, float bias, glm::vec2 texel,
                     const std::function<float(glm::vec2)>& stored_depth) {
    const auto taps = pcf_offsets(filter);
    const auto lit = [&](glm::vec2 o) { return z > stored_depth(uv + o * texel) + bias ? 0.0f : 1.0f; };
    // The shader's order: the corners, then (unless they agree) the rest. Sums of 0s and 1s are
    // exact in float, so the order does not change the full kernel's value.
    float corners = 0.0f, rest = 0.0f;
    for (const glm::vec2& o : taps)
        if (pcf_is_corner(filter, o)) corners += lit(o);
    if (kernel == PcfKernel::EarlyExit && pcf_early_exit_applies(filter) && (corners == 0.0f || corners == 4.0f))
        return corners / 4.0f;
    for (const glm::vec2& o : taps)
        if (!pcf_is_corner(filter, o)) rest += lit(o);
    return (corners + rest) / static_cast<float>(taps.size());
}

}  // namespace penumbra::shadow
