// Shader variants as data: a file pair plus the #defines for the features in use. Which variant
// each draw needs is decided when the frame is planned (no GL here); render/shader_library.h
// compiles a variant on first use. The same list of every variant the renderer can ask for feeds
// the glslangValidator test and the on-context compile test.
#pragma once

#include <string>
#include <vector>

#include "plan/settings.h"
#include "shadow/encoding.h"

namespace penumbra::render {

struct Variant {
    std::string vertex;                // file in shaders_gles2/, e.g. "lit.vert"
    std::string fragment;              // e.g. "lit.frag"
    // "NAME" (written as #define NAME 1) or "NAME TEXT" (#define NAME TEXT: generated code, e.g.
    // the PCF kernel), e.g. {"SHADOW_MAP", "ENC_RGBA", "FILTER_PCF4X4", "PCF_TAPS 16", ...}.
    std::vector<std::string> defines;
    std::string key() const;           // "lit.vert+lit.frag[SHADOW_MAP,ENC_RGBA,...]"
    std::string tag() const;           // the define names joined by "_" (file names)
    std::string name() const;          // "lit.vert+lit.frag[SHADOW_MAP,PCF_TAPS,...]": names, no values
    bool operator==(const Variant& o) const { return key() == o.key(); }
};

// What the lit shader writes: everything, the ambient term only (LIGHT_AMBIENT), or the direct
// term only, scaled by u_light_weight (LIGHT_DIRECT; visibility AOV: u_light_weight).
enum class LightTerm { All, Ambient, Direct };

// --shading deferred: what a lit draw does with the G-buffer (plan/frames/deferred.h).
enum class Gbuffer {
    None,
    WriteAll,  // the geometry pass into the three targets at once (GBUFFER_MRT: EXT_draw_buffers)
    WriteOne,  // into target gbuffer_target only (one geometry pass per target)
    Read       // a lighting pass: the surface read back at the pixel (screen.vert)
};

// What the lit shader needs for one object in one pass.
struct LitFeatures {
    bool shadow_map = false;  // with encoding and filter
    shadow::Encoding encoding = shadow::Encoding::RGBA;
    shadow::Filter filter = shadow::Filter::Hard;
    shadow::PcfKernel pcf_kernel = shadow::PcfKernel::Full;  // EarlyExit changes only kernels it applies to (PCF 4x4)
    bool in_shadow = false;   // planar: the region the stencil marked
    bool textured = false;
    bool spot = false;
    bool visibility_aov = false;
    bool bias_auto = false;          // receiver slope bias (with shadow_map)
    bool faceted = false;            // the receiver's mesh is faceted (scene::Mesh::faceted): bias_auto's slope per vertex
    bool light_perspective = false;  // the light's projection, for bias_auto's depth slope
    bool mediump = false;            // emulate fp16 along the depth path
    int cascades = 0;                // with shadow_map, more than 1: that many cascades in one atlas
    bool cube = false;               // with shadow_map: a point light's six faces in one atlas (shadow/cube.h)
    bool cube_map = false;           // with cube: the faces of a GL cube map instead (--cube-layout cubemap)
    bool cascades_aov = false;       // --aov cascades: the colour tinted by the cascade (or cube face) used
    int pcss_search = 16, pcss_taps = 16;  // filter PCSS: taps of the blocker search and the filter
    bool pcss_layered = true;              // filter PCSS: the layered blocker estimate (PCSS_LAYERED)
    bool area_lookup = false;        // Heckbert-Herf: visibility from the accumulated light samples
    int area_interleave = 1;         // with area_lookup, > 1: filtered over K x K pixel classes
    bool horizon = false;            // a light with a size (PCSS) or one sample of it: the part above the horizon
    // The context has dFdx/dFdy (Caps::standard_derivatives): the horizon is then the triangle's
    // own plane, as the area-light truth takes it, rather than the interpolated normal's, which
    // leans past it on a smooth mesh's terminator (GEOMETRIC_HORIZON; not where the surface is
    // read back from the G-buffer, whose 2x2 quads can straddle two triangles). With PCSS, the
    // filtered visibility is averaged over the pixel quad too (PCSS_QUAD, shadow.glsl).
    bool derivatives = false;
    // Gooch: which terms the pass writes (planes: the ground ambient-only first, then the direct
    // light scaled by u_light_weight added once per plane that lights it) and, with gooch_taps > 0,
    // the visibility from the shadow texture sampled linearly at that many offsets (texture).
    LightTerm light_term = LightTerm::All;
    int gooch_taps = 0;
    // glTF materials: MASK (fragments below the cutoff discarded), BLEND (the alpha written for
    // the blend pass), doubleSided (a back face lit as seen).
    bool alpha_test = false;
    bool alpha_blend = false;
    bool double_sided = false;
    // --effects mirror: drawn as seen in the mirror (the world position on the mirror's far side
    // discarded, u_clip_plane; the colour premultiplied by u_reflectivity, which is its alpha).
    bool reflected = false;
    // --effects portal: the other scene seen through the opening (the world position on the
    // camera's side of the opening's plane discarded, u_clip_plane).
    bool clipped = false;
    // --lights: this many point lights added (u_point_lights); points_only: nothing else.
    int point_lights = 0;
    bool points_only = false;
    Gbuffer gbuffer = Gbuffer::None;
    bool lab = false;        // with shadow_map: the lab's unpackDepth, shadowTest, offset_lookup (LAB)
    int gbuffer_target = 0;  // WriteOne: 0 colour, 1 normal, 2 depth
    bool receives = false;   // WriteAll, WriteOne: the object receives shadows (the depth target's flag)
};

// How a pass that draws casters without their material (depth, stencil, flat) treats a caster's
// alpha: not at all, or the MASK discard with the base colour's alpha (and the base texture's).
struct AlphaTest {
    bool on = false;
    bool textured = false;
};

// How the depth path is compiled: in emulated mediump or not. (The packing is the same on every
// context: pack.glsl writes bytes that any unorm8 conversion keeps.)
struct DepthPath {
    bool mediump = false;
    bool lab = false;  // Settings::lab: the lab's packDepth (LAB)
};

Variant lit_variant(const LitFeatures& f);
// The light's pass (also the planar stencil pass with DepthTex: colour off).
Variant depth_variant(shadow::Encoding e, const DepthPath& path = {}, AlphaTest alpha = {});
Variant light_depth_variant(shadow::Encoding e, bool perspective, const DepthPath& path = {});
// The unorm8 rounding probe's program (a full-screen triangle of one colour, u_value).
Variant probe_variant();
// Triangles of homogeneous points (Draw::triangles) through u_mvp, in one colour (u_value).
Variant volume_variant();
// The precision test pattern: a ramp of depths packed as `e` packs them (R8 or RGBA).
Variant ramp_variant(shadow::Encoding e, const DepthPath& path);

// The PCF kernel of `f` as the shader's defines: PCF_TAPS (the count) and PCF_SUM(F, uv, z, bias),
// the sum of F(offset, uv, z, bias) over shadow::pcf_offsets(f). With the early exit (where it
// applies, shadow::pcf_early_exit_applies) PCF_EARLY_EXIT and, instead of PCF_SUM, the same sum
// split in two: PCF_CORNERS over the 4 corner taps and PCF_REST over the others.
std::vector<std::string> pcf_kernel_defines(shadow::Filter f, shadow::PcfKernel kernel = shadow::PcfKernel::Full);

// A constant colour (u_value) through u_mvp: Gooch's casters into the shadow texture.
Variant flat_variant(AlphaTest alpha = {});

// Gooch's texture taps as the shader's defines: GOOCH_TAPS (the count) and GOOCH_SUM(F), the sum
// of F(offset) over shadow::gooch_disc(taps).
std::vector<std::string> gooch_tap_defines(int taps);

// --effects outline: the object pushed out along its screen-space normals by u_outline_width
// pixels (0: the object itself), in one colour (u_value).
Variant outline_variant();

// --effects mirror: a full-screen triangle on the far plane (depth 1) in one colour (u_value): the
// mirror's depth cleared through the stencil, and its background where nothing is reflected.
Variant far_plane_variant();

// Heckbert-Herf: one light sample's visibility (a texture) added as a count into one channel.
// Interleaved: only one pixel class counts it (u_class).
Variant area_add_variant(bool interleaved = false);

// --post (plan/post.h): one direction of the Gaussian of radius 1..kMaxBlurRadius (BLUR_RADIUS,
// BLUR_SUM generated), the bright pass (also the 2x2 downsample), the image plus its bloom.
Variant blur_variant(int radius);
Variant bright_variant();
Variant bloom_add_variant();

// --aov gbuffer-*: a G-buffer target decoded for people (gbuffer_view.frag through screen.vert).
Variant gbuffer_view_variant(Aov aov);

// penumbra mipmaps (render/mipmaps.h): one level from the level above, the box filter or the
// normal map's (MIP_NORMAL: renormalised); and a level read back by drawing (MIP_READ).
Variant mip_down_variant(bool normal_map);
Variant mip_read_variant();

// Every variant the renderer can build.
std::vector<Variant> all_variants();

}  // namespace penumbra::render
