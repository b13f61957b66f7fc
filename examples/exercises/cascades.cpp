// Cascaded shadow maps over a kilometre of terrain (scenes/terrain_scene.h) under a low sun: the
// number of cascades, the split, the snap, the blend, the cascades view, and a camera that flies
// (camera=x,y,z,yaw,pitch in the URL).
#include "common.h"
#include "scenes/terrain_scene.h"

namespace penumbra::examples::exercises {

Exercise cascades() {
    Exercise x{"cascades", "Cascaded shadow maps: a kilometre of terrain under a low sun",
         "One shadow map stretched over a kilometre gives each texel a quarter of a metre or more: near the camera, "
         "where a metre of ground fills much of the screen, the shadows turn to blocks (perspective aliasing). "
         "Cascades split the camera's depth range into slices, each with a shadow map of its own fitted around it, "
         "so the nearest slice gets texels of a few centimetres and the far ones cover the distance. The split "
         "places the slices' ends between uniform (0: equal depths) and logarithmic (1: equal ratios, near slices "
         "thin). Each cascade's window moves over the world in whole texels (snap), so the shadow's edges stay put "
         "as the camera moves instead of crawling; switch the snap off and walk to see them shimmer. Where one slice "
         "meets the next, the blend band fades one map's shadow into the other's, hiding the seam where the texel "
         "size jumps. The four maps are tiles of one texture (WebGL 1 has no texture arrays); the cascades view tints "
         "each pixel by the map that shadows it, and the plan below lists each slice's depths and texel size.",
         "Cascaded shadow maps for a sun over a kilometre of terrain: fly the camera, show the cascades, set their "
         "number and split, snap them to whole texels and blend across their seams.",
         "Hilly terrain with houses, poles and boulders under a low sun, shadowed by cascaded shadow maps",
         "Switch to one cascade and look at the pole's shadow in front of you: blocks. Back to four, then fly forward "
         "with snapping off and watch the shadow edges crawl.",
         {here_only({"cascades", "Cascades", K::Select, {"1", "2", "3", "4", "auto"}, "Cascades",
           "auto: one per factor of 8 in the depths seen"}),
          here_only({"cascade-split", "Cascades", K::Slider, {"0", "0.25", "0.5", "0.75", "0.9", "0.95", "1"}, "Split",
           "0 uniform, 1 logarithmic", 0.0, 1.0}),
          here_only({"cascade-snap", "Cascades", K::Checkbox, {"on", "off"}, "Snap to whole texels",
           "off: the edges shimmer as the camera moves"}),
          here_only({"cascade-blend", "Cascades", K::Slider, {"0", "0.05", "0.1", "0.2", "0.3", "0.5"}, "Blend",
           "of each slice faded into the next", 0.0, 0.5}),
          {"map-size", "Cascades", K::Select, {"512", "1024", "2048", "auto"}, "Map size",
           "each cascade's; auto: the largest the atlas holds in 64 MiB, for the near slice's ground"},
          {"aov", "View", K::Select, {"cascades", "color", "visibility"}, {},
           "cascades: red, green, blue, yellow from near to far"}},
         // 1024 each, what auto gives four cascades here too (the near slice asks for more than the
         // atlas's 64 MiB hold); auto is one choice away, and gives two cascades 2048 each.
         {{"cascades", "4"}, {"map-size", "1024"}, {"aov", "cascades"}}};
    x.make_scene = scene::make_terrain_km_scene;
    x.fly_bounds = terrain_fly_bounds;
    // Letters whose options it does not use.
    x.keys = {{'N', "cascades", "cascades: the number of cascades 1 / 2 / 3 / 4 / auto, Shift+N backwards"},
              {'K', "cascade-split", "cascades: split 0 / 0.25 / 0.5 / 0.75 / 0.9 / 0.95 / 1 (uniform .. logarithmic)"},
              {'G', "cascade-snap", "cascades: snap the windows to whole texels on / off"},
              {'B', "cascade-blend", "cascades: blend band 0 / 0.05 / 0.1 / 0.2 / 0.3 / 0.5 of a slice"}};
    x.draw = draw_own_scene;
    x.modules = {render::shadow_map_module};
    x.layouts = {render::cascades_layout};
    return x;
}

}  // namespace penumbra::examples::exercises
