#include "exercise_list.h"

#include <algorithm>
#include <stdexcept>


namespace penumbra::examples {

using render::Choice;
using render::OptionInfo;
using render::OptionPart;
using render::OptionType;

namespace {

OptionInfo toggle(std::string_view name, std::string_view help, std::string_view label, std::vector<Choice> choices) {
    return render::make_option_info(name, OptionPart::Technique, OptionType::Choice, help, label, std::move(choices));
}

const std::vector<Choice> kOnOff = {{"on", "on"}, {"off", "off"}};

std::vector<render::Option<Toggles>> make_toggles() {
    std::vector<render::Option<Toggles>> t;
    t.push_back({toggle("light", "the light circles the table", "Light circulation", kOnOff),
                 [](Toggles& g, std::string_view v) { g.light = v == "on"; },
                 [](const Toggles& g) { return std::string(g.light ? "on" : "off"); }});
    t.push_back({toggle("jump", "the teapot jumps", "Teapot jump", kOnOff),
                 [](Toggles& g, std::string_view v) { g.jump = v == "on"; },
                 [](const Toggles& g) { return std::string(g.jump ? "on" : "off"); }});
    t.push_back({toggle("projection", "W09P2a: the light's projection", "Light projection",
                        {{"persp", "perspective (point light)"}, {"ortho", "orthographic (directional light)"}}),
                 [](Toggles& g, std::string_view v) { g.ortho = v == "ortho"; },
                 [](const Toggles& g) { return std::string(g.ortho ? "ortho" : "persp"); }});
    t.push_back({toggle("fbo-view", "W09P2b: what is rendered into the off-screen buffer", "The buffer holds",
                        {{"light", "the view from the light"}, {"camera", "the camera's view"}}),
                 [](Toggles& g, std::string_view v) { g.fbo_light = v == "light"; },
                 [](const Toggles& g) { return std::string(g.fbo_light ? "light" : "camera"); }});
    t.push_back({toggle("rtt", "W09P2b: how the picture gets into the texture", "Render to texture",
                        {{"fbo", "a framebuffer object"},
                         {"copy", "copied from the window (glCopyTexImage2D)"}}),
                 [](Toggles& g, std::string_view v) { g.rtt_copy = v == "copy"; },
                 [](const Toggles& g) { return std::string(g.rtt_copy ? "copy" : "fbo"); }});
    t.push_back({toggle("map-view", "W09P2c: the shadow map, scaled for viewing, in the top right corner",
                        "the shadow map, scaled for viewing", kOnOff),
                 [](Toggles& g, std::string_view v) { g.map_view = v == "on"; },
                 [](const Toggles& g) { return std::string(g.map_view ? "on" : "off"); }});
    t.push_back({toggle("reference",
                        "soft: the reference instead of the method chosen: Heckbert-Herf, 256 light samples, "
                        "converging while nothing moves",
                        "Reference: 256 light samples (Heckbert-Herf)", kOnOff),
                 [](Toggles& g, std::string_view v) { g.reference = v == "on"; },
                 [](const Toggles& g) { return std::string(g.reference ? "on" : "off"); }});
    return t;
}

using K = ControlKind;

std::vector<ExerciseInfo> make_list() {
    const Control light{"light", "Animation", K::Toggle};
    const Control jump{"jump", "Animation", K::Toggle};
    return {
        {Exercise::W09P1, "w09p1", "W09P1: Jumping teapot on a marble table top",
         "The Newell teapot jumps on a marble table top under a point light circling above it. The teapot and the "
         "ground are drawn with different shader programs (the ground textured with the marble); the teapot casts its "
         "planar projected shadow on the table, counted once per pixel in the stencil buffer.",
         "The teapot and the ground drawn with different shader programs; the teapot's planar projected shadow; "
         "buttons for the light's circulation and the teapot's jump.",
         "The teapot on the marble table with its planar projected shadow",
         "Switch the jump off: the teapot lands and its shadow meets its base. Watch the shadow stay flat on "
         "the table as the light circles.",
         render::Technique::Planar, {light, jump}},
        {Exercise::W09P2a, "w09p2a", "W09P2a: Rendering from the point of view of the light source",
         "The scene drawn with the light's own projection and view matrices, the view volume a tight bound around the "
         "table and the teapot: a perspective projection for the point light, an orthographic one for a directional "
         "light along the same line of sight.",
         "The light's own projection and view matrices fitted tightly around the scene: perspective for the point "
         "light, orthographic for a directional one.",
         "The scene seen from the light",
         "Switch between perspective and orthographic: the point light's view spreads out from the light and "
         "makes the near end of the table look larger; the directional light's lines stay parallel.",
         render::Technique::None,
         {light, jump, {"projection", "Light projection", K::Radio}}},
        {Exercise::W09P2b, "w09p2b", "W09P2b: Drawing to an off-screen buffer",
         "Each frame the scene is first rendered into a framebuffer object (a colour texture with a depth "
         "renderbuffer), then drawn from the camera with that texture applied to the ground quad.",
         "The scene rendered into a framebuffer object, and that texture applied to the ground quad.",
         "The scene with the off-screen buffer's picture on the ground quad",
         "The table shows what the off-screen buffer holds; set its texture size to 256 and the picture turns "
         "blocky.",
         render::Technique::None,
         {light, jump, {"fbo-view", "Off-screen buffer", K::Select},
          {"rtt", "Off-screen buffer", K::Radio, {}, {}, "a copy is no larger than the window"},
          {"map-size", "Off-screen buffer", K::Select, {"256", "512", "1024", "2048"}, "Texture size"}}},
        {Exercise::W09P2c, "w09p2c", "W09P2c: Shadow mapping in the fragment shader",
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
         render::Technique::ShadowMap,
         {light, jump, {"encoding", "Shadow map", K::Select},
          {"filter", "Shadow map", K::Checkbox, {"pcf4x4", "hard"}, "4x4 PCF (percentage-closer filtering)",
           "16 lookups, texmapscale = 1/size apart: a softer edge"},
          {"bias", "Shadow map", K::Number, {}, {}, "added to the depth before the comparison"},
          {"map-faces", "Shadow map", K::Select, {}, {}, "the teapot is open: auto draws both sides"},
          {"precision", "Shadow map", K::Select, {}, {}, "mediump keeps about 10 bits, as a phone's GPU does"},
          {"map-size", "Shadow map", K::Select},
          {"aov", "View", K::Select, {"color", "visibility"}},
          {"map-view", "View", K::Checkbox, {"on", "off"}}}},
        {Exercise::Volumes, "volumes", "Shadow volumes: counting shadows in the stencil buffer",
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
         render::Technique::Volumes,
         {light, jump,
          {"volume-method", "Shadow volumes", K::Select, {}, {}, "depth-pass fails when the eye is inside a volume"},
          {"show-volumes", "Shadow volumes", K::Checkbox, {"on", "off"}},
          {"eye", "Shadow volumes", K::Checkbox, {"in-shadow", "scene"}, "Move the eye into a shadow",
           "the eye inside the teapot's shadow, looking across it"},
          {"aov", "View", K::Select, {"color", "visibility", "stencil-count"}, {},
           "stencil count: 1 blue, 2 green, 3 yellow, 4 orange, 5 magenta, 6 white; below zero red"}}},
        {Exercise::Soft, "soft", "Soft shadows: lights with a size",
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
         render::Technique::ShadowMap,
         {light, jump,
          {"light-radius", "Light", K::Slider, {}, {}, "world units; 0 is a point light", 0.0, 1.0},
          {"filter", "Method", K::Select, {"hard", "pcf4x4", "pcss"}, {}, "PCSS: the penumbra from the light's size"},
          {"area-samples", "Method", K::Select, {}, {},
           "Heckbert-Herf: more than 1 averages that many hard shadows (the filter goes back to hard)"},
          {"area-per-frame", "Method", K::Checkbox, {"4", "0"}, "Converge while still",
           "4 light samples added per frame while nothing moves; off: all of them every frame"},
          {"reference", "Method", K::Checkbox, {"on", "off"}, {}, "flip between it and the method chosen"},
          {"pcss-search", "PCSS", K::Select, {}, {}, "taps finding the blockers' depth"},
          {"pcss-taps", "PCSS", K::Select, {}, {}, "taps filtering over the penumbra"},
          {"technique", "Shadows", K::Select, {}, {}, "Heckbert-Herf averages any of them; PCSS filters a shadow map"},
          {"aov", "View", K::Select, {"color", "visibility"}}},
         {{"light", "off"}, {"jump", "off"}, {"light-radius", "0.3"}, {"filter", "pcss"}, {"area-per-frame", "4"}}},
        {Exercise::Stencil, "stencil", "Stencil effects: outline, mirror, portal",
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
         render::Technique::ShadowMap,
         {light, jump,
          {"effects", "Effects", K::Select, {"outline", "none", "mirror", "outline,mirror", "portal", "outline,mirror,portal"}, {},
           "each marks its pixels in a stencil bit of its own"},
          {"outline-width", "Outline", K::Slider, {"1", "2", "3", "5", "8", "12", "16"}, {},
           "pixels, the same at any depth", 0.5, 16.0},
          {"outline-color", "Outline", K::Select},
          {"reflectivity", "Mirror", K::Slider, {"0.25", "0.5", "0.75", "1"}, {},
           "of the table's colour is the reflection", 0.0, 1.0},
          {"technique", "Shadows", K::Select, {"shadowmap", "planar", "volumes", "none"}, {},
           "planar and volumes keep their shadows in the stencil too"}},
         {{"effects", "outline"}}},
        {Exercise::Multipass, "multipass", "Multipass: blur, bloom, a blurred shadow, and deferred shading",
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
         render::Technique::ShadowMap,
         {light, jump,
          {"post", "Post-processing", K::Select, {"shadow-blur:6", "none", "blur:4", "bloom:0.6", "shadow-blur:6,bloom:0.6"},
           {}, "each pass reads the last one's target"},
          {"technique", "Shadows", K::Select, {"shadowmap", "planar", "volumes"}, {}, "any of them blurred"},
          {"aov", "View", K::Select,
           {"color", "visibility", "gbuffer-color", "gbuffer-normal", "gbuffer-position", "gbuffer-depth"}, {},
           "the shadow alone, or the G-buffer"},
          {"shading", "Shading", K::Select, {"forward", "deferred"}, {}, "deferred: a G-buffer, then the lights"},
          {"lights", "Shading", K::Slider, {"0", "8", "32", "64", "128", "256"}, {}, "unshadowed", 0.0, 256.0}},
         {{"post", "shadow-blur:6"}}},
        {Exercise::Cascades, "cascades", "Cascaded shadow maps: a kilometre of terrain under a low sun",
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
         render::Technique::ShadowMap,
         {{"cascades", "Cascades", K::Select, {"1", "2", "3", "4", "auto"}, "Cascades",
           "auto: one per factor of 8 in the depths seen"},
          {"cascade-split", "Cascades", K::Slider, {"0", "0.25", "0.5", "0.75", "0.9", "1"}, "Split",
           "0 uniform, 1 logarithmic", 0.0, 1.0},
          {"cascade-snap", "Cascades", K::Checkbox, {"on", "off"}, "Snap to whole texels",
           "off: the edges shimmer as the camera moves"},
          {"cascade-blend", "Cascades", K::Slider, {"0", "0.05", "0.1", "0.2", "0.3", "0.5"}, "Blend",
           "of each slice faded into the next", 0.0, 0.5},
          {"map-size", "Cascades", K::Select, {"512", "1024", "2048"}, "Map size", "each cascade's"},
          {"aov", "View", K::Select, {"cascades", "color", "visibility"}, {},
           "cascades: red, green, blue, yellow from near to far"}},
         {{"cascades", "4"}, {"aov", "cascades"}},
         ExerciseScene::Terrain},
        {Exercise::Bulb, "bulb", "A point light's cube: a bare bulb in a room",
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
         render::Technique::ShadowMap,
         {{"cascades", "Shadows", K::Select, {"cube", "1", "auto"}, "Shadow maps",
           "cube: six faces around the bulb; 1: one perspective map"},
          {"map-size", "Shadows", K::Select, {"256", "512", "1024"}, "Map size", "each face's"},
          {"cube-layout", "Shadows", K::Select, {"atlas", "cubemap"}, {},
           "atlas: six tiles of one 2D texture; cubemap: a WebGL cube map (not with a depth texture)"},
          {"filter", "Shadows", K::Select, {"hard", "pcf4x4", "pcss"}, {}, "PCSS: the penumbra from the bulb's size"},
          {"light-radius", "Shadows", K::Slider, {"0", "0.02", "0.05", "0.1", "0.2"}, "Bulb radius",
           "metres; 0 is a point", 0.0, 0.2},
          {"aov", "View", K::Select, {"cascades", "color", "visibility"}, {},
           "cascades: each cube face tinted (+x red, -x green, +y blue, -y yellow, +z magenta, -z cyan)"}},
         {{"cascades", "cube"}, {"map-size", "512"}, {"light-radius", "0.05"}, {"aov", "cascades"}},
         ExerciseScene::Room},
    };
}

}  // namespace

const std::vector<render::Option<Toggles>>& toggle_table() {
    static const auto table = make_toggles();
    return table;
}

const std::vector<ExerciseInfo>& exercise_list() {
    static const auto list = make_list();
    return list;
}

bool offers(const ExerciseInfo& x, std::string_view option) {
    return std::any_of(x.controls.begin(), x.controls.end(), [&](const Control& c) { return c.option == option; });
}

const ExerciseInfo& exercise_info(Exercise e) {
    for (const auto& x : exercise_list())
        if (x.id == e) return x;
    throw std::logic_error("exercise_info: unknown exercise");
}

bool parse_exercise(std::string_view name, Exercise& out) {
    for (const auto& x : exercise_list())
        if (x.name == name) {
            out = x.id;
            return true;
        }
    return false;
}

std::string exercise_names() {
    std::string s;
    for (const auto& x : exercise_list()) s += (s.empty() ? "" : ", ") + std::string(x.name);
    return s;
}

const std::vector<KeyBinding>& key_bindings() {
    static const std::vector<KeyBinding> keys = {
        {'L', "light", "light circulation on/off"},
        {'J', "jump", "the teapot's jump on/off"},
        {'O', "projection", "W09P2a: light projection perspective (point light) / orthographic (directional)"},
        {'V', "fbo-view", "W09P2b: the FBO holds the view from the light / from the camera"},
        {'E', "encoding", "W09P2c: next depth encoding (r8, rgba, depthtex where the context has it)"},
        {'F', "filter", "W09P2c: 4x4 PCF on/off (soft: hard / PCF 4x4 / PCSS)"},
        {'R', "precision", "W09P2c: precision highp / emulated mediump (fp16 along the depth path, as on a phone)"},
        {'M', "map-size", "shadow map size (W09P2b: FBO size), Shift+M backwards"},
        {'A', "aov", "W09P2c, soft: view colour / visibility (volumes: / stencil count)"},
        {'S', "map-view", "W09P2c: shadow map view on/off"},
        {'Z', "volume-method", "volumes: method auto / depth-pass (zpass) / depth-fail (zfail)"},
        {'G', "show-volumes", "volumes: show the volumes on/off"},
        {'I', "eye", "volumes: the eye inside the teapot's shadow / the scene's camera"},
        {'N', "area-samples", "soft: light samples (Heckbert-Herf) 1 / 4 / 16 / 64 / 256, Shift+N backwards"},
        {'C', "area-per-frame", "soft: converge while still (4 light samples a frame) / all samples every frame"},
        {'X', "reference", "soft: the reference (256 light samples) / the method chosen"},
        {'T', "technique", "soft, stencil: next technique (shadow map, planar, volumes, ...)"},
        {'K', "pcss-taps", "soft: PCSS filter taps 8 / 16 / 32 / 64"},
        {'Y', "effects", "stencil: effects outline / none / mirror / outline and mirror / portal / all three"},
        {'W', "outline-width", "stencil: outline width 1 / 2 / 3 / 5 / 8 / 12 / 16 px, Shift+W backwards"},
        {'D', "outline-color", "stencil: next outline colour (orange, yellow, cyan, magenta)"},
        {'Q', "reflectivity", "stencil: mirror reflectivity 0.25 / 0.5 / 0.75 / 1, Shift+Q backwards"},
        {'0', "post", "multipass: post-processing shadow blur / none / blur / bloom / shadow blur and bloom"},
        {'9', "shading", "multipass: forward / deferred shading"},
        {',', "lights", "multipass: point lights 0 / 8 / 32 / 64 / 128 / 256, Shift+, backwards"},
        {'.', "rtt", "W09P2b: render to texture through an FBO / in the window, then glCopyTexImage2D"},
        // The cascades exercise: letters whose options it does not use.
        {'N', "cascades", "cascades: the number of cascades 1 / 2 / 3 / 4 / auto, Shift+N backwards", Exercise::Cascades},
        {'K', "cascade-split", "cascades: split 0 / 0.25 / 0.5 / 0.75 / 0.9 / 1 (uniform .. logarithmic)",
         Exercise::Cascades},
        {'G', "cascade-snap", "cascades: snap the windows to whole texels on / off", Exercise::Cascades},
        {'B', "cascade-blend", "cascades: blend band 0 / 0.05 / 0.1 / 0.2 / 0.3 / 0.5 of a slice", Exercise::Cascades},
        // The bulb exercise: the same letter for its shadow maps; K its filter (F looks down there).
        {'N', "cascades", "bulb: shadow maps cube / one map / auto, Shift+N backwards", Exercise::Bulb},
        {'K', "filter", "bulb: filter hard / PCF 4x4 / PCSS", Exercise::Bulb},
        {'C', "cube-layout", "bulb: the cube's faces in an atlas / a cube map", Exercise::Bulb},
    };
    return keys;
}

}  // namespace penumbra::examples
