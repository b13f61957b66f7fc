#include "scene/gltf_writer.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>
#include <stb_image_write.h>  // implementation compiled in src/thirdparty/thirdparty_impl.cpp

#include "scene/file_write.h"
#include "scene/printable.h"

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

// A name in the file as text (JSON is UTF-8): a name that is not valid UTF-8 goes in escaped.
std::string text(const std::string& name) { return valid_utf8(name) ? name : printable(name); }

template <typename V>
bool all_finite(const std::vector<V>& values, size_t& bad) {
    for (size_t i = 0; i < values.size(); ++i)
        for (int k = 0; k < V::length(); ++k)
            if (!std::isfinite(values[i][k])) {
                bad = i;
                return false;
            }
    return true;
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

    // The first value that cannot be written ("" when none): a number that is not finite (JSON has
    // no NaN or infinity; nlohmann would write null, which no loader takes back) or a camera that
    // glTF cannot express.
    const std::string& problem() const { return problem_; }

    json run(const Scene& s) {
        doc_["asset"] = {{"version", "2.0"}, {"generator", text(options_.generator)}};
        for (auto key : {"buffers", "bufferViews", "accessors", "meshes", "nodes", "materials", "images",
                         "samplers", "textures"})
            doc_[key] = json::array();

        json scene_nodes = json::array();
        for (const auto& o : s.objects) {
            const int mesh = mesh_for(s, o);
            if (mesh < 0) continue;
            json node = {{"name", text(o.name)}, {"mesh", mesh}};
            if (o.world != glm::mat4(1.0f)) node["matrix"] = matrix_json(o.world, "object '" + printable(o.name) + "': its world matrix");
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
    // A number for the file; a non-finite one is recorded as the problem (named by `what`).
    double number(double v, const std::string& what) {
        if (!std::isfinite(v)) {
            fail(what + " is not finite (" + (std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf") + ")");
            return 0.0;
        }
        return v;
    }

    void fail(const std::string& why) {
        if (problem_.empty()) problem_ = why;
    }

    json matrix_json(const glm::mat4& m, const std::string& what) {
        json a = json::array();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) a.push_back(number(static_cast<double>(m[c][r]), what));
        return a;
    }

    json vec_json(const float* v, int n, const std::string& what) {
        json a = json::array();
        for (int i = 0; i < n; ++i) a.push_back(number(static_cast<double>(v[i]), what));
        return a;
    }

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
            a["min"] = vec_json(&lo.x, 3, "the positions' bounds");
            a["max"] = vec_json(&hi.x, 3, "the positions' bounds");
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
        const std::string mesh_name = "mesh '" + printable(m.name) + "'";
        size_t bad = 0;
        if (!all_finite(m.positions, bad)) fail(mesh_name + ": position " + std::to_string(bad) + " is not finite");
        if (!all_finite(m.normals, bad)) fail(mesh_name + ": normal " + std::to_string(bad) + " is not finite");
        if (!all_finite(m.uvs, bad)) fail(mesh_name + ": uv " + std::to_string(bad) + " is not finite");
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
            doc_["meshes"].push_back({{"name", text(m.name)}, {"primitives", json::array({prim})}});
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
        const std::string what = "material '" + printable(m.name) + "'";
        const double shininess = number(static_cast<double>(m.shininess), what + ": shininess");
        const double roughness = std::min(1.0, std::sqrt(std::sqrt(2.0 / (std::max(shininess, 0.0) + 2.0))));
        json pbr = {{"baseColorFactor", vec_json(&m.base_color.x, 4, what + ": base colour")},
                    {"metallicFactor", 0.0},
                    {"roughnessFactor", roughness}};
        const int texture = texture_for(s, m.base_color_texture);
        if (texture >= 0) pbr["baseColorTexture"] = {{"index", texture}};
        json mat = {{"name", text(m.name)},
                    {"pbrMetallicRoughness", pbr},
                    {"extras", {{"penumbra", {{"specular", number(static_cast<double>(m.specular), what + ": specular")},
                                              {"shininess", shininess}}}}}};
        // glTF's defaults (OPAQUE, 0.5, single-sided) are left out; the cutoff only with MASK.
        if (m.alpha_mode != AlphaMode::Opaque) mat["alphaMode"] = to_string(m.alpha_mode);
        if (m.alpha_mode == AlphaMode::Mask) {
            const double cutoff = number(static_cast<double>(m.alpha_cutoff), what + ": alpha cutoff");
            if (!(cutoff >= 0.0 && cutoff <= 1.0))
                fail(what + ": alpha cutoff " + std::to_string(cutoff) + " is outside 0..1, which glTF cannot hold");
            mat["alphaCutoff"] = cutoff;
        }
        if (m.double_sided) mat["doubleSided"] = true;
        doc_["materials"].push_back(std::move(mat));
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
        const double yfov = number(static_cast<double>(c.yfov), "the camera's yfov");
        const double znear = number(static_cast<double>(c.znear), "the camera's znear");
        const double zfar = number(static_cast<double>(c.zfar), "the camera's zfar");
        // What glTF's perspective camera requires (and the loader would otherwise replace).
        if (!(yfov > 0.0 && yfov < 3.14159265358979)) fail("the camera's yfov " + std::to_string(yfov) + " is not in (0, pi)");
        if (!(znear > 0.0)) fail("the camera's znear " + std::to_string(znear) + " is not > 0");
        if (!(zfar > znear)) fail("the camera's zfar " + std::to_string(zfar) + " is not > its znear");
        json persp = {{"yfov", yfov}, {"znear", znear}, {"zfar", zfar}};
        const float aspect = c.aspect > 0.0f ? c.aspect : options_.aspect;
        if (aspect > 0.0f) persp["aspectRatio"] = number(static_cast<double>(aspect), "the camera's aspect ratio");
        doc_["cameras"] = json::array({{{"name", "camera"}, {"type", "perspective"}, {"perspective", persp}}});
        // The camera node's world matrix is the inverse of the view, computed in double.
        const glm::mat4 world = glm::mat4(glm::inverse(glm::dmat4(c.view)));
        return add_node({{"name", "camera"}, {"camera", 0}, {"matrix", matrix_json(world, "the camera's matrix")}});
    }

    int add_light(const Light& l) {
        json light = {{"name", "light"},
                      {"color", vec_json(&l.color.x, 3, "the light's colour")},
                      {"intensity", number(static_cast<double>(l.intensity), "the light's intensity")}};
        if (l.radius > 0.0f) light["extras"] = {{"penumbra", {{"radius", number(static_cast<double>(l.radius), "the light's radius")}}}};
        json node = {{"name", "light"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}};
        switch (l.type) {
            case LightType::Directional: light["type"] = "directional"; break;
            case LightType::Point: light["type"] = "point"; break;
            case LightType::Spot:
                light["type"] = "spot";
                light["spot"] = {{"innerConeAngle", number(static_cast<double>(l.spot_inner_cone), "the spot light's inner cone")},
                                 {"outerConeAngle", number(static_cast<double>(l.spot_outer_cone), "the spot light's outer cone")}};
                break;
        }
        if (l.type == LightType::Point) {
            node["translation"] = vec_json(&l.position.x, 3, "the light's position");
        } else {
            vec_json(&l.position.x, 3, "the light's position");
            vec_json(&l.direction.x, 3, "the light's direction");
            node["matrix"] = matrix_json(frame_looking(l.position, l.direction), "the light's matrix");
        }
        doc_["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({light})}}}};
        return add_node(std::move(node));
    }

    const GltfWriteOptions& options_;
    std::string problem_;
    json doc_ = json::object();
    std::vector<std::uint8_t> bin_;
    std::map<std::pair<int, int>, int> meshes_;
    std::map<int, int> materials_;
    std::map<int, int> textures_;
};

}  // namespace

std::string to_gltf(const Scene& scene, const GltfWriteOptions& options, std::string& error) {
    Writer w(options);
    const json doc = w.run(scene);
    error = w.problem();
    if (!error.empty()) return {};
    // Every string went through text(): replacing would only ever touch what that missed.
    return doc.dump(1, ' ', false, json::error_handler_t::replace);
}

std::string to_gltf(const Scene& scene, const GltfWriteOptions& options) {
    std::string error;
    std::string out = to_gltf(scene, options, error);
    if (!error.empty()) throw std::invalid_argument("cannot write glTF: " + error);
    return out;
}

std::string write_gltf(const std::string& path, const Scene& scene, const GltfWriteOptions& options) {
    const std::string name = printable(path);  // one line, valid UTF-8, whatever the path's bytes
    std::string error;
    const std::string doc = to_gltf(scene, options, error);
    if (!error.empty()) return name + ": not written: " + error;
    return write_file(path, doc + "\n");
}

}  // namespace penumbra::scene
