// is_convex (scene.h) in time linear in the mesh. Checking every vertex against every triangle's
// plane costs vertices x triangles, which grows with the square of a mesh's size (docs/scale.md).
// A closed surface is instead convex when it is convex at every edge and at every vertex
// (polyhedral Hadamard: a closed, locally convex, immersed surface bounds a convex body); the
// checks below say that edge by edge and count, once, how many times the surface wraps its Gauss
// sphere.
#include "scene/scene.h"

#include <cmath>

namespace penumbra::scene {
namespace {

glm::vec3 corner(const Topology& t, size_t tri, size_t j) { return t.positions[t.triangles[3 * tri + j % 3]]; }

glm::vec3 face_normal(const Topology& t, size_t tri) {
    const glm::vec3 a = corner(t, tri, 0);
    return glm::cross(corner(t, tri, 1) - a, corner(t, tri, 2) - a);
}

// Whether p lies in front of triangle tri's plane by more than the slack below; `at` is one of
// its corners.
bool folds_in(const Topology& t, size_t tri, size_t at, const glm::vec3& p, float noise) {
    const glm::vec3 n = face_normal(t, tri), d = p - corner(t, tri, at);
    return glm::dot(d, n) > (1e-5f * glm::length(d) + noise) * glm::length(n);
}

// Whether the far corner of the triangle across each edge lies on or behind the near triangle's
// plane. The slack is an angle (1e-5 radians of fold, plus float noise at the mesh's scale), not
// a length: a length would let a finely cut dent through edge by edge.
bool convex_at_every_edge(const Topology& t, float noise) {
    const size_t tris = t.triangles.size() / 3;
    // For each edge, the first triangle corner that runs it; the second meets it below.
    std::vector<std::uint32_t> first(t.edge_count(), UINT32_MAX);
    for (size_t c = 0; c < 3 * tris; ++c) {
        std::uint32_t& f = first[t.corner_edges[c]];
        if (f == UINT32_MAX) {
            f = static_cast<std::uint32_t>(c);
            continue;
        }
        // The corner of each triangle that is not on the edge: two past the edge's first corner.
        // (A sliver's normal is zero: it passes, and its neighbour across the edge decides.)
        if (folds_in(t, f / 3, f % 3, corner(t, c / 3, c % 3 + 2), noise) ||
            folds_in(t, c / 3, c % 3, corner(t, f / 3, f % 3 + 2), noise))
            return false;
    }
    return true;
}

}  // namespace

bool is_convex(const Topology& topology, bool closed) {
    const size_t tris = topology.triangles.size() / 3;
    if (tris == 0) return false;
    Bounds b;
    for (const glm::vec3& p : topology.positions) b.add(p);
    const float size = glm::length(b.max - b.min);
    // The planes of the triangles; a flat surface has one (up to 1e-5 of its size).
    const glm::vec3& a0 = topology.positions[topology.triangles[0]];
    glm::vec3 n0(0.0f);
    for (size_t k = 0; k < tris && glm::length(n0) == 0.0f; ++k) n0 = face_normal(topology, k);
    if (!(glm::length(n0) > 0.0f)) return false;
    n0 = glm::normalize(n0);
    bool flat = true;
    for (const glm::vec3& p : topology.positions) flat = flat && std::fabs(glm::dot(p - a0, n0)) <= 1e-5f * size;
    if (flat) return true;
    if (!closed) return false;
    Topology storage;
    const Topology& t = with_edge_table(topology, storage);
    if (!convex_at_every_edge(t, 1e-6f * size)) return false;

    // Convex at every edge, a surface may still be two convex pieces, a torus, or one that wraps
    // its convex hull twice round two branch points (each vertex convex, the surface not). A
    // sphere (V - E + F = 2) that has exactly one highest vertex in a direction no edge is level
    // in, wrapped once round that vertex, is none of these: the Gauss map's degree is the sum of
    // the windings of the highest vertices, and a degree of one on a sphere leaves every
    // vertex's winding one.
    std::vector<int> used(t.positions.size(), 0);
    for (std::uint32_t v : t.triangles) used[v] = 1;
    long long vertices = 0;
    for (int u : used) vertices += u;
    if (vertices - static_cast<long long>(t.edge_count()) + static_cast<long long>(tris) != 2) return false;
    const glm::vec3 up = glm::normalize(glm::vec3(0.3141593f, 0.8017954f, 0.5093387f));  // level with no axis
    std::vector<int> highest(used);
    for (size_t e = 0; e < t.edge_count(); ++e) {
        const std::uint32_t v = t.edges[2 * e], w = t.edges[2 * e + 1];
        const float hv = glm::dot(t.positions[v], up), hw = glm::dot(t.positions[w], up);
        if (!(hv > hw)) highest[v] = 0;
        if (!(hw > hv)) highest[w] = 0;
    }
    std::uint32_t top = UINT32_MAX;
    for (size_t v = 0; v < highest.size(); ++v)
        if (highest[v]) {
            if (top != UINT32_MAX) return false;
            top = static_cast<std::uint32_t>(v);
        }
    if (top == UINT32_MAX) return false;
    // The winding round the top, seen from above: how many times its triangles' far edges cross a
    // half-line from it, counted by direction.
    const glm::vec3 across = glm::normalize(glm::cross(up, glm::vec3(0.0f, 0.0f, 1.0f))), side = glm::cross(up, across);
    int winding = 0;
    for (size_t c = 0; c < 3 * tris; ++c) {
        if (t.triangles[c] != top) continue;
        const glm::vec3 p = corner(t, c / 3, c % 3 + 1) - t.positions[top], q = corner(t, c / 3, c % 3 + 2) - t.positions[top];
        const float py = glm::dot(p, side), qy = glm::dot(q, side);
        const float turn = glm::dot(glm::cross(p, q), up);
        if (py <= 0.0f && qy > 0.0f && turn > 0.0f) ++winding;
        if (qy <= 0.0f && py > 0.0f && turn < 0.0f) --winding;
    }
    return winding == 1 || winding == -1;
}

}  // namespace penumbra::scene
