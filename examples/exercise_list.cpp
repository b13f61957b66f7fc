// The registry of exercises (examples/exercises/list.h: one line each), the toggles only the
// exercises have, and the desktop keys they all share.
#include "exercise_list.h"

#include <algorithm>


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

}  // namespace

namespace {

// The keys every exercise has (its own come first: Exercise::keys).
const std::vector<KeyBinding>& shared_keys() {
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
    };
    return keys;
}

}  // namespace

const std::vector<render::Option<Toggles>>& toggle_table() {
    static const auto table = make_toggles();
    return table;
}

const std::vector<Exercise>& exercise_list() {
    static const auto list = exercise_registry();
    return list;
}

bool offers(const Exercise& x, std::string_view option) {
    return std::any_of(x.controls.begin(), x.controls.end(), [&](const Control& c) { return c.option == option; });
}

const Exercise* find_exercise(std::string_view name) {
    for (const auto& x : exercise_list())
        if (x.name == name) return &x;
    return nullptr;
}

std::string exercise_names() {
    std::string s;
    for (const auto& x : exercise_list()) s += (s.empty() ? "" : ", ") + std::string(x.name);
    return s;
}

const std::vector<KeyBinding>& key_bindings() {
    static const std::vector<KeyBinding> keys = [] {
        std::vector<KeyBinding> all = shared_keys();
        for (const Exercise& x : exercise_list())
            for (KeyBinding k : x.keys) {
                k.only = x.name;
                all.push_back(k);
            }
        return all;
    }();
    return keys;
}

const std::vector<std::string_view>& here_only_options() {
    static const std::vector<std::string_view> names = {"technique", "post", "shading", "lights", "cascades",
                                                        "cascade-split", "cascade-blend", "cascade-snap", "cube-layout"};
    return names;
}

bool held_here_only(std::string_view option) {
    const auto& names = here_only_options();
    return std::find(names.begin(), names.end(), option) != names.end();
}

}  // namespace penumbra::examples
