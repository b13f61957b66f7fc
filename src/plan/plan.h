// The frame as data. plan() turns a scene, the settings, the context's capabilities and the
// caller's inputs (where the image goes, a view or a light to use instead of the scene's, a
// texture to sample instead of a scene image) into a FramePlan: the resources the frame needs
// (shadow maps, offscreen targets: described by value, allocated by the renderer's pool) and the
// passes that fill them, each with its target, clear, pipeline state, draws (and each draw's shader
// variant), and the uniforms and textures it binds. Renderer::execute() runs a plan; it is the only
// code that draws a frame. No GL here: a plan is made, printed and tested without a context.
//
// The techniques (plan/techniques/) add their passes, resources and shader features to a plan;
// this file's plan() builds what every frame has (the camera's view and its pass) around them.
#pragma once

#include <any>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "gl/caps.h"
#include "gl/state.h"
#include "plan/settings.h"
#include "plan/variants.h"
#include "scene/scene.h"
#include "shadow/light_frustum.h"

namespace penumbra::render {

// ---- the caller's inputs -----------------------------------------------------------------------

// Where the camera's image goes: the window (all of it, or a region: a picture in picture), or a
// texture of the pool that later plans (or read_image) can read.
struct Output {
    bool window = false;
    std::string name = "camera";  // the texture's name in the pool (window: unused)
    int width = 512, height = 512;
    int x = 0, y = 0;   // window: the region's lower-left corner
    bool clip = false;  // window: keep clears inside the region
    gl::Sampling sampling = gl::Sampling::Nearest;  // texture, copy_to: how a later pass samples it
    gl::Wrap wrap = gl::Wrap::Clamp;
    // After the frame, the image drawn (the window's region, or the offscreen image) is copied into
    // the pool's texture of this name with glCopyTexImage2D: the course notes' first way to render
    // to a texture (W09P2b's rtt=copy). A later plan samples it as Output::copied(name, ...).
    std::string copy_to;
    // A texture that a copy fills (copy_to): colour only, no depth buffer of its own.
    bool copied = false;

