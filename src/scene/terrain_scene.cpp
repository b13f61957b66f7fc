#include "scene/terrain_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace penumbra::scene {

namespace {

// Everything below follows tests/data/make_large_scenes.py (and the helpers it takes from
// make_bench_gltf.py and make_gltf.py) step by step, in double precision as Python computes,
// then stored as the glTF file stores it: 32-bit floats.

constexpr double kPi = 3.14159265358979323846;
constexpr double kTerrainSize = 1000.0;
constexpr int kCells = 64;
constexpr double kCell = kTerrainSize / kCells;
constexpr double kCameraX = -60.0, kCameraZ = 440.0, kCameraHeight = 1.9;

struct Hill {
    double a, kx, kz, phase;
};
constexpr std::array<Hill, 4> kHills = {{
    {5.0, 1.0 / 95.0, 0.4 / 95.0, 0.3},
    {3.0, -0.3 / 70.0, 1.0 / 70.0, 1.7},
    {1.5, 0.8 / 38.0, 0.6 / 38.0, 4.1},
    {0.6, -0.7 / 21.0, 0.7 / 21.0, 2.6},
}};

using D3 = std::array<double, 3>;
using D4 = std::array<double, 4>;  // a quaternion as glTF stores it: x, y, z, w

double radians(double deg) { return deg * kPi / 180.0; }

double hill_height(double x, double z) {
    double h = 0.0;
    for (const Hill& k : kHills) h += k.a * std::sin(k.kx * x + k.kz * z + k.phase);
    return h;
}

D3 hill_normal(double x, double z) {
    double dx = 0.0, dz = 0.0;
    for (const Hill& k : kHills) dx += k.a * k.kx * std::cos(k.kx * x + k.kz * z + k.phase);
    for (const Hill& k : kHills) dz += k.a * k.kz * std::cos(k.kx * x + k.kz * z + k.phase);
    const double len = std::sqrt(dx * dx + 1.0 + dz * dz);
    return {-dx / len, 1.0 / len, -dz / len};
}

double grid_coordinate(int i) { return -kTerrainSize / 2.0 + kCell * i; }

double surface_height(double x, double z) {
    const double u = (x - grid_coordinate(0)) / kCell, v = (z - grid_coordinate(0)) / kCell;
    const int i = std::min(static_cast<int>(u), kCells - 1), j = std::min(static_cast<int>(v), kCells - 1);
    const double fu = u - i, fv = v - j;
    const double x0 = grid_coordinate(i), x1 = grid_coordinate(i + 1), z0 = grid_coordinate(j),
                 z1 = grid_coordinate(j + 1);
    const double h00 = hill_height(x0, z0), h11 = hill_height(x1, z1);
    if (fv >= fu) return h00 + fv * (hill_height(x0, z1) - h00) + fu * (h11 - hill_height(x0, z1));
    return h00 + fu * (hill_height(x1, z0) - h00) + fv * (h11 - hill_height(x1, z0));
}

double lowest_under(double x, double z, double radius) {
    double lo = 1e300;
    for (const double dx : {-1.0, 0.0, 1.0})
        for (const double dz : {-1.0, 0.0, 1.0}) lo = std::min(lo, surface_height(x + dx * radius, z + dz * radius));
    return lo;
}

// Python's round(v, digits) for the values these scenes hold (never a tie in practice).
double rounded(double v, int digits) {
    const double k = std::pow(10.0, digits);
    return std::round(v * k) / k + 0.0;
}
D3 rounded(const D3& v, int digits = 3) { return {rounded(v[0], digits), rounded(v[1], digits), rounded(v[2], digits)}; }
D4 rounded(const D4& v, int digits) {
    return {rounded(v[0], digits), rounded(v[1], digits), rounded(v[2], digits), rounded(v[3], digits)};
}

// A 32-bit linear congruential generator (Numerical Recipes' constants), as the script's Lcg.
class Lcg {
public:
    explicit Lcg(std::uint32_t seed) : state_(seed) {}
    double uniform(double lo, double hi) {
        state_ = 1664525u * state_ + 1013904223u;
        return lo + (hi - lo) * (state_ / 4294967296.0);
    }

private:
    std::uint32_t state_;
};

D4 quat_axis_angle(const D3& axis, double degrees) {
    const double s = std::sin(radians(degrees) / 2.0);
    return {axis[0] * s, axis[1] * s, axis[2] * s, std::cos(radians(degrees) / 2.0)};
}

// The quaternion turning a glTF camera (looking down -z, +y up) at eye towards target.
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

D4 light_rotation(double elevation_deg, double azimuth_deg) {
    const double el = radians(elevation_deg), az = radians(azimuth_deg);
    const D3 d = {std::cos(el) * std::cos(az), -std::sin(el), -std::cos(el) * std::sin(az)};
    return look_at_rotation({0.0, 0.0, 0.0}, d);
}

glm::vec3 to_float(const D3& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// A node's matrix as the glTF loader makes it: T * R * S in 32-bit floats.
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

// A mesh from the script's (positions, normals, indices), the normals made unit as the loader does.
Mesh make_mesh(std::string name, const std::vector<D3>& pos, const std::vector<D3>& nrm, std::vector<std::uint32_t> idx) {
    Mesh m;
    m.name = std::move(name);
    for (const D3& p : pos) m.positions.push_back(to_float(p));
    for (const D3& n : nrm) m.normals.push_back(glm::normalize(to_float(n)));
    m.indices = std::move(idx);
    seal(m);
    return m;
}

Mesh terrain_mesh() {
    const int n = kCells + 1;
    std::vector<D3> pos, nrm;
    std::vector<std::uint32_t> idx;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = grid_coordinate(i), z = grid_coordinate(j);
            pos.push_back({x, hill_height(x, z), z});
            nrm.push_back(hill_normal(x, z));
        }
    for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < kCells; ++i) {
            const auto a = static_cast<std::uint32_t>(j * n + i), b = a + 1, c = static_cast<std::uint32_t>((j + 1) * n + i),
                       d = c + 1;
            idx.insert(idx.end(), {a, c, d, a, d, b});
        }
    return make_mesh("terrain", pos, nrm, std::move(idx));
}

