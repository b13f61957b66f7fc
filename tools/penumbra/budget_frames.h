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
#include "plan/techniques/technique.h"
#include "render/renderer.h"

namespace penumbra::tools {

// Frames a budget settles over when the command renders one frame (render, plan without --frames):
// the 12 at the start it does not measure, then the whole ladder from 512 (four steps up to 4096
// and shadow volumes, 10 or 11 frames each), with room to spare.
inline constexpr int kBudgetSettleFrames = 90;

// A caster whose material is alpha-tested: shadow volumes, extruded from its triangles, would
// shadow its whole geometry (alpha_cutouts: 12.5 % of the frame wrong where a 128 map is 0.8 %).
inline bool alpha_tested_caster(const scene::Scene& scene, const render::Settings& s) {
    for (const scene::Object& o : scene.objects)
        if (render::casts(scene, o, s.blend_shadows) && render::material_of(scene, o.material).alpha_mode != scene::AlphaMode::Opaque)
            return true;
    return false;
}

// The controller for settings `s` and a budget of `budget_ms` on this renderer's context, with
// shadow volumes as its top rung where they can draw `scene` with those settings exactly (no
// alpha-tested caster).
inline render::BudgetController budget_for(double budget_ms, const render::Settings& s, render::Renderer& r,
                                           const scene::Scene& scene, const render::FrameInputs& in) {
    render::Settings volumes = s;
    volumes.technique = render::technique_named("volumes");
    const bool can = render::technique_linked(volumes.technique) && !alpha_tested_caster(scene, s) &&
                     r.check(scene, volumes, in).empty();
    return render::BudgetController(budget_ms, s, r.caps().depth_texture, r.caps().max_target_size(), can);
}

// The controller for `o`'s --budget-ms; none when the option is 0. A technique without a map is
// bad input (the returned text, else "").
inline std::optional<render::BudgetController> make_budget(const render::Options& o, render::Renderer& r,
                                                           const scene::Scene& scene, const render::FrameInputs& in,
                                                           std::string& refusal) {
    refusal.clear();
    if (o.job.budget_ms <= 0.0) return std::nullopt;
    if (o.job.max_error > 0.0) {  // before the budget's frames are spent
        refusal = "--max-error and --budget-ms: give one (a time to fit, or an error to keep within)";
        return std::nullopt;
    }
    refusal = render::budget_refusal(o.settings);
    if (!refusal.empty()) return std::nullopt;
    return budget_for(o.job.budget_ms, o.settings, r, scene, in);
}

// Renders `frames` frames of scene_at(i) with b's settings, each finished and timed, and observed;
// returns their times (and, into `rungs` where given, the rung each frame ran).
template <typename SceneAt>
std::vector<double> budget_frames(render::Renderer& r, render::BudgetController& b, const render::FrameInputs& in,
                                  int frames, SceneAt scene_at, std::vector<int>* rungs = nullptr) {
    std::vector<double> ms;
    for (int i = 0; i < frames; ++i) {
        if (rungs) rungs->push_back(b.rung());
        const auto start = std::chrono::steady_clock::now();
        r.render(scene_at(i), b.settings(), in);
        r.finish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        b.observe(ms.back());
    }
    return ms;
}

}  // namespace penumbra::tools
