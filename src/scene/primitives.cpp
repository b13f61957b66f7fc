// Meshes made in code: the table-top quad, a UV sphere and a flat-shaded box. All wind their
// triangles counter-clockwise seen from outside (the GL default front face) with unit normals.
#include "scene/primitives.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace penumbra::scene {

namespace {

constexpr float kPi = 3.14159265358979323846f;

std::uint32_t u32(int i) { return static_cast<std::uint32_t>(i); }

}  // namespace

Mesh make_quad(float size, float uv_repeat) {
    Mesh m;
    m.name = "quad";
    const float h = 0.5f * size;
    // Corners in the order (-x,-z), (-x,+z), (+x,+z), (+x,-z): counter-clockwise seen from +y.
    const float xs[4] = {-h, -h, h, h};
    const float zs[4] = {-h, h, h, -h};
    for (int i = 0; i < 4; ++i) {
        m.positions.emplace_back(xs[i], 0.0f, zs[i]);
        m.normals.emplace_back(0.0f, 1.0f, 0.0f);
        // u along +x, v along +z, each 0..uv_repeat so a texture tiles uv_repeat times.
        m.uvs.emplace_back((xs[i] > 0.0f ? 1.0f : 0.0f) * uv_repeat, (zs[i] > 0.0f ? 1.0f : 0.0f) * uv_repeat);
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    seal(m);
    return m;
}

Mesh make_sphere(float radius, int slices, int stacks) {
    // Fewer than 3 slices or 2 stacks has no volume; clamp rather than return an empty mesh.
    slices = std::max(slices, 3);
    stacks = std::max(stacks, 2);
    Mesh m;
    m.name = "sphere";

    // theta from 0 at the north pole (+y) to pi at the south pole, phi around the y axis with
    // increasing phi going right when seen from outside; v = theta/pi puts the image's top row
    // (row 0, t = 0 in GL) at the north pole.
    const auto add = [&](int i, float u) {
        const float theta = kPi * static_cast<float>(i) / static_cast<float>(stacks);
        const float phi = 2.0f * kPi * u;
        const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
        m.normals.push_back(glm::normalize(n));
        m.positions.push_back(radius * n);
        m.uvs.emplace_back(u, static_cast<float>(i) / static_cast<float>(stacks));
    };

    // Each pole gets one vertex per slice (its u at the slice's middle), so the pole rows are
    // triangles with their own texture coordinate rather than quads with a zero-length edge.
    // Interior rows have slices + 1 vertices: the seam is duplicated for u = 0 and u = 1.
    const int ring = slices + 1;
    for (int j = 0; j < slices; ++j) add(0, (static_cast<float>(j) + 0.5f) / static_cast<float>(slices));
    for (int i = 1; i < stacks; ++i)
        for (int j = 0; j <= slices; ++j) add(i, static_cast<float>(j) / static_cast<float>(slices));
    const int south = slices + (stacks - 1) * ring;
    for (int j = 0; j < slices; ++j) add(stacks, (static_cast<float>(j) + 0.5f) / static_cast<float>(slices));

    const auto row = [&](int i, int j) { return u32(slices + (i - 1) * ring + j); };  // interior rows 1..stacks-1
    m.indices.reserve(static_cast<size_t>(6 * slices * (stacks - 1)));
    for (int j = 0; j < slices; ++j) {
        // North cap: pole, then down-left, down-right (counter-clockwise from outside).
        m.indices.insert(m.indices.end(), {u32(j), row(1, j), row(1, j + 1)});
    }
    for (int i = 1; i + 1 < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = row(i, j), b = row(i + 1, j), c = row(i + 1, j + 1), d = row(i, j + 1);
            m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
        }
    }
    for (int j = 0; j < slices; ++j) {
        // South cap: up-left, pole, up-right.
        m.indices.insert(m.indices.end(), {row(stacks - 1, j), u32(south + j), row(stacks - 1, j + 1)});
    }
    seal(m);
    return m;
}

Mesh make_bowl(float radius, int slices, int stacks) {
    Mesh m = make_sphere(radius, slices, stacks);
    m.name = "bowl";
    std::vector<std::uint32_t> kept;
    const float rim = 1e-4f * radius;
    for (size_t k = 0; k + 2 < m.indices.size(); k += 3) {
        bool low = true;
        for (size_t j = 0; j < 3; ++j) low = low && m.positions[m.indices[k + j]].y <= rim;
        if (low) kept.insert(kept.end(), {m.indices[k], m.indices[k + 1], m.indices[k + 2]});
    }
    m.indices = std::move(kept);
    seal(m);
    return m;
}

Mesh make_box(const glm::vec3& half_extent) {
    Mesh m;
    m.name = "box";
    // A negative extent would mirror the box and turn its faces inside out.
    const glm::vec3 h = glm::abs(half_extent);
    // Each face: outward normal n and in-plane axes u, v with u x v = n, so the corners
    // (-u-v), (+u-v), (+u+v), (-u+v) run counter-clockwise seen from outside.
    struct Face {
        glm::vec3 n, u, v;
    };
    const Face faces[6] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    const float su[4] = {-1, 1, 1, -1};
    const float sv[4] = {-1, -1, 1, 1};
    for (const Face& f : faces) {
        const std::uint32_t base = static_cast<std::uint32_t>(m.positions.size());
        for (int k = 0; k < 4; ++k) {
            m.positions.push_back(h * (f.n + su[k] * f.u + sv[k] * f.v));
            m.normals.push_back(f.n);
            // v = 0 at the face's +v edge: the image's top row (t = 0) is "up" on the side faces.
            m.uvs.emplace_back(0.5f * (su[k] + 1.0f), 0.5f * (1.0f - sv[k]));
        }
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    seal(m);
    return m;
}

}  // namespace penumbra::scene