    static Output offscreen(int width, int height);  // the texture "camera", read back by read_image()
    static Output to_window(int width, int height);
    static Output window_region(int x, int y, int width, int height);  // clipped
    static Output texture(std::string name, int width, int height, gl::Sampling sampling, gl::Wrap wrap);
    // The texture an earlier plan's copy_to filled, as a later plan's ImageOverride names it.
    static Output copied_texture(std::string name, int width, int height, gl::Sampling sampling, gl::Wrap wrap);
    // "offscreen 512x512", "window 800x600 at (0, 0)", "texture w09p2b 1024x1024"
    std::string describe() const;
};

// An object drawn with another mesh or material of the scene (-1: its own).
struct ObjectOverride {
    int object = -1;
    int mesh = -1;
    int material = -1;
};

// Wherever a material samples scene image `image`, sample the texture `texture` instead: an
// earlier plan's Output::texture (described the same way, so both plans declare one resource).
struct ImageOverride {
    int image = -1;
    Output texture;
};

struct FrameInputs {
    Output output = Output::offscreen(512, 512);
    std::optional<glm::mat4> view;        // the camera's view instead of the scene camera's
    std::optional<glm::mat4> projection;  // and its projection instead of yfov/znear/zfar's
    std::optional<scene::Light> light;    // the light instead of the scene's
    std::vector<ObjectOverride> objects;
    std::vector<ImageOverride> images;
};

FrameInputs offscreen(int width, int height);  // the default inputs at another size

// ---- resources ---------------------------------------------------------------------------------

// A render target (and the texture a later pass samples) by value; the pool keeps one per name and
// makes it again when its description changes.
struct ResourceDesc {
    std::string name;  // its role: "shadow-map", "camera", "w09p2b"
    int width = 0, height = 0;
    bool color = true;                                      // an RGBA8 colour texture...
    bool half_float = false;                                // ...RGBA16F instead (Caps::half_float_target)
    int colors = 1;  // colour textures (with color): more than 1, attachments 0.. (Caps::draw_buffers)
    std::optional<gl::RenderbufferFormat> depth_buffer;     // a depth (or depth-stencil) renderbuffer
    bool depth_texture = false;                             // a depth texture (OES_depth_texture)
    // The colour texture is a cube map of six width x width faces (RGBA8; width == height), a
    // framebuffer per face (TargetRef::face) sharing the one depth buffer.
    bool cube = false;
    gl::Sampling sampling = gl::Sampling::Nearest;          // of the texture a pass samples
    gl::Wrap wrap = gl::Wrap::Clamp;
    std::size_t bytes() const;
    std::string describe() const;  // "1024x1024 rgba8 + depth24, nearest, clamp"
    bool operator==(const ResourceDesc& o) const;
    bool operator!=(const ResourceDesc& o) const { return !(*this == o); }
};

struct PlannedResource {
    ResourceDesc desc;
    // What it holds, as a key of everything its passes depend on (e.g. the light's matrix and the
    // casters' transforms). The same non-empty key as in the previous plan: its content is still
    // there, and the passes into it are skipped. Empty: drawn every frame (or only read here).
    std::string content;
    bool reused = false;
    std::string purpose;  // one line for people: "the depth seen from the light"
};

// ---- passes ------------------------------------------------------------------------------------

// Where a pass draws: a resource of the plan, or the default framebuffer (the window); the
// viewport is a region of it (the whole of it unless a region was asked for).
struct TargetRef {
    int resource = -1;  // index into FramePlan::resources; -1: the window
    int width = 0, height = 0;
    int x = 0, y = 0;
    bool clip = false;
    int face = 0;  // a cube resource's face drawn into (ResourceDesc::cube), 0..5
};

struct Clear {
    std::optional<glm::vec4> color;
    bool depth = false;
    bool stencil = false;
};

using UniformValue = std::variant<int, float, glm::vec2, glm::vec3, glm::vec4, glm::mat3, glm::mat4>;
struct Uniform {
    std::string name;
    UniformValue value;
};
struct TextureBinding {
    int unit = 0;
    int resource = -1;   // the resource's sampled texture
    int attachment = 0;  // which of its colour textures (ResourceDesc::colors)
};
// Uniforms and textures that some draws of a pass share: "camera", "spot light", "shadow lookup".
struct Binding {
    std::string name;
    std::vector<Uniform> uniforms;
    std::vector<TextureBinding> textures;
};

// The uniforms the executor sets per draw from the object itself.
enum class ObjectUniforms {
    None,  // a full-screen draw
    Mvp,   // u_mvp = pass view_proj * draw.world
    Lit,   // u_model, u_normal_matrix and the material (colour, specular, shininess, base texture)
    Model, // u_model and u_normal_matrix only (the outline: no material)
};

// The texture unit of a Lit draw's base-colour texture (the techniques' maps take the others).
inline constexpr int kBaseTextureUnit = 1;

struct Draw {
    bool fullscreen = false;  // one triangle over the viewport instead of a mesh
    int object = -1;          // the scene object
    std::string label;        // its name, for listings
    int mesh = -1;            // the mesh drawn (an override may differ from the object's)
    int material = -1;
    glm::mat4 world{1.0f};
    Variant variant;
    std::uint32_t bindings = 0;  // bit i set: the pass's bindings[i] applies to this draw
    int image = -1;              // Lit: the scene image sampled as base colour (-1: none)...
    int image_resource = -1;     // ...or this resource's texture instead (an ImageOverride)
    // Uniforms of this draw alone, set after the pass's bindings (a deferred point light's).
    std::vector<Uniform> uniforms;
    std::optional<gl::Cull> cull;  // the pass's state with this face culling instead (a shadow map's faces)
    // The material's alpha is read (ALPHA_TEST, ALPHA_BLEND): the executor sets u_base_color,
    // u_alpha_cutoff and the base texture (`image`) in any pass, depth and stencil passes too.
    bool alpha = false;
    // Instead of a mesh: triangles of homogeneous world points made for this frame (a shadow
    // volume), drawn with the pass's view_proj (ObjectUniforms::Mvp, world = identity).
    std::shared_ptr<const std::vector<glm::vec4>> triangles;
    // mesh, material and image index the scene's portal's other scene (scene::Portal::beyond).
    bool beyond = false;
};

struct Pass {
    std::string name;    // "shadow-map", "camera", "planar-stencil", ...
    std::string module;  // who added it: "shadowmap", "planar", "frame"
    TargetRef target;
    std::optional<Clear> clear;
    gl::PipelineState state;
    ObjectUniforms object_uniforms = ObjectUniforms::Lit;
    glm::mat4 view_proj{1.0f};  // Mvp: the matrix before each draw's world
    std::vector<Binding> bindings;
    std::vector<Draw> draws;
    bool skipped = false;  // its target's content is reused: nothing is drawn
    // A key of what it draws into its region of the target (a cube face's tile), for a target
    // whose content as a whole has none: the same key as the same pass's in the previous plan,
    // into the same resource, and it is skipped (its region still holds it).
    std::string content;
    // After its draws (a copy pass has none): its target's region copied into this resource's
    // texture with glCopyTexImage2D (Output::copy_to); -1: none.
    int copy_to = -1;
    std::string detail;    // one line for people: "1024x1024 rgba, perspective light, 2 caster(s)"
    std::vector<int> reads() const;  // the resources its draws sample
};

// ---- the stencil -------------------------------------------------------------------------------

// One named use of the stencil buffer in a frame: a module declares it (name, the bits it needs,
// whether it counts) and plan() gives it bits of the target's stencil (allocate_stencil), so that
// two uses in one frame never touch each other's bits. A pass's stencil state is made through its
// use: values are shifted into the use's bits and the read and write masks are those bits.
struct StencilUse {
    std::string name;    // "planar: shadowed ground", "outline: the model's pixels"
    std::string module;  // who declared it
    int bits = 1;        // the bits it needs at least
    // Its values change by incr/decr (planar, gooch: 1 -> 2; volumes: a wrapping count). Those act
    // on the whole stencil value, so a counting use must hold the lowest bits (a carry out of them
    // is masked away); at most one per frame, and it takes every bit the others leave.
    bool counts = false;
    // Given by allocate_stencil: bits [shift, shift + width).
    int shift = 0;
    int width = 0;

