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

// A rung's name: "map 1024", "shadow volumes".
std::string rung_name(int size) { return size == 0 ? "shadow volumes" : "map " + std::to_string(size); }

}  // namespace

// The bench's frame time with a hard-filtered map of each size over the unshadowed frame's: the
// course at t = 0.6, 512x512, moving, median of 3 rounds of 20 frames, llvmpipe on 2 cores with
// nothing else running (29 Nov; docs/budget.md). 128 was not measured: 256's less half the step
// from 512. Shadow volumes (size 0), volumes auto on the same frames: 3.73x. Only the ratios
// between rungs are used, and only until the frames have measured them.
double BudgetController::model_cost(int size, bool depth_texture) {
    if (size == kVolumes) return 3.73;
    struct Point {
        int size;
        double depthtex, rgba;
    };
    static constexpr Point kPoints[] = {{128, 1.30, 1.57}, {256, 1.45, 1.69}, {512, 1.75, 1.93},
                                        {1024, 2.18, 2.48}, {2048, 3.23, 4.35}, {4096, 6.44, 9.24}};
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

BudgetController::BudgetController(double budget_ms, const Settings& base, bool depth_texture, int largest, bool volumes)
    : budget_(budget_ms), depth_texture_(depth_texture), technique_(base.technique) {
    const int top = std::min(kLargestMap, largest);
    for (int s = kSmallestMap; s <= top; s *= 2) sizes_.push_back(s);
    if (sizes_.empty()) sizes_.push_back(kSmallestMap);
    // Shadow volumes, where the caller can draw them: exact hard shadows, the most accurate rung
    // (the course at 512x512: 0.012 % against 0.019 % for a 4096 map), so the top one; a soft
    // filter's penumbra they do not have.
    if (volumes && base.filter != shadow::Filter::PCSS) sizes_.push_back(kVolumes);
    const size_t n = sizes_.size();
    last_ms_.assign(n, -1.0);
    learned_up_.assign(n, -1.0);
    learned_base_.assign(n, -1.0);
    over_count_.assign(n, 0);
    blocked_until_.assign(n, 0);
    block_.assign(n, kFirstBlock);
    // Start at 512 (or the largest below it): cheap enough that the first frames rarely overrun,
    // two steps from the usual answer.
    rung_ = 0;
    while (rung_ + 1 < static_cast<int>(n) && sizes_[static_cast<size_t>(rung_) + 1] <= 512) ++rung_;
    settings_ = apply(base);
}

Settings BudgetController::at_rung(int rung, Settings s) const {
    // A depth texture scores as RGBA packing does and costs less; the hard test is the most accurate
    // against a point light's truth (every PCF adds error there: docs/tradeoffs.md). A soft filter
    // is kept: the light has a size and the penumbra is the point.
    s.encoding = depth_texture_ ? shadow::Encoding::DepthTex : shadow::Encoding::RGBA;
    if (s.filter != shadow::Filter::PCSS) s.filter = shadow::Filter::Hard;
    const int size = sizes_[static_cast<size_t>(rung)];
    s.technique = size == kVolumes ? technique_named("volumes") : technique_;
    if (size != kVolumes) s.map_size = size;
    return s;
}

double BudgetController::measured_ms() const {
    if (static_cast<int>(window_.size()) < kMinSamples) return -1.0;
    return median_of(window_);
}

double BudgetController::ratio(int from, int to) const {
    // The volumes' cost is not a step along the maps': the model's ratio straight to them.
    const int a = sizes_[static_cast<size_t>(from)], b = sizes_[static_cast<size_t>(to)];
    if (a == kVolumes || b == kVolumes) {
        const double scale = volumes_scale_ > 0.0 ? volumes_scale_ : 1.0;  // measured over the model
        const double r = model_cost(b, depth_texture_) / model_cost(a, depth_texture_);
        return b == kVolumes ? r * scale : r / scale;
    }
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
    std::snprintf(b, sizeof b, "frame %ld: %s -> %s (%s)", frame_, rung_name(sizes_[static_cast<size_t>(rung_)]).c_str(),
                  rung_name(sizes_[static_cast<size_t>(rung)]).c_str(), reason.c_str());
    log_.push_back(b);
    previous_ = rung_;
    previous_ms_ = measured_ms();
    last_ms_[static_cast<size_t>(rung_)] = previous_ms_;
    rung_ = rung;
    window_.clear();
    skip_ = 1;
    since_ = 0;
    settings_ = apply(settings_);
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
    if (sizes_[i] == kVolumes && previous_ms_ > 0.0 && previous_ >= 0) learn_volumes(now);
    if (previous_ms_ > 0.0 && static_cast<int>(window_.size()) == kWindow) {
        if (previous_ == rung_ - 1) learned_up_[i - 1] = now / previous_ms_, learned_base_[i - 1] = previous_ms_;
        if (previous_ == rung_ + 1) learned_up_[i] = previous_ms_ / now, learned_base_[i] = now;
        previous_ms_ = -1.0;
    }
    // A ratio learned when this rung took a time far from its time now was learned on another
    // scene (the teapot elsewhere, more on screen) or on a slow stretch of frames: forgotten, so
    // the next rung is tried again under the model's ratio.
    if (learned_up_[i] > 0.0 && std::fabs(now / learned_base_[i] - 1.0) > kRelearn) learned_up_[i] = -1.0;

    // Over the budget: the median of a full window, or, before it is full, every frame so far far
    // over. A stall of the machine's own (a few frames in a row at up to 2x) is under half a
    // window, so it cannot make a rung that fits look over; a rung far over is still left after
    // kFarSamples frames (docs/budget.md).
    const bool full = static_cast<int>(window_.size()) == kWindow;
    const bool far_over = static_cast<int>(window_.size()) >= kFarSamples &&
                          *std::min_element(window_.begin(), window_.end()) > budget_ * kFarOver;
    if (((full && now > budget_ * kDownMargin) || far_over) && rung_ > 0) {
        // Over: block this rung (longer each time), then the largest below that is predicted to fit,
        // at least one step. Not with the up-move's margin: the rung just left is blocked, so the
        // one below cannot flicker with it, and the margin would skip a rung that fits.
        blocked_until_[i] = frame_ + block_[i];
        block_[i] *= 2;
        ++over_count_[i];
        // The step just taken, measured: its ratio replaces the model's (with fewer frames than
        // kWindow, but enough to be over), so the next prediction knows it.
        if (previous_ms_ > 0.0 && previous_ == rung_ - 1) learned_up_[i - 1] = now / previous_ms_, learned_base_[i - 1] = previous_ms_;
        int to = rung_ - 1;
        if (previous_ >= 0 && previous_ < rung_ && (sizes_[i] == kVolumes || since_ <= kRecentFrames)) {
            // Just tried from a rung that fitted when it was left: back there. (The volumes' time
            // says nothing of a map's, however long they ran.)
            to = previous_;
        } else {
            while (to > 0 && predicted_ms(to) > budget_) --to;
        }
        move_to(to, "measured " + ms_str(now) + ", over the budget");
        return true;
    }
    const int up = next_up();
    if (up > rung_ && since_ >= kHoldFrames && frame_ >= blocked_until_[static_cast<size_t>(up)]) {
        const double next = predicted_ms(up);
        // A rung may be tried on a prediction with room for the model's pessimism until it has been
        // over the budget kMaxOvers times (once may be the first frames' warming up, or a slow
        // stretch); after that only on a prediction that fits with margin.
        const bool probe = over_count_[static_cast<size_t>(up)] < kMaxOvers;
        if (next <= budget_ * kUpMargin || (probe && next <= budget_ * kProbeMargin)) {
            move_to(up, "measured " + ms_str(now) + ", predicted " + ms_str(next));
            return true;
        }
    }
    return false;
}

// The volumes' time over the map they were tried from, against the model's ratio: what the
// model misses about this scene's silhouettes and shadowed area, kept for the next prediction.
void BudgetController::learn_volumes(double now) {
    const int from = sizes_[static_cast<size_t>(previous_)];
    volumes_scale_ = (now / previous_ms_) / (model_cost(kVolumes, depth_texture_) / model_cost(from, depth_texture_));
}

int BudgetController::next_up() const {
    const int top = rungs() - 1;
    if (rung_ >= top) return rung_;
    // Shadow volumes cost what their silhouettes and shadowed area cost, not what a map does: where
    // the next map was over the budget, is blocked or is predicted not to fit, they may still fit
    // (the course at 512x512 on llvmpipe: 15.4 ms against 26.5 for a 4096 map), so they are tried
    // past it.
    const size_t next = static_cast<size_t>(rung_) + 1;
    if (sizes_[static_cast<size_t>(top)] != kVolumes || rung_ + 1 >= top) return rung_ + 1;
    const bool next_out = over_count_[next] >= kMaxOvers || frame_ < blocked_until_[next] ||
                          predicted_ms(rung_ + 1) > budget_ * kProbeMargin;
    return next_out ? top : rung_ + 1;
}

std::string BudgetController::why() const {
    const int size = sizes_[static_cast<size_t>(rung_)];
    std::string s = "budget " + ms_str(budget_) + ": ";
    if (size == kVolumes)
        s += "shadow volumes";
    else
        s += std::string(shadow::to_string(settings_.encoding)) + " " + std::string(shadow::to_string(settings_.filter)) + ", " +
             rung_name(size);
    const double now = measured_ms();
    if (now < 0.0) return s + " (not measured yet: too few frames)";
    s += ", measured " + ms_str(now);
    if (size == kVolumes) return s + "; the most accurate (exact hard shadows)";
    if (rung_ + 1 >= rungs()) return s + "; the largest map (" + std::to_string(size) + ")";
    if (rung_ == 0 && now > budget_ * kDownMargin) return s + "; over the budget at the smallest map";
    const int up = next_up();
    const size_t u = static_cast<size_t>(up);
    const bool blocked = frame_ < blocked_until_[u];
    return s + "; " + rung_name(sizes_[u]) + (blocked ? " measured " : " predicted ") +
           ms_str(blocked && last_ms_[u] > 0.0 ? last_ms_[u] : predicted_ms(up));
}

}  // namespace penumbra::render
