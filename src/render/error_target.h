// An error target (issue 56): the least work predicted to keep a frame within P % of the hard
// truth. The ladder is a time budget's (plan/budget.h: map sizes 128 up to the context's largest,
// a depth texture where there is one, the hard test; shadow volumes on top where the caller can
// draw them), ordered by the bench's cost model; each rung's error is predicted by
// plan/error_model.h from the frame's shadow edges (counted in one visibility image drawn with the
// ladder's most accurate rung) and the texels a pixel the plan's resolution match gives that
// rung's map. The cheapest rung predicted within P is chosen; when none is, the one predicted the
// most accurate, and the line says so.
//
// The commands choose once, on the frame at --time (tools/penumbra/max_error.h); the course
// exercises choose again as their frames move (examples/exercises.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "plan/budget.h"
#include "plan/settings.h"
#include "render/renderer.h"

namespace penumbra::render {

struct ErrorRung {
    Settings settings;
    int rung = 0;               // the ladder's (BudgetController::at_rung)
    int map = 0;                // texels a side; 0: shadow volumes
    double cost = 0.0;          // the bench's model: over the unshadowed frame (BudgetController::model_cost)
    double texel_pixels = 0.0;  // pixels a texel spans (0: volumes)
    double predicted_pct = 0.0;
    double ms = -1.0;           // a frame's wall time where it was measured on this frame (the CLI's volumes), else -1
};

struct ErrorChoice {
    std::vector<ErrorRung> rungs;  // cheapest first
    int chosen = 0;                // index into rungs
    long edges = 0, pixels = 0;    // the frame's shadow-edge pixels, of those the scene covers (not background)
    int wanted = 0;                // the plan's resolution match (MapSizeReport::wanted)
    std::string why;               // one line: the target, the choice, its prediction, the next cheaper one's
    const ErrorRung& rung() const { return rungs[static_cast<size_t>(chosen)]; }
    const Settings& settings() const { return rung().settings; }
};

// "--max-error: ..." when `s` cannot be chosen for (no map, a soft filter), else "".
std::string max_error_refusal(const Settings& s);

// The rungs of `ladder` (made for settings `s`), each with its prediction on the frame of `scene`
// drawn with `in` (an offscreen output: two frames are drawn and read back), and the choice for
// `max_pct`. The frame's shadow edges are counted with the ladder's most accurate rung, or with
// its settings and the map matched to the screen where `matched_edges` (a choice made again and
// again: the matched map costs what the screen needs, the largest map 16 times a 1024's texels).
// None, with `refusal` set, when it cannot be made (max_error_refusal, or a plan that does not
// match its map to the screen).
std::optional<ErrorChoice> choose_for_error(double max_pct, const Settings& s, const BudgetController& ladder, Renderer& r,
                                            const scene::Scene& scene, const FrameInputs& in, std::string& refusal,
                                            bool matched_edges = false);

// Puts c.rungs in the order of their cost, stably (after a cost was changed: measured).
void order_by_cost(ErrorChoice& c);

// Sets c.chosen and c.why for `max_pct` from the rungs' predictions (the bench asks several).
void pick_rung(ErrorChoice& c, double max_pct);

// Hysteresis for a choice made again as the frame moves: when the rung in use (the ladder's
// `in_use`) is still predicted within `max_pct` and c's choice is a cheaper one predicted over
// `keep` x `max_pct`, the choice goes back to the rung in use and c.why says so. True when it did.
bool keep_rung(ErrorChoice& c, int in_use, double max_pct, double keep);

// The label of a rung: "shadow volumes" or "depthtex hard 512".
std::string rung_label(const ErrorRung& g);

}  // namespace penumbra::render
