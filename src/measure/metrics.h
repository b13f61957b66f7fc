// Comparing a rendered visibility image with the ground truth, over the pixels the truth marks
// valid. Plain arrays in, numbers out: no GL, no Embree, so any renderer's image (ours, three.js's
// read back from a canvas) is scored by the same code.
//
//  - A rendered pixel is "dark" when its visibility is below one half: byte < 128 of the 8-bit
//    visibility AOV (255 lit, 0 shadowed; a PCF result of exactly half rounds to 128 and is lit).
//  - false shadow: dark where the truth is lit (shadow acne, over-darkening, blur spilling out of
//    the shadow);
//  - false lit: not dark where the truth is shadowed (peter-panning, light leaks, missed thin
//    casters);
//  - error = false shadow + false lit, each a percentage of the valid pixels;
//  - mean absolute error: mean over valid pixels of |v_rendered - v_truth| with v in [0, 1], as a
//    percentage. For a hard (0/1) result it equals the error above; for a filtered one it also
//    counts the partial greys. Against the hard-shadow truth it measures how far the filter
//    strays from the exact answer for this point light; against an area-light truth (optional)
//    it measures how well the filter's blur imitates a real penumbra of a stated light size.
//  - mean absolute error inside the penumbra (with an area-light truth): the same mean over only
//    the valid pixels whose area-light visibility is strictly between 0 and 1 (partly lit), so a
//    large lit or shadowed area around a small penumbra does not dilute it; and their count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::measure {

struct Score {
    std::size_t valid = 0;         // pixels compared
    std::size_t false_shadow = 0;  // counts
    std::size_t false_lit = 0;
    std::size_t truth_shadowed = 0;
    double false_shadow_pct = 0.0;
    double false_lit_pct = 0.0;
    double error_pct = 0.0;     // false_shadow_pct + false_lit_pct
    double mae_pct = 0.0;       // mean |rendered - hard truth|, percent
    double mae_soft_pct = -1.0; // mean |rendered - area-light truth|, percent; -1 without one
    // Over the valid pixels with 0 < area-light truth < 1 only (the penumbra): their count and the
    // mean |rendered - area-light truth| there, percent (0 when there are none); -1 without one.
    std::size_t penumbra = 0;
    double mae_penumbra_pct = -1.0;
};

inline constexpr std::uint8_t kDarkBelow = 128;

// rendered: one byte per pixel (the visibility AOV's red channel). truth_lit: 1 lit, 0 shadowed.
// valid: non-zero where the pixel counts. soft (may be null or empty): area-light visibility in
// [0, 1]. All arrays have the same length; throws std::invalid_argument otherwise.
Score score(const std::vector<std::uint8_t>& rendered, const std::vector<std::uint8_t>& truth_lit,
            const std::vector<std::uint8_t>& valid, const std::vector<float>* soft = nullptr);

// The score of each distance band: the valid pixels whose depth (any per-pixel distance, e.g. the
// camera's view depth of the surface hit) lies in [edges[i], edges[i + 1]). edges ascending, at
// least two; `depth` as long as the images. A band with no valid pixel scores zero (valid 0).
struct BandScore {
    double from = 0.0, to = 0.0;
    Score score;
};
std::vector<BandScore> score_by_band(const std::vector<std::uint8_t>& rendered, const std::vector<std::uint8_t>& truth_lit,
                                     const std::vector<std::uint8_t>& valid, const std::vector<float>& depth,
                                     const std::vector<double>& edges);

// Temporal stability: the share (percent) of the pixels valid in both frames whose lit/shadowed
// state differs between frame a and frame b. lit_a, lit_b: non-zero where lit (a rendered
// visibility byte counts as lit from kDarkBelow up: see lit_flags).
double flip_pct(const std::vector<std::uint8_t>& lit_a, const std::vector<std::uint8_t>& lit_b,
                const std::vector<std::uint8_t>& valid_a, const std::vector<std::uint8_t>& valid_b);
// 1 where a rendered visibility byte is lit (>= kDarkBelow), else 0.
std::vector<std::uint8_t> lit_flags(const std::vector<std::uint8_t>& rendered);

// Per-pixel classification for an error image: 0 agree, 1 false shadow, 2 false lit, 3 not valid.
std::vector<std::uint8_t> classify(const std::vector<std::uint8_t>& rendered, const std::vector<std::uint8_t>& truth_lit,
                                   const std::vector<std::uint8_t>& valid);

// The Pareto front of points (cost, error), both to be minimised: the indices of the points no
// other point beats in one and matches or beats in the other, sorted by cost. A point joins the
// front only when its error is more than `min_gain` below every cheaper point's (e.g. 0.01 when
// errors are shown to two decimals, so two techniques that score alike do not both appear).
struct Point2 {
    double cost = 0.0;
    double error = 0.0;
};
std::vector<std::size_t> pareto_front(const std::vector<Point2>& points, double min_gain = 0.0);

// The median of a sample (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

}  // namespace penumbra::measure
