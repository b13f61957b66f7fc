// --budget-ms N (issue 56): the most accurate shadow-map settings whose frames fit N ms on this
// device, chosen frame by frame from the frames' own measured times. No GL here: the caller renders
// with settings(), times the frame (wall time after glFinish, or a GPU timer) and hands the time to
// observe(); what the controller decides is a pure function of those times.
//
// The ladder: one rung per map size, 128 up to the context's largest (at most 4096), each with the
// encoding and filter that are most accurate for the light (a depth texture where the context has
// one, else RGBA packing, which score the same; the hard test for a point light, the user's soft
// filter for a light with a radius). Against the ray-traced truth a larger map is the larger
// share of the accuracy a budget can buy (docs/resolution.md), so the rungs are ordered by cost
// and by accuracy at once. Where the caller can draw them, shadow volumes (exact hard shadows)
// are the top rung, tried past a map that did not fit: their cost follows their silhouettes and
// shadowed area, not a map's size.
//
// The model: each rung's cost relative to the next, from what the bench measured (llvmpipe, the
// course at 512x512, moving), replaced by the ratio the frames measure once both rungs have been
// run. Hysteresis: a rung is left downwards only when the median of its last kWindow frames exceeds
// the budget by kDownMargin (or, sooner, when each of its first frames is far over it); the next
// one up is taken only after kHoldFrames at the current one, when predicted within kUpMargin of
// the budget (or kProbeMargin, for a rung over the budget fewer than kMaxOvers times), and not
// while it is blocked. A rung left for being over the budget is blocked for a time that doubles
// each time and, after kMaxOvers, tried only on a prediction that fits, so the choice cannot
// flicker between two rungs.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "plan/settings.h"

namespace penumbra::render {

class BudgetController {
public:
    static constexpr int kSmallestMap = 128;
    static constexpr int kLargestMap = 4096;
    static constexpr int kHoldFrames = 10;       // at a rung before trying the next one up
    static constexpr int kWindow = 9;            // the frames whose median is the rung's time, and a down-move's
    static constexpr int kMinSamples = 3;        // before a rung's time is trusted for a prediction
    static constexpr int kFarSamples = 4;        // a down-move before the window is full: this many frames...
    static constexpr double kFarOver = 1.5;      // ...every one over 1.5 x the budget
    static constexpr double kUpMargin = 0.9;     // up when predicted at most 0.9 x the budget
    static constexpr double kProbeMargin = 1.5;  // or, over fewer than kMaxOvers times, up to 1.5 x (the model may be pessimistic)
    static constexpr int kRecentFrames = 30;     // an up-move this recent is undone to where it came from
    static constexpr int kMaxOvers = 2;          // overs after which a rung is tried only on a fitting prediction
    static constexpr double kDownMargin = 1.05;  // down when measured over 1.05 x the budget
    static constexpr int kFirstBlock = 30;       // frames a rung left for its time stays blocked, doubling
    static constexpr int kStartSkip = 12;        // frames not measured at the start
    static constexpr double kRelearn = 0.2;      // a rung's time this far from when a ratio was learned: relearn it

    static constexpr int kVolumes = 0;           // the shadow volumes' rung (map_size())

    // `base`: the user's settings (a shadow-map technique); `depth_texture`: the context has one;
    // `largest`: the largest map side the context renders (clamped to kLargestMap); `volumes`:
    // shadow volumes can draw this scene here (linked, and Renderer::check has no objection), so
    // they are the top rung (not with a soft filter).
    BudgetController(double budget_ms, const Settings& base, bool depth_texture, int largest, bool volumes = false);

    // The settings of the next frame: the base's with the choice applied.
    const Settings& settings() const { return settings_; }
    // `s` with the current choice (encoding, filter, map size) put in: for a caller whose other
    // settings change from frame to frame (the pages' and the desktop's controls).
    Settings apply(Settings s) const { return at_rung(rung_, std::move(s)); }
    // `s` with rung `rung`'s choice put in (the bench times every rung as a fixed setting).
    Settings at_rung(int rung, Settings s) const;
    // The frame rendered with settings() took `ms`; true when the next frame's settings differ.
    bool observe(double ms);

    double budget_ms() const { return budget_; }
    int rung() const { return rung_; }
    int rungs() const { return static_cast<int>(sizes_.size()); }
    int map_size(int rung) const { return sizes_[static_cast<size_t>(rung)]; }  // kVolumes: shadow volumes
    // The time of the current rung (median of its recent frames; < 0: not yet measured).
    double measured_ms() const;
    // The predicted time of `rung`, from the current rung's time and the ratios between (< 0: the
    // current rung is not measured yet).
    double predicted_ms(int rung) const;
    // One line: the budget, the settings chosen, their time, and why not the next one up.
    std::string why() const;
    // The changes so far ("frame 15: map 512 -> map 1024 (measured 7.90 ms, predicted 9.90 ms)"), for -v.
    const std::vector<std::string>& log() const { return log_; }

    // The model: the cost of a frame with a map of side `size` over the unshadowed frame, as the
    // bench measured it (llvmpipe, 2 cores).
    static double model_cost(int size, bool depth_texture);

private:
    void move_to(int rung, const std::string& reason);
    int next_up() const;  // the rung an up-move would try (rung_ at the top)
    void learn_volumes(double now);
    double ratio(int from, int to) const;  // predicted time(to) / time(from), adjacent or not

    double budget_ = 0.0;
    Settings settings_;
    bool depth_texture_ = false;
    Technique technique_{};            // the base's (a map's) for the map rungs
    std::vector<int> sizes_;
    std::vector<double> last_ms_;      // each rung's last measured time (< 0: never run)
    std::vector<double> learned_up_;   // time(k + 1) / time(k) as measured back to back (< 0: not yet)
    std::vector<double> learned_base_; // time(k) when learned_up_[k] was
    std::vector<long> blocked_until_;  // frame number before which the rung is not taken going up
    std::vector<int> block_;           // the next block's length
    std::vector<int> over_count_;      // times the rung was left for being over the budget
    double volumes_scale_ = -1.0;      // the volumes' measured ratio over the model's (< 0: not measured)
    std::vector<double> window_;       // the current rung's recent times
    int rung_ = 0;
    int previous_ = -1;                // the rung run just before this one
    double previous_ms_ = -1.0;        // its time when it was left, until the ratio is learned (then < 0)
    // Frames still to ignore at this rung: after a change the first allocates the map; at the start
    // the first compiles the programs and the next several still run slow (llvmpipe: 10 of 12
    // frames from the start took 7.4-11 ms where later ones take 6.6).
    int skip_ = kStartSkip;
    long frame_ = 0;
    long since_ = 0;                   // frames at this rung
    std::vector<std::string> log_;
};

// "--budget-ms: ..." when the settings cannot be budgeted (no shadow map), else "".
std::string budget_refusal(const Settings& s);

}  // namespace penumbra::render
