// The renderer: plans a frame (plan/plan.h) and executes the plan. It holds what lives on the
// GL context (the scene's meshes and images, the compiled shader variants, the pool of render
// targets) and the last plan it executed, which tells the next plan what it may reuse; a frame's
// passes, targets and variants are the plan's, not the renderer's.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "gl/caps.h"
#include "gl/device.h"
#include "gl/objects.h"
#include "gl/timer.h"
#include "plan/plan.h"
#include "render/pool.h"
#include "plan/settings.h"
#include "render/shader_library.h"
#include "scene/scene.h"

namespace penumbra::render {

class Renderer {
public:
    // `caps` from gl::probe_caps on the current context; the renderer adds what its unorm8 probe
    // finds (Caps::unorm_probe) when unorm_report() first asks, not here: the probe is a program
    // compiled, drawn and read back, which a page's first frame would wait for (docs/payload.md).
    explicit Renderer(gl::Caps caps);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const gl::Caps& caps() const { return caps_; }

    // "" when the settings can render this scene on this context into this output, else one line
    // naming the problem (render::check).
    std::string check(const scene::Scene& scene, const Settings& s, const FrameInputs& in = {}) const;

    // Uploads the scene's meshes and images (and its portal's other scene's). render() does it when the scene's meshes are not the
    // ones uploaded; the animated parts (object matrices, the light) are read at every frame.
    void load(const scene::Scene& scene);
    // Whether `scene` is the one uploaded (its fingerprint: a few of its vertices).
    bool has_loaded(const scene::Scene& scene) const;
    // Uploads image `index` of the loaded scene again, changed in place (the scene's fingerprint
    // does not see images): the marble that the pages make after their first frame.
    void update_image(std::size_t index, const scene::Image& image);

    // The plan of the next frame, without drawing it.
    FramePlan plan(const scene::Scene& scene, const Settings& s, const FrameInputs& in = {}) const;
    // Plans and executes one frame. Throws std::invalid_argument when check() names a problem and
    // gl::Error on any GL failure, naming the pass.
    const FramePlan& render(const scene::Scene& scene, const Settings& s, const FrameInputs& in = {});
    // Runs a plan made by plan() for the same scene; it becomes the previous plan of the next one.
    void execute(const scene::Scene& scene, const FramePlan& plan);
    // The plan last executed (null before the first frame, after load() and after a failure).
    const FramePlan* last_plan() const { return previous_ ? &*previous_ : nullptr; }

    // A texture of the pool (by default the offscreen camera image), RGBA8, top row first.
    std::vector<std::uint8_t> read_image(const std::string& resource = "camera");
    // A region of the window (the default framebuffer), RGBA8, top row first.
    std::vector<std::uint8_t> read_window(int x, int y, int width, int height);
    void finish() { device_.finish(); }

    ShaderLibrary& shaders() { return shaders_; }
    // The shader lab's snippets for Settings::lab frames (render/lab.h checks them first): the
    // previous plan is forgotten, so no map drawn with other snippets is reused.
    void set_snippets(std::string text);
    // For work outside a frame plan on the same context (render/mipmaps.h): its state cache.
    gl::Device& device() { return device_; }
    const ResourcePool& pool() const { return pool_; }
    // GPU time per pass (EXT_disjoint_timer_query, where Caps::timer_query): off until enabled;
    // each frame executed while it is on brackets its passes that draw, and take() reads them.
    gl::PassTimer& gpu_timer() { return timer_; }
    // How this context converts float to unorm8, found by a probe on the first call, in one line
    // for `penumbra caps` and `render -v` (the packing stores the same bytes either way):
    // "float -> unorm8 conversion: round (probed: ... stored as 1, 129, 255; ...)".
    std::string unorm_report();
    // Triangle lists (Draw::triangles: shadow volumes) uploaded since the renderer was made, and
    // those held on the context now: a list a later plan keeps (the same pointer) is drawn from
    // its buffer, not uploaded again.
    std::uint64_t triangle_uploads() const { return triangle_uploads_; }
    std::uint64_t triangle_refills() const { return triangle_refills_; }  // of those, into a dropped list's buffer
    std::size_t triangle_buffers() const { return triangles_.size(); }

private:
    void run(const scene::Scene& scene, const FramePlan& plan);
    void run_pass(const scene::Scene& scene, const FramePlan& plan, const Pass& pass);
    void probe_unorm_rounding();
    std::vector<std::uint8_t> read_rows(const gl::Target& target);
    static std::vector<float> fingerprint(const scene::Scene& scene);

    gl::Caps caps_;
    gl::Device device_;
    ShaderLibrary shaders_;
    // The scene's meshes and images, and its portal's other scene's (Draw::beyond).
    struct Uploaded {
        std::vector<gl::MeshBuffers> meshes;
        std::vector<gl::Texture> images;
    };
    Uploaded upload(const scene::Scene& scene);
    static gl::Texture texture(const scene::Image& img);
    Uploaded scene_, beyond_;
    ResourcePool pool_;
    std::optional<FramePlan> previous_;
    gl::PassTimer timer_;
    // Each Draw::triangles list drawn, uploaded once: the entry holds the list, so no other list can
    // take its address while it is here; a list no plan drew in this run or the one before (two
    // plans of a frame may alternate) is dropped after the run.
    struct TriangleBuffer {
        std::shared_ptr<const std::vector<glm::vec4>> list;
        gl::Buffer buffer;
        std::uint64_t run = 0;
    };
    const gl::Buffer& triangle_buffer(const std::shared_ptr<const std::vector<glm::vec4>>& list);
    std::unordered_map<const std::vector<glm::vec4>*, TriangleBuffer> triangles_;
    // The buffers of dropped lists (a moving caster's volume of two frames ago), refilled by the
    // next lists that fit rather than a buffer made and deleted each frame; at most kSpareBuffers.
    static constexpr std::size_t kSpareBuffers = 8;
    std::vector<gl::Buffer> spare_;
    std::uint64_t runs_ = 0, triangle_uploads_ = 0, triangle_refills_ = 0;
    std::vector<float> loaded_;  // fingerprint of the scene whose meshes and images are uploaded
};

}  // namespace penumbra::render
