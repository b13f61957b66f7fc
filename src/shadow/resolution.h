// Resolution matching (--map-size auto, issue 56): a map's size from the screen pixels it serves.
// The receivers the camera sees cover some pixels of the image and some share of the map (the
// fit's texel use); kTexelsPerPixel texels across each pixel on average over them asks for a map
// of kTexelsPerPixel * sqrt(pixels / use) texels a side, rounded up to a power of two and held
// within the context's largest texture and a memory cap. Averaging is the resolution-matched shadow map's rule at the
// scale of the whole map (Lefohn et al. match per tile); it needs only the fit's points, so it
// costs what the fit costs: a convex hull of the points, O(n log n). No GL here.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::shadow {

// The pixels of a width x height image covered by the convex hull of `points` projected through
// `camera_view_proj` (points at or behind the camera's eye plane left out, the hull clipped to the
// image).
float screen_pixels(const std::vector<glm::vec3>& points, const glm::mat4& camera_view_proj, int width, int height);

// Texels across a pixel's width, on average over the receivers in view. One is the density's
// match on average, but the map's texels stretch where the light meets a receiver at a slant and
// near the camera, and a hard edge then steps a pixel wide: on the bench scenes at 512x512
// (llvmpipe, one frame each) one texel a pixel (maps of 512) is 1.6-2.8x the error of two (1024):
// bench_medium 0.175 % against 0.099 %, the course 0.041 % against 0.025 %.
inline constexpr float kTexelsPerPixel = 2.0f;

struct MatchedSize {
    int size = 0;          // texels a side: a power of two in [smallest, largest]
    int wanted = 0;        // kTexelsPerPixel * sqrt(pixels / use) before rounding and the bounds (0: nothing in view)
    std::string why;       // one line for the plan: the pixels, the use, the size and what bounded it
};

// One map (or each of `maps` equal tiles: a cube's drawn faces) serving `pixels` of the image at
// texel use `use` (0..1; for tiles, their summed uses), `largest` texels a side at most (the
// context's and the memory cap's bound), `smallest` at least.
MatchedSize matched_map_size(float pixels, float use, int maps, int smallest, int largest);

}  // namespace penumbra::shadow
