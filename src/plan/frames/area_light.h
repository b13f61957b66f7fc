// Heckbert and Herf's soft shadows (--area-samples N), a frame shape (frame.h, area_light.cpp):
// the technique run from N points on the light, the visibilities averaged. Its report in the plan.
#pragma once

#include <string>

#include "plan/plan.h"

namespace penumbra::render {

// How far the accumulation of light samples has come. A still frame keeps what earlier frames
// added (progressive with --area-per-frame). Interleaved (--area-interleave K > 1) the steps are
// sample passes, each counting one light sample at one of the K x K pixel classes: K * K rounds of
// the N samples make every pixel's N.
struct AreaStats {
    static constexpr const char* kKey = "area";
    int total = 0;    // sample passes to the end: the samples asked for (times K * K interleaved)
    int done = 0;     // in the accumulation after this frame
    int added = 0;    // drawn by this frame (0: the accumulation was complete and still)
    int samples = 0;  // N, the light samples
    int interleave = 1;        // K
    int pixel_min = 0, pixel_max = 0;  // interleaved: the fewest and most samples a pixel class has
    std::string key;  // what the accumulation depends on (camera, light, objects, settings)
    static std::string text(const AreaStats& a);
    static std::string json(const AreaStats& a);
};

// The plan's light-sample report, or null (not an area-light frame). Inline: a page without the
// area-light frame (frame.h: area_light_shape) asks it too.
inline const AreaStats* area_of(const FramePlan& p) { return p.find<AreaStats>(); }

// Interleaved sampling's order: sample pass s (from 0) of N samples over K x K classes counts light
// sample s mod N at pixel class (x mod K) + K (y mod K) = (block + round) mod K^2, where round =
// s / N and block = (s mod N) K^2 / N: round 0 gives each class one block of consecutive samples
// (stratified on the light), each later round the next block, so after K^2 rounds every class has
// had every sample once.
struct AreaStep {
    int sample = 0;
    int pixel_class = 0;
};
AreaStep area_step(int s, int samples, int interleave);
// How many samples pixel class j has after `done` sample passes.
int area_class_samples(int j, int done, int samples, int interleave);

}  // namespace penumbra::render
