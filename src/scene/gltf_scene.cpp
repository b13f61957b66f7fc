// A parsed glTF model -> scene::Scene: walks the node tree into objects, converts materials and
// their base colour textures, and takes the first perspective camera and the first
// KHR_lights_punctual light (defaults from the scene's bounds when there is none), then looks for
// a ground plane. Primitive geometry comes from gltf_accessors.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/gltf_internal.h"

namespace penumbra::scene::gltf_internal {
namespace {

constexpr float kPi = 3.14159265358979f;

glm::mat4 local_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::mat4 m(1.0f);
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = static_cast<float>(node.matrix[static_cast<size_t>(i)]);
        return m;
    }
    glm::mat4 m(1.0f);
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::vec3(static_cast<float>(node.translation[0]),
                                        static_cast<float>(node.translation[1]),
                                        static_cast<float>(node.translation[2])));
    if (node.rotation.size() == 4) {
        // glTF stores x, y, z, w; glm's constructor takes w first.
        glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                    static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
        if (glm::length(q) > 0.0f) m *= glm::mat4_cast(glm::normalize(q));
    }
    if (node.scale.size() == 3)
        m = glm::scale(m, glm::vec3(static_cast<float>(node.scale[0]), static_cast<float>(node.scale[1]),
                                    static_cast<float>(node.scale[2])));
    return m;
}

std::string short_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

glm::vec3 node_forward(const glm::mat4& world) {
    // Cameras and lights look down their node's -Z.
    const glm::vec3 d = glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f);
    const float len = glm::length(d);
    return len > 0.0f ? d / len : glm::vec3(0.0f, 0.0f, -1.0f);
}

// Builds the Scene from a parsed model; one instance per load so the caches stay local.
class Converter {
public:
    Converter(const tinygltf::Model& model, LoadResult& result, const std::string& path, const LoadContext& context)
        : model_(model), result_(result), scene_(result.scene), path_(path), context_(context) {}

    void run() {
        check_required_extensions();
        walk_nodes();
        if (scene_.objects.empty()) fail("the scene has no meshes to draw");
        check_extent();
        const Bounds bounds = scene_bounds(scene_);
        set_camera(bounds);
        set_light(bounds);
        find_ground();
    }

private:
    void warn(const std::string& w) { result_.warnings.push_back(w); }

    // Every world-space vertex within the limit: beyond it squared distances and matrix products
    // leave float's range, and the ray tracer's bounds turn infinite.
    void check_extent() const {
        const double limit = context_.limits.max_coordinate;
        const std::vector<Bounds> meshes = all_mesh_bounds(scene_);
        for (size_t i = 0; i < scene_.objects.size(); ++i) {
            const Bounds b = object_bounds(meshes, scene_.objects[i]);
            if (b.empty()) continue;
            for (const glm::vec3& c : corners(b))
                for (int k = 0; k < 3; ++k)
                    if (!(std::fabs(static_cast<double>(c[k])) <= limit))
                        fail("nodes[" + std::to_string(object_nodes_[i]) + "] puts '" + scene_.objects[i].name +
                             "' at a coordinate of " + short_number(c[k]) + ": over the limit of " +
                             short_number(limit) + " world units");
        }
    }

    void check_required_extensions() {
        for (const auto& ext : model_.extensionsRequired)
            if (ext != "KHR_lights_punctual") fail("requires the unsupported extension " + ext);
    }

    std::vector<int> root_nodes() const {
        if (!model_.scenes.empty()) {
            size_t s = 0;
            if (in_range(model_.defaultScene, model_.scenes)) s = static_cast<size_t>(model_.defaultScene);
            return model_.scenes[s].nodes;
        }
        // No scenes: every node that is nobody's child is a root.
        std::vector<char> is_child(model_.nodes.size(), 0);
        for (const auto& n : model_.nodes)
            for (int c : n.children)
                if (in_range(c, model_.nodes)) is_child[static_cast<size_t>(c)] = 1;
        std::vector<int> roots;
        for (size_t i = 0; i < model_.nodes.size(); ++i)
            if (!is_child[i]) roots.push_back(static_cast<int>(i));
        return roots;
    }

