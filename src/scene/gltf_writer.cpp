#include "scene/gltf_writer.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>
#include <stb_image_write.h>  // implementation compiled in src/thirdparty/thirdparty_impl.cpp

namespace penumbra::scene {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126;
constexpr int kUint = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

std::string base64(const std::uint8_t* data, size_t size) {
    static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    for (size_t i = 0; i < size; i += 3) {
        const std::uint32_t b0 = data[i];
        const std::uint32_t b1 = i + 1 < size ? data[i + 1] : 0u;
        const std::uint32_t b2 = i + 2 < size ? data[i + 2] : 0u;
        const std::uint32_t v = (b0 << 16) | (b1 << 8) | b2;
        out += kAlphabet[(v >> 18) & 63u];
        out += kAlphabet[(v >> 12) & 63u];
        out += i + 1 < size ? kAlphabet[(v >> 6) & 63u] : '=';
        out += i + 2 < size ? kAlphabet[v & 63u] : '=';
    }
    return out;
}

json matrix_json(const glm::mat4& m) {
    json a = json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) a.push_back(static_cast<double>(m[c][r]));
    return a;
}

json vec_json(const float* v, int n) {
    json a = json::array();
    for (int i = 0; i < n; ++i) a.push_back(static_cast<double>(v[i]));
    return a;
}

