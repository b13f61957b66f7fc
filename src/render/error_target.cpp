#include "render/error_target.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "plan/error_model.h"
#include "plan/techniques/technique.h"
#include "render/frame_edges.h"

namespace penumbra::render {

namespace {

std::string pct(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f %%", v);
    return b;
}

}  // namespace

std::string rung_label(const ErrorRung& g) {
    if (g.map == 0) return "shadow volumes";
    return std::string(shadow::to_string(g.settings.encoding)) + " hard " + std::to_string(g.map);
}

std::string max_error_refusal(const Settings& s) {
    if (!technique_module(s.technique).depth_map())
        return "--max-error: chooses a shadow map's settings; --technique " + std::string(technique_module(s.technique).name()) +
               " has none (use --technique shadowmap)";
    if (s.filter == shadow::Filter::PCSS)
        return "--max-error: predicts a hard shadow's error; --filter pcss draws a penumbra (use --filter hard)";
    return {};
}

std::optional<ErrorChoice> choose_for_error(double max_pct, const Settings& s, const BudgetController& ladder, Renderer& r,
                                            const scene::Scene& scene, const FrameInputs& in, std::string& refusal,
                                            bool matched_edges) {
    refusal = max_error_refusal(s);
    if (!refusal.empty()) return std::nullopt;
    const bool depth_texture = r.caps().depth_texture;

    // The frame's shadow edges from its most accurate rung (the top: volumes or the largest map;
    // or its settings with the matched map), the pixels it covers and its match from the cheapest.
    Settings edges_with = ladder.at_rung(ladder.rungs() - 1, s);
    if (matched_edges && ladder.map_size(ladder.rungs() - 1) != BudgetController::kVolumes)
        edges_with.map_size = Settings::kAutoMapSize;
    const FrameEdges f = measure_frame_edges(r, scene, edges_with, ladder.at_rung(0, s), in);
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
        g.rung = k;
        g.map = ladder.map_size(k);
        g.cost = BudgetController::model_cost(g.map, depth_texture);
        g.texel_pixels = pixels_per_texel(c.wanted, g.map);
        g.predicted_pct = predicted_error_pct(f, g.map);
        c.rungs.push_back(g);
    }
    order_by_cost(c);  // the model's (shadow volumes fall among the maps)
    pick_rung(c, max_pct);
    return c;
}

void order_by_cost(ErrorChoice& c) {
    // An insertion sort: a ladder has at most 7 rungs, and std::stable_sort's merges of
    // Settings-sized records cost every page's module about 1 KB gzipped.
    for (size_t i = 1; i < c.rungs.size(); ++i)
        for (size_t j = i; j > 0 && c.rungs[j].cost < c.rungs[j - 1].cost; --j) std::swap(c.rungs[j], c.rungs[j - 1]);
}

void pick_rung(ErrorChoice& c, double max_pct) {
    int fits = -1, best = 0;
    for (size_t k = 0; k < c.rungs.size(); ++k) {
        if (fits < 0 && c.rungs[k].predicted_pct <= max_pct) fits = static_cast<int>(k);
        if (c.rungs[k].predicted_pct < c.rungs[static_cast<size_t>(best)].predicted_pct) best = static_cast<int>(k);
    }
    c.chosen = fits >= 0 ? fits : best;
    const ErrorRung& g = c.rung();
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

bool keep_rung(ErrorChoice& c, int in_use, double max_pct, double keep) {
    const auto kept = std::find_if(c.rungs.begin(), c.rungs.end(), [&](const ErrorRung& g) { return g.rung == in_use; });
    if (kept == c.rungs.end()) return false;
    const int k = static_cast<int>(kept - c.rungs.begin());
    const ErrorRung& cheaper = c.rung();
    if (!(c.chosen < k && kept->predicted_pct <= max_pct && cheaper.predicted_pct > keep * max_pct)) return false;
    char b[64];
    std::snprintf(b, sizeof b, ", is not within %.2g x the target", keep);
    c.why = "max-error " + pct(max_pct) + ": kept " + rung_label(*kept) + ", predicted " + pct(kept->predicted_pct) +
            "; the cheaper " + rung_label(cheaper) + ", predicted " + pct(cheaper.predicted_pct) + b;
    c.chosen = k;
    return true;
}

}  // namespace penumbra::render