    std::uint32_t mask() const;            // the use's bits: 0x03, 0x80
    int ref(int value) const;              // `value` shifted into them
    std::uint32_t top_bit() const;         // the highest of its bits (a count's sign)
    // The stencil test comparing the use's bits with `value`, `pass` written into its bits only.
    gl::StencilState test(gl::Compare func, int value, gl::StencilOp pass = gl::StencilOp::Keep) const;
    // Two-sided wrapping counting in its bits (gl::stencil_count).
    gl::StencilState count(bool on_depth_fail) const;
    // "bits 0-6 (mask 7f)"
    std::string describe() const;
};

// Gives each use its bits: the counting use (if any) the lowest, and every bit no other use needs;
// the others, in order, from the top bit down, each exactly its `bits`. "" or one line naming the
// uses that do not fit in `available` bits (or the two that both count).
std::string allocate_stencil(std::vector<StencilUse>& uses, int available);

// ---- the plan ----------------------------------------------------------------------------------

// The camera's clear colour (--aov color): what is seen where nothing is, in a mirror too.
inline constexpr glm::vec4 kBackground{0.12f, 0.13f, 0.16f, 1.0f};

struct CameraView {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::mat4 view_proj{1.0f};
    glm::vec3 position{0.0f};
};

// What executing a plan asks of GL, counted from the plan alone (Renderer::run_pass's rules): the
// pipeline-state calls are only those that change something (gl::Device::apply compares), a
// program is switched only when the next draw's differs, and a texture is not bound again to a unit
// that holds it already (gl::Device::bind_texture): those are counted as skipped.
struct StateCounts {
    int passes = 0;          // passes that run (not skipped)
    int state_calls = 0;     // depth, cull, colour mask, stencil calls
    int program_switches = 0;
    int uniform_sets = 0;    // shared-binding uniforms (per-draw ones not counted)
    int texture_binds = 0;          // made
    int texture_binds_skipped = 0;  // asked for, but the unit held the texture already
    int draws = 0;
};

// A module's statistics of the frame (the shadow map's light frustum and texel use, its cascades,
// a cube's faces, the shadow volumes' cost, the light samples' progress): a value of the module's
// own type, and how it prints (its lines for `penumbra plan`, its JSON value), both the module's.
// The plan holds them as a list: it knows no technique's results. The module's header says the
// type (T::kKey is the report's key; plan/techniques/reports.h, plan/frames/area_light.h).
struct Report {
    std::string key;
    std::any value;
    std::string (*text)(const std::any&) = nullptr;  // lines, each ending in a newline ("" none)
    std::string (*json)(const std::any&) = nullptr;  // its JSON value
};

// Where a report of this key goes in `penumbra plan`'s text and JSON, and the JSON written when no
// module reported it this frame (the registry's list, plan/techniques/techniques.cpp): each key
// is always in the JSON. Keys not in the list follow, in the order they were reported.
struct ReportSlot {
    std::string_view key;
    std::string_view absent_json;
};
const std::vector<ReportSlot>& report_slots();

struct FramePlan {
    Settings settings;
    std::string output;  // "offscreen 512x512", "window 800x600", "texture w09p2b 1024x1024"
    std::vector<PlannedResource> resources;
    std::vector<Pass> passes;
    std::vector<std::string> notes;  // e.g. a clamped map size
    CameraView camera;
    // The modules' statistics of this frame (Report), at most one of each key.
    std::vector<Report> reports;
    // The frame's stencil uses with their bits (empty: the frame uses no stencil) out of
    // stencil_bits, the target's.
    std::vector<StencilUse> stencil;
    int stencil_bits = 0;
    const StencilUse* stencil_use(std::string_view name) const;  // null when absent

