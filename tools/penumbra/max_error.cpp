// --max-error: see max_error.h.
#include "max_error.h"

#include "budget_frames.h"

namespace penumbra::tools {

std::optional<ErrorChoice> choose_for_error(double max_pct, const render::Settings& s, render::Renderer& r,
                                            const scene::Scene& scene, const render::FrameInputs& in, std::string& refusal) {
    refusal = render::max_error_refusal(s);
    if (!refusal.empty()) return std::nullopt;  // before the ladder's check draws anything
    return render::choose_for_error(max_pct, s, budget_for(1.0, s, r, scene, in), r, scene, in, refusal);
}

std::optional<ErrorChoice> make_error_choice(const render::Options& o, render::Renderer& r, const scene::Scene& scene,
                                             const render::FrameInputs& in, std::string& refusal) {
    refusal.clear();
    if (o.job.max_error <= 0.0) return std::nullopt;
    if (o.job.budget_ms > 0.0) {
        refusal = "--max-error and --budget-ms: give one (a time to fit, or an error to keep within)";
        return std::nullopt;
    }
    return choose_for_error(o.job.max_error, o.settings, r, scene, in, refusal);
}

}  // namespace penumbra::tools
