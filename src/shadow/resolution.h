// Resolution matching (--map-size auto): a map's size from the screen pixels it serves. The
// receivers the camera sees cover some pixels of the image and some share of the map;
// kTexelsPerPixel texels across each pixel on average over them asks for a map of
// kTexelsPerPixel * sqrt(pixels / share) texels a side, and the densest tiles of the map (the
// resolution-matched shadow map's rule, Lefohn et al., at the scale of 8 x 8 tiles, from the plan
// instead of the depth buffer) may ask for more. Rounded up to a power of two and held within the
// context's largest texture and a memory cap. O(n) in the receivers. No GL here.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

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

// What the receivers in view ask of a map, part by part: each receiver's box clipped to the
// camera's view, the spot's cone and the map's window, and that part's convex hull projected onto
// the image (its pixels) and onto the map (its share). Summed part by part, so a scene of many
// small receivers costs one small hull each (a hull over all their points at once cost 40 ms of a
// 100,000-object frame here), and overlapping parts count once each.
//
// Where the density varies across a map (a wide perspective window, a receiver met at a grazing
// angle) an average under-samples its densest part. So the window is also cut into kDenseTiles x
// kDenseTiles tiles, a part across tiles is clipped again by each, and the size must also give
// kDenseTexelsPerPixel texels a pixel over kDenseShare of the pixels, tile by tile. The share
// lets a sliver seen at a grazing angle over a few pixels go under-sampled rather than double the
// map. One texel a pixel there leaves the average's choice where the density is even and raises
// it where a face sees a receiver edge-on (docs/resolution.md has the figures).
inline constexpr int kDenseTiles = 8;
inline constexpr float kDenseTexelsPerPixel = 1.0f;
inline constexpr double kDenseShare = 0.9;
struct Demand {
    double pixels = 0.0;  // of a width x height image, summed over the parts
    double share = 0.0;   // of the map, summed over the parts (may pass 1 where parts overlap)
    double dense = 0.0;   // texels a side kDenseTexelsPerPixel a pixel want over kDenseShare of the pixels
};
// For the receivers' boxes seen by a camera of `camera_view_proj` (a width x height image), in
// the window of `map_view_proj`. O(n): one clip a receiver, again per tile for those across tiles.
Demand receiver_demand(const scene::Light& light, const std::vector<scene::Bounds>& receivers, const glm::mat4& camera_view_proj,
                       int width, int height, const glm::mat4& map_view_proj);

// An image under 512 x 512 pixels is matched as if it were that large (its width and height
// scaled alike): at a fixed number of texels a pixel the error, as a share of the image's pixels,
// grows as the image shrinks (an edge crosses fewer pixels, but of fewer in all).
inline constexpr double kMatchedSide = 512.0;
// The width and height an image of width x height is matched as: itself, or scaled up to
// kMatchedSide pixels a side on average (sqrt(width x height)).
struct MatchedImage {
    int width = 0, height = 0;
    bool scaled = false;
};
MatchedImage matched_image(int width, int height);

struct MatchedSize {
    int size = 0;          // texels a side in [smallest, largest]: a power of two, or a step of one (map_size_step)
    int wanted = 0;        // kTexelsPerPixel * sqrt(pixels / use) before rounding and the bounds (0: nothing in view)
    std::string why;       // one line for the plan: the pixels, the use, the size and what bounded it
};

// How a want is rounded up. Tiles of an atlas (a cube's faces, cascades) share a power of two.
// One map alone may take any size (GLES 2.0 3.8.2 and WebGL 1 allow a texture that is not a power
// of two, clamped and without mipmaps, as every map is), and rounding its want up to the next power
// of two gave it up to twice the texels a side that the screen asks for, each of them drawn: so it
// is rounded up to an eighth of the want's octave (576, 640, ... 1024; 1152, ... 2048), at most
// 12.5 % more than the want and never more than the power of two would give.
enum class SizeSteps { PowersOfTwo, Eighths };
// The size a want of `wanted` texels a side is given, `smallest` at least (a power of two).
int map_size_step(double wanted, int smallest, SizeSteps steps);

// One map (or each of `maps` equal tiles: a cube's drawn faces) serving `pixels` of the image at
// texel use `use` (0..1; for tiles, their summed uses), `largest` texels a side at most (the
// context's and the memory cap's bound), `smallest` at least.
// `dense`: receiver_demand's, the one wanted where it is more than the average's.
MatchedSize matched_map_size(float pixels, float use, int maps, int smallest, int largest, double dense = 0.0,
                             bool scaled = false, SizeSteps steps = SizeSteps::PowersOfTwo);

}  // namespace penumbra::shadow
