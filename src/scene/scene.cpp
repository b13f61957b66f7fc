#include "scene/scene.h"

#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>

namespace penumbra::scene {

bool is_closed(const Mesh& mesh) {
    if (mesh.indices.size() < 12 || mesh.indices.size() % 3 != 0) return false;  // fewer than 4 triangles
    const Bounds b = mesh_bounds(mesh);
    const float size = glm::length(b.max - b.min);
    if (!(size > 0.0f) || !std::isfinite(size)) return false;
    const float cell = 1e-6f * size;
    // Weld: one id per rounded position.
    std::map<std::tuple<long long, long long, long long>, std::uint32_t> ids;
    std::vector<std::uint32_t> weld(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 q = glm::round(mesh.positions[i] / cell);
        const auto key = std::make_tuple(static_cast<long long>(q.x), static_cast<long long>(q.y), static_cast<long long>(q.z));
        weld[i] = ids.emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
    }
    // Each directed edge once; its reverse once.
    std::unordered_map<std::uint64_t, int> edges;
    const auto key = [](std::uint32_t from, std::uint32_t to) { return (static_cast<std::uint64_t>(from) << 32) | to; };
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::uint32_t v[3];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = mesh.indices[t + static_cast<size_t>(k)];
            if (i >= weld.size()) return false;
            v[k] = weld[i];
        }
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
        for (int k = 0; k < 3; ++k)
            if (++edges[key(v[k], v[(k + 1) % 3])] > 1) return false;  // an edge run twice the same way
    }
    if (edges.empty()) return false;
    for (const auto& [e, n] : edges)
        if (!edges.count(key(static_cast<std::uint32_t>(e & 0xffffffffu), static_cast<std::uint32_t>(e >> 32)))) return false;
    return true;
}

Bounds mesh_bounds(const Mesh& mesh) {
    Bounds b;
    for (const auto& p : mesh.positions) b.add(p);
    return b;
}

std::vector<glm::vec3> corners(const Bounds& b) {
    std::vector<glm::vec3> out;
    out.reserve(8);
    for (int i = 0; i < 8; ++i)
        out.emplace_back((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    return out;
}

Bounds object_bounds(const Scene& scene, const Object& object) {
    Bounds out;
    if (object.mesh < 0 || object.mesh >= static_cast<int>(scene.meshes.size())) return out;
    const Bounds local = mesh_bounds(scene.meshes[static_cast<size_t>(object.mesh)]);
    if (local.empty()) return out;
    for (const auto& c : corners(local)) out.add(glm::vec3(object.world * glm::vec4(c, 1.0f)));
    return out;
}

Bounds scene_bounds(const Scene& scene, bool casters_only) {
    Bounds out;
    for (const auto& o : scene.objects)
        if (!casters_only || o.casts_shadow) out.add(object_bounds(scene, o));
    return out;
}

}  // namespace penumbra::scene