// make_bench_gltf.box(0, 0.5, 0, 1, 1, 1): a unit box standing on y = 0, flat-shaded.
Mesh unit_box() {
    const double h = 0.5;
    struct Face {
        D3 n;
        std::array<D3, 4> corners;
    };
    const std::array<Face, 6> faces = {{
        {{1, 0, 0}, {{{h, -h, h}, {h, -h, -h}, {h, h, -h}, {h, h, h}}}},
        {{-1, 0, 0}, {{{-h, -h, -h}, {-h, -h, h}, {-h, h, h}, {-h, h, -h}}}},
        {{0, 1, 0}, {{{-h, h, h}, {h, h, h}, {h, h, -h}, {-h, h, -h}}}},
        {{0, -1, 0}, {{{-h, -h, -h}, {h, -h, -h}, {h, -h, h}, {-h, -h, h}}}},
        {{0, 0, 1}, {{{-h, -h, h}, {h, -h, h}, {h, h, h}, {-h, h, h}}}},
        {{0, 0, -1}, {{{h, -h, -h}, {-h, -h, -h}, {-h, h, -h}, {h, h, -h}}}},
    }};
    std::vector<D3> pos, nrm;
    std::vector<std::uint32_t> idx;
    for (const Face& f : faces) {
        const auto base = static_cast<std::uint32_t>(pos.size());
        for (const D3& p : f.corners) {
            pos.push_back({p[0], 0.5 + p[1], p[2]});
            nrm.push_back(f.n);
        }
        idx.insert(idx.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return make_mesh("unit box", pos, nrm, std::move(idx));
}

// make_bench_gltf.cylinder(0, 0, 0.5, 1, segments=12): capped, smooth sides, flat caps.
Mesh unit_cylinder() {
    const int segments = 12;
    const double radius = 0.5, height = 1.0, y0 = 0.0;
    std::vector<D3> pos, nrm;
    std::vector<std::uint32_t> idx;
    for (int i = 0; i <= segments; ++i) {
        const double a = 2.0 * kPi * i / segments;
        const D3 n = {std::cos(a), 0.0, -std::sin(a)};
        pos.push_back({radius * n[0], y0, radius * n[2]});
        pos.push_back({radius * n[0], y0 + height, radius * n[2]});
        nrm.push_back(n);
        nrm.push_back(n);
    }
    for (int i = 0; i < segments; ++i) {
        const auto a = static_cast<std::uint32_t>(2 * i), b = a + 2;
        idx.insert(idx.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
    for (const auto& [y, ny] : {std::pair<double, double>{y0 + height, 1.0}, {y0, -1.0}}) {
        const auto centre = static_cast<std::uint32_t>(pos.size());
        pos.push_back({0.0, y, 0.0});
        nrm.push_back({0.0, ny, 0.0});
        for (int i = 0; i <= segments; ++i) {
            const double a = 2.0 * kPi * i / segments;
            pos.push_back({radius * std::cos(a), y, -radius * std::sin(a)});
            nrm.push_back({0.0, ny, 0.0});
        }
        for (int i = 0; i < segments; ++i) {
            const auto p = centre + 1 + static_cast<std::uint32_t>(i), q = p + 1;
            if (ny > 0) idx.insert(idx.end(), {centre, p, q});
            else idx.insert(idx.end(), {centre, q, p});
        }
    }
    return make_mesh("unit cylinder", pos, nrm, std::move(idx));
}

// make_gltf.uv_sphere(1, 24, 12).
Mesh unit_sphere() {
    const int slices = 24, stacks = 12;
    std::vector<D3> pos, nrm;
    std::vector<std::uint32_t> idx;
    for (int j = 0; j <= stacks; ++j) {
        const double theta = kPi * j / stacks;
        for (int i = 0; i <= slices; ++i) {
            const double phi = 2.0 * kPi * i / slices;
            const D3 n = {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
            nrm.push_back(n);
            pos.push_back(n);
        }
    }
    const int row = slices + 1;
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const auto a = static_cast<std::uint32_t>(j * row + i), b = static_cast<std::uint32_t>((j + 1) * row + i);
            if (j != 0) idx.insert(idx.end(), {a, a + 1, b});
            if (j != stacks - 1) idx.insert(idx.end(), {a + 1, b + 1, b});
        }
    return make_mesh("unit sphere", pos, nrm, std::move(idx));
}

enum Kind { House, Pole, Post, Boulder };
struct Size {
    double a = 0, b = 0, c = 0;  // house: x, y, z; pole and post: thickness, height; boulder: radius
};

double footprint(Kind kind, const Size& s) {
    if (kind == House) return 0.5 * std::hypot(s.a, s.c);
    if (kind == Boulder) return s.a;
    return 0.5 * s.a * std::sqrt(2.0);
}

struct Builder {
    Scene scene;
    int box = -1, cylinder = -1, sphere = -1;                     // meshes
    int grass = -1, stone = -1, wood = -1, plaster = -1;          // materials
    struct Placed {
        double x, z, r;
    };
    std::vector<Placed> placed;

    int material(const char* name, double r, double g, double b) {
        Material m;
        m.name = name;
        m.base_color = glm::vec4(static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), 1.0f);
        scene.materials.push_back(m);
        return static_cast<int>(scene.materials.size()) - 1;
    }
    int mesh(Mesh m) {
        scene.meshes.push_back(std::move(m));
        return static_cast<int>(scene.meshes.size()) - 1;
    }
    void place(std::string name, int mesh_index, int material_index, const D3& t, const D4* r, const D3* s) {
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
    // One object standing on the terrain at x, z (the script's put()).
    void put(const std::string& name, Kind kind, double x, double z, const Size& size, double turn) {
        const double r = footprint(kind, size);
        const double base = lowest_under(x, z, r) - 0.1;
        const D4 rotation = quat_axis_angle({0, 1, 0}, turn);
        if (kind == House) {
            const D3 s = {size.a, size.b, size.c};
            place(name, box, plaster, {x, base, z}, &rotation, &s);
        } else if (kind == Boulder) {
            const D3 s = {size.a, size.a, size.a};
            place(name, sphere, stone, {x, surface_height(x, z) + 0.9 * size.a, z}, nullptr, &s);
        } else {
            const D3 s = {size.a, size.b, size.a};
            if (kind == Pole) place(name, cylinder, wood, {x, base, z}, nullptr, &s);
            else place(name, box, plaster, {x, base, z}, &rotation, &s);
        }
        placed.push_back({x, z, r});
    }
};

const char* kind_name(Kind k) {
    switch (k) {
        case House: return "house";
        case Pole: return "pole";
        case Post: return "post";
        case Boulder: return "boulder";
    }
    return "";
}

}  // namespace

float terrain_km_height(float x, float z) {
    const double h = kTerrainSize / 2.0 - 1e-6;
    return static_cast<float>(surface_height(std::clamp(static_cast<double>(x), -h, h), std::clamp(static_cast<double>(z), -h, h)));
}

Scene make_terrain_km_scene() {
    Builder b;
    b.grass = b.material("grass", 0.45, 0.6, 0.35);
    b.stone = b.material("stone", 0.6, 0.58, 0.55);
    b.wood = b.material("wood", 0.55, 0.4, 0.25);
    b.plaster = b.material("plaster", 0.85, 0.8, 0.7);
    // The meshes in the order the loader makes them: as the nodes first use them.
    const int ground = b.mesh(terrain_mesh());
    b.cylinder = b.mesh(unit_cylinder());
    b.sphere = b.mesh(unit_sphere());
    b.box = b.mesh(unit_box());
    {
        Object o;
        o.name = "terrain";
        o.mesh = ground;
        o.material = b.grass;
        b.scene.objects.push_back(o);
    }

    // Hand-placed objects 6-40 m in front of the camera (right, ahead: the view looks along -z).
    Lcg rng(20240611u);
    struct Near {
        Kind kind;
        double right, ahead;
        Size size;
    };
    const Near near[] = {
        {Pole, 2.0, -7.0, {0.3, 6.0}},          {Boulder, -2.5, -9.0, {0.6}},     {Post, 5.0, -12.0, {0.4, 5.0}},
        {Boulder, 1.0, -15.0, {0.9}},           {House, -14.0, -22.0, {6, 4, 5}}, {Pole, -4.0, -19.0, {0.4, 8.0}},
        {Pole, 9.0, -24.0, {0.3, 5.5}},         {Boulder, -1.5, -28.0, {1.2}},    {House, 16.0, -36.0, {8, 5, 6}},
        {Post, -8.0, -32.0, {0.6, 9.0}},        {Pole, 4.0, -38.0, {0.8, 11.0}},  {Boulder, -4.0, -40.0, {1.8}},
    };
    int k = 0;
    for (const Near& n : near) {
        const double turn = rng.uniform(0.0, 90.0);
        b.put("near " + std::string(kind_name(n.kind)) + " " + std::to_string(k++), n.kind, kCameraX + n.right,
              kCameraZ + n.ahead, n.size, turn);
    }
    // 348 scattered over the kilometre, none within 45 m of the camera, no two overlapping.
    int count = 0;
    while (count < 348) {
        const double x = rng.uniform(-480.0, 480.0), z = rng.uniform(-480.0, 480.0);
        const double roll = rng.uniform(0.0, 1.0);
        Kind kind;
        Size size;
        if (roll < 0.3) {
            kind = House;
            size.a = rng.uniform(4.0, 15.0);
            size.b = rng.uniform(3.0, 9.0);
            size.c = rng.uniform(4.0, 15.0);
        } else if (roll < 0.75) {
            kind = roll < 0.6 ? Pole : Post;
            size.a = rng.uniform(0.3, 1.0);
            size.b = rng.uniform(5.0, 12.0);
        } else {
            kind = Boulder;
            size.a = rng.uniform(0.5, 2.0);
        }
        const double turn = rng.uniform(0.0, 90.0);
        const double r = footprint(kind, size);
        if (std::hypot(x - kCameraX, z - kCameraZ) < 45.0 + r) continue;
        bool overlaps = false;
        for (const auto& p : b.placed) overlaps = overlaps || std::hypot(x - p.x, z - p.z) < r + p.r + 2.0;
        if (overlaps) continue;
        b.put(std::string(kind_name(kind)) + " " + std::to_string(count), kind, x, z, size, turn);
        ++count;
    }

    // The camera: 1.9 m above the ground, 4 degrees down, turned 8 degrees right of north (-z).
    Scene& s = b.scene;
    const D3 eye = {kCameraX, surface_height(kCameraX, kCameraZ) + kCameraHeight, kCameraZ};
    const double yaw = radians(8.0), pitch = radians(-4.0);
    const D3 target = {eye[0] + 100.0 * std::sin(yaw) * std::cos(pitch), eye[1] + 100.0 * std::sin(pitch),
                       eye[2] - 100.0 * std::cos(yaw) * std::cos(pitch)};
    {
        const D3 t = rounded(eye);
        const D4 r = rounded(look_at_rotation(eye, target), 5);
        const glm::mat4 w = node_world(t, &r, nullptr);
        // The loader's rigid view (gltf_scene.cpp).
        s.camera.view = glm::inverse(rigid_frame(w));
        s.camera.yfov = static_cast<float>(radians(58.0));
        s.camera.znear = 0.5f;
        s.camera.zfar = 1500.0f;
        s.camera.aspect = 0.0f;
    }
    // The sun: 32 degrees up, travelling down-left and towards the camera.
    {
        const D4 r = rounded(light_rotation(32.0, 197.0), 5);
        const glm::mat4 w = node_world({0.0, 300.0, 0.0}, &r, nullptr);
        s.light = Light{};
        s.light.type = LightType::Directional;
        s.light.position = glm::vec3(w[3]);
        s.light.direction = glm::normalize(glm::mat3(w) * glm::vec3(0.0f, 0.0f, -1.0f));
        s.light.color = glm::vec3(1.0f, 0.97f, 0.9f);
        s.light.intensity = 3.0f;
        s.light.radius = 0.0f;
    }
    return s;
}

}  // namespace penumbra::scene
