// W09P2c: shadow mapping: depth encoding, 4x4 PCF, bias (fixed, the encoding's default or auto),
// precision (highp or emulated mediump), map size, and the shadow map shown scaled for viewing in a
// corner.
#include "common.h"
#include "plan/snippets.h"

namespace penumbra::examples::exercises {

namespace {

// The shadow-mapped image, and the shadow map scaled for viewing, a quarter of the smaller side,
// in the top right corner.
void draw(Host& host, render::Settings s, render::FrameInputs in) {
    if (s.aov == render::Aov::StencilCount) s.aov = render::Aov::Color;  // no volumes here
    host.render(s, in);
    if (!host.toggles().map_view) return;
    const int width = host.width(), height = host.height();
    const int side = std::max(16, std::min(width, height) / 4);
    const int margin = std::max(2, side / 16);
    if (side + margin > width || side + margin > height) return;
    s.aov = render::Aov::LightDepth;
    in.output = render::Output::window_region(width - side - margin, height - side - margin, side, side);
    host.render(s, in, "map view");
}

}  // namespace

Exercise w09p2c() {
    const Control light = light_toggle(), jump = jump_toggle();
    Exercise x{"w09p2c", "W09P2c: Shadow mapping in the fragment shader",
         "Two passes: the depth seen from the light into a shadow map, then the scene from the camera, each fragment "
         "compared with the map at its light-space position. The map is shown scaled for visualisation in the top "
         "right corner. The bias starts on auto (the encoding's depth quantum plus the surface's slope): the sheet's "
         "constants (2^-8 + e = 0.005 for 8 bits, 0.0015 once mediump's 10 bits bound the packed value) leave rings "
         "of acne on the teapot where the light grazes it. Choose the sheet's bias to see them.",
         "The depth encodings (8-bit red, bit-shift RGBA, depth texture), 4x4 PCF, the bias and the map size, with the "
         "shadow map shown scaled for visualisation.",
         "The teapot on the table, shadowed by a shadow map, with the shadow map in the corner",
         "Choose the sheet's bias with 8-bit red: dark rings of acne appear on the teapot. Then tick PCF and "
         "watch the shadow's edge soften.",
         {light, jump,
          {"budget-ms", "Speed", K::Select, {}, "Faster or more accurate",
           "the map size, encoding and filter chosen from the frames' times (the settings below set aside)"},
          {"max-error", "Speed", K::Select, {}, "Error target",
           "the smallest map predicted within this share of the ray-traced truth, from the frame's shadow edges "
           "(the settings below set aside; one of this and the budget)"},
          {"encoding", "Shadow map", K::Select},
          {"filter", "Shadow map", K::Checkbox, {"pcf4x4", "hard"}, "4x4 PCF (percentage-closer filtering)",
           "16 lookups, texmapscale = 1/size apart: a softer edge"},
          {"bias", "Shadow map", K::Number, {}, {}, "added to the depth before the comparison"},
          {"map-faces", "Shadow map", K::Select, {}, {}, "the teapot is open: auto draws both sides"},
          {"precision", "Shadow map", K::Select, {}, {}, "mediump keeps about 10 bits, as a phone's GPU does"},
          {"map-size", "Shadow map", K::Select},
          {"aov", "View", K::Select, {"color", "visibility"}},
          {"map-view", "View", K::Checkbox, {"on", "off"}}}};
    x.draw = draw;
    // The course's map: fitted around what the camera sees, the table in it (where the sheet's
    // bias lessons show their acne), not only where the teapot's shadow falls (--light-fit shadows).
    // And a map of 1024 whatever the canvas: the 4x4 PCF's blur, texmapscale apart, is what the
    // sheet teaches, and auto's 2048 on a 748-pixel canvas (docs/resolution.md) leaves it under two
    // pixels wide. auto is one choice away in the select.
    x.defaults = {{"light-fit", "tight"}, {"map-size", "1024"}};
    x.modules = {render::shadow_map_module};
    x.lab = render::snippet_block;
    x.trade = course_trade;
    return x;
}

}  // namespace penumbra::examples::exercises
