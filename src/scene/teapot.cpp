// Tessellation of the Newell teapot: evaluates its 32 bicubic Bezier patches on a regular
// parameter grid into an indexed, outward-facing, y-up triangle mesh.
#include "scene/teapot.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra::scene {
namespace {

#include "scene/teapot_data.inc"

// Cubic Bernstein polynomials and their derivatives at one parameter value.
struct Basis {
    std::array<double, 4> b;
    std::array<double, 4> d;
};

Basis bernstein(double t) {
    const double u = 1.0 - t;
    return {{u * u * u, 3.0 * t * u * u, 3.0 * t * t * u, t * t * t},
            {-3.0 * u * u, 3.0 * u * u - 6.0 * t * u, 6.0 * t * u - 3.0 * t * t, 3.0 * t * t}};
}

using Patch = std::array<std::array<glm::dvec3, 4>, 4>;  // [row][column]

// The patch is P(s, t) = sum_r sum_c B_r(t) B_c(s) ctrl[r][c]: s runs along a row of control
// points, t across the rows.
struct Sample {
    glm::dvec3 p;
    glm::dvec3 ds;   // dP/ds
    glm::dvec3 dt;   // dP/dt
    glm::dvec3 dst;  // d2P/(ds dt), only needed where a whole edge collapses into a point
};

Sample evaluate(const Patch& ctrl, const Basis& bs, const Basis& bt) {
    Sample out{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
    for (std::size_t r = 0; r < 4; ++r) {
        for (std::size_t c = 0; c < 4; ++c) {
            const glm::dvec3& q = ctrl[r][c];
            out.p += bt.b[r] * bs.b[c] * q;
            out.ds += bt.b[r] * bs.d[c] * q;
            out.dt += bt.d[r] * bs.b[c] * q;
            out.dst += bt.d[r] * bs.d[c] * q;
        }
    }
    return out;
}

bool negligible(const glm::dvec3& n, const glm::dvec3& ds, const glm::dvec3& dt) {
    const double scale = glm::dot(ds, ds) + glm::dot(dt, dt);
    return glm::dot(n, n) <= 1e-20 * scale * scale;
}

// Unnormalised cross(dP/ds, dP/dt), with its limit where the patch pinches to a point (the lid
// knob top and the bottom centre): there a whole row of control points coincides, so one
// derivative vanishes along that edge, but it grows linearly away from it, so the direction
// of cross(ds, dt) near the edge is that of the cross product with the mixed derivative.
glm::dvec3 surface_normal(const Patch& ctrl, const Sample& e, double s, double t) {
    const glm::dvec3 n = glm::cross(e.ds, e.dt);
    if (!negligible(n, e.ds, e.dt)) return n;
    // Row collapsed at t = 0 or 1: ds ~ (t - t_edge) * dst; a column at s = 0 or 1 likewise.
    const bool row_collapsed = glm::dot(e.ds, e.ds) < glm::dot(e.dt, e.dt);
    const glm::dvec3 a = row_collapsed ? e.dst * (t < 0.5 ? 1.0 : -1.0) : e.ds;
    const glm::dvec3 b = row_collapsed ? e.dt : e.dst * (s < 0.5 ? 1.0 : -1.0);
    const glm::dvec3 limit = glm::cross(a, b);
    if (!negligible(limit, a, b)) return limit;
    // No patch of the data gets here; should one, a point just inside the patch still has a
    // tangent plane, and its normal is close enough to the limit for shading.
    constexpr double kNudge = 1e-4;
    const Sample inner = evaluate(ctrl, bernstein(s + (s < 0.5 ? kNudge : -kNudge)),
                                  bernstein(t + (t < 0.5 ? kNudge : -kNudge)));
    return glm::cross(inner.ds, inner.dt);
}

Patch load_patch(int index) {
    Patch out{};
    for (std::size_t r = 0; r < 4; ++r) {
        for (std::size_t c = 0; c < 4; ++c) {
            const float* q = kTeapotPoints[kTeapotPatches[index][r * 4 + c]];
            // The data is z-up; a rotation about x (not a mirror, so windings survive) makes it y-up.
            out[r][c] = glm::dvec3(q[0], q[2], -q[1]);
        }
    }
    return out;
}

}  // namespace

Mesh make_teapot(int level) {
    if (level < 1) level = 1;
    const auto n = static_cast<std::size_t>(level);
    const std::size_t row = n + 1;

    Mesh mesh;
    mesh.name = "teapot";
    mesh.positions.reserve(kTeapotPatchCount * row * row);
    mesh.normals.reserve(kTeapotPatchCount * row * row);
    mesh.uvs.reserve(kTeapotPatchCount * row * row);
    mesh.indices.reserve(kTeapotPatchCount * n * n * 6);

    std::vector<Basis> basis(row);
    for (std::size_t i = 0; i < row; ++i) basis[i] = bernstein(static_cast<double>(i) / static_cast<double>(n));

    for (int patch = 0; patch < kTeapotPatchCount; ++patch) {
        const Patch ctrl = load_patch(patch);
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());

        for (std::size_t i = 0; i < row; ++i) {
            for (std::size_t j = 0; j < row; ++j) {
                const double s = static_cast<double>(j) / static_cast<double>(n);
                const double t = static_cast<double>(i) / static_cast<double>(n);
                const Sample e = evaluate(ctrl, basis[j], basis[i]);
                mesh.positions.emplace_back(e.p);
                mesh.normals.emplace_back(glm::normalize(surface_normal(ctrl, e, s, t)));
                mesh.uvs.emplace_back(static_cast<float>(s), static_cast<float>(t));
            }
        }

        // Quad (a, b, c, d) steps s then t, so a-b-c turns like cross(ds, dt): counter-clockwise
        // seen from outside, since every patch of this data set has cross(ds, dt) pointing out
        // of the pot (the ray-cast test in test_teapot.cpp holds it to that).
        const auto at = [&](std::size_t i, std::size_t j) {
            return base + static_cast<std::uint32_t>(i * row + j);
        };
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; j < n; ++j) {
                const std::uint32_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
                mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
            }
        }
    }

    // Stand the pot on y = 0 and centre it on x/z, from the tessellated points so that each
    // level is exactly placed.
    Bounds bounds;
    for (const auto& p : mesh.positions) bounds.add(p);
    const glm::vec3 shift(bounds.center().x, bounds.min.y, bounds.center().z);
    for (auto& p : mesh.positions) p -= shift;

    // Where a patch pinches to a point, one triangle of each quad on that edge has two corners
    // in the same place (and at level 1 the spout tip's corners lie on one line): such triangles
    // have no area, draw nothing and would only give NaN face normals downstream.
    const glm::vec3 extent = bounds.max - bounds.min;
    const float min_double_area = 1e-9f * glm::dot(extent, extent);
    std::size_t kept = 0;
    for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
        const glm::vec3& p0 = mesh.positions[mesh.indices[k]];
        const glm::vec3& p1 = mesh.positions[mesh.indices[k + 1]];
        const glm::vec3& p2 = mesh.positions[mesh.indices[k + 2]];
        if (glm::length(glm::cross(p1 - p0, p2 - p0)) <= min_double_area) continue;
        for (std::size_t m = 0; m < 3; ++m) mesh.indices[kept + m] = mesh.indices[k + m];
        kept += 3;
    }
    mesh.indices.resize(kept);
    seal(mesh);  // the Newell teapot has no bottom and an open rim: false
    return mesh;
}

}  // namespace penumbra::scene
