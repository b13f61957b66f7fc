// W09P2a: the scene from the light, its own view and projection fitted tightly around the scene:
// perspective for the point light, orthographic for a directional light.
#include "common.h"

namespace penumbra::examples::exercises {

namespace {

// Seen from the light, nothing is in shadow.
void draw(Host& host, render::Settings s, render::FrameInputs in) {
    s.aov = render::Aov::Color;
    host.render(s, host.light_view(in.output, host.toggles().ortho, in.output));
}

}  // namespace

Exercise w09p2a() {
    const Control light = light_toggle(), jump = jump_toggle();
    Exercise x{"w09p2a", "W09P2a: Rendering from the point of view of the light source",
         "The scene drawn with the light's own projection and view matrices, the view volume a tight bound around the "
         "table and the teapot: a perspective projection for the point light, an orthographic one for a directional "
         "light along the same line of sight.",
         "The light's own projection and view matrices fitted tightly around the scene: perspective for the point "
         "light, orthographic for a directional one.",
         "The scene seen from the light",
         "Switch between perspective and orthographic: the point light's view spreads out from the light and "
         "makes the near end of the table look larger; the directional light's lines stay parallel.",
         {light, jump, {"projection", "Light projection", K::Radio}}};
    x.frame = {{"technique", "none"}};
    x.draw = draw;
    x.modules = {};  // no shadows: the module every page has
    return x;
}

}  // namespace penumbra::examples::exercises