// A rigid frame whose -Z is `forward` (glTF cameras and lights look down their -Z), at `origin`.
glm::mat4 frame_looking(const glm::vec3& origin, const glm::vec3& forward) {
    const float len = glm::length(forward);
    const glm::vec3 f = len > 0.0f ? forward / len : glm::vec3(0.0f, 0.0f, -1.0f);
    const glm::vec3 z = -f;
    const glm::vec3 up = std::fabs(z.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 x = glm::normalize(glm::cross(up, z));
    const glm::vec3 y = glm::cross(z, x);
    glm::mat4 m(1.0f);
    m[0] = glm::vec4(x, 0.0f);
    m[1] = glm::vec4(y, 0.0f);
    m[2] = glm::vec4(z, 0.0f);
    m[3] = glm::vec4(origin, 1.0f);
    return m;
}

class Writer {
public:
    explicit Writer(const GltfWriteOptions& o) : options_(o) {}

    json run(const Scene& s) {
        doc_["asset"] = {{"version", "2.0"}, {"generator", options_.generator}};
        for (auto key : {"buffers", "bufferViews", "accessors", "meshes", "nodes", "materials", "images",
                         "samplers", "textures"})
            doc_[key] = json::array();

        json scene_nodes = json::array();
        for (const auto& o : s.objects) {
            const int mesh = mesh_for(s, o);
            if (mesh < 0) continue;
            json node = {{"name", o.name}, {"mesh", mesh}};
            if (o.world != glm::mat4(1.0f)) node["matrix"] = matrix_json(o.world);
            if (!o.casts_shadow || !o.receives_shadow)
                node["extras"] = {{"penumbra", {{"castsShadow", o.casts_shadow}, {"receivesShadow", o.receives_shadow}}}};
            scene_nodes.push_back(add_node(std::move(node)));
        }
        scene_nodes.push_back(add_camera(s.camera));
        scene_nodes.push_back(add_light(s.light));

        doc_["buffers"].push_back({{"byteLength", bin_.size()},
                                   {"uri", "data:application/octet-stream;base64," + base64(bin_.data(), bin_.size())}});
        doc_["scenes"] = json::array({{{"nodes", scene_nodes}}});
        doc_["scene"] = 0;
        doc_["extensionsUsed"] = json::array({"KHR_lights_punctual"});
        // glTF forbids empty top-level arrays.
        for (auto key : {"materials", "images", "samplers", "textures"})
            if (doc_[key].empty()) doc_.erase(key);
        return doc_;
    }

private:
    int add_node(json node) {
        doc_["nodes"].push_back(std::move(node));
        return static_cast<int>(doc_["nodes"].size()) - 1;
    }

    int view(const void* data, size_t bytes, int target) {
        while (bin_.size() % 4) bin_.push_back(0);
        const size_t offset = bin_.size();
        bin_.resize(offset + bytes);
        std::memcpy(bin_.data() + offset, data, bytes);
        doc_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}});
        return static_cast<int>(doc_["bufferViews"].size()) - 1;
    }

    int accessor(json a) {
        doc_["accessors"].push_back(std::move(a));
        return static_cast<int>(doc_["accessors"].size()) - 1;
    }

    int vec3_accessor(const std::vector<glm::vec3>& v, bool bounds) {
        json a = {{"bufferView", view(v.data(), v.size() * sizeof(glm::vec3), kArrayBuffer)},
                  {"componentType", kFloat},
                  {"count", v.size()},
                  {"type", "VEC3"}};
        if (bounds) {  // required on POSITION
            glm::vec3 lo = v.front(), hi = v.front();
            for (const auto& p : v) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            a["min"] = vec_json(&lo.x, 3);
            a["max"] = vec_json(&hi.x, 3);
        }
        return accessor(std::move(a));
    }

    // Each scene mesh becomes one glTF mesh the first time an object uses it; -1 for objects
    // that draw nothing (no such mesh, no triangles).
    int mesh_for(const Scene& s, const Object& o) {
        if (o.mesh < 0 || o.mesh >= static_cast<int>(s.meshes.size())) return -1;
        const auto key = std::make_pair(o.mesh, o.material);
        if (const auto it = meshes_.find(key); it != meshes_.end()) return it->second;
        const Mesh& m = s.meshes[static_cast<size_t>(o.mesh)];
        int out = -1;
        if (!m.positions.empty() && m.indices.size() >= 3) {
            json attributes = {{"POSITION", vec3_accessor(m.positions, true)}};
            if (m.normals.size() == m.positions.size()) attributes["NORMAL"] = vec3_accessor(m.normals, false);
            if (m.uvs.size() == m.positions.size())
                attributes["TEXCOORD_0"] =
                    accessor({{"bufferView", view(m.uvs.data(), m.uvs.size() * sizeof(glm::vec2), kArrayBuffer)},
                              {"componentType", kFloat},
                              {"count", m.uvs.size()},
                              {"type", "VEC2"}});
            const size_t n = m.indices.size() / 3 * 3;
            json prim = {{"attributes", attributes},
                         {"indices", accessor({{"bufferView", view(m.indices.data(), n * sizeof(std::uint32_t),
                                                                   kElementArrayBuffer)},
                                               {"componentType", kUint},
                                               {"count", n},
                                               {"type", "SCALAR"}})},
                         {"mode", 4}};
            const int material = material_for(s, o.material);
            if (material >= 0) prim["material"] = material;
            doc_["meshes"].push_back({{"name", m.name}, {"primitives", json::array({prim})}});
            out = static_cast<int>(doc_["meshes"].size()) - 1;
        }
        meshes_[key] = out;
        return out;
    }

    int material_for(const Scene& s, int index) {
        if (index < 0 || index >= static_cast<int>(s.materials.size())) return -1;
        if (const auto it = materials_.find(index); it != materials_.end()) return it->second;
        const Material& m = s.materials[static_cast<size_t>(index)];
        // Phong shininess as a roughness (Blinn-Phong <-> Beckmann: alpha^2 = 2 / (n + 2)), not
        // metallic: what a PBR renderer needs to look alike; the Phong values ride along in extras.
        const double roughness = std::sqrt(std::sqrt(2.0 / (static_cast<double>(m.shininess) + 2.0)));
        json pbr = {{"baseColorFactor", vec_json(&m.base_color.x, 4)},
                    {"metallicFactor", 0.0},
                    {"roughnessFactor", roughness}};
        const int texture = texture_for(s, m.base_color_texture);
        if (texture >= 0) pbr["baseColorTexture"] = {{"index", texture}};
        doc_["materials"].push_back(
            {{"name", m.name},
             {"pbrMetallicRoughness", pbr},
             {"extras", {{"penumbra", {{"specular", static_cast<double>(m.specular)},
                                       {"shininess", static_cast<double>(m.shininess)}}}}}});
        const int out = static_cast<int>(doc_["materials"].size()) - 1;
        materials_[index] = out;
        return out;
    }

    int texture_for(const Scene& s, int image) {
        if (image < 0 || image >= static_cast<int>(s.images.size())) return -1;
        if (const auto it = textures_.find(image); it != textures_.end()) return it->second;
        const Image& img = s.images[static_cast<size_t>(image)];
        int out = -1;
        if (img.width > 0 && img.height > 0 &&
            img.rgba.size() >= static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 4u) {
            std::vector<std::uint8_t> png;
            const auto sink = [](void* ctx, void* data, int size) {
                auto* v = static_cast<std::vector<std::uint8_t>*>(ctx);
                const auto* p = static_cast<const std::uint8_t*>(data);
                v->insert(v->end(), p, p + size);
            };
            if (stbi_write_png_to_func(sink, &png, img.width, img.height, 4, img.rgba.data(), img.width * 4) &&
                !png.empty()) {
                doc_["images"].push_back({{"mimeType", "image/png"},
                                          {"uri", "data:image/png;base64," + base64(png.data(), png.size())}});
                if (doc_["samplers"].empty())
                    // What the renderer uses for a power-of-two image: trilinear, repeat.
                    doc_["samplers"].push_back({{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}});
                doc_["textures"].push_back({{"sampler", 0}, {"source", doc_["images"].size() - 1}});
                out = static_cast<int>(doc_["textures"].size()) - 1;
            }
        }
        textures_[image] = out;
        return out;
    }

    int add_camera(const Camera& c) {
        json persp = {{"yfov", static_cast<double>(c.yfov)},
                      {"znear", static_cast<double>(c.znear)},
                      {"zfar", static_cast<double>(c.zfar)}};
        const float aspect = c.aspect > 0.0f ? c.aspect : options_.aspect;
        if (aspect > 0.0f) persp["aspectRatio"] = static_cast<double>(aspect);
        doc_["cameras"] = json::array({{{"name", "camera"}, {"type", "perspective"}, {"perspective", persp}}});
        // The camera node's world matrix is the inverse of the view, computed in double.
        const glm::mat4 world = glm::mat4(glm::inverse(glm::dmat4(c.view)));
        return add_node({{"name", "camera"}, {"camera", 0}, {"matrix", matrix_json(world)}});
    }

    int add_light(const Light& l) {
        json light = {{"name", "light"}, {"color", vec_json(&l.color.x, 3)}, {"intensity", static_cast<double>(l.intensity)}};
        if (l.radius > 0.0f) light["extras"] = {{"penumbra", {{"radius", static_cast<double>(l.radius)}}}};
        json node = {{"name", "light"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}};
        switch (l.type) {
            case LightType::Directional: light["type"] = "directional"; break;
            case LightType::Point: light["type"] = "point"; break;
            case LightType::Spot:
                light["type"] = "spot";
                light["spot"] = {{"innerConeAngle", static_cast<double>(l.spot_inner_cone)},
                                 {"outerConeAngle", static_cast<double>(l.spot_outer_cone)}};
                break;
        }
        if (l.type == LightType::Point) {
            node["translation"] = vec_json(&l.position.x, 3);
        } else {
            node["matrix"] = matrix_json(frame_looking(l.position, l.direction));
        }
        doc_["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({light})}}}};
        return add_node(std::move(node));
    }

    const GltfWriteOptions& options_;
    json doc_ = json::object();
    std::vector<std::uint8_t> bin_;
    std::map<std::pair<int, int>, int> meshes_;
    std::map<int, int> materials_;
    std::map<int, int> textures_;
};

}  // namespace

std::string to_gltf(const Scene& scene, const GltfWriteOptions& options) {
    Writer w(options);
    return w.run(scene).dump(1);
}

std::string write_gltf(const std::string& path, const Scene& scene, const GltfWriteOptions& options) {
    const std::string text = to_gltf(scene, options);
    const std::string tmp = path + ".tmp";
    {
        std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
        if (!f) return path + ": cannot write (" + std::strerror(errno) + ")";
        f << text << "\n";
        f.flush();
        if (!f) {
            std::remove(tmp.c_str());
            return path + ": write failed";
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        return path + ": cannot rename into place (" + why + ")";
    }
    return {};
}

}  // namespace penumbra::scene
