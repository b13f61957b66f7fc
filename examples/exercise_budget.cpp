// The course exercises' time budget's predicted error and their error target (exercises.h:
// budget-ms, max-error): what each frame's settings are chosen by, measured on frames drawn again
// offscreen after the window's frame is timed.
#include <chrono>
#include <optional>
#include <utility>

#include "exercises.h"
#include "render/error_target.h"
#include "render/frame_edges.h"

namespace penumbra::examples {

CourseApp::EdgesFrame CourseApp::edges_frame(int width, int height) const {
    EdgesFrame f;
    f.light = clock_.light;
    f.jump = clock_.jump;
    f.width = width;
    f.height = height;
    f.camera = camera();
    return f;
}

void CourseApp::predict_budget_error(int width, int height) {
    const EdgesFrame frame = edges_frame(width, height);
    if (budget_->rung() == budget_error_rung_ && (++budget_error_age_ < kErrorEvery || frame == budget_error_frame_)) return;
    budget_error_rung_ = budget_->rung();
    budget_error_frame_ = frame;
    budget_error_age_ = 0;
    const render::Settings s = frame_settings();
    budget_error_ = -1.0;
    if (s.filter == shadow::Filter::PCSS) return;  // the model is a hard shadow's
    // The window's frame is drawn; the same frame again offscreen, its shadow edges and the pixels
    // the scene covers read back.
    // Not GPU-timed: the per-pass times are the window's frames'.
    renderer_->gpu_timer().enable(false);
    const render::FrameEdges f = render::measure_frame_edges(*renderer_, scene(), s, s, render::offscreen(width, height));
    renderer_->gpu_timer().enable(gpu_timing_);
    budget_error_ = render::predicted_error_pct(f, budget_->map_size(budget_->rung()));
}

void CourseApp::reset_error_target() {
    error_ladder_.reset();
    error_choice_.reset();
    error_refusal_.clear();
    error_age_ = 0;
    error_choices_ = 0;
}

void CourseApp::choose_for_error(int width, int height) {
    // Two frames drawn offscreen for a still frame would choose what they chose before.
    const EdgesFrame frame = edges_frame(width, height);
    if ((error_choice_ || !error_refusal_.empty()) && (++error_age_ < kErrorEvery || frame == error_frame_)) return;
    error_age_ = 0;
    error_frame_ = frame;
    ++error_choices_;
    const render::Settings base = exercise_settings();
    // Map sizes only, as the exercises' budget: a page teaches its own technique.
    if (!error_ladder_)
        error_ladder_.emplace(1.0, base, renderer_->caps().depth_texture, renderer_->caps().max_target_size());
    // The rung in use, to keep while it is still predicted within the target (hysteresis).
    const int in_use = error_choice_ ? error_choice_->rung().rung : -1;
    renderer_->gpu_timer().enable(false);  // the per-pass times are the window's frames'
    const auto start = std::chrono::steady_clock::now();
    std::optional<render::ErrorChoice> c =
        render::choose_for_error(max_error_, base, *error_ladder_, *renderer_, scene(), render::offscreen(width, height), error_refusal_,
                                 /*matched_edges=*/true);
    renderer_->finish();
    error_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    renderer_->gpu_timer().enable(gpu_timing_);
    if (c && in_use >= 0) render::keep_rung(*c, in_use, max_error_, kErrorKeep);
    error_choice_ = std::move(c);
}

}  // namespace penumbra::examples
