// --max-error P (issue 56): a hard shadow's error against the ray-traced truth, predicted for a
// frame before choosing its settings. No GL here: the caller counts the frame's shadow edges in
// one visibility image (Aov::Visibility) and reads the texels a pixel from the plan's resolution
// match (MapSizeReport::wanted).
//
// Why this shape: a hard shadow goes wrong only along its edges. Where a map's texel spans t
// pixels on screen, each edge steps by up to a texel, so about kPerTexel * t of the pixels beside
// each edge pixel flip. However fine the map, a share kMapEdge of the edge pixels still differ
// from the ray tracer's one ray a pixel: the bias and the caster's silhouette rasterised into
// the map shift an edge by a fraction of a texel. An exact method (shadow volumes) agrees with
// the truth but for a share kExactEdge (its rasteriser's ties). The error, as a share of the
// pixels the scene covers, is edges / pixels * (kMapEdge + kPerTexel * t) with a map, and
// edges / pixels * kExactEdge without. The constants are the course's; the bench's error-target
// section shows how well they predict its other scenes (docs/budget.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::render {

// Fitted to the course's four bench frames at 512x512 against the hard truth (llvmpipe; the 30 Nov
// bench, whose truth starts each shadow ray on its own line; docs/budget.md). kExactEdge: the
// least no shadow-volumes frame exceeds (0.0009, rounded up). kMapEdge and kPerTexel: the upper
// envelope of the 24 map rungs (128 to 4096) with the least summed prediction, so that none
// measures more than predicted (0.64-1.00x, median 0.78) and a choice errs towards more work.
// The constants before that truth (0.02 for every rung, 0.07) were fitted to edges it had moved
// by a third of a pixel: they predicted shadow volumes' error 20 times over or more, and the
// course maps' 1.7 times (median).
struct ErrorModel {
    static constexpr double kExactEdge = 0.001;  // wrong pixels per edge pixel with shadow volumes
    static constexpr double kMapEdge = 0.009;    // ... with a map however fine
    static constexpr double kPerTexel = 0.073;   // ... and per edge pixel per pixel a texel spans
};

// The pixels of a width x height visibility image (one byte a pixel: 0 shadow .. 255 lit) with a
// right or lower neighbour on the other side of half: the shadows' edges on screen.
long shadow_edge_pixels(const std::vector<std::uint8_t>& visibility, int width, int height);

// Pixels a texel spans on screen, on average over the receivers in view, for a map of `size`
// texels a side where two texels a pixel want `wanted` (shadow/resolution.h); 0 for `size` 0
// (shadow volumes: no texels).
double pixels_per_texel(int wanted, int size);

// The predicted share (%) of `pixels` (those the scene covers) wrong against the hard truth, with
// `edges` shadow-edge pixels and, with a map (`map`), texels spanning `texel_pixels` pixels;
// without one (shadow volumes), exact.
double predicted_error_pct(long edges, long pixels, bool map, double texel_pixels);

}  // namespace penumbra::render
