// The option table: every option's entry (name, part, type, help, label, choices, range) with
// how it is stored in and printed from render::Options. The rules that check and parse the values
// are options.cpp's; the table's order is the printing order (--help, -v, to_args).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "plan/options.h"
#include "plan/post.h"

// A browser page never shows an option's help: its controls carry their own hints, and the
// pages' tooltips come from the catalogue, which is built with it. So a page's module keeps only
// a text option's, which messages quote as what its value may be (web/CMakeLists.txt sets
// PENUMBRA_OPTION_HELP=0 for the pages' library; the help's literals then fold away).
#ifndef PENUMBRA_OPTION_HELP
#define PENUMBRA_OPTION_HELP 1
#endif
#if !PENUMBRA_OPTION_HELP
#define make_option_info(name, part, type, help, ...)                                                        \
    make_option_info(name, part, type, (type) == OptionType::Text ? std::string_view(help) : std::string_view(), \
                     __VA_ARGS__)
#endif

namespace penumbra::render {
namespace {

template <typename E, size_t N>
E enum_of(std::string_view v, const E (&all)[N]) {
    for (E e : all)
        if (to_string(e) == v) return e;
    return all[0];  // unreachable: check_value accepted v among the choices
}

int int_of(std::string_view v) {
    int x = 0;
    parse_int(v, x);
    return x;
}

double number_of(std::string_view v) {
    double x = 0.0;
    parse_number(v, x);
    return x;
}

std::vector<Option<Options>> make_table() {
    using P = OptionPart;
    using T = OptionType;
    std::vector<Option<Options>> t;
    const auto add = [&](OptionInfo info, void (*store)(Options&, std::string_view), std::string (*print)(const Options&)) {
        t.push_back({std::move(info), store, print});
    };

    OptionInfo scene = make_option_info("scene", P::Job, T::Text,
                                        "teapot (the course scene), FILE.gltf / FILE.glb, or pile:N / forest:N "
                                        "(N pyramids; :spot or :sun for another light)",
                                        "Scene");
    add(scene, [](Options& o, std::string_view v) { o.job.scene = std::string(v); },
        [](const Options& o) { return o.job.scene; });

    OptionInfo time = make_option_info("time", P::Job, T::Number, "seconds; the animation is a pure function of t", "Time (s)");
    time.min = -kMaxTime;
    time.max = kMaxTime;
    add(time, [](Options& o, std::string_view v) { o.job.time = number_of(v); },
        [](const Options& o) { return format_number(o.job.time); });

    OptionInfo size = make_option_info("size", P::Job, T::Size, "WxH of the image", "Image size");
    size.min = 1;
    size.max = kMaxImageSide;
    add(size, [](Options& o, std::string_view v) { parse_size(v, o.job.width, o.job.height); },
        [](const Options& o) { return std::to_string(o.job.width) + "x" + std::to_string(o.job.height); });

    OptionInfo encoding = make_option_info("encoding", P::Technique, T::Choice, "the depth in the shadow map", "Depth encoding",
                        {{"r8", "8-bit: the red channel only (r8)"}, {"rgba", "bit-shift packing into RGBA (rgba)"}, {"depthtex", "depth texture (depthtex)"}});
    add(encoding, [](Options& o, std::string_view v) { o.settings.encoding = enum_of(v, shadow::kAllEncodings); },
        [](const Options& o) { return std::string(shadow::to_string(o.settings.encoding)); });

    OptionInfo filter = make_option_info("filter", P::Technique, T::Choice, "percentage-closer filtering of the lookup", "Filter",
                      {{"hard", "hard: one tap"}, {"pcf2x2", "2x2 PCF"}, {"pcf4x4", "4x4 PCF"},
                       {"pcss", "PCSS: penumbra from the light's size"}});
    add(filter, [](Options& o, std::string_view v) { o.settings.filter = enum_of(v, shadow::kAllFilters); },
        [](const Options& o) { return std::string(shadow::to_string(o.settings.filter)); });

    OptionInfo pcf_kernel = make_option_info("pcf-kernel", P::Technique, T::Choice,
                          "how pcf4x4 reads its 16 taps: the 4 corners first, the rest only where they disagree "
                          "(early-exit), or always all (full, the course's kernel)",
                          "PCF kernel",
                          {{"early-exit", "early exit: the 4 corner taps first"}, {"full", "full: every tap"}});
    add(pcf_kernel, [](Options& o, std::string_view v) { o.settings.pcf_kernel = enum_of(v, shadow::kAllPcfKernels); },
        [](const Options& o) { return std::string(shadow::to_string(o.settings.pcf_kernel)); });

    OptionInfo map_size = make_option_info("map-size", P::Technique, T::Integer,
                                           "shadow map width = height in texels; auto = matched to the screen: two texels "
                                           "a pixel on average over the receivers in view, one over 90% of them, rounded up by "
                                           "eighths of an octave (a cube's faces or cascades: a power of two, each matched, all at "
                                           "the size the most asking wants)",
                                           "Shadow map size", {{"auto", "auto: matched to the screen"}});
    map_size.min = 1;
    map_size.max = kMaxMapSize;
    map_size.presets = {{"256", "256 x 256"}, {"512", "512 x 512"}, {"1024", "1024 x 1024"}, {"2048", "2048 x 2048"},
                        {"4096", "4096 x 4096"}, {"auto", "auto: matched to the screen"}};
    add(map_size,
        [](Options& o, std::string_view v) { o.settings.map_size = v == "auto" ? Settings::kAutoMapSize : int_of(v); },
        [](const Options& o) {
            return o.settings.map_size == Settings::kAutoMapSize ? std::string("auto") : std::to_string(o.settings.map_size);
        });

    OptionInfo cascades = make_option_info("cascades", P::Technique, T::Choice,
                         "cascaded shadow maps for a directional light: the camera's depth range split into N maps "
                         "of --map-size each, side by side in one atlas (near slices get the finer texels); cube = "
                         "a point light's six faces (omnidirectional), each --map-size; auto = from the scene, the "
                         "camera and the light (cascades: one per factor of 8 in the depth range seen; a cube: a "
                         "point light inside the scene, or a point or spot light lighting receivers in view beyond one "
                         "map's 75 degrees a side, a spot's only the faces its cone reaches); 1 = one map",
                         "Cascades",
                         {{"1", "1 (one map)"}, {"2", "2"}, {"3", "3"}, {"4", "4"}, {"cube", "cube (point light)"}, {"auto", "auto"}});
    add(cascades,
        [](Options& o, std::string_view v) {
            o.settings.cascades = v == "auto" ? 0 : v == "cube" ? Settings::kCube : int_of(v);
        },
        [](const Options& o) {
            const int n = o.settings.cascades;
            return n == 0 ? std::string("auto") : n == Settings::kCube ? std::string("cube") : std::to_string(n);
        });

    OptionInfo cascade_split = make_option_info("cascade-split", P::Technique, T::Number,
                         "--cascades: where the slices end, a blend of logarithmic (1: equal depth ratios) and uniform "
                         "(0: equal lengths) splits", "Cascade split");
    cascade_split.min = 0.0;
    cascade_split.max = 1.0;
    cascade_split.step = 0.05;
    add(cascade_split, [](Options& o, std::string_view v) { o.settings.cascade_split = static_cast<float>(number_of(v)); },
        [](const Options& o) { return shortest_float(o.settings.cascade_split); });

    OptionInfo cascade_snap = make_option_info("cascade-snap", P::Technique, T::Choice,
                         "--cascades: each cascade's window moved by whole texels only, so the shadow's edges do not "
                         "shimmer as the camera moves (off: shown for contrast)", "Snap to texels",
                         {{"on", "on"}, {"off", "off"}});
    add(cascade_snap, [](Options& o, std::string_view v) { o.settings.cascade_snap = v == "on"; },
        [](const Options& o) { return std::string(o.settings.cascade_snap ? "on" : "off"); });

    OptionInfo cascade_blend = make_option_info("cascade-blend", P::Technique, T::Number,
                         "--cascades: the share of each slice, at its far end, where its shadow fades into the next "
                         "cascade's (0: a hard seam)", "Cascade blend");
    cascade_blend.min = 0.0;
    cascade_blend.max = 0.5;
    cascade_blend.step = 0.05;
    add(cascade_blend, [](Options& o, std::string_view v) { o.settings.cascade_blend = static_cast<float>(number_of(v)); },
        [](const Options& o) { return shortest_float(o.settings.cascade_blend); });

    OptionInfo cube_layout = make_option_info("cube-layout", P::Technique, T::Choice,
                         "--cascades cube: the six faces as tiles of one 2D texture, 3 x 2, each a little wider than "
                         "90 degrees for the filter's taps at its edges (atlas), or the faces of a GL cube map read "
                         "with textureCube, whose taps past an edge read the next face (cubemap; rgba and r8 "
                         "encodings only)", "Cube layout",
                         {{"atlas", "atlas (3 x 2 tiles)"}, {"cubemap", "cube map"}});
    add(cube_layout, [](Options& o, std::string_view v) { o.settings.cube_map = v == "cubemap"; },
        [](const Options& o) { return std::string(o.settings.cube_map ? "cubemap" : "atlas"); });

    OptionInfo bias = make_option_info("bias", P::Technique, T::NumberOrWord,
                    "depth offset: 'auto' (the encoding's quantum + the receiver's slope), 'sheet' (the exercise sheet's constant: r8 0.005, rgba and depthtex 0.0015) or a number",
                    "Bias", {{"auto", "auto: from the packing's precision and the surface's slope"}, {"sheet", "the sheet's constant"}});
    bias.min = 0.0;
    bias.max = 1.0;
    bias.step = 0.0005;
    add(bias,
        [](Options& o, std::string_view v) {
            o.settings.bias_auto = v == "auto";
            if (v == "sheet" || v == "auto") o.settings.bias.reset();
            else o.settings.bias = static_cast<float>(number_of(v));
        },
        [](const Options& o) {
            const Settings& s = o.settings;
            return s.bias_auto ? std::string("auto") : s.bias ? shortest_float(*s.bias) : "sheet";
        });

    OptionInfo map_faces = make_option_info("map-faces", P::Technique, T::Choice,
                         "which faces of each caster go into the shadow map: auto = back faces of closed meshes (no "
                         "self-shadowing of lit surfaces), both faces of open ones", "Faces in the map",
                         {{"auto", "auto: back faces of closed meshes, both of open ones"},
                          {"front", "front faces (towards the light)"},
                          {"back", "back faces (away from the light)"},
                          {"both", "both faces"}});
    add(map_faces, [](Options& o, std::string_view v) { o.settings.map_faces = enum_of(v, kAllMapFaces); },
        [](const Options& o) { return std::string(to_string(o.settings.map_faces)); });

    OptionInfo light_fit = make_option_info("light-fit", P::Technique, T::Choice,
                         "the light's frustum: shadows = where the casters' shadows can fall on the receivers the "
                         "camera sees, drawing only the casters that shadow one; tight = around the receivers the "
                         "camera sees and every caster in front of them (the course's map, the table in it); scene = "
                         "around the whole scene", "Light frustum",
                         {{"shadows", "shadows: where they fall"}, {"tight", "tight: what the camera sees"},
                          {"scene", "the whole scene"}});
    add(light_fit, [](Options& o, std::string_view v) { o.settings.light_fit = enum_of(v, kAllLightFits); },
        [](const Options& o) { return std::string(to_string(o.settings.light_fit)); });

    OptionInfo precision = make_option_info("precision", P::Technique, T::Choice,
                         "mediump: emulated fp16 along the depth path, as a phone computes it", "Precision",
                         {{"highp", "highp (float32)"}, {"mediump", "mediump, emulated (fp16, as on a phone)"}});
    add(precision,
        [](Options& o, std::string_view v) {
            constexpr shadow::Precision all[] = {shadow::Precision::Highp, shadow::Precision::Mediump};
            o.settings.precision = enum_of(v, all);
        },
        [](const Options& o) { return std::string(shadow::to_string(o.settings.precision)); });

    OptionInfo volume_method = make_option_info("volume-method", P::Technique, T::Choice,
                         "shadow volumes: auto = depth-pass where no volume can reach the eye's near plane, depth-fail "
                         "elsewhere; zpass = depth-pass (Heidmann), fails with the eye in a shadow; zfail = depth-fail "
                         "(Carmack's reverse) with caps", "Volume method",
                         {{"auto", "auto: depth-pass unless the eye may be in a shadow"},
                          {"zpass", "depth-pass (counts in front of the surface)"},
                          {"zfail", "depth-fail (counts behind the surface)"}});
    add(volume_method, [](Options& o, std::string_view v) { o.settings.volume_method = enum_of(v, kAllVolumeMethods); },
        [](const Options& o) { return std::string(to_string(o.settings.volume_method)); });

    OptionInfo show_volumes = make_option_info("show-volumes", P::Technique, T::Choice,
                         "shadow volumes: draw them translucent over the image (faces towards the eye orange, away blue)",
                         "Show the volumes", {{"off", "off"}, {"on", "on"}});
    add(show_volumes, [](Options& o, std::string_view v) { o.settings.show_volumes = v == "on"; },
        [](const Options& o) { return std::string(o.settings.show_volumes ? "on" : "off"); });

    OptionInfo light_radius = make_option_info("light-radius", P::Technique, T::NumberOrWord,
                         "the light's size for soft shadows: a sphere's radius in world units (point, spot) or the "
                         "sun's angular radius in radians (directional); 'scene' = the scene's (glTF light extras "
                         "penumbra.radius; the course scene's is 0); 0 = a point light",
                         "Light radius", {{"scene", "the scene's"}});
    light_radius.min = 0.0;
    light_radius.max = kMaxLightRadius;
    light_radius.step = 0.01;
    add(light_radius,
        [](Options& o, std::string_view v) {
            if (v == "scene") o.settings.light_radius.reset();
            else o.settings.light_radius = static_cast<float>(number_of(v));
        },
        [](const Options& o) {
            return o.settings.light_radius ? shortest_float(*o.settings.light_radius) : std::string("scene");
        });

    OptionInfo pcss_search = make_option_info("pcss-search", P::Technique, T::Integer,
                         "--filter pcss: taps of the blocker search (a Vogel disc turned per pixel)", "PCSS search taps");
    pcss_search.min = 1;
    pcss_search.max = 64;
    pcss_search.presets = {{"8", "8"}, {"16", "16"}, {"32", "32"}};
    add(pcss_search, [](Options& o, std::string_view v) { o.settings.pcss_search = int_of(v); },
        [](const Options& o) { return std::to_string(o.settings.pcss_search); });

    OptionInfo pcss_taps = make_option_info("pcss-taps", P::Technique, T::Integer,
                         "--filter pcss: taps of the filter over the penumbra's width", "PCSS filter taps");
    pcss_taps.min = 1;
    pcss_taps.max = 64;
    pcss_taps.presets = {{"8", "8"}, {"16", "16"}, {"32", "32"}, {"64", "64"}};
    add(pcss_taps, [](Options& o, std::string_view v) { o.settings.pcss_taps = int_of(v); },
        [](const Options& o) { return std::to_string(o.settings.pcss_taps); });

    OptionInfo pcss_blockers = make_option_info(
        "pcss-blockers", P::Technique, T::Choice,
        "--filter pcss: which blockers size the penumbra: layered = those inside the cone from the receiver to the "
        "light at their own depth, beyond the receiver's plane (stacked casters, a pole's foot); mean = the mean depth "
        "of every tap nearer than the receiver (Fernando 2005)",
        "PCSS blockers", {{"layered", "layered: the blockers over the receiver"}, {"mean", "mean of all blockers"}});
    add(pcss_blockers, [](Options& o, std::string_view v) { o.settings.pcss_layered = v == "layered"; },
        [](const Options& o) { return std::string(o.settings.pcss_layered ? "layered" : "mean"); });

    OptionInfo area_samples = make_option_info("area-samples", P::Technique, T::Integer,
                         "Heckbert-Herf soft shadows: the technique run for N points on the light (stratified, the "
                         "same every frame), the visibilities averaged; 1 = the light's centre (hard)",
                         "Light samples");
    area_samples.min = 1;
    area_samples.max = kMaxAreaSamples;
    area_samples.presets = {{"1", "1 (hard)"}, {"4", "4"}, {"16", "16"}, {"64", "64"}, {"256", "256"}};
    add(area_samples, [](Options& o, std::string_view v) { o.settings.area_samples = int_of(v); },
        [](const Options& o) { return std::to_string(o.settings.area_samples); });

    OptionInfo area_per_frame = make_option_info("area-per-frame", P::Technique, T::Integer,
                         "with --area-samples: 0 = all samples every frame; K = a still frame adds K samples per frame "
                         "until all are in (converges while nothing moves)", "Samples per frame");
    area_per_frame.min = 0;
    area_per_frame.max = kMaxAreaSamples;
    area_per_frame.presets = {{"0", "all (no progressive)"}, {"1", "1"}, {"4", "4"}, {"16", "16"}};
    add(area_per_frame, [](Options& o, std::string_view v) { o.settings.area_per_frame = int_of(v); },
        [](const Options& o) { return std::to_string(o.settings.area_per_frame); });

    OptionInfo area_interleave = make_option_info("area-interleave", P::Technique, T::Choice,
                         "with --area-samples N: interleaved sampling, the image tiled K x K and each pixel of a tile "
                         "counting a different N / K^2 of the samples per round, filtered over the tile (most of the "
                         "bands of thin casters' shadow copies go); a still frame adds the other rounds until every "
                         "pixel has all N (then the same image as 1); 1 = off", "Interleave",
                         {{"1", "1 (off)"}, {"2", "2 x 2"}, {"4", "4 x 4"}});
    add(area_interleave, [](Options& o, std::string_view v) { o.settings.area_interleave = int_of(v); },
        [](const Options& o) { return std::to_string(o.settings.area_interleave); });

    OptionInfo gooch_planes = make_option_info("gooch-planes", P::Technique, T::Integer,
                         "--technique gooch: how many receiving planes, offset towards and away from the light by up "
                         "to a spread from the light's radius, are averaged (texture: taps); 1 = the planar shadow",
                         "Gooch planes");
    gooch_planes.min = 1;
    gooch_planes.max = kMaxGoochPlanes;
    gooch_planes.presets = {{"1", "1 (planar)"}, {"4", "4"}, {"8", "8"}, {"16", "16"}};
    add(gooch_planes, [](Options& o, std::string_view v) { o.settings.gooch_planes = int_of(v); },
        [](const Options& o) { return std::to_string(o.settings.gooch_planes); });

    OptionInfo gooch_method = make_option_info("gooch-method", P::Technique, T::Choice,
                         "--technique gooch: planes = the casters flattened onto offset planes, moved back to the "
                         "ground and averaged through the stencil (the ground only); texture = the casters from the "
                         "light into a small texture, sampled linearly at offsets on every receiver that casts "
                         "nothing", "Gooch method",
                         {{"planes", "offset planes (stencil)"}, {"texture", "shadow texture, linear filtering"}});
    add(gooch_method, [](Options& o, std::string_view v) { o.settings.gooch_method = enum_of(v, kAllGoochMethods); },
        [](const Options& o) { return std::string(to_string(o.settings.gooch_method)); });

    OptionInfo blend_shadows = make_option_info("blend-shadows", P::Technique, T::Choice,
                         "glTF alphaMode BLEND objects: off = they cast no shadow; on = they cast one, alpha-tested at "
                         "their alphaCutoff (0.5 by default) like MASK cut-outs", "Translucent casters",
                         {{"off", "off: translucent objects cast no shadow"}, {"on", "on: cut out at their alpha cutoff"}});
    add(blend_shadows, [](Options& o, std::string_view v) { o.settings.blend_shadows = v == "on"; },
        [](const Options& o) { return std::string(o.settings.blend_shadows ? "on" : "off"); });

    OptionInfo effects = make_option_info("effects", P::Technique, T::Choice,
                         "effects drawn after the camera pass with any technique, a comma list: outline = the shadow "
                         "casters but the ground outlined in --outline-color, --outline-width pixels wide (through the "
                         "stencil); mirror = the ground (the table top) a planar mirror, --reflectivity of its colour the "
                         "scene reflected in it (drawn where the stencil marks the mirror); portal = a frame standing on "
                         "the table through which another scene is seen, with its own light and shadows (drawn where "
                         "the stencil marks the opening; the course scene's); none = no effects", "Effects",
                         {{"none", "none"}, {"outline", "outline the teapot"}, {"mirror", "the table top a mirror"},
                          {"portal", "a portal into another scene"}});
    effects.list = true;
    add(effects,
        [](Options& o, std::string_view v) {
            o.settings.effects.clear();
            const std::vector<std::string_view> items = list_items(v);
            for (Effect e : kAllEffects)  // kAllEffects' order, whatever the list's
                if (std::find(items.begin(), items.end(), to_string(e)) != items.end()) o.settings.effects.push_back(e);
        },
        [](const Options& o) {
            std::string s;
            for (Effect e : o.settings.effects) s += (s.empty() ? "" : ",") + std::string(to_string(e));
            return s.empty() ? std::string("none") : s;
        });

    OptionInfo outline_color = make_option_info("outline-color", P::Technique, T::Text,
                         "--effects outline: the outline's colour as six hex digits RRGGBB (sRGB bytes, no '#': "
                         "ff8c00 is orange)", "Outline colour");
    // What a page's select offers (any six hex digits are taken).
    outline_color.presets = {{"ff8c00", "orange"}, {"ffff00", "yellow"}, {"00ffff", "cyan"}, {"ff00ff", "magenta"}};
    outline_color.form = [](std::string_view v) -> std::string {
        if (v.size() != 6) return "expected six hex digits RRGGBB (e.g. ff8c00)";
        for (char ch : v)
            if (!std::isxdigit(static_cast<unsigned char>(ch))) return "expected six hex digits RRGGBB (e.g. ff8c00)";
        return {};
    };
    add(outline_color,
        [](Options& o, std::string_view v) {
            for (int i = 0; i < 3; ++i)
                o.settings.outline_color[i] =
                    static_cast<float>(std::stoi(std::string(v.substr(static_cast<size_t>(2 * i), 2)), nullptr, 16)) / 255.0f;
        },
        [](const Options& o) {
            char buf[8];
            const glm::vec3& c = o.settings.outline_color;
            const auto byte = [](float x) { return static_cast<int>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); };
            std::snprintf(buf, sizeof buf, "%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
            return std::string(buf);
        });

    OptionInfo outline_width = make_option_info("outline-width", P::Technique, T::Number,
                         "--effects outline: the outline's width in pixels, the same at any depth", "Outline width (px)");
    outline_width.min = kMinOutlineWidth;
    outline_width.max = kMaxOutlineWidth;
    outline_width.step = 0.5;
    add(outline_width, [](Options& o, std::string_view v) { o.settings.outline_width = static_cast<float>(number_of(v)); },
        [](const Options& o) { return shortest_float(o.settings.outline_width); });

    OptionInfo reflectivity = make_option_info("reflectivity", P::Technique, T::Number,
                         "--effects mirror: the share of the mirror's colour that is the reflection (0 = the table as "
                         "it is, 1 = a perfect mirror)", "Reflectivity");
    reflectivity.min = 0.0;
    reflectivity.max = 1.0;
    reflectivity.step = 0.05;
    add(reflectivity, [](Options& o, std::string_view v) { o.settings.reflectivity = static_cast<float>(number_of(v)); },
        [](const Options& o) { return shortest_float(o.settings.reflectivity); });

    OptionInfo post = make_option_info("post", P::Technique, T::Text,
                         "passes over the finished image, a comma list applied in its order: blur:R = a Gaussian of "
                         "radius R pixels (1..32, sigma R/3) by ping-pong between two targets; bloom:T = what is "
                         "brighter than T (0..1) blurred at 1/2 and 1/4 size and added back; shadow-blur:R = the "
                         "shadow's visibility alone blurred in screen space before shading (a cheap soft shadow); "
                         "none = nothing", "Post-processing");
    post.presets = {{"none", "none"}, {"blur:4", "blur, radius 4 px"}, {"bloom:0.6", "bloom above 0.6"},
                    {"shadow-blur:6", "shadow blur, radius 6 px"}, {"shadow-blur:6,bloom:0.6", "shadow blur and bloom"}};
    post.form = post_form;
    add(post, [](Options& o, std::string_view v) { o.settings.post = parse_post(v); },
        [](const Options& o) { return post_text(o.settings.post); });

    OptionInfo shading = make_option_info("shading", P::Technique, T::Choice,
                         "forward = each object lit as it is drawn (the point lights in batches of 16, one pass "
                         "each); deferred = the objects drawn once into a G-buffer (colour, normal, depth), then "
                         "its pixels lit: the main light and its shadow in one full-screen pass, each point light "
                         "over the square its range covers", "Shading",
                         {{"forward", "forward"}, {"deferred", "deferred (G-buffer)"}});
    add(shading, [](Options& o, std::string_view v) { o.settings.shading = enum_of(v, kAllShadings); },
        [](const Options& o) { return std::string(to_string(o.settings.shading)); });

    OptionInfo lights = make_option_info("lights", P::Technique, T::Integer,
                        "point lights beside the scene's light, unshadowed, each with a range, placed over the "
                        "ground around the objects", "Point lights");
    lights.min = 0;
    lights.max = kMaxLights;
    lights.presets = {{"0", "none"}, {"8", "8"}, {"32", "32"}, {"128", "128"}, {"256", "256"}};
    add(lights, [](Options& o, std::string_view v) { o.settings.lights = int_of(v); },
        [](const Options& o) { return std::to_string(o.settings.lights); });

    OptionInfo aov = make_option_info("aov", P::Technique, T::Choice, "what the image shows", "Show",
                   {{"color", "colour"}, {"visibility", "visibility (white lit, black shadowed)"},
                    {"light-depth", "the shadow map's depth"},
                    {"stencil-count", "the stencil count of shadow volumes, in false colour"},
                    {"gbuffer-color", "G-buffer: colour (--shading deferred)"},
                    {"gbuffer-normal", "G-buffer: normal"},
                    {"gbuffer-position", "G-buffer: position"},
                    {"gbuffer-depth", "G-buffer: depth"},
                    {"cascades", "the cascade of each pixel (--cascades), tinted"}});
    add(aov, [](Options& o, std::string_view v) { o.settings.aov = enum_of(v, kAllAovs); },
        [](const Options& o) { return std::string(to_string(o.settings.aov)); });

    OptionInfo technique = make_option_info("technique", P::Technique, T::Choice, "the shadow technique", "Technique",
                         {{"shadowmap", "shadow map"}, {"planar", "planar projected shadows (stencil)"},
                          {"volumes", "shadow volumes (stencil)"},
                          {"gooch", "Gooch's soft shadow (offset planes or a shadow texture)"}, {"none", "no shadows"}});
    add(technique, [](Options& o, std::string_view v) { o.settings.technique = enum_of(v, kAllTechniques); },
        [](const Options& o) { return std::string(to_string(o.settings.technique)); });

    OptionInfo eye = make_option_info("eye", P::Job, T::Choice,
                   "scene = the scene's camera; in-shadow = inside the shadow of the largest caster, looking along "
                   "it (where shadow volumes' depth-pass fails)", "Eye",
                   {{"scene", "the scene's camera"}, {"in-shadow", "inside the teapot's shadow"}});
    add(eye, [](Options& o, std::string_view v) { o.job.eye_in_shadow = v == "in-shadow"; },
        [](const Options& o) { return std::string(o.job.eye_in_shadow ? "in-shadow" : "scene"); });

    OptionInfo out = make_option_info("out", P::Job, T::Text, "FILE.png (top row first); none: write nothing", "Output");
    out.may_be_empty = true;
    // "none" is stored as no file, as the help says ("" reads back the same).
    add(out, [](Options& o, std::string_view v) { o.job.out = v == "none" ? std::string() : std::string(v); },
        [](const Options& o) { return o.job.out; });

    OptionInfo frames = make_option_info("frames", P::Job, T::Integer, "render N frames, t advancing 1/60 s, and print the median ms/frame",
                      "Frames");
    frames.min = 1;
    frames.max = kMaxFrames;
    add(frames, [](Options& o, std::string_view v) { o.job.frames = int_of(v); },
        [](const Options& o) { return std::to_string(o.job.frames); });

    OptionInfo budget = make_option_info("budget-ms", P::Job, T::Number,
                                         "0: off; else the most accurate shadow map whose frames fit N ms here, "
                                         "chosen frame by frame from their measured times (encoding, filter, map size; "
                                         "shadow volumes at the top where they can draw the scene)",
                                         "Time budget (ms)");
    budget.min = 0.0;
    budget.max = kMaxBudgetMs;
    // The pages' "faster / more accurate" select: a frame rate's worth each.
    budget.presets = {{"0", "off: the settings below"}, {"4", "4 ms: fastest"}, {"8", "8 ms"},
                      {"16", "16 ms (60 frames a second)"}, {"33", "33 ms (30 frames a second): most accurate"}};
    add(budget, [](Options& o, std::string_view v) { o.job.budget_ms = number_of(v); },
        [](const Options& o) { return format_number(o.job.budget_ms); });

    OptionInfo max_error = make_option_info("max-error", P::Job, T::Number,
                                            "0: off; else the least work predicted to keep the frame within P % of the "
                                            "hard truth (map size, or shadow volumes), from its shadow edges and the "
                                            "texels a pixel each map gives them (render, plan, bench; the desktop app and the pages choose again "
                                            "as the frame moves, among map sizes)",
                                            "Error target (%)");
    max_error.min = 0.0;
    max_error.max = kMaxErrorPct;
    // The pages' "error target" select: the bench's targets (docs/budget.md).
    max_error.presets = {{"0", "off: the settings below"}, {"0.2", "0.2 %: least work"}, {"0.1", "0.1 %"},
                         {"0.05", "0.05 %"}, {"0.025", "0.025 %: most accurate"}};
    add(max_error, [](Options& o, std::string_view v) { o.job.max_error = number_of(v); },
        [](const Options& o) { return format_number(o.job.max_error); });
    return t;
}

}  // namespace

const std::vector<Option<Options>>& option_table() {
    static const std::vector<Option<Options>> table = make_table();
    return table;
}

const OptionInfo& option_info(std::string_view name) {
    if (const auto* o = find_option(option_table(), name)) return o->info;
    throw std::logic_error("no option --" + std::string(name));
}

}  // namespace penumbra::render
