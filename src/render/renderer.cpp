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
           encoding == o.encoding && size == o.size;
}

std::string FramePlan::describe() const {
    std::string out;
    for (size_t i = 0; i < passes.size(); ++i)
        out += std::to_string(i + 1) + ". " + passes[i].name + ": " + passes[i].detail + "\n";
    return out;
}

Renderer::Renderer(gl::Caps caps) : caps_(std::move(caps)) {}
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

void Renderer::load(const scene::Scene& scene) {
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
                               int size) {
    device_.bind_target({&shadow_->fb, size, size});
    gl::PipelineState st;
    st.cull = gl::Cull::None;  // open meshes (the teapot's rim, glTF sheets) must cast from both sides
    st.color_write = e != shadow::Encoding::DepthTex;
    device_.apply(st);
    // White is the farthest depth in every encoding: nothing drawn there, nothing shadows.
    device_.clear(e == shadow::Encoding::DepthTex ? nullptr : &kWhite, true, false);
    const gl::Program& p = shaders_.get(depth_variant(e));
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
        device_.bind_texture(kBaseTextureUnit, images_[static_cast<size_t>(m.base_color_texture)]);
        p.set("u_base_texture", kBaseTextureUnit);
    }
    if (f.shadow_map) {
        device_.bind_texture(kShadowUnit, shadow_->map);
        p.set("u_shadow_map", kShadowUnit);
        p.set("u_light_matrix", shadow::clip_to_texture() * frustum_.view_proj());
        const float texel = 1.0f / static_cast<float>(shadow_->size);
        p.set("u_texmapscale", glm::vec2(texel, texel));
        p.set("u_bias", s.effective_bias());
    }
    device_.draw(meshes_[static_cast<size_t>(o.mesh)].buffers);
}

void Renderer::draw_light_depth(shadow::Encoding e) {
    gl::PipelineState st;
    st.depth_test = false;
    st.depth_write = false;
    st.cull = gl::Cull::None;
    device_.apply(st);
    const gl::Program& p = shaders_.get(light_depth_variant(e, frustum_.perspective));
    device_.use(p);
    device_.bind_texture(kShadowUnit, shadow_->map);
    p.set("u_shadow_map", kShadowUnit);
    p.set("u_near_far", glm::vec2(frustum_.znear, frustum_.zfar));
    device_.draw_fullscreen();
}

const FramePlan& Renderer::render(const scene::Scene& scene, const Settings& s, const gl::Target* window) {
    if (meshes_.size() != scene.meshes.size()) load(scene);
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
        plan_.map_size = size;
        frustum_ = shadow::fit_light_frustum(scene.light, scene::corners(shadowed), shadowed.center());
        ensure_shadow_target(s.encoding, size);
        ShadowKey key;
        key.light_view_proj = frustum_.view_proj();
        key.encoding = s.encoding;
        key.size = size;
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
            draw_shadow_map(scene, casters, s.encoding, size);
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
        draw_light_depth(s.encoding);
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
                                std::string(shadow::to_string(s.encoding)) + ", bias " + std::to_string(s.effective_bias());
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
    const gl::Program& flat = shaders_.get(depth_variant(shadow::Encoding::DepthTex));
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
