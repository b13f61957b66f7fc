// Multipass: post-processing (blur, bloom, a blurred shadow) and deferred shading.
#include "common.h"

namespace penumbra::examples::exercises {

namespace {

// Colour, visibility or a G-buffer view, through the post passes.
void draw(Host& host, render::Settings s, render::FrameInputs in) {
    if (s.aov != render::Aov::Visibility && !render::gbuffer_aov(s.aov)) s.aov = render::Aov::Color;
    host.render(s, in);
}

}  // namespace

Exercise multipass() {
    const Control light = light_toggle(), jump = jump_toggle();
    Exercise x{"multipass", "Multipass: blur, bloom, a blurred shadow, and deferred shading",
         "A frame object (FBO) lets a pass draw into a texture that a later pass reads: the whole image drawn into "
         "one, then a triangle over the screen that reads it and writes into a second, and back. A Gaussian blur is "
         "two such passes, because it is separable: each pixel the weighted sum of its row's neighbours, then of its "
         "column's, 2R + 1 lookups each instead of (2R + 1) squared. Bloom keeps what is brighter than a threshold, "
         "shrinks it to half size (linear filtering averages four pixels at once), blurs it there and again at "
         "quarter size, where the same radius reaches twice as far, and adds both back. The shadow blur draws the "
         "shadow's visibility alone, white lit and black shadowed, blurs that, and lights the scene with it: a soft "
         "edge for two cheap passes, but one that knows nothing of depth, so it is as wide by the teapot's foot as "
         "far from it, and it bleeds across the teapot's outline. The passes' targets are half floats where the "
         "context can draw into them (OES_texture_half_float with EXT_color_buffer_half_float), else 8-bit. "
         "Deferred shading turns the frame around: the objects are drawn once into a G-buffer, three textures "
         "holding each pixel's colour, normal and depth (at once where the context has WEBGL_draw_buffers, else one "
         "pass per texture), and only then lit, the main light and its shadow map over every pixel, each point "
         "light over the square of the screen its range covers. Forward shading pays for every light on every "
         "object it draws; deferred pays once for the objects and then per lit pixel.",
         "Render to a texture, then draw from it: a separable Gaussian blur by ping-pong between two targets, bloom at "
         "half and quarter size, the shadow's visibility blurred on its own as a cheap soft shadow, and deferred "
         "shading from a G-buffer with up to 256 point lights.",
         "The teapot on the table, the image passed through a blur, a bloom or a blurred shadow",
         "Blur the shadow alone, then look at the teapot's foot: the edge is as soft there as far away, where a light "
         "with a size (the soft exercise) keeps it sharp. Add bloom. With no post pass, add 64 lights and switch to "
         "deferred: the same image, faster.",
         {light, jump,
          here_only({"post", "Post-processing", K::Select, {"shadow-blur:6", "none", "blur:4", "bloom:0.6", "shadow-blur:6,bloom:0.6"},
           {}, "each pass reads the last one's target"}),
          here_only({"technique", "Shadows", K::Select, {"shadowmap", "planar", "volumes"}, {}, "any of them blurred"}),
          {"aov", "View", K::Select,
           {"color", "visibility", "gbuffer-color", "gbuffer-normal", "gbuffer-position", "gbuffer-depth"}, {},
           "the shadow alone, or the G-buffer"},
          here_only({"shading", "Shading", K::Select, {"forward", "deferred"}, {}, "deferred: a G-buffer, then the lights"}),
          here_only({"lights", "Shading", K::Slider, {"0", "8", "32", "64", "128", "256"}, {}, "unshadowed", 0.0, 256.0})},
         {{"post", "shadow-blur:6"}}};
    x.draw = draw;
    x.modules = {render::shadow_map_module, render::planar_module, render::volumes_module};
    x.frames = {render::deferred_shape, render::shadow_blur_shape, render::image_post_shape};
    return x;
}

}  // namespace penumbra::examples::exercises
