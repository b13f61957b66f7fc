// A point light's cube of six shadow maps in a room (scenes/room_scene.h): the cube or one map, the
// map size, the filter, the cube's faces tinted, and the same fly camera, kept in the room.
#include "common.h"
#include "scenes/room_scene.h"

namespace penumbra::examples::exercises {

Exercise bulb() {
    Exercise x{"bulb", "A point light's cube: a bare bulb in a room",
         "One shadow map sees the scene through one frustum, and a point light in a room shines every way: whatever "
         "lies outside that frustum is lit, shadow or not. The cube gives the bulb six shadow maps instead, one for "
         "each face of a cube around it (+x, -x, +y, -y, +z, -z), each a perspective view of 90 degrees, so every "
         "direction from the bulb lands in exactly one face: the floor, the ceiling and the four walls all get their "
         "shadows. A fragment's direction from the light picks the face by its largest component and is looked up "
         "there. The six faces are kept two ways (Cube layout): as tiles of one 2D texture, 3 x 2, read with the "
         "same texture2D as every other map, each tile holding a guard band beyond its face's edge so a filter's "
         "taps near a seam still read real depth; or as the faces of a WebGL cube map, read with textureCube by the "
         "direction itself, whose taps past an edge land in the next face. Only the faces that see a receiver in "
         "view are drawn, and a face whose light and casters did not move is kept from the last frame. The faces "
         "view tints each pixel by the face that shadows it, and the plan below lists each face's pass.",
         "A point light's six shadow maps, the faces of a cube around a bare bulb in a room: show the faces, compare "
         "the cube with one shadow map, set the faces' size and the filter, fly around the room.",
         "A room with boxes and spheres on the floor, on stands and hanging from the ceiling, lit by a bare bulb "
         "whose shadows fall on every wall",
         "Switch to one map: the shadows on the walls behind you and on the ceiling vanish (outside its frustum, all is "
         "lit). Back to the cube, show the faces and fly up to the ceiling to see where they meet.",
         {here_only({"cascades", "Shadows", K::Select, {"cube", "1", "auto"}, "Shadow maps",
           "cube: six faces around the bulb; 1: one perspective map"}),
          {"map-size", "Shadows", K::Select, {"256", "512", "1024"}, "Map size", "each face's"},
          here_only({"cube-layout", "Shadows", K::Select, {"atlas", "cubemap"}, {},
           "atlas: six tiles of one 2D texture; cubemap: a WebGL cube map (not with a depth texture)"}),
          {"filter", "Shadows", K::Select, {"hard", "pcf4x4", "pcss"}, {}, "PCSS: the penumbra from the bulb's size"},
          {"light-radius", "Shadows", K::Slider, {"0", "0.02", "0.05", "0.1", "0.2"}, "Bulb radius",
           "metres; 0 is a point", 0.0, 0.2},
          {"aov", "View", K::Select, {"cascades", "color", "visibility"}, {},
           "cascades: each cube face tinted (+x red, -x green, +y blue, -y yellow, +z magenta, -z cyan)"}},
         {{"cascades", "cube"}, {"map-size", "512"}, {"light-radius", "0.05"}, {"aov", "cascades"}}};
    x.make_scene = scene::make_bulb_room_scene;
    x.fly_bounds = room_fly_bounds;
    // The same letter as the cascades' for its shadow maps; K its filter (F looks down here).
    x.keys = {{'N', "cascades", "bulb: shadow maps cube / one map / auto, Shift+N backwards"},
              {'K', "filter", "bulb: filter hard / PCF 4x4 / PCSS"},
              {'C', "cube-layout", "bulb: the cube's faces in an atlas / a cube map"}};
    x.draw = draw_own_scene;
    x.modules = {render::shadow_map_module};
    x.layouts = {render::cube_layout};
    return x;
}

}  // namespace penumbra::examples::exercises
