// What the error model (plan/error_model.h) needs of a frame, measured on the frame itself: its
// shadow edges, the pixels the scene covers, and the resolution match of its map. --max-error
// chooses with it (tools/penumbra/max_error.h); the course exercises show a budget's predicted
// error with it (examples/exercises.h).
#pragma once

#include "plan/plan.h"
#include "plan/settings.h"
#include "render/renderer.h"

namespace penumbra::render {

struct FrameEdges {
    long edges = 0;    // pixels of the visibility frame beside the other side of a shadow's edge
    long covered = 0;  // pixels not of the background's colour
    int wanted = -1;   // texels a side two texels a pixel want (MapSizeReport::wanted); -1: the plan
                       // does not match its map to the screen (cascades, Gooch's texture, W09P2b)
};

// Draws `scene` at in.output's size (an offscreen output): `edges_with`'s visibility, for its
// shadow edges, and `s`'s colour, for the pixels covered; plans `s` with --map-size auto for the
// match. Three plans, two frames drawn and read back: for a choice, not for every frame.
FrameEdges measure_frame_edges(Renderer& r, const scene::Scene& scene, const Settings& edges_with, const Settings& s,
                               const FrameInputs& in);

// The model's prediction (%) for that frame with a map of `map_size` texels a side (0: shadow
// volumes, exact); < 0 when a map's cannot be predicted (no match).
double predicted_error_pct(const FrameEdges& f, int map_size);

}  // namespace penumbra::render
