// The frame: from the scene and the settings to the passes the scene requires, their render
// targets and shader variants, and the drawing. Only what the scene asks for exists: no shadow
// pass without casters, no stencil without planar shadows, no map redrawn whose light and casters
// did not move.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/caps.h"
#include "gl/device.h"
#include "gl/objects.h"
#include "render/settings.h"
#include "render/shader_library.h"
#include "scene/scene.h"
#include "shadow/light_frustum.h"

namespace penumbra::render {

struct PassInfo {
    std::string name;    // "shadow-map", "camera", "planar-stencil", ...
    std::string detail;  // target, size, variant, what it draws
};

struct FramePlan {
    std::vector<PassInfo> passes;
    bool shadow_map = false;       // this frame looks up a shadow map
    bool shadow_redrawn = false;   // ...drawn this frame (false: reused from an earlier frame)
    int map_size = 0;              // after clamping to the context's maximum
    std::vector<std::string> notes;  // e.g. a clamped map size
    std::string describe() const;  // one line per pass, for --verbose
};

class Renderer {
public:
    explicit Renderer(gl::Caps caps);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const gl::Caps& caps() const { return caps_; }

    // "" when the settings can render this scene on this context, else one line naming the problem.
    std::string check(const scene::Scene& scene, const Settings& s) const;

    // Uploads the scene's meshes and images. Call once per scene (the animated parts, object
    // matrices and the light, are read from the scene at every render()).
    void load(const scene::Scene& scene);

    // Renders one frame, loading the scene first if its meshes are not the ones uploaded. Headless
    // (window == nullptr) it draws into an offscreen target of the settings' size; read_image()
    // reads it back. Throws gl::Error on any GL failure, naming the pass.
    const FramePlan& render(const scene::Scene& scene, const Settings& s, const gl::Target* window = nullptr);

    // The last offscreen frame, RGBA8, top row first.
    std::vector<std::uint8_t> read_image();
    void finish() { device_.finish(); }

    const shadow::LightFrustum& light_frustum() const { return frustum_; }
    const glm::mat4& camera_view_proj() const { return camera_view_proj_; }
    // Bytes held by the shadow map's targets (0 when there is none).
    std::size_t shadow_map_bytes() const;
    ShaderLibrary& shaders() { return shaders_; }

    // For the exercise apps (W09P2b: the scene rendered into an FBO, that texture on the ground):
    // wherever a material uses scene image `image`, sample `texture` (caller-owned; it must stay
    // alive while set) instead of the uploaded image. nullptr removes the override.
    void set_image_override(int image, const gl::Texture* texture);
    // The pixels of `target` (the window, an FBO, or a region of one), RGBA8, top row first.
    std::vector<std::uint8_t> read_target(const gl::Target& target);
    // How this context converts float to unorm8, found by a probe when the renderer was made;
    // the packing shaders are compiled for it (PACK_FLOOR when it truncates).
    shadow::UnormRounding unorm_rounding() const { return rounding_; }

private:
    struct GpuMesh;
    struct ShadowTarget;
    struct CameraTarget;
    struct ShadowKey {
        glm::mat4 light_view_proj{0.0f};
        std::vector<glm::mat4> casters;
        std::vector<int> meshes;
        shadow::Encoding encoding = shadow::Encoding::RGBA;
        int size = 0;
        bool mediump = false;
        bool operator==(const ShadowKey& o) const;
    };

    void ensure_shadow_target(shadow::Encoding e, int size);
    void ensure_camera_target(int width, int height, bool stencil);
    void draw_shadow_map(const scene::Scene& scene, const std::vector<int>& casters, shadow::Encoding e, int size,
                         const DepthPath& path);
    void draw_lit(const scene::Scene& scene, const scene::Object& object, const LitFeatures& features,
                  const Settings& s);
    void draw_light_depth(shadow::Encoding e, const DepthPath& path);
    shadow::UnormRounding probe_unorm_rounding();
    static std::vector<float> fingerprint(const scene::Scene& scene);
    DepthPath depth_path(const Settings& s) const;

    gl::Caps caps_;
    gl::Device device_;
    ShaderLibrary shaders_;
    std::vector<GpuMesh> meshes_;
    std::vector<gl::Texture> images_;
    std::vector<const gl::Texture*> image_overrides_;  // by scene image index; null: none
    std::unique_ptr<ShadowTarget> shadow_;
    std::unique_ptr<CameraTarget> camera_target_;
    std::optional<ShadowKey> drawn_key_;
    shadow::LightFrustum frustum_;
    glm::mat4 camera_view_proj_{1.0f};
    glm::vec3 camera_pos_{0.0f};
    FramePlan plan_;
    shadow::UnormRounding rounding_ = shadow::UnormRounding::Round;
    std::vector<float> loaded_;  // fingerprint of the scene whose meshes and images are uploaded
};

}  // namespace penumbra::render
