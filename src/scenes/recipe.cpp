#include "scenes/recipe.h"

#include <cmath>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace penumbra::scene::recipe {

double rounded(double v, int digits) {
    const double k = std::pow(10.0, digits);
    return std::round(v * k) / k + 0.0;
}
D3 rounded(const D3& v, int digits) { return {rounded(v[0], digits), rounded(v[1], digits), rounded(v[2], digits)}; }
D4 rounded(const D4& v, int digits) {
    return {rounded(v[0], digits), rounded(v[1], digits), rounded(v[2], digits), rounded(v[3], digits)};
}

D4 quat_axis_angle(const D3& axis, double degrees) {
    const double s = std::sin(radians(degrees) / 2.0);
    return {axis[0] * s, axis[1] * s, axis[2] * s, std::cos(radians(degrees) / 2.0)};
}

D4 look_at_rotation(const D3& eye, const D3& target) {
    D3 f = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& c : f) c /= fl;
    const D3 z = {-f[0], -f[1], -f[2]};
    const D3 up = {0.0, 1.0, 0.0};
    D3 x = {up[1] * z[2] - up[2] * z[1], up[2] * z[0] - up[0] * z[2], up[0] * z[1] - up[1] * z[0]};
    const double xl = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    for (double& c : x) c /= xl;
    const D3 y = {z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]};
    const double m[3][3] = {{x[0], y[0], z[0]}, {x[1], y[1], z[1]}, {x[2], y[2], z[2]}};
    const double tr = m[0][0] + m[1][1] + m[2][2];
    if (tr > 0) {
        const double s = std::sqrt(tr + 1.0) * 2;
        return {(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s};
    }
    if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
        const double s = std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2;
        return {0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s};
    }
    if (m[1][1] > m[2][2]) {
        const double s = std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2;
        return {(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s};
    }
    const double s = std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2;
    return {(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s};
}

glm::vec3 to_float(const D3& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

glm::mat4 node_world(const D3& t, const D4* r, const D3* s) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), to_float(t));
    if (r) {
        const glm::quat q(static_cast<float>((*r)[3]), static_cast<float>((*r)[0]), static_cast<float>((*r)[1]),
                          static_cast<float>((*r)[2]));
        m *= glm::mat4_cast(glm::normalize(q));
    }
    if (s) m = glm::scale(m, to_float(*s));
    return m;
}

glm::mat4 camera_view(const D3& eye, const D3& target) {
    const D3 t = rounded(eye);
    const D4 r = rounded(look_at_rotation(eye, target), 5);
    // The loader's rigid view (gltf_scene.cpp).
    return glm::inverse(rigid_frame(node_world(t, &r, nullptr)));
}

Mesh make_mesh(std::string name, const std::vector<D3>& pos, const std::vector<D3>& nrm, std::vector<std::uint32_t> idx) {
    Mesh m;
    m.name = std::move(name);
    for (const D3& p : pos) m.positions.push_back(to_float(p));
    for (const D3& n : nrm) m.normals.push_back(glm::normalize(to_float(n)));
    m.indices = std::move(idx);
    seal(m);
    return m;
}

Mesh box_mesh(std::string name, const D3& centre, const D3& size) {
    const double hx = size[0] / 2.0, hy = size[1] / 2.0, hz = size[2] / 2.0;
    struct Face {
        D3 n;
        std::array<D3, 4> corners;  // counter-clockwise seen from outside
    };
    const std::array<Face, 6> faces = {{
        {{1, 0, 0}, {{{hx, -hy, hz}, {hx, -hy, -hz}, {hx, hy, -hz}, {hx, hy, hz}}}},
        {{-1, 0, 0}, {{{-hx, -hy, -hz}, {-hx, -hy, hz}, {-hx, hy, hz}, {-hx, hy, -hz}}}},
        {{0, 1, 0}, {{{-hx, hy, hz}, {hx, hy, hz}, {hx, hy, -hz}, {-hx, hy, -hz}}}},
        {{0, -1, 0}, {{{-hx, -hy, -hz}, {hx, -hy, -hz}, {hx, -hy, hz}, {-hx, -hy, hz}}}},
        {{0, 0, 1}, {{{-hx, -hy, hz}, {hx, -hy, hz}, {hx, hy, hz}, {-hx, hy, hz}}}},
        {{0, 0, -1}, {{{hx, -hy, -hz}, {-hx, -hy, -hz}, {-hx, hy, -hz}, {hx, hy, -hz}}}},
    }};
    std::vector<D3> pos, nrm;
    std::vector<std::uint32_t> idx;
    for (const Face& f : faces) {
        const auto base = static_cast<std::uint32_t>(pos.size());
        for (const D3& p : f.corners) {
            pos.push_back({centre[0] + p[0], centre[1] + p[1], centre[2] + p[2]});
            nrm.push_back(f.n);
        }
        idx.insert(idx.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return make_mesh(std::move(name), pos, nrm, std::move(idx));
}

Mesh uv_sphere_mesh(std::string name, double radius, int slices, int stacks) {
    std::vector<D3> pos, nrm;
    std::vector<std::uint32_t> idx;
    for (int j = 0; j <= stacks; ++j) {
        const double theta = kPi * j / stacks;
        for (int i = 0; i <= slices; ++i) {
            const double phi = 2.0 * kPi * i / slices;
            const D3 n = {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
            nrm.push_back(n);
            pos.push_back({radius * n[0], radius * n[1], radius * n[2]});
        }
    }
    const int row = slices + 1;
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const auto a = static_cast<std::uint32_t>(j * row + i), b = static_cast<std::uint32_t>((j + 1) * row + i);
            // Counter-clockwise seen from outside; the pole rows lose their degenerate triangle.
            if (j != 0) idx.insert(idx.end(), {a, a + 1, b});
            if (j != stacks - 1) idx.insert(idx.end(), {a + 1, b + 1, b});
        }
    return make_mesh(std::move(name), pos, nrm, std::move(idx));
}

int SceneBuilder::material(const char* name, double r, double g, double b) {
    Material m;
    m.name = name;
    m.base_color = glm::vec4(static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), 1.0f);
    scene.materials.push_back(m);
    return static_cast<int>(scene.materials.size()) - 1;
}

int SceneBuilder::mesh(Mesh m) {
    scene.meshes.push_back(std::move(m));
    return static_cast<int>(scene.meshes.size()) - 1;
}

void SceneBuilder::place(std::string name, int mesh_index, int material_index, const D3& t, const D4* r, const D3* s) {
    Object o;
    o.name = std::move(name);
    o.mesh = mesh_index;
    o.material = material_index;
    const D3 tr = rounded(t);
    D4 rr{};
    D3 sr{};
    if (r) rr = rounded(*r, 5);
    if (s) sr = rounded(*s);
    o.world = node_world(tr, r ? &rr : nullptr, s ? &sr : nullptr);
    scene.objects.push_back(std::move(o));
}

}  // namespace penumbra::scene::recipe
