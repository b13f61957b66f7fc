// Shadow volumes counted in the stencil buffer: depth-pass, depth-fail or auto, the volumes
// drawn over the image, the stencil count in false colour, and the eye moved into the teapot's
// shadow (where depth-pass fails).
#include "common.h"
#include "scene/eye.h"

namespace penumbra::examples::exercises {

namespace {

// Colour, visibility or the stencil count; the volumes drawn or not.
void draw(Host& host, render::Settings s, render::FrameInputs in) {
    if (s.aov == render::Aov::LightDepth) s.aov = render::Aov::Color;  // no shadow map here
    host.render(s, in);
}

}  // namespace

Exercise volumes() {
    const Control light = light_toggle(), jump = jump_toggle();
    Exercise x{"volumes", "Shadow volumes: counting shadows in the stencil buffer",
         "Each silhouette edge of the teapot, seen from the light, is extruded away from the light into a shadow "
         "volume. The stencil buffer counts, per pixel, the volume faces between the eye and the surface: a count above "
         "zero means the surface is inside a volume, in shadow. Depth-pass counts the faces in front of the surface "
         "(+1 entering, -1 leaving); it fails when the eye is inside a shadow volume: the count starts one too low, so "
         "shadows vanish and lit ground turns dark. Depth-fail counts the faces behind the surface instead, with the "
         "volumes closed by caps, and holds wherever the eye is. Auto takes depth-pass unless the eye may be inside "
         "the volume.",
         "Shadow volumes counted in the stencil buffer: depth-pass against depth-fail with the eye inside a shadow, "
         "the volumes drawn, and the stencil count in false colour.",
         "The teapot on the table, shadowed by shadow volumes counted in the stencil buffer",
         "Move the eye into the teapot's shadow, then compare depth-pass with depth-fail (the stencil count "
         "view shows the counts).",
         {light, jump,
          {"volume-method", "Shadow volumes", K::Select, {}, {}, "depth-pass fails when the eye is inside a volume"},
          {"show-volumes", "Shadow volumes", K::Checkbox, {"on", "off"}},
          {"eye", "Shadow volumes", K::Checkbox, {"in-shadow", "scene"}, "Move the eye into a shadow",
           "the eye inside the teapot's shadow, looking across it"},
          {"aov", "View", K::Select, {"color", "visibility", "stencil-count"}, {},
           "stencil count: 1 blue, 2 green, 3 yellow, 4 orange, 5 magenta, 6 white; below zero red"}}};
    x.frame = {{"technique", "volumes"}};
    x.draw = draw;
    x.modules = {render::volumes_module};
    x.eye_in_shadow = scene::place_eye_in_shadow;
    return x;
}

}  // namespace penumbra::examples::exercises