    int resource_index(std::string_view name) const;  // -1 when absent
    const PlannedResource* resource(std::string_view name) const;
    bool has_pass(std::string_view name) const;
    // A pass into the resource ran in this plan (false when it was reused or is absent).
    bool drawn(std::string_view name) const;

    // The report of type T (its key T::kKey), or null.
    template <typename T>
    const T* find() const {
        for (const Report& r : reports)
            if (r.key == T::kKey) return std::any_cast<T>(&r.value);
        return nullptr;
    }
    template <typename T>
    T* find() {
        for (Report& r : reports)
            if (r.key == T::kKey) return std::any_cast<T>(&r.value);
        return nullptr;
    }
    // Reports `value` (in place of a report of the same key), printed by T::text and T::json; the
    // reference holds until the next put.
    template <typename T>
    T& put(T value) {
        drop(T::kKey);
        reports.push_back({T::kKey, std::any(std::move(value)),
                           [](const std::any& a) { return T::text(*std::any_cast<T>(&a)); },
                           [](const std::any& a) { return T::json(*std::any_cast<T>(&a)); }});
        return *std::any_cast<T>(&reports.back().value);
    }
    void drop(std::string_view key);

    StateCounts state_counts() const;
    std::string describe() const;  // one line per pass (render -v)
    std::string to_text() const;   // every pass and resource in full (penumbra plan)
    std::string to_json() const;   // the same as JSON (penumbra plan --json)
};

// "" when the settings can render this scene on this context into this output, else one line
// naming the problem.
std::string check(const scene::Scene& scene, const Settings& settings, const gl::Caps& caps,
                  const FrameInputs& inputs = {});

// The plan of one frame. `previous`, the plan last executed on the same renderer (or null), tells
// which resources still hold what this frame needs.
FramePlan plan(const scene::Scene& scene, const Settings& settings, const gl::Caps& caps,
               const FrameInputs& inputs = {}, const FramePlan* previous = nullptr);

// The camera's view and projection for a frame: the inputs' view or projection, else the scene
// camera's (its aspect, or the output's when it has none).
CameraView camera_view(const scene::Scene& scene, const FrameInputs& inputs);

// Whether an object casts a shadow in this frame: it casts (Object::casts_shadow), has a mesh,
// and its material is not glTF BLEND, unless blend_shadows (--blend-shadows on) says BLEND casts.
bool casts(const scene::Scene& scene, const scene::Object& object, bool blend_shadows);
// The material of a draw or object (a default one for an index out of range).
const scene::Material& material_of(const scene::Scene& scene, int material);

// The world bounds of every object that casts or receives shadows.
scene::Bounds shadowed_bounds(const scene::Scene& scene);
// The world bounds of the objects (with a valid mesh) that receive shadows and of those that cast
// them, each in scene order (PlanContext::casters' order).
struct ShadowBounds {
    std::vector<scene::Bounds> receivers;
    std::vector<scene::Bounds> casters;
    shadow::CastingInfo casting;  // their objects and the casters' convexity (the shadows fit's)
};
ShadowBounds shadow_bounds(const scene::Scene& scene, bool blend_shadows = false);
// The light's frustum fitted tightly around the receivers a camera with this view-projection
// sees and the casters that can shadow them (shadow::fit_light_frustum_tight): the shadow map's
// fit, and exercise W09P2a's view from the light.
shadow::LightFrustum fit_light_view(const scene::Scene& scene, const scene::Light& light, const glm::mat4& camera_view_proj);

}  // namespace penumbra::render
