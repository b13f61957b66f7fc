#include "render/options.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "render/post.h"

namespace penumbra::render {

bool Job::operator==(const Job& o) const {
    return scene == o.scene && time == o.time && width == o.width && height == o.height && out == o.out &&
           frames == o.frames && eye_in_shadow == o.eye_in_shadow;
}

// ---- parsing ----------------------------------------------------------------------------------

bool parse_int(std::string_view v, int& out) {
    if (v.empty() || v.size() > 11) return false;
    const std::string s(v);
    char* end = nullptr;
    const long x = std::strtol(s.c_str(), &end, 10);
    if (end != s.c_str() + s.size() || std::isspace(static_cast<unsigned char>(s.front()))) return false;
    if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max()) return false;
    out = static_cast<int>(x);
    return true;
}

bool parse_number(std::string_view v, double& out) {
    const std::string s(v);
    if (s.empty() || std::isspace(static_cast<unsigned char>(s.front()))) return false;
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(x)) return false;
    out = x;
    return true;
}

bool parse_size(std::string_view v, int& w, int& h) {
    const auto x = v.find('x');
    return x != std::string_view::npos && parse_int(v.substr(0, x), w) && parse_int(v.substr(x + 1), h);
}

std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string shortest_float(float f) {
    for (int precision = 1; precision <= 9; ++precision) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.*g", precision, static_cast<double>(f));
        if (static_cast<float>(std::strtod(buf, nullptr)) == f) return buf;
    }
    return format_number(static_cast<double>(f));
}

namespace {

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);  // 1000000, not 1e+06
    return buf;
}

// The items of a comma list ("outline,mirror"), empty ones included ("a,,b" has three).
std::vector<std::string_view> list_items(std::string_view value) {
    std::vector<std::string_view> items;
    for (size_t start = 0; start <= value.size();) {
        size_t end = value.find(',', start);
        if (end == std::string_view::npos) end = value.size();
        items.push_back(value.substr(start, end - start));
        start = end + 1;
    }
    return items;
}

std::string word_list(const std::vector<Choice>& choices, const char* quote = "") {
    std::string s;
    for (const Choice& c : choices) s += (s.empty() ? "" : ", ") + std::string(quote) + std::string(c.value) + quote;
    return s;
}

// "" when v lies in the option's range, else the rule it breaks.
std::string range_problem(const OptionInfo& o, double v) {
    const bool low = std::isfinite(o.min), high = std::isfinite(o.max);
    if ((!low || v >= o.min) && (!high || v <= o.max)) return {};
    if (low && high) return "must lie in [" + number_text(o.min) + ", " + number_text(o.max) + "]";
    if (low) return "must be at least " + number_text(o.min);
    return "must be at most " + number_text(o.max);
}

std::string range_words(const OptionInfo& o) {
    const bool low = std::isfinite(o.min), high = std::isfinite(o.max);
    if (low && high) return " in [" + number_text(o.min) + ", " + number_text(o.max) + "]";
    if (low) return " >= " + number_text(o.min);
    if (high) return " <= " + number_text(o.max);
    return {};
}

}  // namespace

std::string accepted_values(const OptionInfo& o) {
    switch (o.type) {
        case OptionType::Choice:
            if (o.list && !o.choices.empty())
                return "a comma list of " + word_list({o.choices.begin() + 1, o.choices.end()}) + ", or " +
                       std::string(o.choices.front().value);
            return word_list(o.choices);
        case OptionType::Integer: return "a whole number" + range_words(o);
        case OptionType::Number: return "a number" + range_words(o);
        case OptionType::Size: return "WIDTHxHEIGHT" + (std::isfinite(o.max) ? ", each <= " + number_text(o.max) : std::string());
        case OptionType::Text: return std::string(o.help);
        case OptionType::NumberOrWord: return "a number" + range_words(o) + ", or " + word_list(o.choices);
    }
    return {};
}

std::string check_value(const OptionInfo& o, std::string_view value) {
    const std::string opt = "--" + std::string(o.name) + ": ";
    const std::string quoted = "'" + scene::printable(value) + "'";  // one line, valid UTF-8
    const auto among = [&] {
        for (const Choice& c : o.choices)
            if (c.value == value) return true;
        return false;
    };
    switch (o.type) {
        case OptionType::Choice:
            if (o.list && !o.choices.empty() && value != o.choices.front().value) {
                // A comma list: each item one of the choices after the first, and each once.
                std::vector<std::string_view> seen;
                for (std::string_view item : list_items(value)) {
                    bool known = false;
                    for (size_t i = 1; i < o.choices.size(); ++i) known = known || o.choices[i].value == item;
                    if (!known)
                        return opt + "unknown value '" + scene::printable(item) + "' in " + quoted + " (" +
                               accepted_values(o) + ")";
                    if (std::find(seen.begin(), seen.end(), item) != seen.end())
                        return opt + "'" + scene::printable(item) + "' twice in " + quoted;
                    seen.push_back(item);
                }
                return {};
            }
            if (!among()) return opt + "unknown value " + quoted + " (" + word_list(o.choices) + ")";
            return {};
        case OptionType::Integer: {
            int v = 0;
            if (!parse_int(value, v)) return opt + "not a whole number: " + quoted;
            if (std::string r = range_problem(o, v); !r.empty()) return opt + r + ", got " + quoted;
            return {};
        }
        case OptionType::Number:
        case OptionType::NumberOrWord: {
            if (o.type == OptionType::NumberOrWord && among()) return {};
            double v = 0.0;
            if (!parse_number(value, v)) {
                const std::string text(value);
                char* end = nullptr;
                const double x = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
                if (!text.empty() && end == text.c_str() + text.size() && !std::isfinite(x))
                    return opt + "must be a finite number" + range_words(o) + ", got " + quoted;
                return opt + "not a number: " + quoted +
                       (o.type == OptionType::NumberOrWord ? " (or " + word_list(o.choices, "'") + ")" : "");
            }
            if (std::string r = range_problem(o, v); !r.empty()) return opt + r + ", got " + quoted;
            return {};
        }
        case OptionType::Size: {
            int w = 0, h = 0;
            if (!parse_size(value, w, h)) return opt + "expected WIDTHxHEIGHT, got " + quoted;
            if (w < 1 || h < 1) return opt + "width and height must be at least 1, got " + quoted;
            if (std::isfinite(o.max) && (w > o.max || h > o.max))
                return opt + "width and height must be at most " + number_text(o.max) + " (the maximum), got " + quoted;
            return {};
        }
        case OptionType::Text:
            if (value.empty() && !o.may_be_empty) return opt + "needs a value: " + std::string(o.help);
            if (o.form)
                if (std::string why = o.form(value); !why.empty()) return opt + why + ", got " + quoted;
            return {};
    }
    return {};
}

