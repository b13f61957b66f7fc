#include "render/renderer.h"

#include <algorithm>
#include <sstream>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/check.h"
#include "shadow/planar.h"

namespace penumbra::render {

struct Renderer::GpuMesh {
    gl::MeshBuffers buffers;
};

struct Renderer::ShadowTarget {
    shadow::Encoding encoding = shadow::Encoding::RGBA;
    int size = 0;
    gl::Texture map;          // RGBA8 (r8, rgba) or depth (depthtex): what the camera pass samples
    gl::Renderbuffer depth;   // depth buffer for the RGBA8 encodings
    gl::Framebuffer fb;
};

struct Renderer::CameraTarget {
    int width = 0, height = 0;
    bool stencil = false;
    gl::Texture color;
    gl::Renderbuffer depth;
    gl::Framebuffer fb;
};

namespace {

constexpr glm::vec4 kBackground{0.12f, 0.13f, 0.16f, 1.0f};
constexpr glm::vec4 kWhite{1.0f};
constexpr float kAmbient = 0.25f;
constexpr int kShadowUnit = 0;
constexpr int kBaseTextureUnit = 1;

bool valid_mesh(const scene::Scene& s, const scene::Object& o) {
    return o.mesh >= 0 && o.mesh < static_cast<int>(s.meshes.size());
}

const scene::Material& material_of(const scene::Scene& s, const scene::Object& o) {
    static const scene::Material fallback{};
    if (o.material < 0 || o.material >= static_cast<int>(s.materials.size())) return fallback;
    return s.materials[static_cast<size_t>(o.material)];
}

bool power_of_two(int v) { return v > 0 && (v & (v - 1)) == 0; }

std::string size_str(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

bool Renderer::ShadowKey::operator==(const ShadowKey& o) const {
    return light_view_proj == o.light_view_proj && casters == o.casters && meshes == o.meshes &&
           encoding == o.encoding && size == o.size && mediump == o.mediump;
}

std::string FramePlan::describe() const {
    std::string out;
    for (size_t i = 0; i < passes.size(); ++i)
        out += std::to_string(i + 1) + ". " + passes[i].name + ": " + passes[i].detail + "\n";
    return out;
}

Renderer::Renderer(gl::Caps caps) : caps_(std::move(caps)) { rounding_ = probe_unorm_rounding(); }

shadow::UnormRounding Renderer::probe_unorm_rounding() {
    // 0.6/255 is 1 when the context rounds and 0 when it truncates; 128.6/255 and 254.6/255 check
    // the same in the middle and at the top of the range.
    gl::TextureDesc d;
    d.width = d.height = 1;
    d.label = "unorm8 probe";
    gl::Texture tex(d);
    gl::FramebufferDesc fd;
    fd.color = &tex;
    fd.label = "unorm8 probe framebuffer";
    gl::Framebuffer fb(fd);
    device_.bind_target({&fb, 1, 1});
    gl::PipelineState st;
    st.depth_test = false;
    st.cull = gl::Cull::None;
    device_.apply(st);
    const gl::Program& p = shaders_.get(probe_variant());
    device_.use(p);
    p.set("u_value", glm::vec4(0.6f, 128.6f, 254.6f, 255.0f) / 255.0f);
    device_.draw_fullscreen();
    const auto px = device_.read_rgba(1, 1);
    device_.apply(gl::PipelineState{});
    gl::check_errors("the unorm8 probe");
    const bool rounds = px[0] == 1 && px[1] == 129 && px[2] == 255;
    const bool floors = px[0] == 0 && px[1] == 128 && px[2] == 254;
    if (!rounds && !floors)
        throw gl::Error("unorm8 probe: the context stored 0.6/255, 128.6/255, 254.6/255 as " + std::to_string(px[0]) +
                        ", " + std::to_string(px[1]) + ", " + std::to_string(px[2]) + ": neither rounding nor truncation");
    return rounds ? shadow::UnormRounding::Round : shadow::UnormRounding::Floor;
}

DepthPath Renderer::depth_path(const Settings& s) const {
    return {s.precision == shadow::Precision::Mediump, rounding_ == shadow::UnormRounding::Floor};
}
Renderer::~Renderer() = default;

std::string Renderer::check(const scene::Scene& scene, const Settings& s) const {
    const int max = caps_.max_target_size();
    if (s.width > max || s.height > max)
        return "--size " + size_str(s.width, s.height) + ": beyond this context's maximum of " + std::to_string(max);
    if (s.technique == Technique::ShadowMap && s.encoding == shadow::Encoding::DepthTex && !caps_.depth_texture)
        return "--encoding depthtex: this context has no OES_depth_texture / WEBGL_depth_texture";
    if (s.technique == Technique::Planar) {
        if (!scene.ground_plane || scene.ground_object < 0)
            return "--technique planar: the scene has no ground plane (a flat object named ground, floor, plane or "
                   "table)";
        if (!caps_.packed_depth_stencil)
            return "--technique planar: this context has no OES_packed_depth_stencil for the stencil buffer";
    }
    if (s.aov == Aov::LightDepth) {
        if (s.technique != Technique::ShadowMap) return "--aov light-depth: needs --technique shadowmap";
        const bool casters = std::any_of(scene.objects.begin(), scene.objects.end(), [&](const scene::Object& o) {
            return o.casts_shadow && valid_mesh(scene, o);
        });
        if (!casters) return "--aov light-depth: the scene has no shadow casters, so there is no shadow map";
    }
    return {};
}

std::vector<float> Renderer::fingerprint(const scene::Scene& scene) {
    // Counts and a few sample positions per mesh and image: cheap enough for every frame, and a
    // different scene (even one allocated where the last one was) is all but sure to differ.
    std::vector<float> f;
    for (const auto& m : scene.meshes) {
        f.push_back(static_cast<float>(m.positions.size()));
        f.push_back(static_cast<float>(m.indices.size()));
        for (size_t i : {size_t{0}, m.positions.size() / 2, m.positions.size() - 1})
            if (i < m.positions.size()) f.insert(f.end(), {m.positions[i].x, m.positions[i].y, m.positions[i].z});
    }
    for (const auto& img : scene.images) f.insert(f.end(), {static_cast<float>(img.width), static_cast<float>(img.height)});
    return f;
}

void Renderer::load(const scene::Scene& scene) {
    loaded_ = fingerprint(scene);
    meshes_.clear();
    images_.clear();
    drawn_key_.reset();
    for (const auto& m : scene.meshes)
        meshes_.push_back(GpuMesh{device_.upload_mesh(m.positions, m.normals, m.uvs, m.indices,
                                                      caps_.element_index_uint, m.name.c_str())});
    for (const auto& img : scene.images) {
        gl::TextureDesc d;
        d.width = img.width;
        d.height = img.height;
        d.rgba = img.rgba.data();
        // GLES2 mipmaps and repeat need power-of-two sizes.
        const bool pot = power_of_two(img.width) && power_of_two(img.height);
        d.sampling = pot ? gl::Sampling::LinearMipmap : gl::Sampling::Linear;
        d.wrap = pot ? gl::Wrap::Repeat : gl::Wrap::Clamp;
        d.label = "scene image";
        images_.emplace_back(d);
    }
}

void Renderer::ensure_shadow_target(shadow::Encoding e, int size) {
    if (shadow_ && shadow_->encoding == e && shadow_->size == size) return;
    auto t = std::make_unique<ShadowTarget>();
    t->encoding = e;
    t->size = size;
    gl::TextureDesc d;
    d.width = d.height = size;
    // Packed depths must never be interpolated: blending two packed values is meaningless.
    d.sampling = gl::Sampling::Nearest;
    d.wrap = gl::Wrap::Clamp;
    d.label = "shadow map";
    gl::FramebufferDesc fd;
    fd.label = "shadow map framebuffer";
    if (e == shadow::Encoding::DepthTex) {
        d.format = gl::TextureFormat::Depth;
        t->map = gl::Texture(d);
        fd.depth_texture = &t->map;
    } else {
        t->map = gl::Texture(d);
        t->depth = gl::Renderbuffer(caps_.depth24 ? gl::RenderbufferFormat::Depth24 : gl::RenderbufferFormat::Depth16,
                                    size, size, "shadow map depth");
        fd.color = &t->map;
        fd.depth = &t->depth;
    }
    t->fb = gl::Framebuffer(fd);
    shadow_ = std::move(t);
    drawn_key_.reset();
}

void Renderer::ensure_camera_target(int width, int height, bool stencil) {
    if (camera_target_ && camera_target_->width == width && camera_target_->height == height &&
        camera_target_->stencil == stencil)
        return;
    auto t = std::make_unique<CameraTarget>();
    t->width = width;
    t->height = height;
    t->stencil = stencil;
    gl::TextureDesc d;
    d.width = width;
    d.height = height;
    d.label = "camera colour";
    t->color = gl::Texture(d);
    const auto depth_format = stencil ? gl::RenderbufferFormat::Depth24Stencil8
                              : caps_.depth24 ? gl::RenderbufferFormat::Depth24
                                              : gl::RenderbufferFormat::Depth16;
    t->depth = gl::Renderbuffer(depth_format, width, height, "camera depth");
    gl::FramebufferDesc fd;
    fd.color = &t->color;
    fd.depth = &t->depth;
    fd.label = "camera framebuffer";
    t->fb = gl::Framebuffer(fd);
    camera_target_ = std::move(t);
}

std::size_t Renderer::shadow_map_bytes() const {
    if (!shadow_) return 0;
    return shadow_->map.bytes() + (shadow_->depth.id() ? shadow_->depth.bytes() : 0u);
}

void Renderer::draw_shadow_map(const scene::Scene& scene, const std::vector<int>& casters, shadow::Encoding e,
                               int size, const DepthPath& path) {
    device_.bind_target({&shadow_->fb, size, size});
    gl::PipelineState st;
    st.cull = gl::Cull::None;  // open meshes (the teapot's rim, glTF sheets) must cast from both sides
    st.color_write = e != shadow::Encoding::DepthTex;
    device_.apply(st);
    // White is the farthest depth in every encoding: nothing drawn there, nothing shadows.
    device_.clear(e == shadow::Encoding::DepthTex ? nullptr : &kWhite, true, false);
    const gl::Program& p = shaders_.get(depth_variant(e, path));
    device_.use(p);
    const glm::mat4 vp = frustum_.view_proj();
    for (int i : casters) {
        const auto& o = scene.objects[static_cast<size_t>(i)];
        p.set("u_mvp", vp * o.world);
        device_.draw(meshes_[static_cast<size_t>(o.mesh)].buffers);
    }
    gl::check_errors("the shadow-map pass");
}

void Renderer::draw_lit(const scene::Scene& scene, const scene::Object& o, const LitFeatures& f, const Settings& s) {
    const gl::Program& p = shaders_.get(lit_variant(f));
    device_.use(p);
    const scene::Material& m = material_of(scene, o);
    const scene::Light& light = scene.light;
    p.set("u_model", o.world);
    p.set("u_normal_matrix", glm::inverseTranspose(glm::mat3(o.world)));
    p.set("u_view_proj", camera_view_proj_);
    p.set("u_camera_pos", camera_pos_);
    p.set("u_base_color", m.base_color);
    p.set("u_specular", m.specular);
    p.set("u_shininess", m.shininess);
    p.set("u_ambient", kAmbient);
    p.set("u_light_color", light.color);
    p.set("u_light", light.type == scene::LightType::Directional ? glm::vec4(-light.direction, 0.0f)
                                                                  : glm::vec4(light.position, 1.0f));
    if (f.spot) {
        p.set("u_spot_direction", glm::normalize(light.direction));
        p.set("u_spot_cos", glm::vec2(std::cos(light.spot_outer_cone), std::cos(light.spot_inner_cone)));
    }
    if (f.textured) {
        const auto image = static_cast<size_t>(m.base_color_texture);
        const bool overridden = image < image_overrides_.size() && image_overrides_[image];
        device_.bind_texture(kBaseTextureUnit, overridden ? *image_overrides_[image] : images_[image]);
        p.set("u_base_texture", kBaseTextureUnit);
    }
    if (f.shadow_map) {
        device_.bind_texture(kShadowUnit, shadow_->map);
        p.set("u_shadow_map", kShadowUnit);
        p.set("u_light_matrix", shadow::clip_to_texture() * frustum_.view_proj());
        const float texel = 1.0f / static_cast<float>(shadow_->size);
        p.set("u_texmapscale", glm::vec2(texel, texel));
        p.set("u_bias", s.effective_bias());
        if (f.bias_auto) {
            // 1/P[0][0] and 1/P[1][1]: tan of the half-angles (perspective) or the half-extents
            // (orthographic) of the light's frustum.
            const glm::mat4& proj = frustum_.proj;
            p.set("u_light_rotation", glm::mat3(frustum_.view));
            p.set("u_bias_slope", glm::vec4(1.0f / proj[0][0], 1.0f / proj[1][1], frustum_.znear, frustum_.zfar));
            p.set("u_bias_kernel", glm::vec2(2.0f / static_cast<float>(shadow_->size), shadow::kernel_reach_texels(s.filter)));
        }
    }
    device_.draw(meshes_[static_cast<size_t>(o.mesh)].buffers);
}

void Renderer::draw_light_depth(shadow::Encoding e, const DepthPath& path) {
    gl::PipelineState st;
    st.depth_test = false;
    st.depth_write = false;
    st.cull = gl::Cull::None;
    device_.apply(st);
    const gl::Program& p = shaders_.get(light_depth_variant(e, frustum_.perspective, path));
    device_.use(p);
    device_.bind_texture(kShadowUnit, shadow_->map);
    p.set("u_shadow_map", kShadowUnit);
    p.set("u_near_far", glm::vec2(frustum_.znear, frustum_.zfar));
    device_.draw_fullscreen();
}

const FramePlan& Renderer::render(const scene::Scene& scene, const Settings& s, const gl::Target* window) {
    if (fingerprint(scene) != loaded_) load(scene);
    plan_ = FramePlan{};

    // What the scene requires.
    std::vector<int> casters, drawable;
    scene::Bounds shadowed;  // casters and receivers: what the light's frustum must hold
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const auto& o = scene.objects[i];
        if (!valid_mesh(scene, o)) continue;
        drawable.push_back(static_cast<int>(i));
        if (o.casts_shadow) casters.push_back(static_cast<int>(i));
        if (o.casts_shadow || o.receives_shadow) shadowed.add(scene::object_bounds(scene, o));
    }
    const bool want_map = s.technique == Technique::ShadowMap && !casters.empty();
    const bool planar = s.technique == Technique::Planar && scene.ground_object >= 0 && scene.ground_plane;

    // Pass 1: the shadow map, drawn only when its light or casters moved.
    if (want_map) {
        int size = s.map_size;
        const int max = caps_.max_target_size();
        if (size > max) {
            plan_.notes.push_back("--map-size " + std::to_string(size) + " clamped to " + std::to_string(max) +
                                  ", this context's maximum");
            size = max;
        }
        // Below 16 texels the one or few texels hold the nearest caster's depth for everything
        // behind it and the whole frame falls into shadow: that is no longer a shadow map.
        constexpr int kMinMap = 16;
        if (size < kMinMap) {
            plan_.notes.push_back("--map-size " + std::to_string(size) + " raised to " + std::to_string(kMinMap) +
                                  ", the smallest map that still resolves a shadow");
            size = kMinMap;
        }
        plan_.map_size = size;
        frustum_ = shadow::fit_light_frustum(scene.light, scene::corners(shadowed), shadowed.center());
        ensure_shadow_target(s.encoding, size);
        ShadowKey key;
        key.light_view_proj = frustum_.view_proj();
        key.encoding = s.encoding;
        key.size = size;
        key.mediump = s.precision == shadow::Precision::Mediump;
        for (int i : casters) {
            key.casters.push_back(scene.objects[static_cast<size_t>(i)].world);
            key.meshes.push_back(scene.objects[static_cast<size_t>(i)].mesh);
        }
        plan_.shadow_map = true;
        const std::string what = size_str(size, size) + " " + std::string(shadow::to_string(s.encoding)) + ", " +
                                 (frustum_.perspective ? "perspective" : "orthographic") + " light, " +
                                 std::to_string(casters.size()) + " caster(s)";
        if (drawn_key_ && *drawn_key_ == key) {
            plan_.passes.push_back({"shadow-map", "reused (light and casters unchanged): " + what});
        } else {
            draw_shadow_map(scene, casters, s.encoding, size, depth_path(s));
            drawn_key_ = std::move(key);
            plan_.shadow_redrawn = true;
            plan_.passes.push_back({"shadow-map", what});
        }
    } else if (s.technique == Technique::ShadowMap) {
        plan_.notes.push_back("no shadow casters: no shadow pass");
    }

    // The camera's target.
    gl::Target target;
    if (window) {
        target = *window;
    } else {
        ensure_camera_target(s.width, s.height, planar);
        target = {&camera_target_->fb, s.width, s.height};
    }
    device_.bind_target(target);
    const scene::Camera& cam = scene.camera;
    const float aspect =
        cam.aspect > 0.0f ? cam.aspect : static_cast<float>(target.width) / static_cast<float>(target.height);
    camera_view_proj_ = (cam.projection ? *cam.projection : glm::perspective(cam.yfov, aspect, cam.znear, cam.zfar)) * cam.view;
    camera_pos_ = glm::vec3(glm::inverse(cam.view)[3]);
    const std::string target_name = (window ? "window " : "offscreen ") + size_str(target.width, target.height);

    if (s.aov == Aov::LightDepth) {
        device_.apply(gl::PipelineState{});
        device_.clear(&kWhite, true, false);
        draw_light_depth(s.encoding, depth_path(s));
        gl::check_errors("the light-depth view");
        plan_.passes.push_back({"light-depth view", target_name + ", the shadow map scaled for viewing"});
        return plan_;
    }

    const bool visibility = s.aov == Aov::Visibility;
    device_.apply(gl::PipelineState{});
    device_.clear(visibility ? &kWhite : &kBackground, true, planar);

    LitFeatures base;
    base.visibility_aov = visibility;
    base.spot = scene.light.type == scene::LightType::Spot;
    const auto features_for = [&](const scene::Object& o) {
        LitFeatures f = base;
        const auto& m = material_of(scene, o);
        f.textured = m.base_color_texture >= 0 && m.base_color_texture < static_cast<int>(images_.size()) &&
                     meshes_[static_cast<size_t>(o.mesh)].buffers.has_uv;
        f.shadow_map = want_map && o.receives_shadow;
        f.encoding = s.encoding;
        f.filter = s.filter;
        f.bias_auto = s.bias_auto;
        f.light_perspective = frustum_.perspective;
        f.mediump = s.precision == shadow::Precision::Mediump;
        return f;
    };

    if (!planar) {
        for (int i : drawable) {
            const auto& o = scene.objects[static_cast<size_t>(i)];
            draw_lit(scene, o, features_for(o), s);
        }
        gl::check_errors("the camera pass");
        std::string detail = target_name + ", " + std::to_string(drawable.size()) + " object(s)";
        if (want_map) detail += ", shadow lookup " + std::string(shadow::to_string(s.filter)) + " " +
                                std::string(shadow::to_string(s.encoding)) + ", bias " +
                                (s.bias_auto ? "auto (" + std::to_string(s.effective_bias()) + " + slope)"
                                             : std::to_string(s.effective_bias())) +
                                (s.precision == shadow::Precision::Mediump ? ", mediump emulated" : "");
        else detail += ", no shadows";
        if (visibility) detail += ", visibility AOV";
        plan_.passes.push_back({"camera", detail});
        return plan_;
    }

    // Planar projected shadows (seed 001), drawn once per pixel through the stencil buffer:
    // the ground marks its visible pixels 1, the flattened casters turn 1 into 2 (never twice, so
    // overlapping triangles darken once), and the ground is drawn again, unlit, where it is 2.
    // The shadow is never depth-tested against the ground, so there is nothing to fight.
    const int ground = scene.ground_object;
    for (int i : drawable) {
        if (i == ground) continue;
        const auto& o = scene.objects[static_cast<size_t>(i)];
        draw_lit(scene, o, features_for(o), s);
    }
    gl::PipelineState mark;
    mark.stencil.enabled = true;
    mark.stencil.func = gl::Compare::Always;
    mark.stencil.ref = 1;
    mark.stencil.pass = gl::StencilOp::Replace;
    device_.apply(mark);
    const scene::Object& ground_obj = scene.objects[static_cast<size_t>(ground)];
    draw_lit(scene, ground_obj, features_for(ground_obj), s);
    gl::check_errors("the camera pass");
    plan_.passes.push_back({"camera", target_name + ", " + std::to_string(drawable.size()) +
                                          " object(s), the ground marks stencil 1"});

    const glm::vec4 light_h = scene.light.type == scene::LightType::Directional
                                  ? glm::vec4(-scene.light.direction, 0.0f)
                                  : glm::vec4(scene.light.position, 1.0f);
    const glm::mat4 flatten = shadow::planar_projection(*scene.ground_plane, light_h);
    gl::PipelineState project;
    project.depth_test = false;
    project.depth_write = false;
    project.color_write = false;
    project.cull = gl::Cull::None;
    project.stencil.enabled = true;
    project.stencil.func = gl::Compare::Equal;
    project.stencil.ref = 1;
    project.stencil.pass = gl::StencilOp::Incr;
    device_.apply(project);
    const gl::Program& flat = shaders_.get(depth_variant(shadow::Encoding::DepthTex, depth_path(s)));
    device_.use(flat);
    int projected = 0;
    for (int i : casters) {
        if (i == ground) continue;
        const auto& o = scene.objects[static_cast<size_t>(i)];
        flat.set("u_mvp", camera_view_proj_ * flatten * o.world);
        device_.draw(meshes_[static_cast<size_t>(o.mesh)].buffers);
        ++projected;
    }
    gl::check_errors("the planar stencil pass");
    plan_.passes.push_back({"planar-stencil", std::to_string(projected) +
                                                  " caster(s) flattened onto the ground, stencil 1 -> 2, colour and depth off"});

    gl::PipelineState shade;
    shade.depth_test = false;
    shade.depth_write = false;
    shade.stencil.enabled = true;
    shade.stencil.func = gl::Compare::Equal;
    shade.stencil.ref = 2;
    device_.apply(shade);
    LitFeatures in_shadow = features_for(ground_obj);
    in_shadow.shadow_map = false;
    in_shadow.in_shadow = true;
    draw_lit(scene, ground_obj, in_shadow, s);
    device_.apply(gl::PipelineState{});
    gl::check_errors("the planar shadow pass");
    plan_.passes.push_back({"planar-shadow", "the ground again, unlit, where stencil = 2"});
    return plan_;
}

void Renderer::set_image_override(int image, const gl::Texture* texture) {
    if (image < 0) return;
    const auto i = static_cast<size_t>(image);
    if (i >= image_overrides_.size()) image_overrides_.resize(i + 1, nullptr);
    image_overrides_[i] = texture;
}

std::vector<std::uint8_t> Renderer::read_target(const gl::Target& target) {
    device_.bind_target(target);
    std::vector<std::uint8_t> px = device_.read_rgba(target.x, target.y, target.width, target.height);
    // GL reads the bottom row first; images are stored top row first.
    const size_t row = static_cast<size_t>(target.width) * 4u;
    std::vector<std::uint8_t> out(px.size());
    for (int y = 0; y < target.height; ++y)
        std::copy_n(px.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(target.height - 1 - y) * row),
                    row, out.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(y) * row));
    return out;
}

std::vector<std::uint8_t> Renderer::read_image() {
    if (!camera_target_) throw gl::Error("read_image: nothing rendered offscreen yet");
    const int w = camera_target_->width, h = camera_target_->height;
    device_.bind_target({&camera_target_->fb, w, h});
    std::vector<std::uint8_t> px = device_.read_rgba(w, h);
    // GL reads the bottom row first; images are stored top row first.
    const size_t row = static_cast<size_t>(w) * 4u;
    for (int y = 0; y < h / 2; ++y)
        std::swap_ranges(px.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(y) * row),
                         px.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(y + 1) * row),
                         px.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(h - 1 - y) * row));
    return px;
}

}  // namespace penumbra::render
