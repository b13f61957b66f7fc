// What the renderer is asked to do, as one value type: the technique part of the options (the
// job part, what to render and where it goes, is render::Job in options.h). Every field has one
// entry in the option table (options.h), which parses and prints it for the command line, the
// pages, the desktop app and the bench alike.
#pragma once

#include <optional>
#include <string_view>

#include "shadow/encoding.h"

namespace penumbra::render {

enum class Technique { ShadowMap, Planar, None };
enum class Aov {
    Color,       // the shaded image
    Visibility,  // 8-bit grey: 255 where the light reaches the surface seen at the pixel, 0 in shadow
    LightDepth   // the shadow map, depth scaled for viewing
};
inline constexpr Technique kAllTechniques[] = {Technique::ShadowMap, Technique::Planar, Technique::None};
inline constexpr Aov kAllAovs[] = {Aov::Color, Aov::Visibility, Aov::LightDepth};

std::string_view to_string(Technique t);
std::string_view to_string(Aov a);

struct Settings {
    Technique technique = Technique::ShadowMap;
    shadow::Encoding encoding = shadow::Encoding::RGBA;
    shadow::Filter filter = shadow::Filter::Hard;
    // PCF 4x4's corners-first early exit, or every tap (the course's kernel); shadow/pcf.h.
    shadow::PcfKernel pcf_kernel = shadow::PcfKernel::EarlyExit;
    int map_size = 1024;
    std::optional<float> bias;  // absent: the encoding's default (shadow::default_bias)
    bool bias_auto = false;     // --bias auto: the encoding's quantum plus a receiver slope term
    shadow::Precision precision = shadow::Precision::Highp;  // mediump: emulated fp16 depth path
    Aov aov = Aov::Color;

    // The constant bias: the chosen one, the encoding's default, or with bias_auto the quantum part.
    float effective_bias() const {
        if (bias_auto) return shadow::auto_bias_constant(encoding, precision);
        return bias ? *bias : shadow::default_bias(encoding);
    }
    bool operator==(const Settings& o) const;
    bool operator!=(const Settings& o) const { return !(*this == o); }
};

}  // namespace penumbra::render
