// glTF 2.0 (.gltf / .glb) -> scene::Scene. tinygltf parses the JSON, decodes data URIs and
// images; everything that indexes into its arrays or buffers is validated here, because
// tinygltf checks little beyond the JSON syntax and a bad file must give an error, not a crash.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tiny_gltf.h>  // implementation compiled in src/thirdparty/thirdparty_impl.cpp

namespace penumbra::scene {
namespace {

constexpr float kPi = 3.14159265358979f;

// Thrown by the helpers below with a message naming the offending glTF element; load_gltf
// catches it and prefixes the file name. Keeps every check a one-liner at its call site.
struct GltfError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& what) { throw GltfError(what); }

// tinygltf reports several problems in one multi-line string, sometimes quoting a whole
// base64 data URI; the result must stay one readable line.
std::string one_line(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '\r') continue;
        if (c == '\n') {
            out += "; ";
        } else if (static_cast<unsigned char>(c) < 0x20) {
            out += ' ';
        } else {
            out += c;
        }
        if (c == ',' && out.size() >= 7 && out.compare(out.size() - 7, 7, "base64,") == 0) {
            size_t end = i + 1;
            while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '+' ||
                                      s[end] == '/' || s[end] == '='))
                ++end;
            if (end - (i + 1) > 16) {
                out += s.substr(i + 1, 16) + "...";
                i = end - 1;
            }
        }
    }
    return out;
}

std::vector<std::string> split_lines(const std::string& s) {
    std::vector<std::string> out;
    std::istringstream in(s);
    std::string line;
    while (std::getline(in, line))
        if (!line.empty()) out.push_back(line);
    return out;
}

std::string lower(std::string s) {
    for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string file_extension(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return lower(path.substr(dot));
}

template <typename T>
bool in_range(int index, const std::vector<T>& v) {
    return index >= 0 && static_cast<size_t>(index) < v.size();
}

std::string component_type_name(int t) {
    switch (t) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        default: return "component type " + std::to_string(t);
    }
}

std::string type_name(int t) {
    switch (t) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        default: return "type " + std::to_string(t);
    }
}

std::string mode_name(int m) {
    switch (m) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
        default: return "unknown";
    }
}

size_t component_size(int t) {
    switch (t) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

// A validated window onto an accessor's bytes: element i starts at data + i * stride and
// every byte of every element lies inside the buffer.
struct AccessorData {
    const unsigned char* data = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int component_type = 0;
    size_t components = 0;
};

// `what` names the use (e.g. "POSITION of mesh 'sphere' primitive 0") for the error message.
AccessorData view_accessor(const tinygltf::Model& model, int index, const std::string& what,
                           std::initializer_list<int> component_types, int type) {
    const std::string name = "accessor " + std::to_string(index) + " (" + what + ")";
    if (!in_range(index, model.accessors)) fail(name + " does not exist");
    const auto& acc = model.accessors[static_cast<size_t>(index)];
    if (acc.sparse.isSparse) fail(name + " is sparse, which is not supported");
    if (std::find(component_types.begin(), component_types.end(), acc.componentType) ==
        component_types.end())
        fail(name + " has unsupported component type " + component_type_name(acc.componentType));
    if (acc.type != type)
        fail(name + " is " + type_name(acc.type) + ", expected " + type_name(type));
    if (acc.count == 0) fail(name + " has no elements");
    if (acc.bufferView < 0) fail(name + " has no bufferView (implicit zeros are not supported)");
    if (!in_range(acc.bufferView, model.bufferViews))
        fail(name + " refers to bufferView " + std::to_string(acc.bufferView) + ", which does not exist");
    const auto& view = model.bufferViews[static_cast<size_t>(acc.bufferView)];
    const std::string view_name = "bufferView " + std::to_string(acc.bufferView);
    if (!in_range(view.buffer, model.buffers))
        fail(view_name + " refers to buffer " + std::to_string(view.buffer) + ", which does not exist");
    const auto& buffer = model.buffers[static_cast<size_t>(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
        fail(view_name + " (offset " + std::to_string(view.byteOffset) + ", length " +
             std::to_string(view.byteLength) + ") lies outside buffer " + std::to_string(view.buffer) +
             " (" + std::to_string(buffer.data.size()) + " bytes)");

    const size_t components = static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type)));
    const size_t element = component_size(acc.componentType) * components;
    size_t stride = element;
    if (view.byteStride != 0) {
        // Elements may interleave but must not overlap; 252 is glTF's maximum stride.
        if (view.byteStride < element || view.byteStride > 252)
            fail(name + ": " + view_name + " has byteStride " + std::to_string(view.byteStride) +
                 ", invalid for " + std::to_string(element) + "-byte elements");
        stride = view.byteStride;
    }
    // Last byte read = byteOffset + (count - 1) * stride + element, computed without overflow.
    const size_t available = view.byteLength;
    const size_t max_count = std::numeric_limits<size_t>::max() / stride;
    if (acc.byteOffset > available || acc.count - 1 > max_count ||
        (acc.count - 1) * stride > available - acc.byteOffset ||
        element > available - acc.byteOffset - (acc.count - 1) * stride)
        fail(name + " reads past the end of its data: " + std::to_string(acc.count) + " elements of " +
             std::to_string(element) + " bytes (stride " + std::to_string(stride) + ", offset " +
             std::to_string(acc.byteOffset) + ") do not fit in the " + std::to_string(available) +
             " bytes of " + view_name);

    AccessorData out;
    out.data = buffer.data.data() + view.byteOffset + acc.byteOffset;
    out.stride = stride;
    out.count = acc.count;
    out.component_type = acc.componentType;
    out.components = components;
    return out;
}