std::string parse_list(const OptionInfo& o, std::string_view text, std::vector<std::string>& out) {
    std::vector<std::string> items;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find(',', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view item = text.substr(start, end - start);
        if (std::string err = check_value(o, item); !err.empty()) return err;
        items.emplace_back(item);
        start = end + 1;
    }
    out.insert(out.end(), items.begin(), items.end());
    return {};
}

// ---- the table --------------------------------------------------------------------------------

OptionInfo make_option_info(std::string_view name, OptionPart part, OptionType type, std::string_view help,
                            std::string_view label, std::vector<Choice> choices) {
    OptionInfo o;
    o.name = name;
    o.part = part;
    o.type = type;
    o.help = help;
    o.label = label;
    o.choices = std::move(choices);
    return o;
}

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

    OptionInfo scene = make_option_info("scene", P::Job, T::Text, "teapot (the course scene) or FILE.gltf / FILE.glb", "Scene");
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

    OptionInfo map_size = make_option_info("map-size", P::Technique, T::Integer, "shadow map width = height in texels", "Shadow map size");
    map_size.min = 1;
    map_size.max = kMaxMapSize;
    map_size.presets = {{"256", "256 x 256"}, {"512", "512 x 512"}, {"1024", "1024 x 1024"}, {"2048", "2048 x 2048"},
                        {"4096", "4096 x 4096"}};
    add(map_size, [](Options& o, std::string_view v) { o.settings.map_size = int_of(v); },
        [](const Options& o) { return std::to_string(o.settings.map_size); });

    OptionInfo cascades = make_option_info("cascades", P::Technique, T::Choice,
                         "cascaded shadow maps for a directional light: the camera's depth range split into N maps "
                         "of --map-size each, side by side in one atlas (near slices get the finer texels); auto = "
                         "from the depth range the camera sees (one map per factor of 8); 1 = one map",
                         "Cascades", {{"1", "1 (one map)"}, {"2", "2"}, {"3", "3"}, {"4", "4"}, {"auto", "auto"}});
    add(cascades, [](Options& o, std::string_view v) { o.settings.cascades = v == "auto" ? 0 : int_of(v); },
        [](const Options& o) { return o.settings.cascades == 0 ? std::string("auto") : std::to_string(o.settings.cascades); });

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
                         "the light's frustum: tight = around the receivers the camera sees and the casters that can "
                         "shadow them; scene = around the whole scene", "Light frustum",
                         {{"tight", "tight: what the camera sees"}, {"scene", "the whole scene"}});
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

std::string parse_option(Options& o, std::string_view name, std::string_view value) {
    return set_option(option_table(), o, name, value);
}

std::string parse_option(Settings& s, std::string_view name, std::string_view value) {
    const auto* o = find_option(option_table(), name);
    if (o && o->info.part != OptionPart::Technique) return "--" + scene::printable(name) + ": not a technique setting";
    Options all;
    all.settings = s;
    std::string err = parse_option(all, name, value);
    if (err.empty()) s = all.settings;
    return err;
}

std::vector<std::pair<std::string, std::string>> to_pairs(const Options& o) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& opt : option_table()) out.emplace_back(std::string(opt.info.name), opt.print(o));
    return out;
}

std::vector<std::pair<std::string, std::string>> to_pairs(const Settings& s) {
    Options o;
    o.settings = s;
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& opt : option_table())
        if (opt.info.part == OptionPart::Technique) out.emplace_back(std::string(opt.info.name), opt.print(o));
    return out;
}

namespace {
std::string args_of(const std::vector<std::pair<std::string, std::string>>& pairs) {
    std::string out;
    for (const auto& [k, v] : pairs) {
        if (k == "out" && v.empty()) continue;
        out += (out.empty() ? "--" : " --") + k + " " + scene::printable(v);  // a log's one line
    }
    return out;
}
}  // namespace

std::string to_args(const Options& o) { return args_of(to_pairs(o)); }
std::string to_args(const Settings& s) { return args_of(to_pairs(s)); }

}  // namespace penumbra::render
