// Shader variants: a file pair plus the #defines for the features in use, compiled once on first
// use and cached. The same list of every variant the renderer can ask for feeds the
// glslangValidator test and the on-context compile test.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "render/settings.h"

namespace penumbra::render {

struct Variant {
    std::string vertex;                // file in shaders_gles2/, e.g. "lit.vert"
    std::string fragment;              // e.g. "lit.frag"
    std::vector<std::string> defines;  // e.g. {"SHADOW_MAP", "ENC_RGBA", "FILTER_PCF4X4"}
    std::string key() const;           // "lit.vert+lit.frag[SHADOW_MAP,ENC_RGBA,...]"
};

// The embedded source of `file` with `#define NAME 1` lines inserted after `#version 100`.
// Throws gl::Error when the file is not embedded.
std::string variant_source(const std::string& file, const std::vector<std::string>& defines);

// What the lit shader needs for one object in one pass.
struct LitFeatures {
    bool shadow_map = false;  // with encoding and filter
    shadow::Encoding encoding = shadow::Encoding::RGBA;
    shadow::Filter filter = shadow::Filter::Hard;
    bool in_shadow = false;   // planar: the region the stencil marked
    bool textured = false;
    bool spot = false;
    bool visibility_aov = false;
    bool bias_auto = false;          // receiver slope bias (with shadow_map)
    bool light_perspective = false;  // the light's projection, for bias_auto's depth slope
    bool mediump = false;            // emulate fp16 along the depth path
};

// How the depth path is compiled on this context: the emulated precision and what the unorm8
// probe found (PACK_FLOOR when the context truncates).
struct DepthPath {
    bool mediump = false;
    bool pack_floor = false;
};

Variant lit_variant(const LitFeatures& f);
// The light's pass (also the planar stencil pass with DepthTex: colour off).
Variant depth_variant(shadow::Encoding e, const DepthPath& path = {});
Variant light_depth_variant(shadow::Encoding e, bool perspective, const DepthPath& path = {});
// The unorm8 rounding probe's program.
Variant probe_variant();
// The precision test pattern: a ramp of depths packed as `e` packs them (R8 or RGBA).
Variant ramp_variant(shadow::Encoding e, const DepthPath& path);

// Every variant the renderer can build.
std::vector<Variant> all_variants();

class ShaderLibrary {
public:
    const gl::Program& get(const Variant& v);
    std::size_t compiled() const { return programs_.size(); }
    void clear() { programs_.clear(); }

private:
    std::map<std::string, gl::Program> programs_;
};

}  // namespace penumbra::render
