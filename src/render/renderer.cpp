#include "render/renderer.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <glm/gtc/matrix_inverse.hpp>

#include "gl/check.h"

namespace penumbra::render {

namespace {

bool power_of_two(int v) { return v > 0 && (v & (v - 1)) == 0; }

void set_uniform(const gl::Program& p, const Uniform& u) {
    std::visit([&](const auto& v) { p.set(u.name.c_str(), v); }, u.value);
}

}  // namespace

Renderer::Renderer(gl::Caps caps) : caps_(std::move(caps)), timer_(caps_.timer_query) {}
Renderer::~Renderer() = default;

void Renderer::probe_unorm_rounding() {
    // 0.6/255 is 1 when the context rounds and 0 when it truncates; 128.6/255 and 254.6/255 check
    // the same in the middle and at the top of the range. A plan of one full-screen pass into a
    // 1x1 target, run like any frame.
    FramePlan probe;
    probe.output = "the unorm8 probe";
    ResourceDesc d;
    d.name = "unorm8 probe";
    d.width = d.height = 1;
    PlannedResource r;
    r.desc = d;
    r.purpose = "how this context turns a float into a byte";
    probe.resources.push_back(r);
    Pass p;
    p.name = "unorm8 probe";
    p.module = "renderer";
    p.target = {0, 1, 1, 0, 0, false};
    p.state.depth_test = false;
    p.state.cull = gl::Cull::None;
    p.object_uniforms = ObjectUniforms::None;
    p.bindings.push_back({"value", {{"u_value", glm::vec4(0.6f, 128.6f, 254.6f, 255.0f) / 255.0f}}, {}});
    Draw draw;
    draw.fullscreen = true;
    draw.variant = probe_variant();
    draw.bindings = 1u;
    p.draws.push_back(draw);
    probe.passes.push_back(p);
    run(scene::Scene{}, probe);
    const auto px = read_image(d.name);
    caps_.unorm_probe = {px[0], px[1], px[2]};
}

std::string Renderer::unorm_report() {
    if (caps_.unorm_probe[0] < 0) probe_unorm_rounding();
    const auto& b = caps_.unorm_probe;
    const std::string kind = caps_.unorm_rounds()   ? "round"
                             : caps_.unorm_floors() ? "floor"
                                                    : "mixed (either closest byte)";
    return "float -> unorm8 conversion: " + kind + " (probed: 0.6/255, 128.6/255, 254.6/255 stored as " +
           std::to_string(b[0]) + ", " + std::to_string(b[1]) + ", " + std::to_string(b[2]) +
           "; the packing stores the same bytes under each)";
}

void Renderer::set_snippets(std::string text) {
    if (text == shaders_.snippets()) return;
    shaders_.set_snippets(std::move(text));
    previous_.reset();
}

std::string Renderer::check(const scene::Scene& scene, const Settings& s, const FrameInputs& in) const {
    return render::check(scene, s, caps_, in);
}

std::vector<float> Renderer::fingerprint(const scene::Scene& scene) {
    // Counts and a few sample positions and indices per mesh and image: cheap enough for every
    // frame, and a different scene (even one allocated where the last one was, or the same points
    // with the triangles' winding turned) is all but sure to differ.
    std::vector<float> f;
    for (const auto& m : scene.meshes) {
        f.push_back(static_cast<float>(m.positions.size()));
        f.push_back(static_cast<float>(m.indices.size()));
        for (size_t i : {size_t{0}, m.positions.size() / 2, m.positions.size() - 1})
            if (i < m.positions.size()) f.insert(f.end(), {m.positions[i].x, m.positions[i].y, m.positions[i].z});
        for (size_t i : {size_t{1}, m.indices.size() / 2, m.indices.size() - 2})
            if (i < m.indices.size()) f.push_back(static_cast<float>(m.indices[i]));
    }
    for (const auto& img : scene.images) f.insert(f.end(), {static_cast<float>(img.width), static_cast<float>(img.height)});
    if (scene.portal && scene.portal->beyond) {
        const std::vector<float> beyond = fingerprint(*scene.portal->beyond);
        f.push_back(-1.0f);  // where the portal's scene begins
        f.insert(f.end(), beyond.begin(), beyond.end());
    }
    return f;
}

void Renderer::load(const scene::Scene& scene) {
    loaded_ = fingerprint(scene);
    previous_.reset();
    scene_ = upload(scene);
    beyond_ = scene.portal && scene.portal->beyond ? upload(*scene.portal->beyond) : Uploaded{};
}

Renderer::Uploaded Renderer::upload(const scene::Scene& scene) {
    Uploaded u;
    for (const auto& m : scene.meshes)
        u.meshes.push_back(device_.upload_mesh(m.positions, m.normals, m.uvs, m.indices, caps_.element_index_uint,
                                               m.name.c_str()));
    for (const auto& img : scene.images) u.images.push_back(texture(img));
    return u;
}

gl::Texture Renderer::texture(const scene::Image& img) {
    gl::TextureDesc d;
    d.width = img.width;
    d.height = img.height;
    d.rgba = img.rgba.data();
    // GLES2 mipmaps and repeat need power-of-two sizes.
    const bool pot = power_of_two(img.width) && power_of_two(img.height);
    d.sampling = pot ? gl::Sampling::LinearMipmap : gl::Sampling::Linear;
    d.wrap = pot ? gl::Wrap::Repeat : gl::Wrap::Clamp;
    d.label = "scene image";
    return gl::Texture(d);
}

bool Renderer::has_loaded(const scene::Scene& scene) const { return !loaded_.empty() && fingerprint(scene) == loaded_; }

void Renderer::update_image(std::size_t index, const scene::Image& image) {
    if (index < scene_.images.size()) scene_.images[index] = texture(image);
}

FramePlan Renderer::plan(const scene::Scene& scene, const Settings& s, const FrameInputs& in) const {
    // A scene other than the uploaded one starts without a previous plan (render() loads it first).
    const bool same = fingerprint(scene) == loaded_;
    return render::plan(scene, s, caps_, in, same && previous_ ? &*previous_ : nullptr);
}

const FramePlan& Renderer::render(const scene::Scene& scene, const Settings& s, const FrameInputs& in) {
    if (fingerprint(scene) != loaded_) load(scene);
    if (const std::string problem = check(scene, s, in); !problem.empty()) throw std::invalid_argument(problem);
    FramePlan next = render::plan(scene, s, caps_, in, previous_ ? &*previous_ : nullptr);
    previous_.reset();  // until the new plan has run through: a failure leaves nothing to reuse
    run(scene, next);
    previous_ = std::move(next);
    return *previous_;
}

void Renderer::execute(const scene::Scene& scene, const FramePlan& plan) {
    if (fingerprint(scene) != loaded_) load(scene);
    previous_.reset();
    run(scene, plan);
    previous_ = plan;
}

void Renderer::run(const scene::Scene& scene, const FramePlan& plan) {
    ++runs_;
    pool_.prepare(plan);
    device_.forget_textures();
    timer_.begin_frame();
    for (const Pass& pass : plan.passes) {
        if (!pass.skipped) timer_.begin_pass(pass.name);
        run_pass(scene, plan, pass);
        timer_.end_pass();
        if (!gl::kErrorQueryWaits && !pass.skipped) gl::check_errors(("the " + pass.name + " pass").c_str());
    }
    // In the browser one check for the whole frame (each is a stall: gl/check.h), which also
    // takes what the objects made since the last one raised (gl::check_made).
    if (gl::kErrorQueryWaits) {
        std::string passes;
        for (const Pass& pass : plan.passes)
            if (!pass.skipped) passes += (passes.empty() ? "" : ", ") + pass.name;
        gl::check_errors(("the frame's passes (" + passes + ") or the GL objects made for them").c_str());
    }
    timer_.end_frame();
    device_.apply(gl::PipelineState{});
    for (auto it = triangles_.begin(); it != triangles_.end();) {
        if (it->second.run + 1 >= runs_) {
            ++it;
            continue;
        }
        if (spare_.size() < kSpareBuffers && it->second.buffer.id() != 0) spare_.push_back(std::move(it->second.buffer));
        it = triangles_.erase(it);
    }
}

const gl::Buffer& Renderer::triangle_buffer(const std::shared_ptr<const std::vector<glm::vec4>>& list) {
    TriangleBuffer& b = triangles_[list.get()];
    if (b.list != list) {  // new here
        b.list = list;
        const std::size_t bytes = list->size() * sizeof(glm::vec4);
        // The smallest spare buffer it fits, refilled; else a new one with a quarter to spare (a
        // moving volume grows and shrinks a little from frame to frame).
        auto fit = spare_.end();
        for (auto it = spare_.begin(); it != spare_.end(); ++it)
            if (it->bytes() >= bytes && (fit == spare_.end() || it->bytes() < fit->bytes())) fit = it;
        if (fit != spare_.end()) {
            b.buffer = std::move(*fit);
            spare_.erase(fit);
            b.buffer.update(list->data(), bytes);
            ++triangle_refills_;
        } else {
            b.buffer = device_.upload_points(*list, "triangles (a shadow volume)", bytes + bytes / 4);
        }
        ++triangle_uploads_;
    }
    b.run = runs_;
    return b.buffer;
}

// The only code that draws a frame: each pass binds its target, clears, sets its state, binds its
// textures, and draws, setting a binding's uniforms whenever the program or the draw's bindings
// change and the object's own uniforms for every draw.
void Renderer::run_pass(const scene::Scene& scene, const FramePlan& plan, const Pass& pass) {
    if (pass.skipped) return;
    device_.bind_target(pool_.target(plan, pass.target));
    if (pass.clear) device_.clear(pass.clear->color ? &*pass.clear->color : nullptr, pass.clear->depth, pass.clear->stencil);
    device_.apply(pass.state);
    for (const Binding& b : pass.bindings)
        for (const TextureBinding& t : b.textures)
            device_.bind_texture(t.unit,
                                 pool_.texture(plan.resources[static_cast<size_t>(t.resource)].desc.name, t.attachment));
    const gl::Program* program = nullptr;
    std::uint32_t bound = 0;
    gl::Cull cull = pass.state.cull;
    for (const Draw& d : pass.draws) {
        if (d.cull.value_or(pass.state.cull) != cull) {
            gl::PipelineState st = pass.state;
            st.cull = cull = d.cull.value_or(pass.state.cull);
            device_.apply(st);
        }
        // The draw's mesh, material and image: the scene's, or its portal's other scene's.
        if (d.beyond && !(scene.portal && scene.portal->beyond))
            throw gl::Error("the " + pass.name + " pass: a draw from the portal's scene, but this scene has no portal");
        const scene::Scene& from = d.beyond ? *scene.portal->beyond : scene;
        const Uploaded& up = d.beyond ? beyond_ : scene_;
        const gl::Program& p = shaders_.get(d.variant);
        if (&p != program || d.bindings != bound) {
            device_.use(p);
            for (size_t i = 0; i < pass.bindings.size(); ++i)
                if (d.bindings & (1u << i))
                    for (const Uniform& u : pass.bindings[i].uniforms) set_uniform(p, u);
            program = &p;
            bound = d.bindings;
        }
        if (pass.object_uniforms == ObjectUniforms::Mvp) {
            p.set("u_mvp", pass.view_proj * d.world);
            if (d.alpha) {  // a cut-out caster: its alpha, as the camera pass reads it
                const scene::Material& m = material_of(from, d.material);
                p.set("u_base_color", m.base_color);
                p.set("u_alpha_cutoff", m.alpha_cutoff);
                if (d.image >= 0) {
                    device_.bind_texture(kBaseTextureUnit, up.images[static_cast<size_t>(d.image)]);
                    p.set("u_base_texture", kBaseTextureUnit);
                }
            }
        } else if (pass.object_uniforms == ObjectUniforms::Model) {
            p.set("u_model", d.world);
            p.set("u_normal_matrix", glm::inverseTranspose(glm::mat3(d.world)));
        } else if (pass.object_uniforms == ObjectUniforms::Lit) {
            const scene::Material& m = material_of(from, d.material);
            p.set("u_model", d.world);
            p.set("u_normal_matrix", glm::inverseTranspose(glm::mat3(d.world)));
            p.set("u_base_color", m.base_color);
            p.set("u_specular", m.specular);
            p.set("u_shininess", m.shininess);
            // BLEND (d.alpha too) is blended, not cut: only MASK's variant has ALPHA_TEST's cutoff.
            if (m.alpha_mode == scene::AlphaMode::Mask) p.set("u_alpha_cutoff", m.alpha_cutoff);
            if (d.image >= 0) {
                device_.bind_texture(kBaseTextureUnit,
                                     d.image_resource >= 0
                                         ? pool_.texture(plan.resources[static_cast<size_t>(d.image_resource)].desc.name)
                                         : up.images[static_cast<size_t>(d.image)]);
                p.set("u_base_texture", kBaseTextureUnit);
            }
        }
        for (const Uniform& u : d.uniforms) set_uniform(p, u);
        if (d.fullscreen) device_.draw_fullscreen();
        else if (d.triangles) {
            if (!d.triangles->empty()) device_.draw_points(triangle_buffer(d.triangles), d.triangles->size());
        }
        else device_.draw(up.meshes[static_cast<size_t>(d.mesh)]);
    }
    if (pass.copy_to >= 0) {
        const gl::Target t = pool_.target(plan, pass.target);
        pool_.copy_into(plan.resources[static_cast<size_t>(pass.copy_to)].desc.name, t.x, t.y, t.width, t.height);
        device_.forget_textures();
    }
}

std::vector<std::uint8_t> Renderer::read_rows(const gl::Target& target) {
    device_.bind_target(target);
    std::vector<std::uint8_t> px = device_.read_rgba(target.x, target.y, target.width, target.height);
    // GL reads the bottom row first; images are stored top row first.
    const size_t row = static_cast<size_t>(target.width) * 4u;
    for (int y = 0; y < target.height / 2; ++y)
        std::swap_ranges(px.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(y) * row),
                         px.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(y + 1) * row),
                         px.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(target.height - 1 - y) * row));
    return px;
}

std::vector<std::uint8_t> Renderer::read_image(const std::string& resource) {
    if (!pool_.has(resource)) throw gl::Error("read_image: no '" + resource + "' target: nothing rendered offscreen yet");
    return read_rows(pool_.whole(resource));
}

std::vector<std::uint8_t> Renderer::read_window(int x, int y, int width, int height) {
    return read_rows(gl::Target{nullptr, width, height, x, y, false});
}

}  // namespace penumbra::render
