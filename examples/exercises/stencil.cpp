// Stencil effects: the outline, the mirror and the portal, with any shadow technique.
#include "common.h"
#include "scenes/portal_scene.h"

namespace penumbra::examples::exercises {

Exercise stencil() {
    const Control light = light_toggle(), jump = jump_toggle();
    Exercise x{"stencil", "Stencil effects: outline, mirror, portal",
         "The stencil buffer is a mask with a value per pixel: a draw first writes a pattern into it, and later draws "
         "pass only where it holds a given value. The outline uses it twice: the teapot is drawn with colour and depth "
         "writes off, setting its pixels' stencil bit; then it is drawn again, enlarged, in one colour, only where the "
         "bit is not set, so only a band around the teapot shows, never the teapot itself. The course notes enlarge the "
         "model by scaling it; here each vertex is pushed out along its normal's direction on the screen by a constant "
         "number of pixels, because a scale about the centre moves each point by its distance from the centre, so the "
         "band would be wide round the body, thin at the spout and the handle, and narrower the farther the teapot is. "
         "The outline's bit sits beside the shadows' own stencil values (planar shadows' mark, shadow volumes' "
         "count), so it works with each technique. The mirror marks the table top's visible pixels in its own bit, "
         "clears their depth, and draws the scene a second time through the camera reflected in the table's plane, "
         "only there: the reflected teapot is lit by the same light and shadowed by the same shadow map, and what "
         "would lie below the table is cut away in the shader (WebGL 1 has no clip planes). The reflectivity mixes "
         "the reflection with the table's own colour and shadows. The portal marks the opening of a frame standing at the "
         "back of the table where it is seen (depth tested: the teapot in front of it hides it), sets their depth to "
         "the far plane and draws another scene there, with its own light and its own shadow map, cut away on the "
         "near side of the opening's plane.",
         "The stencil buffer as a mask: the teapot's pixels marked, then a copy pushed out by a constant number of "
         "pixels drawn only where they are not, outlining the teapot with any shadow technique; and the table top "
         "made a mirror, the reflected scene drawn only in its pixels; a portal into another scene through a frame.",
         "The teapot on the table, outlined in colour through the stencil buffer, the table a mirror",
         "Widen the outline: the band stays as wide round the spout as round the body. Choose the mirror, then the "
         "portal: the teapot jumps in front of another world. Planar and volumes share the stencil with them.",
         {light, jump,
          {"effects", "Effects", K::Select, {"outline", "none", "mirror", "outline,mirror", "portal", "outline,mirror,portal"}, {},
           "each marks its pixels in a stencil bit of its own"},
          {"outline-width", "Outline", K::Slider, {"1", "2", "3", "5", "8", "12", "16"}, {},
           "pixels, the same at any depth", 0.5, 16.0},
          {"outline-color", "Outline", K::Select},
          {"reflectivity", "Mirror", K::Slider, {"0.25", "0.5", "0.75", "1"}, {},
           "of the table's colour is the reflection", 0.0, 1.0},
          here_only({"technique", "Shadows", K::Select, {"shadowmap", "planar", "volumes", "none"}, {},
           "planar and volumes keep their shadows in the stencil too"})},
         {{"effects", "outline"}}};
    x.draw = draw_colour;
    x.portal = scene::make_course_portal;
    x.modules = {render::shadow_map_module, render::planar_module, render::volumes_module, render::outline_module,
                 render::mirror_module, render::portal_module};
    return x;
}

}  // namespace penumbra::examples::exercises
