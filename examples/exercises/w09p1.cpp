// W09P1: the jumping teapot on the marble table, its planar projected shadow (stencil); buttons
// for the light's circulation and the teapot's jump.
#include "common.h"

namespace penumbra::examples::exercises {

Exercise w09p1() {
    const Control light = light_toggle(), jump = jump_toggle();
    Exercise x{"w09p1", "W09P1: Jumping teapot on a marble table top",
         "The Newell teapot jumps on a marble table top under a point light circling above it. The teapot and the "
         "ground are drawn with different shader programs (the ground textured with the marble); the teapot casts its "
         "planar projected shadow on the table, counted once per pixel in the stencil buffer.",
         "The teapot and the ground drawn with different shader programs; the teapot's planar projected shadow; "
         "buttons for the light's circulation and the teapot's jump.",
         "The teapot on the marble table with its planar projected shadow",
         "Switch the jump off: the teapot lands and its shadow meets its base. Watch the shadow stay flat on "
         "the table as the light circles.", {light, jump}};
    x.frame = {{"technique", "planar"}};
    x.draw = draw_colour;
    x.modules = {render::planar_module};
    return x;
}

}  // namespace penumbra::examples::exercises
