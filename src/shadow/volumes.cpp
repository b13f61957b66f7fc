#include "shadow/volumes.h"

#include <algorithm>
#include <cstddef>
#include <cmath>

namespace penumbra::shadow {

ShadowVolume extrude_volume(const scene::Topology& topology, const glm::mat4& world, const glm::vec4& light,
                            bool closed, bool caps) {
    // The edge table weld made (a topology made by hand gets one here).
    scene::Topology storage;
    const scene::Topology& t = scene::with_edge_table(topology, storage);
    ShadowVolume v;
    const glm::vec3 l(light);
    const bool directional = light.w == 0.0f;
    std::vector<glm::vec3> p(t.positions.size());
    for (size_t i = 0; i < p.size(); ++i) p[i] = glm::vec3(world * glm::vec4(t.positions[i], 1.0f));
    // A mirroring transform turns the mesh's winding round.
    const bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;
    const auto away = [&](std::uint32_t i) { return glm::vec4(directional ? -l : p[i] - l, 0.0f); };
    const auto at = [&](std::uint32_t i) { return glm::vec4(p[i], 1.0f); };

    // Net uses of each edge, counted in the direction from its lower to its higher index.
    std::vector<int> net(t.edge_count(), 0);
    if (caps) {  // at most every triangle: no regrowth (and copy) while they are added
        v.near_cap.reserve(t.triangles.size());
        if (!directional) v.far_cap.reserve(t.triangles.size());
    }
    for (size_t k = 0; k + 2 < t.triangles.size(); k += 3) {
        std::uint32_t a = t.triangles[k], b = t.triangles[k + 1], c = t.triangles[k + 2];
        if (mirrored) std::swap(b, c);
        const glm::vec3 n = glm::cross(p[b] - p[a], p[c] - p[a]);
        const glm::vec3 to_light = directional ? l : l - p[a];
        const float facing = glm::dot(n, to_light);
        if (!(facing != 0.0f)) continue;       // edge-on (or not finite): a volume of no thickness
        if (closed && facing > 0.0f) continue;  // the dark cap: the faces away from the light only
        if (facing < 0.0f) std::swap(b, c);      // turned to face the light
        // The mesh's corner order, or (mirrored xor turned) reversed: each edge runs the other way.
        const int turn = mirrored != (facing < 0.0f) ? -1 : 1;
        for (size_t j = 0; j < 3; ++j) {
            const std::uint32_t from = t.triangles[k + j], to = t.triangles[k + (j + 1) % 3];
            net[t.corner_edges[k + j]] += from < to ? turn : -turn;
        }
        if (caps) {
            v.near_cap.insert(v.near_cap.end(), {at(a), at(b), at(c)});
            if (!directional) v.far_cap.insert(v.far_cap.end(), {away(a), away(c), away(b)});
        }
    }
    for (size_t e = 0; e < net.size(); ++e) {
        const int n = net[e];
        if (n == 0) continue;
        std::uint32_t u = t.edges[2 * e], w = t.edges[2 * e + 1];
        if (n < 0) std::swap(u, w);  // the triangles run the edge u -> w
        for (int k = 0; k < std::abs(n); ++k) {
            ++v.silhouette_edges;
            // Seen from outside the volume the quad runs w, u, u at infinity, w at infinity.
            if (directional) {
                v.sides.insert(v.sides.end(), {at(w), at(u), away(u)});
            } else {
                v.sides.insert(v.sides.end(), {at(w), at(u), away(u), at(w), away(u), away(w)});
            }
        }
    }
    return v;
}

std::array<glm::vec3, 4> near_rectangle(const glm::mat4& view_proj) {
    const glm::mat4 inv = glm::inverse(view_proj);
    const glm::vec2 ndc[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    std::array<glm::vec3, 4> out{};
    for (int i = 0; i < 4; ++i) {
        const glm::vec4 h = inv * glm::vec4(ndc[i], -1.0f, 1.0f);
        out[static_cast<size_t>(i)] = glm::vec3(h) / h.w;
    }
    return out;
}

bool may_shadow_near_plane(const std::array<glm::vec3, 4>& r, const glm::vec4& light, const scene::Bounds& b) {
    if (b.empty()) return false;
    const std::vector<glm::vec3> box = scene::corners(b);
    for (const auto& c : box)
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return true;
    // The pyramid's points: the rectangle and the light, or the rectangle swept towards a
    // directional light further than any point of the box lies from it.
    std::vector<glm::vec3> hull(r.begin(), r.end());
    std::vector<glm::vec3> axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, glm::cross(r[1] - r[0], r[3] - r[0])};
    if (light.w != 0.0f) {
        const glm::vec3 l = glm::vec3(light) / light.w;
        hull.push_back(l);
        for (size_t i = 0; i < 4; ++i) axes.push_back(glm::cross(r[i] - l, r[(i + 1) % 4] - l));
    } else {
        const glm::vec3 d = glm::normalize(glm::vec3(light));
        float reach = 1.0f;
        for (const auto& c : box)
            for (const auto& q : r) reach = std::max(reach, 2.0f * glm::length(c - q));
        for (size_t i = 0; i < 4; ++i) {
            hull.push_back(r[i] + reach * d);
            axes.push_back(glm::cross(r[(i + 1) % 4] - r[i], d));
        }
    }
    for (const glm::vec3& axis : axes) {
        if (!(glm::dot(axis, axis) > 1e-20f)) continue;
        float h0 = INFINITY, h1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
        for (const auto& q : hull) {
            h0 = std::min(h0, glm::dot(axis, q));
            h1 = std::max(h1, glm::dot(axis, q));
        }
        for (const auto& q : box) {
            b0 = std::min(b0, glm::dot(axis, q));
            b1 = std::max(b1, glm::dot(axis, q));
        }
        // Separated along this axis, with a margin for rounding.
        const float margin = 1e-5f * std::max({std::abs(h0), std::abs(h1), std::abs(b0), std::abs(b1), 1e-30f});
        if (h1 + margin < b0 || b1 + margin < h0) return false;
    }
    return true;
}

namespace {

// A convex polygon of clip-space points, on the stack: covered_pixels runs every moving frame
// over every volume triangle, and a vector per clip made allocation its largest cost. A triangle
// clipped by the six planes of the view volume gains at most one vertex per plane (9); rounding
// can make a polygon a hair from convex, whose clip may gain more, so room for 16 and nothing
// written past it (a sliver's vertex lost: an area of about nothing).
struct Polygon {
    std::array<glm::vec4, 16> p;
    size_t n = 0;
    void add(const glm::vec4& v) {
        if (n < p.size()) p[n++] = v;
    }
};

// Clips `in` to `dot(plane, p) >= 0`.
Polygon clip(const Polygon& in, const glm::vec4& plane) {
    Polygon out;
    for (size_t i = 0; i < in.n; ++i) {
        const glm::vec4& a = in.p[i];
        const glm::vec4& b = in.p[(i + 1) % in.n];
        const float da = glm::dot(plane, a), db = glm::dot(plane, b);
        if (da >= 0.0f) out.add(a);
        if ((da >= 0.0f) != (db >= 0.0f)) out.add(a + (b - a) * (da / (da - db)));
    }
    return out;
}

}  // namespace

double covered_pixels(const std::vector<glm::vec4>& tris, const glm::mat4& view_proj, int width, int height) {
    static const glm::vec4 planes[6] = {{1, 0, 0, 1}, {-1, 0, 0, 1}, {0, 1, 0, 1}, {0, -1, 0, 1}, {0, 0, 1, 1}, {0, 0, -1, 1}};
    double area = 0.0;
    for (size_t k = 0; k + 2 < tris.size(); k += 3) {
        Polygon poly;
        poly.p[0] = view_proj * tris[k];
        poly.p[1] = view_proj * tris[k + 1];
        poly.p[2] = view_proj * tris[k + 2];
        poly.n = 3;
        for (const glm::vec4& plane : planes) {
            // A plane every corner is inside leaves the polygon as it is (clip would copy it).
            if (std::all_of(poly.p.begin(), poly.p.begin() + static_cast<std::ptrdiff_t>(poly.n),
                            [&](const glm::vec4& q) { return glm::dot(plane, q) >= 0.0f; }))
                continue;
            poly = clip(poly, plane);
            if (poly.n < 3) break;
        }
        if (poly.n < 3) continue;
        double twice = 0.0;
        for (size_t i = 0; i < poly.n; ++i) {
            const glm::vec4& a = poly.p[i];
            const glm::vec4& b = poly.p[(i + 1) % poly.n];
            if (!(a.w > 0.0f) || !(b.w > 0.0f)) continue;
            const double ax = 0.5 * (a.x / a.w + 1.0) * width, ay = 0.5 * (a.y / a.w + 1.0) * height;
            const double bx = 0.5 * (b.x / b.w + 1.0) * width, by = 0.5 * (b.y / b.w + 1.0) * height;
            twice += ax * by - bx * ay;
        }
        area += std::abs(twice) * 0.5;
    }
    return area;
}

bool infinite_far(glm::mat4& proj) {
    // glm's perspective: [2][3] = -1, [3][3] = 0, [2][2] = -(f+n)/(f-n), [3][2] = -2fn/(f-n).
    if (proj[2][3] != -1.0f || proj[3][3] != 0.0f || proj[2][2] == 1.0f) return false;
    const float n = proj[3][2] / (proj[2][2] - 1.0f);
    if (!(n > 0.0f) || !std::isfinite(n)) return false;
    constexpr float eps = 1.0f / 1048576.0f;  // 2^-20: points at infinity land just inside the far plane
    proj[2][2] = eps - 1.0f;
    proj[3][2] = (eps - 2.0f) * n;
    return true;
}

}  // namespace penumbra::shadow
