// Soft shadows from a light with a size: the radius, hard / PCF 4x4 / PCSS / Heckbert-Herf (light
// samples averaged, converging while the scene stands still), each technique, and a 256-sample
// reference to flip to.
#include "common.h"

namespace penumbra::examples::exercises {

namespace {

// One plan: the light samples accumulate over still frames.
void draw(Host& host, render::Settings s, render::FrameInputs in) {
    if (s.aov != render::Aov::Visibility) s.aov = render::Aov::Color;
    host.render(s, in);
}

// The methods exclude each other: a filter other than hard takes one light sample, more than one
// light sample the hard filter (the last one set wins).
void on_set(render::Settings& t, std::string_view name) {
    if (name == "filter" && t.filter != shadow::Filter::Hard) t.area_samples = 1;
    if (name == "area-samples" && t.area_samples > 1) t.filter = shadow::Filter::Hard;
}

// The reference: Heckbert-Herf with kReferenceSamples, whatever the method chosen.
void settings(const Toggles& toggles, render::Settings& s) {
    if (!toggles.reference) return;
    s.filter = shadow::Filter::Hard;
    s.area_samples = kReferenceSamples;
    s.area_per_frame = kReferencePerFrame;
    s.area_interleave = 1;
}

}  // namespace

Exercise soft() {
    const Control light = light_toggle(), jump = jump_toggle();
    Exercise x{"soft", "Soft shadows: lights with a size",
         "A real light has a size: seen from a point in its penumbra, part of it is hidden behind the teapot. Hard "
         "shadow mapping and PCF's fixed blur ignore that. PCSS estimates it from the shadow map: a blocker search "
         "finds the average depth of what lies between the point and the light, the light's size and that depth give "
         "the penumbra's width, and PCF filters over it. Heckbert-Herf renders the hard shadow from many points on "
         "the light and averages them: correct in the limit, and it works with each technique (shadow map, planar, "
         "shadow volumes); while nothing moves, each frame adds light samples, so the picture converges. The scene "
         "stands still (turn the light or the jump on to see a frame restart).",
         "Soft shadows from a light with a size: PCF's constant blur, PCSS and Heckbert-Herf's averaged light "
         "samples against a 256-sample reference, converging while the scene stands still.",
         "The teapot on the table with soft shadows from a light with a size",
         "The penumbra widens away from where the teapot touches the table: compare PCF's constant blur with "
         "PCSS and the averaged light samples, and flip to the reference.",
         {light, jump,
          {"light-radius", "Light", K::Slider, {}, {}, "world units; 0 is a point light", 0.0, 1.0},
          {"filter", "Method", K::Select, {"hard", "pcf4x4", "pcss"}, {}, "PCSS: the penumbra from the light's size"},
          {"area-samples", "Method", K::Select, {}, {},
           "Heckbert-Herf: more than 1 averages that many hard shadows (the filter goes back to hard)"},
          {"area-per-frame", "Method", K::Checkbox, {"4", "0"}, "Converge while still",
           "4 light samples added per frame while nothing moves; off: all of them every frame"},
          {"area-interleave", "Method", K::Select, {}, {},
           "Heckbert-Herf: neighbouring pixels take different light samples, filtered over the tile (no bands on "
           "thin casters); a still frame goes on until every pixel has them all"},
          {"reference", "Method", K::Checkbox, {"on", "off"}, {}, "flip between it and the method chosen"},
          {"pcss-search", "PCSS", K::Select, {}, {}, "taps finding the blockers' depth"},
          {"pcss-taps", "PCSS", K::Select, {}, {}, "taps filtering over the penumbra"},
          {"pcss-blockers", "PCSS", K::Select, {}, {},
           "layered: the blockers over the receiver size its penumbra; mean: every blocker found (Fernando's)"},
          here_only({"technique", "Shadows", K::Select, {}, {}, "Heckbert-Herf averages any of them; PCSS filters a shadow map"}),
          {"aov", "View", K::Select, {"color", "visibility"}}},
         {{"light", "off"}, {"jump", "off"}, {"light-radius", "0.3"}, {"filter", "pcss"}, {"area-per-frame", "4"}}};
    x.on_set = on_set;
    x.settings = settings;
    x.draw = draw;
    x.modules = {render::shadow_map_module, render::planar_module, render::volumes_module, render::gooch_module};
    x.frames = {render::area_light_shape};
    return x;
}

}  // namespace penumbra::examples::exercises
