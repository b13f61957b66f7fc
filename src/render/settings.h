// Every technique choice in one value type, with one parser and one printer, used alike by the
// command line, the web page's URL, the desktop keys and the benchmark sweep. A result is always
// labelled with the exact settings that made it (to_args()).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shadow/encoding.h"

namespace penumbra::render {

enum class Technique { ShadowMap, Planar, None };
enum class Aov {
    Color,       // the shaded image
    Visibility,  // 8-bit grey: 255 where the light reaches the surface seen at the pixel, 0 in shadow
    LightDepth   // the shadow map, depth scaled for viewing
};

std::string_view to_string(Technique t);
std::string_view to_string(Aov a);

struct Settings {
    std::string scene = "teapot";  // "teapot" or a .gltf/.glb path
    double time = 0.0;             // seconds; animation is a pure function of it
    int width = 512;
    int height = 512;
    shadow::Encoding encoding = shadow::Encoding::RGBA;
    shadow::Filter filter = shadow::Filter::Hard;
    int map_size = 1024;
    std::optional<float> bias;  // absent: the encoding's default (shadow::default_bias)
    bool bias_auto = false;     // --bias auto: the encoding's quantum plus a receiver slope term
    shadow::Precision precision = shadow::Precision::Highp;  // mediump: emulated fp16 depth path
    Aov aov = Aov::Color;
    Technique technique = Technique::ShadowMap;
    std::string out;  // PNG path; empty: write nothing
    int frames = 1;

    // The constant bias: the chosen one, the encoding's default, or with bias_auto the quantum part.
    float effective_bias() const {
        if (bias_auto) return shadow::auto_bias_constant(encoding, precision);
        return bias ? *bias : shadow::default_bias(encoding);
    }
    bool operator==(const Settings& o) const;
};

// The options in their command-line spelling, without the leading "--", in printing order.
const std::vector<std::string_view>& option_names();

// Parse one option's value into s. Returns an empty string on success, else one line naming the
// problem ("--encoding: unknown value 'r16' (r8, rgba, depthtex)"). s is unchanged on failure.
std::string parse_option(Settings& s, std::string_view name, std::string_view value);

// Every option with its value, as parse_option reads it back (an absent bias prints "default").
std::vector<std::pair<std::string, std::string>> to_pairs(const Settings& s);
// "--scene teapot --time 0 ..." for labels and logs.
std::string to_args(const Settings& s);

}  // namespace penumbra::render
