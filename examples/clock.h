// The course scene's two clocks: the light's (its circle over the table) and the jump's (the
// teapot's), advanced by the frames' time while their motion is on and time is not paused. No GL.
#pragma once

#include <algorithm>

#include "scenes/course_scene.h"

namespace penumbra::examples {

struct CourseClock {
    double light = 0.0;  // seconds on the light's clock
    double jump = 0.0;   // and on the jump's
    bool paused = false;

    // Advances by dt: the light's clock while `light_moves`, the jump's while `jumps`; switched off
    // in mid-air, the teapot comes down and rests on the table.
    void advance(double dt, bool light_moves, bool jumps) {
        if (paused || !(dt > 0.0)) return;
        dt = std::min(dt, 0.25);  // a tab in the background must not make the teapot leap
        if (light_moves) light += dt;
        if (jumps) jump += dt;
        else jump = std::min(jump + dt, scene::course_teapot_landing(jump));
    }
    // Both clocks at t.
    void set(double t) { light = jump = t; }
    // One time for both (time=T in the URL keeps it only then).
    bool together() const { return light == jump; }
};

}  // namespace penumbra::examples
