#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/gtc/type_precision.hpp>

namespace penumbra::scene {

namespace {

// For each of n items, the first item with the same key (itself when none came before): open
// addressing over a power-of-two table with linear probing: two flat arrays, where a std::map's
// node per key and its tree walks made the teapot's weld the longest step of the pages' main() in
// wasm (docs/payload.md).
template <class Hash, class Same>
std::vector<std::uint32_t> first_alike(size_t n, Hash hash, Same same) {
    size_t size = 16;
    while (size < 2 * n) size *= 2;
    std::vector<std::uint32_t> table(size, UINT32_MAX), first(n);
    for (size_t i = 0; i < n; ++i) {
        size_t h = hash(i) & (size - 1);
        while (table[h] != UINT32_MAX && !same(table[h], i)) h = (h + 1) & (size - 1);
        if (table[h] == UINT32_MAX) table[h] = static_cast<std::uint32_t>(i);
        first[i] = table[h];
    }
    return first;
}

// A 64-bit finaliser (splitmix64's): neighbouring keys land far apart in the table.
size_t mix(std::uint64_t k) {
    k = (k ^ (k >> 30)) * 0xbf58476d1ce4e5b9ULL;
    k = (k ^ (k >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<size_t>(k ^ (k >> 31));
}

}  // namespace

Topology weld(const Mesh& mesh) {
    Topology t;
    const Bounds b = mesh_bounds(mesh);
    const float size = glm::length(b.max - b.min);
    if (!(size > 0.0f) || !std::isfinite(size) || mesh.indices.size() % 3 != 0) return t;
    const float cell = 1e-6f * size;
    // One id per rounded position, in the order the positions first come.
    std::vector<glm::i64vec3> keys(mesh.positions.size());
    for (size_t i = 0; i < keys.size(); ++i) keys[i] = glm::i64vec3(glm::round(mesh.positions[i] / cell));
    const std::vector<std::uint32_t> first = first_alike(
        keys.size(),
        [&](size_t i) {
            return mix(static_cast<std::uint64_t>(keys[i].x) * 0x9e3779b97f4a7c15ULL ^
                       static_cast<std::uint64_t>(keys[i].y) * 0xc2b2ae3d27d4eb4fULL ^ static_cast<std::uint64_t>(keys[i].z));
        },
        [&](size_t i, size_t j) { return keys[i] == keys[j]; });
    std::vector<std::uint32_t> id(mesh.positions.size());
    for (size_t i = 0; i < id.size(); ++i) {
        if (first[i] == i) {
            id[i] = static_cast<std::uint32_t>(t.positions.size());
            t.positions.push_back(mesh.positions[i]);
        } else {
            id[i] = id[first[i]];
        }
    }
    for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
        std::uint32_t v[3];
        bool inside = true;
        for (int j = 0; j < 3; ++j) {
            const std::uint32_t i = mesh.indices[k + static_cast<size_t>(j)];
            inside = inside && i < id.size();
            v[j] = inside ? id[i] : 0;
        }
        if (!inside || v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
        t.triangles.insert(t.triangles.end(), {v[0], v[1], v[2]});
    }
    index_edges(t);
    return t;
}

void index_edges(Topology& t) {
    t.edges.clear();
    const size_t corners = t.triangles.size() / 3 * 3;
    // Each corner's edge as its two vertices, lower first, in one 64-bit key.
    std::vector<std::uint64_t> keys(corners);
    for (size_t c = 0; c < corners; ++c) {
        const std::uint32_t a = t.triangles[c], b = t.triangles[c - c % 3 + (c % 3 + 1) % 3];
        keys[c] = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    }
    const std::vector<std::uint32_t> first =
        first_alike(corners, [&](size_t c) { return mix(keys[c]); }, [&](size_t c, size_t d) { return keys[c] == keys[d]; });
    t.corner_edges.assign(corners, 0);
    for (size_t c = 0; c < corners; ++c) {
        if (first[c] == c) {
            t.corner_edges[c] = static_cast<std::uint32_t>(t.edges.size() / 2);
            t.edges.insert(t.edges.end(), {static_cast<std::uint32_t>(keys[c] >> 32), static_cast<std::uint32_t>(keys[c])});
        } else {
            t.corner_edges[c] = t.corner_edges[first[c]];
        }
    }
}

const Topology& with_edge_table(const Topology& topology, Topology& storage) {
    if (topology.corner_edges.size() == topology.triangles.size() / 3 * 3) return topology;
    storage = topology;
    index_edges(storage);
    return storage;
}

bool is_closed(const Topology& topology) {
    if (topology.triangles.size() < 12) return false;  // fewer than 4 triangles
    Topology storage;
    const Topology& t = with_edge_table(topology, storage);
    // Every edge run once from its lower vertex to its higher, once back.
    std::vector<int> up(t.edge_count(), 0), down(t.edge_count(), 0);
    for (size_t k = 0; k + 2 < t.triangles.size(); k += 3)
        for (size_t j = 0; j < 3; ++j)
            ++(t.triangles[k + j] < t.triangles[k + (j + 1) % 3] ? up : down)[t.corner_edges[k + j]];
    for (size_t e = 0; e < up.size(); ++e)
        if (up[e] != 1 || down[e] != 1) return false;
    return true;
}

bool is_closed(const Mesh& mesh) {
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) return false;
    return is_closed(weld(mesh));
}

bool is_faceted(const Mesh& mesh) {
    if (mesh.indices.size() < 3 || mesh.normals.size() != mesh.positions.size()) return false;
    constexpr float kCos = 0.9999995f;  // cos(1e-3)
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t v[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
        for (std::uint32_t k : v)
            if (k >= mesh.positions.size()) return false;
        const glm::vec3 g = glm::cross(mesh.positions[v[1]] - mesh.positions[v[0]], mesh.positions[v[2]] - mesh.positions[v[0]]);
        const float len = glm::length(g);
        if (!(len > 0.0f)) continue;
        for (std::uint32_t k : v) {
            const glm::vec3& n = mesh.normals[k];
            const float nl = glm::length(n);
            if (!(nl > 0.0f) || std::abs(glm::dot(n, g)) < kCos * nl * len) return false;
        }
    }
    return true;
}

void seal(Mesh& mesh) {
    auto t = std::make_shared<Topology>(weld(mesh));
    bool in_range = true;
    for (std::uint32_t i : mesh.indices) in_range = in_range && i < mesh.positions.size();
    mesh.closed = in_range && is_closed(*t);
    mesh.convex = in_range && is_convex(*t, mesh.closed);
    mesh.faceted = in_range && is_faceted(mesh);
    mesh.topology = std::move(t);
}

Bounds mesh_bounds(const Mesh& mesh) {
    Bounds b;
    for (const auto& p : mesh.positions) b.add(p);
    return b;
}

glm::mat4 reflection(const glm::vec4& plane) {
    const glm::vec3 n(plane);
    glm::mat4 r(1.0f);
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) r[col][row] -= 2.0f * n[row] * n[col];
    r[3] = glm::vec4(-2.0f * plane.w * n, 1.0f);
    return r;
}

std::vector<glm::vec3> corners(const Bounds& b) {
    std::vector<glm::vec3> out;
    out.reserve(8);
    for (int i = 0; i < 8; ++i)
        out.emplace_back((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    return out;
}

namespace {

Bounds placed(const Bounds& local, const glm::mat4& world) {
    Bounds out;
    if (local.empty()) return out;
    for (const auto& c : corners(local)) out.add(glm::vec3(world * glm::vec4(c, 1.0f)));
    return out;
}

}  // namespace

Bounds object_bounds(const Scene& scene, const Object& object) {
    if (object.mesh < 0 || object.mesh >= static_cast<int>(scene.meshes.size())) return {};
    return placed(mesh_bounds(scene.meshes[static_cast<size_t>(object.mesh)]), object.world);
}

std::vector<Bounds> all_mesh_bounds(const Scene& scene) {
    std::vector<Bounds> out;
    out.reserve(scene.meshes.size());
    for (const Mesh& m : scene.meshes) out.push_back(mesh_bounds(m));
    return out;
}

Bounds object_bounds(const std::vector<Bounds>& mesh_bounds, const Object& object) {
    if (object.mesh < 0 || object.mesh >= static_cast<int>(mesh_bounds.size())) return {};
    return placed(mesh_bounds[static_cast<size_t>(object.mesh)], object.world);
}

glm::mat4 rigid_frame(const glm::mat4& w) {
    glm::mat4 rigid(1.0f);
    const glm::vec3 z = glm::normalize(glm::vec3(w[2]));
    const glm::vec3 x = glm::normalize(glm::cross(glm::vec3(w[1]), z));
    rigid[0] = glm::vec4(x, 0.0f);
    rigid[1] = glm::vec4(glm::cross(z, x), 0.0f);
    rigid[2] = glm::vec4(z, 0.0f);
    rigid[3] = w[3];
    return rigid;
}

Bounds scene_bounds(const Scene& scene, bool casters_only) {
    const std::vector<Bounds> meshes = all_mesh_bounds(scene);
    Bounds out;
    for (const auto& o : scene.objects)
        if (!casters_only || o.casts_shadow) out.add(object_bounds(meshes, o));
    return out;
}

const char* to_string(AlphaMode m) {
    switch (m) {
        case AlphaMode::Opaque: return "OPAQUE";
        case AlphaMode::Mask: return "MASK";
        case AlphaMode::Blend: return "BLEND";
    }
    return "OPAQUE";
}

bool repeats(const Image& image) {
    const auto pot = [](int v) { return v > 0 && (v & (v - 1)) == 0; };
    return pot(image.width) && pot(image.height);
}

float sample_alpha(const Image& image, glm::vec2 uv, bool repeat) {
    const int w = image.width, h = image.height;
    if (w <= 0 || h <= 0 || image.rgba.size() < static_cast<size_t>(w) * static_cast<size_t>(h) * 4u) return 1.0f;
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return 1.0f;
    const auto texel = [&](int x, int y) {
        if (repeat) {
            x %= w;
            y %= h;
            if (x < 0) x += w;
            if (y < 0) y += h;
        } else {
            x = x < 0 ? 0 : x >= w ? w - 1 : x;
            y = y < 0 ? 0 : y >= h ? h - 1 : y;
        }
        return static_cast<float>(image.rgba[(static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * 4u + 3u]) /
               255.0f;
    };
    // Far outside [0, 1] the repeat is the same texels; keep the floor's int in range.
    if (repeat) uv -= glm::floor(uv);
    else uv = glm::clamp(uv, glm::vec2(-1.0f), glm::vec2(2.0f));
    const float fx = uv.x * static_cast<float>(w) - 0.5f, fy = uv.y * static_cast<float>(h) - 0.5f;
    const float x0f = std::floor(fx), y0f = std::floor(fy);
    const float tx = fx - x0f, ty = fy - y0f;
    const int x0 = static_cast<int>(x0f), y0 = static_cast<int>(y0f);
    const float top = texel(x0, y0) * (1.0f - tx) + texel(x0 + 1, y0) * tx;
    const float bottom = texel(x0, y0 + 1) * (1.0f - tx) + texel(x0 + 1, y0 + 1) * tx;
    return top * (1.0f - ty) + bottom * ty;
}

}  // namespace penumbra::scene
