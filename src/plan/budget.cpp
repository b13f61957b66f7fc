#include "plan/budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plan/techniques/technique.h"

namespace penumbra::render {

namespace {

double median_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string ms_str(double ms) {
    char b[32];
    std::snprintf(b, sizeof b, "%.2f ms", ms);
    return b;
}

}  // namespace

// The bench's median frame time with a hard-filtered map of each size over the unshadowed frame's
// (results/bench/results.csv of 23 Nov: 8 scene frames at 512x512, moving, llvmpipe on 2 cores).
// 128 was not measured: taken as 256's less the step from 512 to 256. Only the ratios between
// neighbours are used, and only until the frames have measured them.
double BudgetController::model_cost(int size, bool depth_texture) {
    struct Point {
        int size;
        double depthtex, rgba;
    };
    static constexpr Point kPoints[] = {{128, 2.07, 1.77}, {256, 2.18, 2.08}, {512, 2.29, 2.39},
                                        {1024, 2.87, 3.24}, {2048, 5.58, 6.62}, {4096, 9.85, 17.58}};
    for (const Point& p : kPoints)
        if (size <= p.size) return depth_texture ? p.depthtex : p.rgba;
    return depth_texture ? kPoints[5].depthtex : kPoints[5].rgba;
}

std::string budget_refusal(const Settings& s) {
    if (!technique_module(s.technique).depth_map())
        return "--budget-ms: chooses a shadow map's settings; --technique " + std::string(technique_module(s.technique).name()) +
               " has none (use --technique shadowmap)";
    return {};
}

BudgetController::BudgetController(double budget_ms, const Settings& base, bool depth_texture, int largest)
    : budget_(budget_ms), depth_texture_(depth_texture) {
    const int top = std::min(kLargestMap, largest);
    for (int s = kSmallestMap; s <= top; s *= 2) sizes_.push_back(s);
    if (sizes_.empty()) sizes_.push_back(kSmallestMap);
    const size_t n = sizes_.size();
    last_ms_.assign(n, -1.0);
    learned_up_.assign(n, -1.0);
    learned_base_.assign(n, -1.0);
    was_over_.assign(n, false);
    blocked_until_.assign(n, 0);
    block_.assign(n, kFirstBlock);
    // Start at 512 (or the largest below it): cheap enough that the first frames rarely overrun,
    // two steps from the usual answer.
    rung_ = 0;
    while (rung_ + 1 < static_cast<int>(n) && sizes_[static_cast<size_t>(rung_) + 1] <= 512) ++rung_;
    settings_ = apply(base);
}

Settings BudgetController::apply(Settings s) const {
    // A depth texture scores as RGBA packing does and costs less; the hard test is the most accurate
    // against a point light's truth (every PCF adds error there: docs/tradeoffs.md). A soft filter
    // is kept: the light has a size and the penumbra is the point.
    s.encoding = depth_texture_ ? shadow::Encoding::DepthTex : shadow::Encoding::RGBA;
    if (s.filter != shadow::Filter::PCSS) s.filter = shadow::Filter::Hard;
    s.map_size = sizes_[static_cast<size_t>(rung_)];
    return s;
}

double BudgetController::measured_ms() const {
    if (static_cast<int>(window_.size()) < kMinSamples) return -1.0;
    return median_of(window_);
}

double BudgetController::ratio(int from, int to) const {
    double r = 1.0;
    for (int k = std::min(from, to); k < std::max(from, to); ++k) {
        const size_t i = static_cast<size_t>(k);
        const double up = learned_up_[i] > 0.0 ? learned_up_[i]
                                               : model_cost(sizes_[i + 1], depth_texture_) / model_cost(sizes_[i], depth_texture_);
        r *= up;
    }
    return to >= from ? r : 1.0 / r;
}

double BudgetController::predicted_ms(int rung) const {
    const double now = measured_ms();
    if (now < 0.0) return -1.0;
    return now * ratio(rung_, rung);
}

void BudgetController::move_to(int rung, const std::string& reason) {
    char b[160];
    std::snprintf(b, sizeof b, "frame %ld: map %d -> %d (%s)", frame_, sizes_[static_cast<size_t>(rung_)],
                  sizes_[static_cast<size_t>(rung)], reason.c_str());
    log_.push_back(b);
    previous_ = rung_;
    previous_ms_ = measured_ms();
    last_ms_[static_cast<size_t>(rung_)] = previous_ms_;
    rung_ = rung;
    window_.clear();
    skip_ = 1;
    since_ = 0;
    settings_.map_size = sizes_[static_cast<size_t>(rung_)];
}

bool BudgetController::observe(double ms) {
    ++frame_;
    ++since_;
    if (skip_ > 0) {
        --skip_;
        return false;
    }
    window_.push_back(ms);
    if (static_cast<int>(window_.size()) > kWindow) window_.erase(window_.begin());
    const double now = measured_ms();
    if (now < 0.0) return false;
    const size_t i = static_cast<size_t>(rung_);
    last_ms_[i] = now;
    // Two neighbours run back to back: their measured ratio replaces the model's, once the window
    // is full (a median of kWindow frames: one slow frame does not make the ratio).
    if (previous_ms_ > 0.0 && static_cast<int>(window_.size()) == kWindow) {
        if (previous_ == rung_ - 1) learned_up_[i - 1] = now / previous_ms_, learned_base_[i - 1] = previous_ms_;
        if (previous_ == rung_ + 1) learned_up_[i] = previous_ms_ / now, learned_base_[i] = now;
        previous_ms_ = -1.0;
    }
    // A ratio learned when this rung took a time far from its time now was learned on another
    // scene (the teapot elsewhere, more on screen) or on a slow stretch of frames: forgotten, so
    // the next rung is tried again under the model's ratio.
    if (learned_up_[i] > 0.0 && std::fabs(now / learned_base_[i] - 1.0) > kRelearn) learned_up_[i] = -1.0;

    if (now > budget_ * kDownMargin && rung_ > 0) {
        // Over: block this rung (longer each time), then the largest below that is predicted to fit
        // with margin, at least one step.
        blocked_until_[i] = frame_ + block_[i];
        block_[i] *= 2;
        was_over_[i] = true;
        int to = rung_ - 1;
        while (to > 0 && predicted_ms(to) > budget_ * kUpMargin) --to;
        move_to(to, "measured " + ms_str(now) + ", over the budget");
        return true;
    }
    if (rung_ + 1 < rungs() && since_ >= kHoldFrames && frame_ >= blocked_until_[i + 1]) {
        const double next = predicted_ms(rung_ + 1);
        // A rung never run (and not yet measured against this one) may be tried on the model's word
        // with room for its pessimism; one that was over the budget before only on a prediction that
        // fits with margin.
        const bool probe = learned_up_[i] < 0.0 && !was_over_[i + 1];
        if (next <= budget_ * kUpMargin || (probe && next <= budget_ * kProbeMargin)) {
            move_to(rung_ + 1, "measured " + ms_str(now) + ", predicted " + ms_str(next));
            return true;
        }
    }
    return false;
}

std::string BudgetController::why() const {
    const int size = sizes_[static_cast<size_t>(rung_)];
    std::string s = "budget " + ms_str(budget_) + ": " + std::string(shadow::to_string(settings_.encoding)) + " " +
                    std::string(shadow::to_string(settings_.filter)) + ", map " + std::to_string(size);
    const double now = measured_ms();
    if (now < 0.0) return s + " (not measured yet: too few frames)";
    s += ", measured " + ms_str(now);
    if (rung_ + 1 >= rungs()) return s + "; the largest map (" + std::to_string(size) + ")";
    if (rung_ == 0 && now > budget_ * kDownMargin) return s + "; over the budget at the smallest map";
    const double next = predicted_ms(rung_ + 1);
    const bool blocked = frame_ < blocked_until_[static_cast<size_t>(rung_) + 1];
    return s + "; map " + std::to_string(sizes_[static_cast<size_t>(rung_) + 1]) + (blocked ? " measured " : " predicted ") +
           ms_str(blocked && last_ms_[static_cast<size_t>(rung_) + 1] > 0.0 ? last_ms_[static_cast<size_t>(rung_) + 1] : next);
}

}  // namespace penumbra::render