    // Depth-first, parents before children, in file order; an explicit stack so a deep (or
    // hostile) hierarchy cannot overflow the call stack.
    void walk_nodes() {
        if (model_.defaultScene >= 0 && !in_range(model_.defaultScene, model_.scenes))
            warn("scene " + std::to_string(model_.defaultScene) + " does not exist in " + path_ +
                 ": using scene 0");
        const std::vector<int> roots = root_nodes();
        std::vector<char> visited(model_.nodes.size(), 0);
        std::vector<std::pair<int, glm::mat4>> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::mat4(1.0f));
        while (!stack.empty()) {
            const auto [index, parent] = stack.back();
            stack.pop_back();
            if (!in_range(index, model_.nodes)) fail("node " + std::to_string(index) + " does not exist");
            // glTF nodes form strict trees, so reaching one twice means a cycle or a shared child.
            if (visited[static_cast<size_t>(index)])
                fail("node " + std::to_string(index) + " is reached twice (the node hierarchy is not a tree)");
            visited[static_cast<size_t>(index)] = 1;
            const auto& node = model_.nodes[static_cast<size_t>(index)];
            const glm::mat4 world = parent * local_matrix(node);
            if (!finite(world)) fail("node " + std::to_string(index) + " has a non-finite transform");
            visit(index, node, world);
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
                stack.emplace_back(*it, world);
        }
    }

    void visit(int index, const tinygltf::Node& node, const glm::mat4& world) {
        if (node.mesh >= 0) add_mesh_instance(index, node, world);
        if (node.camera >= 0 && !camera_node_) {
            if (!in_range(node.camera, model_.cameras))
                fail("node " + std::to_string(index) + " refers to camera " + std::to_string(node.camera) +
                     ", which does not exist");
            if (model_.cameras[static_cast<size_t>(node.camera)].type == "perspective") {
                camera_node_ = world;
                camera_index_ = node.camera;
                camera_node_index_ = index;
            } else if (!warned_ortho_) {
                warned_ortho_ = true;
                warn("orthographic camera in " + path_ + " ignored: only perspective cameras are used");
            }
        }
        const auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext != node.extensions.end() && !light_node_) {
            // tinygltf 2.7 has no Node::light; the reference stays a raw extension object.
            const tinygltf::Value& v = ext->second;
            if (!v.IsObject() || !v.Has("light") || !v.Get("light").IsNumber())
                fail("node " + std::to_string(index) + " has a malformed KHR_lights_punctual reference");
            const int light = v.Get("light").GetNumberAsInt();
            if (!in_range(light, model_.lights))
                fail("node " + std::to_string(index) + " refers to light " + std::to_string(light) +
                     ", which does not exist");
            const std::string& type = model_.lights[static_cast<size_t>(light)].type;
            if (type == "directional" || type == "point" || type == "spot") {
                light_node_ = world;
                light_index_ = light;
            } else {
                warn("light " + std::to_string(light) + " in " + path_ + " has unknown type '" + type +
                     "': ignored");
            }
        }
    }

    void add_mesh_instance(int index, const tinygltf::Node& node, const glm::mat4& world) {
        if (!in_range(node.mesh, model_.meshes))
            fail("node " + std::to_string(index) + " refers to mesh " + std::to_string(node.mesh) +
                 ", which does not exist");
        const auto& mesh = model_.meshes[static_cast<size_t>(node.mesh)];
        std::string base = !node.name.empty() ? node.name
                           : !mesh.name.empty() ? mesh.name
                                                : "node " + std::to_string(index);
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const int mesh_index = primitive_mesh(node.mesh, p);
            const bool has_uvs = !scene_.meshes[static_cast<size_t>(mesh_index)].uvs.empty();
            Object o;
            o.name = mesh.primitives.size() > 1 ? base + "#" + std::to_string(p) : base;
            o.mesh = mesh_index;
            o.material = material(mesh.primitives[p].material, has_uvs);
            o.world = world;
            scene_.objects.push_back(std::move(o));
            object_nodes_.push_back(index);
        }
    }

    // Each (mesh, primitive) is converted once and shared by every node that instances it.
    int primitive_mesh(int mesh_index, size_t p) {
        const auto key = std::make_pair(mesh_index, p);
        const auto found = mesh_cache_.find(key);
        if (found != mesh_cache_.end()) return found->second;
        scene_.meshes.push_back(convert_primitive(model_, mesh_index, p));
        const int out = static_cast<int>(scene_.meshes.size()) - 1;
        mesh_cache_[key] = out;
        return out;
    }

    // The same glTF material can become two scene materials: with its texture for primitives
    // that have TEXCOORD_0, without it for those that do not (the texture cannot be sampled).
    int material(int gltf_material, bool has_uvs) {
        if (gltf_material < 0) {
            if (default_material_ < 0) {
                Material m;
                m.name = "default";
                m.base_color = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
                scene_.materials.push_back(m);
                default_material_ = static_cast<int>(scene_.materials.size()) - 1;
            }
            return default_material_;
        }
        if (!in_range(gltf_material, model_.materials))
            fail("material " + std::to_string(gltf_material) + " does not exist");
        const auto key = std::make_pair(gltf_material, has_uvs);
        const auto found = material_cache_.find(key);
        if (found != material_cache_.end()) return found->second;

        const auto& src = model_.materials[static_cast<size_t>(gltf_material)];
        const auto& pbr = src.pbrMetallicRoughness;
        Material m;
        m.name = src.name.empty() ? "material " + std::to_string(gltf_material) : src.name;
        if (pbr.baseColorFactor.size() == 4)
            m.base_color = glm::vec4(static_cast<float>(pbr.baseColorFactor[0]),
                                     static_cast<float>(pbr.baseColorFactor[1]),
                                     static_cast<float>(pbr.baseColorFactor[2]),
                                     static_cast<float>(pbr.baseColorFactor[3]));
        if (pbr.baseColorTexture.index >= 0 && has_uvs) m.base_color_texture = texture_image(gltf_material);
        // alphaMode and alphaCutoff were checked by validate_json (one of the three, 0..1).
        m.alpha_mode = src.alphaMode == "MASK"    ? AlphaMode::Mask
                       : src.alphaMode == "BLEND" ? AlphaMode::Blend
                                                  : AlphaMode::Opaque;
        m.alpha_cutoff = static_cast<float>(src.alphaCutoff);
        m.double_sided = src.doubleSided;
        scene_.materials.push_back(m);
        const int out = static_cast<int>(scene_.materials.size()) - 1;
        material_cache_[key] = out;
        return out;
    }

    // Problems with a texture only cost the texture: the material keeps its base colour.
    int texture_image(int gltf_material) {
        const auto& info = model_.materials[static_cast<size_t>(gltf_material)].pbrMetallicRoughness.baseColorTexture;
        const std::string where = "material " + std::to_string(gltf_material) + " in " + path_;
        if (info.texCoord != 0) {
            warn(where + " samples TEXCOORD_" + std::to_string(info.texCoord) +
                 ", only TEXCOORD_0 is loaded: texture ignored");
            return -1;
        }
        if (!in_range(info.index, model_.textures)) {
            warn(where + " refers to texture " + std::to_string(info.index) + ", which does not exist: ignored");
            return -1;
        }
        const int source = model_.textures[static_cast<size_t>(info.index)].source;
        if (!in_range(source, model_.images)) {
            warn(where + ": texture " + std::to_string(info.index) + " has no image: ignored");
            return -1;
        }
        const auto found = image_cache_.find(source);
        if (found != image_cache_.end()) return found->second;
        int out = -1;
        Image img;
        std::string problem;
        const auto known = context_.image_problems.find(source);
        if (known == context_.image_problems.end() &&
            convert_image(model_.images[static_cast<size_t>(source)], img, problem)) {
            scene_.images.push_back(std::move(img));
            out = static_cast<int>(scene_.images.size()) - 1;
        } else {
            if (known != context_.image_problems.end()) problem = known->second;
            warn("image " + std::to_string(source) + " in " + path_ + " " + problem + ": texture ignored");
        }
        image_cache_[source] = out;
        return out;
    }

    // tinygltf asks stb for 4 channels, but 16-bit PNGs stay 16-bit and a custom decoder could
    // keep 1-3 channels; normalize all of them to 8-bit RGBA.
    static bool convert_image(const tinygltf::Image& src, Image& dst, std::string& problem) {
        if (src.width <= 0 || src.height <= 0 || src.image.empty()) {
            problem = "was not decoded";
            return false;
        }
        if (src.component < 1 || src.component > 4 || (src.bits != 8 && src.bits != 16)) {
            problem = "has an unsupported format (" + std::to_string(src.component) + " channels of " +
                      std::to_string(src.bits) + " bits)";
            return false;
        }
        const size_t w = static_cast<size_t>(src.width), h = static_cast<size_t>(src.height);
        const size_t comps = static_cast<size_t>(src.component), bytes = static_cast<size_t>(src.bits / 8);
        if (w > (1u << 16) || h > (1u << 16) || src.image.size() < w * h * comps * bytes) {
            problem = "has a pixel buffer that does not match its size";
            return false;
        }
        dst.width = src.width;
        dst.height = src.height;
        dst.rgba.resize(w * h * 4);
        auto channel = [&](size_t pixel, size_t c) -> std::uint8_t {
            const unsigned char* p = src.image.data() + (pixel * comps + c) * bytes;
            if (bytes == 1) return *p;
            std::uint16_t v;
            std::memcpy(&v, p, sizeof v);  // stb's 16-bit output is in native byte order
            return static_cast<std::uint8_t>((static_cast<std::uint32_t>(v) * 255u + 32767u) / 65535u);
        };
        for (size_t i = 0; i < w * h; ++i) {
            std::uint8_t* out = &dst.rgba[i * 4];
            if (comps <= 2) {  // grey, grey + alpha
                out[0] = out[1] = out[2] = channel(i, 0);
                out[3] = comps == 2 ? channel(i, 1) : 255;
            } else {
                for (size_t c = 0; c < 3; ++c) out[c] = channel(i, c);
                out[3] = comps == 4 ? channel(i, 3) : 255;
            }
        }
        return true;
    }

    void set_camera(const Bounds& bounds) {
        const glm::vec3 centre = bounds.center();
        const float radius = std::max(0.5f * glm::length(bounds.max - bounds.min), 1e-3f);
        Camera& cam = scene_.camera;
        if (camera_node_) {
            const auto& src = model_.cameras[static_cast<size_t>(camera_index_)].perspective;
            // The view must be rigid: drop any scale on the camera node (glTF forbids it, but
            // a scaled view would distort depth and lighting).
            const glm::mat4& w = *camera_node_;
            // A camera node scaled to zero (or flattened) has no view: its axes must be usable.
            const float sx = glm::length(glm::vec3(w[0])), sy = glm::length(glm::vec3(w[1])),
                        sz = glm::length(glm::vec3(w[2]));
            const float ortho = glm::length(glm::cross(glm::vec3(w[1]), glm::vec3(w[2])));
            if (!(sx > 1e-12f && sy > 1e-12f && sz > 1e-12f && ortho > 1e-6f * sy * sz))
                fail("nodes[" + std::to_string(camera_node_index_) + "] (camera " + std::to_string(camera_index_) +
                     "): its transform is singular (scaled to zero or flattened), so the camera has no view");
            const glm::mat4 rigid = rigid_frame(w);
            cam.view = finite(rigid) ? glm::inverse(rigid) : glm::inverse(w);
            cam.yfov = static_cast<float>(src.yfov);
            if (!(cam.yfov > 0.0f && cam.yfov < kPi)) {
                warn("camera " + std::to_string(camera_index_) + " in " + path_ + " has yfov " +
                     std::to_string(src.yfov) + ": using 45 degrees");
                cam.yfov = kPi / 4.0f;
            }
            const glm::vec3 eye(w[3]);
            // Farthest point of the scene from the eye: bounds the depth range when the file leaves it open.
            float farthest = 0.0f;
            for (const auto& c : corners(bounds)) farthest = std::max(farthest, glm::length(c - eye));
            cam.znear = static_cast<float>(src.znear);
            if (!(cam.znear > 0.0f)) {
                cam.znear = std::max(farthest, radius) * 1e-3f;
                warn("camera " + std::to_string(camera_index_) + " in " + path_ + " has no valid znear: using " +
                     std::to_string(cam.znear));
            }
            cam.zfar = static_cast<float>(src.zfar);
            if (src.zfar <= 0.0) {
                // Infinite projection: GLES2 depth buffers are 16/24-bit, so a far plane just past
                // the scene keeps more precision than 1000 * znear would; never closer than that.
                cam.zfar = farthest > 0.0f ? std::max(farthest * 1.5f, cam.znear * 10.0f) : cam.znear * 1000.0f;
            } else if (!(cam.zfar > cam.znear)) {
                warn("camera " + std::to_string(camera_index_) + " in " + path_ + " has zfar <= znear: using " +
                     "1000 * znear");
                cam.zfar = cam.znear * 1000.0f;
            }
            cam.aspect = src.aspectRatio > 0.0 ? static_cast<float>(src.aspectRatio) : 0.0f;
            return;
        }
        // From +z and 30 degrees above, far enough that the bounding sphere fits the vertical
        // field of view with a 10% margin.
        cam.yfov = kPi / 4.0f;
        const float distance = 1.1f * radius / std::sin(0.5f * cam.yfov);
        const float elevation = kPi / 6.0f;
        const glm::vec3 eye = centre + distance * glm::vec3(0.0f, std::sin(elevation), std::cos(elevation));
        cam.view = glm::lookAt(eye, centre, glm::vec3(0.0f, 1.0f, 0.0f));
        cam.znear = std::max(0.5f * (distance - radius), 0.01f * distance);
        cam.zfar = 1.5f * (distance + radius);
        cam.aspect = 0.0f;
        warn("no camera in " + path_ + ": using a default view of the scene's bounds");
    }

    // extras {"penumbra": {"radius": R}}: the light's size (scene::Light::radius); 0 when absent.
    float light_radius_extra(const tinygltf::Value& extras) {
        if (!extras.IsObject() || !extras.Has("penumbra")) return 0.0f;
        const tinygltf::Value& p = extras.Get("penumbra");
        if (!p.IsObject() || !p.Has("radius")) return 0.0f;
        const tinygltf::Value& r = p.Get("radius");
        const double v = r.IsNumber() ? r.GetNumberAsDouble() : -1.0;
        if (!(v >= 0.0 && v < 1e6)) {
            warn("the light's extras.penumbra.radius in " + path_ + " is not a number >= 0: using 0 (a point light)");
            return 0.0f;
        }
        return static_cast<float>(v);
    }

    void set_light(const Bounds& bounds) {
        const glm::vec3 centre = bounds.center();
        const float radius = std::max(0.5f * glm::length(bounds.max - bounds.min), 1e-3f);
        Light& light = scene_.light;
        if (light_node_) {
            const auto& src = model_.lights[static_cast<size_t>(light_index_)];
            const glm::mat4& w = *light_node_;
            light.position = glm::vec3(w[3]);
            light.direction = node_forward(w);
            if (src.color.size() == 3)
                light.color = glm::vec3(static_cast<float>(src.color[0]), static_cast<float>(src.color[1]),
                                        static_cast<float>(src.color[2]));
            // Physical units (lux, candela) are passed through; the renderer decides the scale.
            light.intensity = static_cast<float>(src.intensity);
            light.radius = light_radius_extra(src.extras);
            if (src.type == "directional") {
                light.type = LightType::Directional;
            } else if (src.type == "spot") {
                light.type = LightType::Spot;
                light.spot_outer_cone = static_cast<float>(src.spot.outerConeAngle);
                light.spot_inner_cone = static_cast<float>(src.spot.innerConeAngle);
                if (!(light.spot_outer_cone > 0.0f && light.spot_outer_cone <= 0.5f * kPi)) {
                    warn("spot light in " + path_ + " has outer cone " + std::to_string(light.spot_outer_cone) +
                         ": using pi/4");
                    light.spot_outer_cone = 0.25f * kPi;
                }
                if (!(light.spot_inner_cone >= 0.0f && light.spot_inner_cone < light.spot_outer_cone))
                    light.spot_inner_cone = 0.0f;
            } else {
                // A point light shines everywhere; the shadow map still needs an aim, and the
                // scene's centre is what the renderer frames.
                light.type = LightType::Point;
                const glm::vec3 to_centre = centre - light.position;
                const float len = glm::length(to_centre);
                light.direction = len > 1e-6f ? to_centre / len : glm::vec3(0.0f, -1.0f, 0.0f);
            }
            return;
        }
        light = Light{};
        light.type = LightType::Directional;
        light.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
        // Directional lights have no position; this one marks where a shadow camera could sit.
        light.position = centre - 2.0f * radius * light.direction;
        warn("no light in " + path_ + ": using a default directional light");
    }

    void find_ground() {
        static const char* const kNames[] = {"ground", "floor", "plane", "table"};
        for (size_t i = 0; i < scene_.objects.size(); ++i) {
            const Object& o = scene_.objects[i];
            const std::string name = lower(o.name);
            bool named = false;
            for (const char* k : kNames) named = named || name.find(k) != std::string::npos;
            if (!named) continue;
            const Bounds b = object_bounds(scene_, o);
            if (b.empty()) continue;
            const glm::vec3 size = b.max - b.min;
            const float width = std::max(size.x, size.z);
            if (width > 0.0f && size.y < 1e-3f * width) {
                scene_.ground_object = static_cast<int>(i);
                scene_.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, -b.center().y);
                return;
            }
        }
    }

    const tinygltf::Model& model_;
    LoadResult& result_;
    Scene& scene_;
    const std::string& path_;
    const LoadContext& context_;
    std::vector<int> object_nodes_;  // the node of each scene object, for messages
    std::map<std::pair<int, size_t>, int> mesh_cache_;
    std::map<std::pair<int, bool>, int> material_cache_;
    std::map<int, int> image_cache_;
    int default_material_ = -1;
    std::optional<glm::mat4> camera_node_;
    int camera_index_ = -1;
    int camera_node_index_ = -1;
    bool warned_ortho_ = false;
    std::optional<glm::mat4> light_node_;
    int light_index_ = -1;
};

}  // namespace

void build_scene(const tinygltf::Model& model, LoadResult& result, const std::string& path, const LoadContext& context) {
    Converter(model, result, path, context).run();
}

}  // namespace penumbra::scene::gltf_internal
