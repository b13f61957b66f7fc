#include "scenes/terrain_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "scenes/recipe.h"

namespace penumbra::scene {

namespace {

using namespace recipe;

// Everything below follows tests/data/make_large_scenes.py (and the helpers it takes from
// make_bench_gltf.py and make_gltf.py) step by step, in double precision as Python computes,
// then stored as the glTF file stores it: 32-bit floats.

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

D4 light_rotation(double elevation_deg, double azimuth_deg) {
    const double el = radians(elevation_deg), az = radians(azimuth_deg);
    const D3 d = {std::cos(el) * std::cos(az), -std::sin(el), -std::cos(el) * std::sin(az)};
    return look_at_rotation({0.0, 0.0, 0.0}, d);
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

enum Kind { House, Pole, Post, Boulder };
struct Size {
    double a = 0, b = 0, c = 0;  // house: x, y, z; pole and post: thickness, height; boulder: radius
};

double footprint(Kind kind, const Size& s) {
    if (kind == House) return 0.5 * std::hypot(s.a, s.c);
    if (kind == Boulder) return s.a;
    return 0.5 * s.a * std::sqrt(2.0);
}

struct Builder : recipe::SceneBuilder {
    int box = -1, cylinder = -1, sphere = -1;                     // meshes
    int grass = -1, stone = -1, wood = -1, plaster = -1;          // materials
    struct Placed {
        double x, z, r;
    };
    std::vector<Placed> placed;

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
    b.sphere = b.mesh(uv_sphere_mesh("unit sphere", 1.0, 24, 12));
    b.box = b.mesh(box_mesh("unit box", {0.0, 0.5, 0.0}, {1.0, 1.0, 1.0}));  // standing on y = 0
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
    s.camera.view = camera_view(eye, target);
    s.camera.yfov = static_cast<float>(radians(58.0));
    s.camera.znear = 0.5f;
    s.camera.zfar = 1500.0f;
    s.camera.aspect = 0.0f;
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
