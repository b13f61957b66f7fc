// Heckbert and Herf's soft shadows (--area-samples N), a frame shape (frame.h, area_light.cpp):
// the technique run from N points on the light, the visibilities averaged. Its report in the plan.
#pragma once

#include <string>

#include "plan/plan.h"

namespace penumbra::render {

// How far the accumulation of light samples has come. A still frame keeps what earlier frames
// added (progressive with --area-per-frame).
struct AreaStats {
    static constexpr const char* kKey = "area";
    int total = 0;    // samples asked for
    int done = 0;     // in the accumulation after this frame
    int added = 0;    // drawn by this frame (0: the accumulation was complete and still)
    std::string key;  // what the accumulation depends on (camera, light, objects, settings)
    static std::string text(const AreaStats& a);
    static std::string json(const AreaStats& a);
};

// The plan's light-sample report, or null (not an area-light frame).
const AreaStats* area_of(const FramePlan& p);

}  // namespace penumbra::render
