// What the renderer is asked to do, as one value type: the technique part of the options (the
// job part, what to render and where it goes, is render::Job in options.h). Every field has one
// entry in the option table (options.h), which parses and prints it for the command line, the
// pages, the desktop app and the bench alike.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "shadow/encoding.h"

namespace penumbra::render {

enum class Technique { ShadowMap, Planar, Volumes, Gooch, None };
// --technique gooch: how Gooch's soft shadow is made (plan/techniques/gooch.cpp).
enum class GoochMethod {
    Planes,  // the casters flattened onto K offset planes, each moved back to the ground, averaged (stencil)
    Texture  // the casters from the light into a small texture, sampled linearly at K offsets per pixel
};
inline constexpr GoochMethod kAllGoochMethods[] = {GoochMethod::Planes, GoochMethod::Texture};
enum class Aov {
    Color,        // the shaded image
    Visibility,   // 8-bit grey: 255 where the light reaches the surface seen at the pixel, 0 in shadow
    LightDepth,   // the shadow map, depth scaled for viewing
    StencilCount,  // shadow volumes: the stencil count in false colour over the unlit image
    // --shading deferred: what the G-buffer holds, decoded (plan/frames/deferred.h)
    GbufferColor,     // the base colour
    GbufferNormal,    // the world normal, n * 0.5 + 0.5
    GbufferPosition,  // the world position, over the shadowed objects' bounds (0..1 per axis)
    GbufferDepth,     // the camera's linear depth, near white, far black
    Cascades          // --cascades: the image tinted by the cascade that shades each pixel (red, green, blue, yellow)
};
// --shading: how the camera's image is lit. Forward draws every object once per batch of lights;
// deferred draws the objects once into a G-buffer (colour, normal, depth) and then lights its
// pixels: the main light in one full-screen pass, each point light over the screen-space square
// its range covers (plan/frames/deferred.h).
enum class Shading { Forward, Deferred };
inline constexpr Shading kAllShadings[] = {Shading::Forward, Shading::Deferred};
// --lights N: point lights beside the scene's light, unshadowed (plan/lights.h).
inline constexpr int kMaxLights = 256;
std::string_view to_string(Shading s);
// How shadow volumes count in the stencil buffer.
enum class VolumeMethod {
    Auto,   // depth-pass for casters whose volume cannot reach the near plane, depth-fail for the rest
    ZPass,  // depth-pass (Heidmann): wrong where the eye is inside a volume
    ZFail   // depth-fail (Carmack's reverse), with caps and an infinite far plane
};
inline constexpr VolumeMethod kAllVolumeMethods[] = {VolumeMethod::Auto, VolumeMethod::ZPass, VolumeMethod::ZFail};
// Which faces of each caster go into the shadow map.
enum class MapFaces {
    Auto,   // the back faces of a closed mesh (scene::Mesh::closed), both faces of an open one
    Front,  // the faces towards the light (what the sheet draws)
    Back,   // the faces away from it: a lit surface is compared with its object's far side
    Both    // every face: open meshes (the teapot's rim, a sheet of paper) cast from either side
};
// How the light's frustum is fitted.
enum class LightFit {
    Shadows,  // where the casters' shadows fall on the receivers the camera sees; only casters that shadow one
    Tight,    // around the receivers the camera sees and the casters in front of them (the course's map)
    Scene     // around every caster's and receiver's bounds (the frustum before the tight fit)
};
inline constexpr LightFit kAllLightFits[] = {LightFit::Shadows, LightFit::Tight, LightFit::Scene};
inline constexpr MapFaces kAllMapFaces[] = {MapFaces::Auto, MapFaces::Front, MapFaces::Back, MapFaces::Both};
inline constexpr Technique kAllTechniques[] = {Technique::ShadowMap, Technique::Planar, Technique::Volumes,
                                              Technique::Gooch, Technique::None};
// Effects drawn after the camera pass, beside the shadow technique (plan/techniques/outline.cpp,
// mirror.cpp, portal.cpp): each is a module of the plan that declares its stencil use.
enum class Effect { Outline, Mirror, Portal };
inline constexpr Effect kAllEffects[] = {Effect::Outline, Effect::Mirror, Effect::Portal};
// --post: what is done to finished images (plan/post.cpp). Blur and bloom are passes over the
// camera's image, in the list's order, ping-ponged between two targets; shadow-blur blurs the
// shadow's visibility alone in screen space before the camera pass shades with it.
enum class PostKind {
    Blur,       // a separable Gaussian, taps -R..R pixels (sigma R/3), horizontal then vertical
    Bloom,      // what exceeds the threshold T (per channel), blurred at 1/2 and 1/4 size, added back
    ShadowBlur  // the visibility AOV blurred (radius R) and the image shaded with it
};
struct PostStep {
    PostKind kind = PostKind::Blur;
    float value = 0.0f;  // blur, shadow-blur: the radius R in pixels (whole, 1..kMaxBlurRadius); bloom: T, 0..1
    bool operator==(const PostStep& o) const { return kind == o.kind && value == o.value; }
};
inline constexpr int kMaxBlurRadius = 32;
std::string_view to_string(PostKind k);

// --outline-width: pixels on the screen, whatever the object's depth.
inline constexpr float kMinOutlineWidth = 0.5f, kMaxOutlineWidth = 32.0f;
inline constexpr Aov kAllAovs[] = {Aov::Color,        Aov::Visibility,    Aov::LightDepth,      Aov::StencilCount,
                                   Aov::GbufferColor, Aov::GbufferNormal, Aov::GbufferPosition, Aov::GbufferDepth,
                                   Aov::Cascades};
// The AOVs that show the G-buffer (--shading deferred).
inline bool gbuffer_aov(Aov a) {
    return a == Aov::GbufferColor || a == Aov::GbufferNormal || a == Aov::GbufferPosition || a == Aov::GbufferDepth;
}

std::string_view to_string(Technique t);
// The technique of that name (to_string's, the option table's choice): what a tool that picks
// techniques to compare names them by; std::invalid_argument for a name that is none.
Technique technique_named(std::string_view name);
std::string_view to_string(Aov a);
std::string_view to_string(MapFaces f);
std::string_view to_string(LightFit f);
std::string_view to_string(VolumeMethod m);
std::string_view to_string(GoochMethod m);
std::string_view to_string(Effect e);

// Heckbert-Herf accumulates one count per light sample in a channel of an RGBA8 target: 4 x 255.
inline constexpr int kMaxAreaSamples = 1020;
// Gooch: the planes' stencil counts 1..K+1 and the texture's taps are compiled in.
inline constexpr int kMaxGoochPlanes = 16;

struct Settings {
    Technique technique = Technique::ShadowMap;
    shadow::Encoding encoding = shadow::Encoding::RGBA;
    shadow::Filter filter = shadow::Filter::Hard;
    // PCF 4x4's corners-first early exit, or every tap (the course's kernel); shadow/pcf.h.
    shadow::PcfKernel pcf_kernel = shadow::PcfKernel::EarlyExit;
    // Texels a side; with cascades each cascade's map (the atlas holds them side by side), with a
    // cube each face's. kAutoMapSize, the default: matched to the screen pixels the map serves
    // (shadow/resolution.h), so a larger image or a shadow filling more of it gets more texels.
    static constexpr int kAutoMapSize = 0;
    int map_size = kAutoMapSize;
    // What a part that takes a fixed size uses under auto (Gooch's texture, W09P2b) and where the
    // cascades' fit starts from.
    int fixed_map_size() const { return map_size == kAutoMapSize ? 1024 : map_size; }
    // --cascades: the camera's depth range split into this many shadow maps, 1..4 (1: one map);
    // kCube: a point light's six faces (shadow/cube.h); 0 = auto (one map, cascades or a cube from
    // the scene, the camera and the light: shadow::auto_cascade_count, shadow::cube_wanted).
    static constexpr int kCube = 6;
    int cascades = 0;
    // --cascade-split: 0 uniform splits, 1 logarithmic. 0.95, not the 0.9 often quoted: with a near
    // plane far nearer than what the view holds (the ground under a walker), 0.9's uniform share puts
    // the first split far out and gives the near shadows coarse texels (docs/cascades.md).
    float cascade_split = 0.95f;
    bool cascade_snap = true;    // --cascade-snap: each cascade's window on whole texels (no shimmer)
    float cascade_blend = 0.1f;  // --cascade-blend: the share of a slice blended into the next, 0..0.5
    // --cube-layout: a cube's six faces as tiles of one 2D atlas (false) or the faces of a GL cube
    // map read with textureCube (true; packed encodings only: WebGL 1 has no cube depth texture).
    bool cube_map = false;
    std::optional<float> bias;  // a constant offset; absent (and not auto): the sheet's (shadow::sheet_bias)
    bool bias_auto = true;      // --bias auto (the default): the encoding's quantum plus a receiver slope term
    MapFaces map_faces = MapFaces::Auto;
    LightFit light_fit = LightFit::Shadows;
    shadow::Precision precision = shadow::Precision::Highp;  // mediump: emulated fp16 depth path
    VolumeMethod volume_method = VolumeMethod::Auto;
    bool show_volumes = false;  // the volumes drawn translucent over the image
    Aov aov = Aov::Color;
    // The light's size (scene::Light::radius) instead of the scene's: world units for point and
    // spot lights, radians for a directional one; 0 a point light.
    std::optional<float> light_radius;
    // --filter pcss: blocker-search taps and filter taps (Vogel discs turned per pixel).
    int pcss_search = 16;
    int pcss_taps = 16;
    // --pcss-blockers: layered = the blockers inside the receiver's cone to the light, beyond its
    // plane, size the penumbra (shadow::pcss_blocker_depth); mean = every tap nearer than the
    // receiver, Fernando's.
    bool pcss_layered = true;
    // Heckbert and Herf: the technique run for this many points on the light, the visibilities
    // accumulated (1: the light's centre only, the hard shadow). With area_per_frame > 0 a still
    // frame adds that many per frame until all are in (progressive); 0: all in one frame.
    int area_samples = 1;
    int area_per_frame = 0;
    // Interleaved sampling (plan/frames/area_light.cpp): 1 = off; K = 2 or 4 tiles the image K x K,
    // each pixel class counting its own share of the samples per round (a frame adds one round of
    // N sample passes, or area_per_frame of them), the camera pass filtering over the tile until
    // K * K rounds give every pixel all N (then it equals area_interleave 1 exactly).
    int area_interleave = 1;
    // --technique gooch: planes (or texture taps) averaged; 1 = the planar shadow (planes).
    int gooch_planes = 8;
    GoochMethod gooch_method = GoochMethod::Planes;
    // glTF alphaMode BLEND objects cast shadows (alpha-tested at their cutoff) instead of none.
    bool blend_shadows = false;
    // --effects: in kAllEffects' order, each once (empty: none).
    std::vector<Effect> effects;
    glm::vec3 outline_color{1.0f, 140.0f / 255.0f, 0.0f};  // --outline-color RRGGBB: ff8c00
    float outline_width = 3.0f;                   // --outline-width: pixels
    // --effects mirror: the share of the mirror's colour that is the reflection (1: a perfect
    // mirror, 0: the table as it was).
    float reflectivity = 0.5f;
    // --post: each kind at most once; blur and bloom applied in the list's order.
    std::vector<PostStep> post;
    Shading shading = Shading::Forward;
    int lights = 0;  // --lights: point lights beside the scene's, 0..kMaxLights
    // The shader lab (render/lab.h, docs/snippets.md): the depth pass packs and the camera pass
    // unpacks, tests and looks up through the sheet's functions, written by a student (the
    // renderer's snippets) or the sheet's answer, in place of the renderer's exact packing.
    // Set by `render --snippets`, the pages' lab panel and the desktop app; no option of its own.
    bool lab = false;

    // The step of that kind, or null.
    const PostStep* post_step(PostKind k) const {
        for (const PostStep& p : post)
            if (p.kind == k) return &p;
        return nullptr;
    }
    bool has(Effect e) const {
        for (Effect x : effects)
            if (x == e) return true;
        return false;
    }

    // The constant bias: with bias_auto the quantum part, else the chosen one or the sheet's.
    float effective_bias() const {
        if (bias_auto) return shadow::auto_bias_constant(encoding, precision);
        return bias ? *bias : shadow::sheet_bias(encoding);
    }
    bool operator==(const Settings& o) const;
    bool operator!=(const Settings& o) const { return !(*this == o); }
};

// What the shader lab can run (Settings::lab): the shadow-map technique with one 2D map, the r8 or
// rgba encoding, the hard or a PCF filter, a constant bias, forward shading, no point lights,
// effects or light samples. "" when `s` fits, else one line naming what does not.
std::string lab_refusal(const Settings& s);

}  // namespace penumbra::render
