// --max-error P in the commands (render, plan, bench; issue 56): the least work predicted to keep
// a frame within P % of the hard truth. The ladder is --budget-ms's (plan/budget.h: map sizes 128
// up to the context's largest, a depth texture where there is one, the hard test; shadow volumes
// on top where they can draw the scene), ordered by the bench's cost model; each rung's error is
// predicted by plan/error_model.h from the frame's shadow edges (counted in one visibility image
// drawn with the ladder's most accurate rung) and the texels a pixel the plan's resolution match
// gives that rung's map. The cheapest rung predicted within P is chosen; when none is, the one
// predicted the most accurate, and the line says so.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "plan/options.h"
#include "plan/settings.h"
#include "render/renderer.h"

namespace penumbra::tools {

struct ErrorRung {
    render::Settings settings;
    int map = 0;                // texels a side; 0: shadow volumes
    double cost = 0.0;          // the bench's model: over the unshadowed frame (BudgetController::model_cost)
    double texel_pixels = 0.0;  // pixels a texel spans (0: volumes)
    double predicted_pct = 0.0;
};

struct ErrorChoice {
    std::vector<ErrorRung> rungs;  // cheapest first
    int chosen = 0;                // index into rungs
    long edges = 0, pixels = 0;    // the frame's shadow-edge pixels, of those the scene covers (not background)
    int wanted = 0;                // the plan's resolution match (MapSizeReport::wanted)
    std::string why;               // one line: the target, the choice, its prediction, the next cheaper one's
    const render::Settings& settings() const { return rungs[static_cast<size_t>(chosen)].settings; }
};

// "--max-error: ..." when `s` cannot be chosen for (no map, a soft filter, a plan without the
// resolution match), else "".
std::string max_error_refusal(const render::Settings& s);

// The choice for `max_pct` on `scene`'s frame; none, with `refusal` set, when it cannot be made.
std::optional<ErrorChoice> choose_for_error(double max_pct, const render::Settings& s, render::Renderer& r,
                                            const scene::Scene& scene, const render::FrameInputs& in, std::string& refusal);

// Sets c.chosen and c.why for `max_pct` from the rungs' predictions (the bench asks several).
void pick_rung(ErrorChoice& c, double max_pct);

// The options' --max-error choice (none when it is 0), refusing it beside --budget-ms.
std::optional<ErrorChoice> make_error_choice(const render::Options& o, render::Renderer& r, const scene::Scene& scene,
                                             const render::FrameInputs& in, std::string& refusal);

}  // namespace penumbra::tools
