#include "render/settings.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace penumbra::render {

std::string_view to_string(Technique t) {
    switch (t) {
        case Technique::ShadowMap: return "shadowmap";
        case Technique::Planar: return "planar";
        case Technique::None: return "none";
    }
    return "?";
}

std::string_view to_string(Aov a) {
    switch (a) {
        case Aov::Color: return "color";
        case Aov::Visibility: return "visibility";
        case Aov::LightDepth: return "light-depth";
    }
    return "?";
}

bool Settings::operator==(const Settings& o) const {
    return scene == o.scene && time == o.time && width == o.width && height == o.height && encoding == o.encoding &&
           filter == o.filter && map_size == o.map_size && bias == o.bias && bias_auto == o.bias_auto &&
           precision == o.precision && aov == o.aov &&
           technique == o.technique && out == o.out && frames == o.frames;
}

const std::vector<std::string_view>& option_names() {
    static const std::vector<std::string_view> names = {"scene", "time",      "size", "encoding", "filter",
                                                        "map-size", "bias", "precision", "aov", "technique",
                                                        "out", "frames"};
    return names;
}

namespace {

// Finds `value` among the printed names of an enum's members.
template <typename E, size_t N>
bool parse_enum(std::string_view value, const E (&all)[N], E& out) {
    for (E e : all)
        if (to_string(e) == value) {
            out = e;
            return true;
        }
    return false;
}

template <typename E, size_t N>
std::string choices(const E (&all)[N]) {
    std::string s;
    for (E e : all) s += (s.empty() ? "" : ", ") + std::string(to_string(e));
    return s;
}

bool parse_int(std::string_view v, int& out) {
    const char* end = v.data() + v.size();
    auto [p, ec] = std::from_chars(v.data(), end, out);
    return ec == std::errc() && p == end;
}

bool parse_double(std::string_view v, double& out) {
    // strtod accepts what people type (1e-3, .5); reject trailing junk, inf and nan.
    const std::string s(v);
    if (s.empty()) return false;
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(out);
}

std::string format_double(double v) {
    std::ostringstream o;
    o.precision(17);
    o << v;
    return o.str();
}

constexpr shadow::Precision kPrecisions[] = {shadow::Precision::Highp, shadow::Precision::Mediump};
constexpr Aov kAovs[] = {Aov::Color, Aov::Visibility, Aov::LightDepth};
constexpr Technique kTechniques[] = {Technique::ShadowMap, Technique::Planar, Technique::None};

}  // namespace

std::string parse_option(Settings& s, std::string_view name, std::string_view value) {
    const std::string opt = "--" + std::string(name);
    const auto bad = [&](const std::string& why) { return opt + ": " + why; };
    const std::string quoted = "'" + std::string(value) + "'";
    Settings t = s;
    if (name == "scene") {
        if (value.empty()) return bad("needs 'teapot' or a .gltf/.glb file");
        t.scene = std::string(value);
    } else if (name == "time") {
        if (!parse_double(value, t.time)) return bad("not a number: " + quoted);
    } else if (name == "size") {
        const auto x = value.find('x');
        int w = 0, h = 0;
        if (x == std::string_view::npos || !parse_int(value.substr(0, x), w) || !parse_int(value.substr(x + 1), h))
            return bad("expected WIDTHxHEIGHT, got " + quoted);
        if (w <= 0 || h <= 0) return bad("width and height must be at least 1, got " + quoted);
        t.width = w;
        t.height = h;
    } else if (name == "encoding") {
        if (!parse_enum(value, shadow::kAllEncodings, t.encoding))
            return bad("unknown value " + quoted + " (" + choices(shadow::kAllEncodings) + ")");
    } else if (name == "filter") {
        if (!parse_enum(value, shadow::kAllFilters, t.filter)) return bad("unknown value " + quoted + " (" + choices(shadow::kAllFilters) + ")");
    } else if (name == "map-size") {
        if (!parse_int(value, t.map_size)) return bad("not a whole number: " + quoted);
        if (t.map_size <= 0) return bad("must be at least 1, got " + quoted);
    } else if (name == "bias") {
        double b = 0.0;
        if (value == "default" || value == "auto") {
            t.bias.reset();
            t.bias_auto = value == "auto";
        } else if (!parse_double(value, b)) {
            return bad("not a number: " + quoted + " (or 'default', 'auto')");
        } else if (b < 0.0 || b > 1.0) {
            return bad("must lie in [0, 1] (a depth offset), got " + quoted);
        } else {
            t.bias = static_cast<float>(b);
            t.bias_auto = false;
        }
    } else if (name == "precision") {
        if (!parse_enum(value, kPrecisions, t.precision))
            return bad("unknown value " + quoted + " (" + choices(kPrecisions) + ")");
    } else if (name == "aov") {
        if (!parse_enum(value, kAovs, t.aov)) return bad("unknown value " + quoted + " (" + choices(kAovs) + ")");
    } else if (name == "technique") {
        if (!parse_enum(value, kTechniques, t.technique))
            return bad("unknown value " + quoted + " (" + choices(kTechniques) + ")");
    } else if (name == "out") {
        t.out = std::string(value);
    } else if (name == "frames") {
        if (!parse_int(value, t.frames)) return bad("not a whole number: " + quoted);
        if (t.frames < 1) return bad("must be at least 1, got " + quoted);
    } else {
        return "unknown option " + opt;
    }
    s = t;
    return {};
}

std::vector<std::pair<std::string, std::string>> to_pairs(const Settings& s) {
    return {
        {"scene", s.scene},
        {"time", format_double(s.time)},
        {"size", std::to_string(s.width) + "x" + std::to_string(s.height)},
        {"encoding", std::string(to_string(s.encoding))},
        {"filter", std::string(to_string(s.filter))},
        {"map-size", std::to_string(s.map_size)},
        {"bias", s.bias_auto ? "auto" : s.bias ? format_double(static_cast<double>(*s.bias)) : "default"},
        {"precision", std::string(to_string(s.precision))},
        {"aov", std::string(to_string(s.aov))},
        {"technique", std::string(to_string(s.technique))},
        {"out", s.out},
        {"frames", std::to_string(s.frames)},
    };
}

std::string to_args(const Settings& s) {
    std::string out;
    for (const auto& [k, v] : to_pairs(s)) {
        if (k == "out" && v.empty()) continue;
        out += (out.empty() ? "--" : " --") + k + " " + v;
    }
    return out;
}

}  // namespace penumbra::render
