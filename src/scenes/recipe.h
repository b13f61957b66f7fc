// The steps the glTF scripts of tests/data (make_gltf.py, make_bench_gltf.py, make_large_scenes.py)
// take to make a scene, in double precision as Python computes them and then stored as the glTF
// file stores them (32-bit floats, node fields rounded as the scripts round them), so a scene
// built in code from a script's recipe is the scene the glTF loader reads from the script's file.
// Used by the scenes the browser pages build without a glTF loader: scenes/terrain_scene.h
// (terrain_km.gltf) and scenes/room_scene.h (bulb_room.gltf).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::scene::recipe {

using D3 = std::array<double, 3>;
using D4 = std::array<double, 4>;  // a quaternion as glTF stores it: x, y, z, w

inline constexpr double kPi = 3.14159265358979323846;
inline double radians(double deg) { return deg * kPi / 180.0; }

// Python's round(v, digits) (+ 0.0) for the values these scenes hold (never a tie in practice).
double rounded(double v, int digits);
D3 rounded(const D3& v, int digits = 3);
D4 rounded(const D4& v, int digits);

// make_gltf.quat_axis_angle.
D4 quat_axis_angle(const D3& axis, double degrees);
// make_bench_gltf.look_at_rotation: the quaternion turning a glTF camera (looking down -z, +y up)
// at eye towards target.
D4 look_at_rotation(const D3& eye, const D3& target);

glm::vec3 to_float(const D3& v);
// A node's matrix as the glTF loader makes it: T * R * S in 32-bit floats.
glm::mat4 node_world(const D3& t, const D4* r, const D3* s);
// The view of a camera node at eye looking at target, its fields rounded as the scripts write
// them (translation to millimetres, rotation to 5 digits), made rigid as the loader makes it.
glm::mat4 camera_view(const D3& eye, const D3& target);

// A mesh from a script's (positions, normals, indices), the normals made unit as the loader does,
// sealed (closed, topology) as every mesh.
Mesh make_mesh(std::string name, const std::vector<D3>& pos, const std::vector<D3>& nrm, std::vector<std::uint32_t> idx);
// make_bench_gltf.box(cx, cy, cz, sx, sy, sz): a flat-shaded box (24 vertices) centred at c.
Mesh box_mesh(std::string name, const D3& centre, const D3& size);
// make_gltf.uv_sphere(radius, slices, stacks).
Mesh uv_sphere_mesh(std::string name, double radius, int slices, int stacks);

// The scripts' Scene: materials (base colour only: the loader reads no more of them), meshes
// instanced by many nodes, and nodes placed with their fields rounded (Scene.place).
struct SceneBuilder {
    Scene scene;
    int material(const char* name, double r, double g, double b);
    int mesh(Mesh m);
    void place(std::string name, int mesh_index, int material_index, const D3& t, const D4* r = nullptr,
               const D3* s = nullptr);
};

}  // namespace penumbra::scene::recipe
