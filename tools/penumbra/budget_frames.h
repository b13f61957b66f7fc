// --budget-ms in the commands (render, plan, bench): frames rendered with the settings a
// render::BudgetController chooses, each timed by wall clock after glFinish (what `render --frames`
// reports) and handed back to it.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "plan/budget.h"
#include "plan/options.h"
#include "render/renderer.h"

namespace penumbra::tools {

// Frames a budget settles over when the command renders one frame (render, plan without --frames):
// at most two steps up at 10 frames each and a blocked probe, with room to spare.
inline constexpr int kBudgetSettleFrames = 60;

// The controller for `o`'s --budget-ms on this renderer's context; none when the option is 0.
// A technique without a map is bad input (the returned text, else "").
inline std::optional<render::BudgetController> make_budget(const render::Options& o, const render::Renderer& r,
                                                           std::string& refusal) {
    refusal.clear();
    if (o.job.budget_ms <= 0.0) return std::nullopt;
    refusal = render::budget_refusal(o.settings);
    if (!refusal.empty()) return std::nullopt;
    return render::BudgetController(o.job.budget_ms, o.settings, r.caps().depth_texture, r.caps().max_target_size());
}

// Renders `frames` frames of scene_at(i) with b's settings, each finished and timed, and observed;
// returns their times.
template <typename SceneAt>
std::vector<double> budget_frames(render::Renderer& r, render::BudgetController& b, const render::FrameInputs& in,
                                  int frames, SceneAt scene_at) {
    std::vector<double> ms;
    for (int i = 0; i < frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        r.render(scene_at(i), b.settings(), in);
        r.finish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        b.observe(ms.back());
    }
    return ms;
}

}  // namespace penumbra::tools
