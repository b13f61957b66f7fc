// glTF mesh primitives -> scene::Mesh. Every accessor a primitive reads is validated against its
// bufferView and buffer before a byte of it is read (tinygltf checks none of this), then its
// positions, indices, normals and TEXCOORD_0 are copied out.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>

#include "scene/gltf_internal.h"

namespace penumbra::scene::gltf_internal {
namespace {

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

// `name` names the accessor in the message when an element is not finite (NaN or infinite
// floats would reach every matrix, bound and ray built from them).
std::vector<glm::vec3> read_vec3(const AccessorData& a, const std::string& name) {
    std::vector<glm::vec3> out(a.count);
    for (size_t i = 0; i < a.count; ++i) {
        out[i] = glm::vec3(read_float(a, i, 0), read_float(a, i, 1), read_float(a, i, 2));
        if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
            fail(name + ": element " + std::to_string(i) + " is not finite");
    }
    return out;
}

std::string accessor_name(int index, const std::string& what) {
    return "accessors[" + std::to_string(index) + "] (" + what + ")";
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

}  // namespace

Mesh convert_primitive(const tinygltf::Model& model, int mesh_index, size_t p) {
    const auto& src = model.meshes[static_cast<size_t>(mesh_index)];
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
    const auto pos = view_accessor(model, pos_it->second, "POSITION of " + where,
                                   {TINYGLTF_COMPONENT_TYPE_FLOAT}, TINYGLTF_TYPE_VEC3);
    if (pos.count > std::numeric_limits<std::uint32_t>::max())
        fail(where + " has more vertices than 32-bit indices can address");
    mesh.positions = read_vec3(pos, accessor_name(pos_it->second, "POSITION of " + where));
    const size_t n = mesh.positions.size();

    if (prim.indices >= 0) {
        const auto idx = view_accessor(model, prim.indices, "indices of " + where,
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
        const auto nrm = view_accessor(model, nrm_it->second, "NORMAL of " + where,
                                       {TINYGLTF_COMPONENT_TYPE_FLOAT}, TINYGLTF_TYPE_VEC3);
        if (nrm.count != n)
            fail(where + " has " + std::to_string(nrm.count) + " normals for " + std::to_string(n) +
                 " vertices");
        mesh.normals = read_vec3(nrm, accessor_name(nrm_it->second, "NORMAL of " + where));
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
        const auto uv = view_accessor(model, uv_it->second, "TEXCOORD_0 of " + where,
                                      {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                      TINYGLTF_TYPE_VEC2);
        if (uv.count != n)
            fail(where + " has " + std::to_string(uv.count) + " texture coordinates for " +
                 std::to_string(n) + " vertices");
        mesh.uvs.resize(n);
        for (size_t i = 0; i < n; ++i) {
            mesh.uvs[i] = glm::vec2(read_float(uv, i, 0), read_float(uv, i, 1));
            if (!std::isfinite(mesh.uvs[i].x) || !std::isfinite(mesh.uvs[i].y))
                fail(accessor_name(uv_it->second, "TEXCOORD_0 of " + where) + ": element " + std::to_string(i) +
                     " is not finite");
        }
    }
    seal(mesh);
    return mesh;
}

}  // namespace penumbra::scene::gltf_internal