// Component c of element i as a float; integer types are read as normalized (the only integer
// attribute accepted here is TEXCOORD_0, for which glTF requires normalized).
float read_float(const AccessorData& a, size_t i, size_t c) {
    const unsigned char* p = a.data + i * a.stride + c * component_size(a.component_type);
    switch (a.component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return static_cast<float>(*p) / 255.0f;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, sizeof v);
            return static_cast<float>(v) / 65535.0f;
        }
        default: {
            float v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
    }
}

std::uint32_t read_index(const AccessorData& a, size_t i) {
    const unsigned char* p = a.data + i * a.stride;
    switch (a.component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
        default: {
            std::uint32_t v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
    }
}

std::vector<glm::vec3> read_vec3(const AccessorData& a) {
    std::vector<glm::vec3> out(a.count);
    for (size_t i = 0; i < a.count; ++i)
        out[i] = glm::vec3(read_float(a, i, 0), read_float(a, i, 1), read_float(a, i, 2));
    return out;
}

// Area-weighted sum of the face normals around each vertex: smooth where triangles share
// vertices, flat where they do not (e.g. unindexed meshes). Isolated or degenerate vertices get +y.
std::vector<glm::vec3> compute_normals(const std::vector<glm::vec3>& positions,
                                       const std::vector<std::uint32_t>& indices) {
    std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const auto a = indices[t], b = indices[t + 1], c = indices[t + 2];
        // The cross product's length is twice the area: larger faces weigh more.
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        sum[a] += n;
        sum[b] += n;
        sum[c] += n;
    }
    for (auto& n : sum) {
        const float len = glm::length(n);
        n = (len > 0.0f && std::isfinite(len)) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return sum;
}

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
    Converter(const tinygltf::Model& model, LoadResult& result, const std::string& path)
        : model_(model), result_(result), scene_(result.scene), path_(path) {}

    void run() {
        check_required_extensions();
        walk_nodes();
        if (scene_.objects.empty()) fail("the scene has no meshes to draw");
        const Bounds bounds = scene_bounds(scene_);
        set_camera(bounds);
        set_light(bounds);
        find_ground();
    }

private:
    void warn(const std::string& w) { result_.warnings.push_back(w); }

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
        }
    }

    // Each (mesh, primitive) is converted once and shared by every node that instances it.
    int primitive_mesh(int mesh_index, size_t p) {
        const auto key = std::make_pair(mesh_index, p);
        const auto found = mesh_cache_.find(key);
        if (found != mesh_cache_.end()) return found->second;
        scene_.meshes.push_back(convert_primitive(mesh_index, p));
        const int out = static_cast<int>(scene_.meshes.size()) - 1;
        mesh_cache_[key] = out;
        return out;
    }

    Mesh convert_primitive(int mesh_index, size_t p) const {
        const auto& src = model_.meshes[static_cast<size_t>(mesh_index)];
        const auto& prim = src.primitives[p];
        const std::string where = "mesh " + std::to_string(mesh_index) +
                                  (src.name.empty() ? "" : " '" + src.name + "'") + " primitive " +
                                  std::to_string(p);
        // tinygltf fills in TRIANGLES when "mode" is absent; -1 only if a caller built the model.
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1)
            fail(where + " uses primitive mode " + std::to_string(prim.mode) + " (" + mode_name(prim.mode) +
                 "): only TRIANGLES (4) is supported");

        Mesh mesh;
        mesh.name = src.name.empty() ? "mesh " + std::to_string(mesh_index) : src.name;
        if (src.primitives.size() > 1) mesh.name += "#" + std::to_string(p);

        const auto pos_it = prim.attributes.find("POSITION");
        if (pos_it == prim.attributes.end()) fail(where + " has no POSITION attribute");
        const auto pos = view_accessor(model_, pos_it->second, "POSITION of " + where,
                                       {TINYGLTF_COMPONENT_TYPE_FLOAT}, TINYGLTF_TYPE_VEC3);
        if (pos.count > std::numeric_limits<std::uint32_t>::max())
            fail(where + " has more vertices than 32-bit indices can address");
        mesh.positions = read_vec3(pos);
        const size_t n = mesh.positions.size();

        if (prim.indices >= 0) {
            const auto idx = view_accessor(model_, prim.indices, "indices of " + where,
                                           {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                           TINYGLTF_TYPE_SCALAR);
            if (idx.count % 3 != 0)
                fail(where + " has " + std::to_string(idx.count) + " indices, not a multiple of 3");
            mesh.indices.resize(idx.count);
            for (size_t i = 0; i < idx.count; ++i) {
                const std::uint32_t v = read_index(idx, i);
                if (v >= n)
                    fail(where + ": index " + std::to_string(v) + " at position " + std::to_string(i) +
                         " is out of range (" + std::to_string(n) + " vertices)");
                mesh.indices[i] = v;
            }
        } else {
            if (n % 3 != 0)
                fail(where + " has no indices and " + std::to_string(n) + " vertices, not a multiple of 3");
            mesh.indices.resize(n);
            for (size_t i = 0; i < n; ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
        }

        const auto nrm_it = prim.attributes.find("NORMAL");
        if (nrm_it != prim.attributes.end()) {
            const auto nrm = view_accessor(model_, nrm_it->second, "NORMAL of " + where,
                                           {TINYGLTF_COMPONENT_TYPE_FLOAT}, TINYGLTF_TYPE_VEC3);
            if (nrm.count != n)
                fail(where + " has " + std::to_string(nrm.count) + " normals for " + std::to_string(n) +
                     " vertices");
            mesh.normals = read_vec3(nrm);
            // Shaders assume unit normals; files are not always careful. Zero or broken ones
            // fall back to the computed normal of that vertex.
            std::vector<glm::vec3> computed;
            for (size_t i = 0; i < n; ++i) {
                const float len = glm::length(mesh.normals[i]);
                if (len > 1e-12f && std::isfinite(len)) {
                    mesh.normals[i] /= len;
                } else {
                    if (computed.empty()) computed = compute_normals(mesh.positions, mesh.indices);
                    mesh.normals[i] = computed[i];
                }
            }
        } else {
            mesh.normals = compute_normals(mesh.positions, mesh.indices);
        }

        const auto uv_it = prim.attributes.find("TEXCOORD_0");
        if (uv_it != prim.attributes.end()) {
            const auto uv = view_accessor(model_, uv_it->second, "TEXCOORD_0 of " + where,
                                          {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                          TINYGLTF_TYPE_VEC2);
            if (uv.count != n)
                fail(where + " has " + std::to_string(uv.count) + " texture coordinates for " +
                     std::to_string(n) + " vertices");
            mesh.uvs.resize(n);
            for (size_t i = 0; i < n; ++i) mesh.uvs[i] = glm::vec2(read_float(uv, i, 0), read_float(uv, i, 1));
        }
        return mesh;
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
        if (convert_image(model_.images[static_cast<size_t>(source)], img, problem)) {
            scene_.images.push_back(std::move(img));
            out = static_cast<int>(scene_.images.size()) - 1;
        } else {
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
            glm::mat4 rigid(1.0f);
            const glm::vec3 z = glm::normalize(glm::vec3(w[2]));
            const glm::vec3 x = glm::normalize(glm::cross(glm::vec3(w[1]), z));
            rigid[0] = glm::vec4(x, 0.0f);
            rigid[1] = glm::vec4(glm::cross(z, x), 0.0f);
            rigid[2] = glm::vec4(z, 0.0f);
            rigid[3] = w[3];
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
    std::map<std::pair<int, size_t>, int> mesh_cache_;
    std::map<std::pair<int, bool>, int> material_cache_;
    std::map<int, int> image_cache_;
    int default_material_ = -1;
    std::optional<glm::mat4> camera_node_;
    int camera_index_ = -1;
    bool warned_ortho_ = false;
    std::optional<glm::mat4> light_node_;
    int light_index_ = -1;
};

}  // namespace

LoadResult load_gltf(const std::string& path) {
    LoadResult result;
    try {
        const std::string ext = file_extension(path);
        if (ext != ".gltf" && ext != ".glb") {
            result.error = path + ": unknown file extension '" + ext + "' (expected .gltf or .glb)";
            return result;
        }
        {
            // tinygltf's own message for a missing file is vaguer than errno's.
            errno = 0;
            std::ifstream probe(path, std::ios::binary);
            if (!probe) {
                result.error = path + ": cannot open file: " + (errno ? std::strerror(errno) : "unreadable");
                return result;
            }
        }
        tinygltf::TinyGLTF loader;
        tinygltf::Model model;
        std::string err, warn;
        const bool parsed = ext == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                                          : loader.LoadASCIIFromFile(&model, &err, &warn, path);
        for (const auto& w : split_lines(warn)) result.warnings.push_back(path + ": " + w);
        if (!parsed) {
            result.error = path + ": invalid glTF: " + (err.empty() ? "tinygltf could not parse it" : one_line(err));
            return result;
        }
        Converter(model, result, path).run();
        result.ok = true;
    } catch (const std::exception& e) {  // GltfError, and bad_alloc on absurd sizes
        result.error = path + ": " + e.what();
    } catch (...) {
        result.error = path + ": unexpected error while loading";
    }
    if (!result.ok) result.scene = Scene{};  // no half-built scene escapes a failed load
    return result;
}

}  // namespace penumbra::scene
