// The passes of a plan into a point light's cube faces ("shadow-map face +x"...), and how many of
// them ran (not skipped): what the cube's unit and extremes tests count.
#pragma once

#include "plan/plan.h"

namespace penumbra::test {

inline int cube_face_passes(const render::FramePlan& p, int* ran = nullptr) {
    int n = 0, r = 0;
    for (const render::Pass& pass : p.passes)
        if (pass.name.rfind("shadow-map face ", 0) == 0) {
            ++n;
            r += !pass.skipped;
        }
    if (ran) *ran = r;
    return n;
}

}  // namespace penumbra::test
