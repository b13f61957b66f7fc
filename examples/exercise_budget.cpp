// The course exercises' time budget and error target (exercises.h: budget-ms, max-error): what
// each frame's settings are chosen by, measured on frames drawn again offscreen after the window's
// frame is timed. The host reaches all of it through course_trade()'s hooks, so that a browser
// page's module has it only where its exercise offers the controls (Exercise::trade).
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

void CourseApp::start_trade() {
    if (budget_ms_ > 0.0 && !budget_)
        budget_.emplace(budget_ms_, exercise_settings(), renderer_->caps().depth_texture, renderer_->caps().max_target_size());
}

render::Settings CourseApp::traded(render::Settings s) const {
    if (budget_ && render::budget_refusal(s).empty()) s = budget_->apply(s);
    if (error_choice_ && render::max_error_refusal(s).empty()) s = error_ladder_->at_rung(error_choice_->rung().rung, s);
    return s;
}

void CourseApp::after_trade(double ms, int width, int height) {
    if (budget_) {
        budget_->observe(ms);
        predict_budget_error(width, height);  // after the frame's time: it is not part of it
    }
    if (max_error_ > 0.0) choose_for_error(width, height);  // for the next frame, after this one's time
}

const CourseTrade& course_trade() {
    static const CourseTrade hooks{&CourseApp::start_trade, &CourseApp::traded, &CourseApp::after_trade};
    return hooks;
}

}  // namespace penumbra::examples
