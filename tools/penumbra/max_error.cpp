// --max-error: see max_error.h.
#include "max_error.h"

#include <algorithm>
#include <cstdio>

#include "budget_frames.h"
#include "plan/budget.h"
#include "plan/error_model.h"
#include "render/frame_edges.h"
#include "plan/techniques/technique.h"

namespace penumbra::tools {

namespace {

std::string rung_label(const ErrorRung& g) {
    if (g.map == 0) return "shadow volumes";
    return std::string(shadow::to_string(g.settings.encoding)) + " hard " + std::to_string(g.map);
}

std::string pct(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f %%", v);
    return b;
}

}  // namespace

std::string max_error_refusal(const render::Settings& s) {
    if (!render::technique_module(s.technique).depth_map())
        return "--max-error: chooses a shadow map's settings; --technique " + std::string(render::technique_module(s.technique).name()) +
               " has none (use --technique shadowmap)";
    if (s.filter == shadow::Filter::PCSS)
        return "--max-error: predicts a hard shadow's error; --filter pcss draws a penumbra (use --filter hard)";
    return {};
}

std::optional<ErrorChoice> choose_for_error(double max_pct, const render::Settings& s, render::Renderer& r,
                                            const scene::Scene& scene, const render::FrameInputs& in, std::string& refusal) {
    refusal = max_error_refusal(s);
    if (!refusal.empty()) return std::nullopt;
    const render::BudgetController ladder = budget_for(1.0, s, r, scene, in);
    const bool depth_texture = r.caps().depth_texture;

    // The frame's shadow edges from its most accurate rung (the top: volumes or the largest map),
    // the pixels it covers and its match from the cheapest.
    const render::Settings cheapest = ladder.at_rung(0, s);
    const render::FrameEdges f =
        render::measure_frame_edges(r, scene, ladder.at_rung(ladder.rungs() - 1, s), cheapest, in);
    if (f.wanted < 0) {
        refusal = "--max-error: this frame's plan does not match its map to the screen (cascades, Gooch's texture and "
                  "W09P2b keep their size), so its error cannot be predicted (try --cascades 0)";
        return std::nullopt;
    }
    ErrorChoice c;
    c.wanted = f.wanted;
    c.pixels = f.covered;
    c.edges = f.edges;
    for (int k = 0; k < ladder.rungs(); ++k) {
        ErrorRung g;
        g.settings = ladder.at_rung(k, s);
        g.map = ladder.map_size(k);
        g.cost = render::BudgetController::model_cost(g.map, depth_texture);
        g.texel_pixels = render::pixels_per_texel(c.wanted, g.map);
        g.predicted_pct = render::predicted_error_pct(f, g.map);
        c.rungs.push_back(g);
    }
    std::stable_sort(c.rungs.begin(), c.rungs.end(), [](const ErrorRung& a, const ErrorRung& b) { return a.cost < b.cost; });

    pick_rung(c, max_pct);
    return c;
}

void pick_rung(ErrorChoice& c, double max_pct) {
    int fits = -1, best = 0;
    for (size_t k = 0; k < c.rungs.size(); ++k) {
        if (fits < 0 && c.rungs[k].predicted_pct <= max_pct) fits = static_cast<int>(k);
        if (c.rungs[k].predicted_pct < c.rungs[static_cast<size_t>(best)].predicted_pct) best = static_cast<int>(k);
    }
    c.chosen = fits >= 0 ? fits : best;
    const ErrorRung& g = c.rungs[static_cast<size_t>(c.chosen)];
    char b[160];
    std::snprintf(b, sizeof b, ": %ld shadow-edge pixels (%.2f %% of the scene's), ", c.edges,
                  c.pixels > 0 ? 100.0 * static_cast<double>(c.edges) / static_cast<double>(c.pixels) : 0.0);
    c.why = "max-error " + pct(max_pct) + ": " + rung_label(g) + ", predicted " + pct(g.predicted_pct) + b;
    if (g.map) {
        std::snprintf(b, sizeof b, "%.2f pixels a texel", g.texel_pixels);
        c.why += b;
    } else {
        c.why += "no texels (exact)";
    }
    if (fits < 0)
        c.why += "; nothing is predicted within it, this is the most accurate";
    else if (fits > 0)
        c.why += "; the next cheaper, " + rung_label(c.rungs[static_cast<size_t>(fits) - 1]) + ", is predicted " +
                 pct(c.rungs[static_cast<size_t>(fits) - 1].predicted_pct);
    else
        c.why += "; the cheapest setting";
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
