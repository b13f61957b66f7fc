#include "scenes/room_scene.h"

#include <string>
#include <vector>

#include "scenes/recipe.h"

namespace penumbra::scene {

namespace {

using namespace recipe;

// Everything below follows bulb_room() in tests/data/make_large_scenes.py step by step.

constexpr double kWidth = 8.0, kHeight = 3.0, kDepth = 6.0;  // ROOM
constexpr D3 kBulb = {0.2, 1.8, -0.1};                          // BULB

// make_large_scenes.panel(): a unit square in the x-z plane facing +y.
Mesh panel(std::string name) {
    const std::vector<D3> pos = {{-0.5, 0.0, -0.5}, {-0.5, 0.0, 0.5}, {0.5, 0.0, 0.5}, {0.5, 0.0, -0.5}};
    const std::vector<D3> nrm(4, D3{0.0, 1.0, 0.0});
    return make_mesh(std::move(name), pos, nrm, {0, 1, 2, 0, 2, 3});
}

struct Room : SceneBuilder {
    int box_red = -1, box_blue = -1, box_metal = -1, sphere_red = -1, sphere_green = -1;  // meshes
    int red = -1, blue = -1, green = -1, metal = -1;                                      // materials

    void put(const std::string& name, int mesh_index, int material_index, const D3& t, const D3& s) {
        place(name, mesh_index, material_index, t, nullptr, &s);
    }
    // A thin metal stand from the floor to `top` with a box or a sphere resting on it.
    void on_stand(const std::string& name, double x, double z, double top, int mesh_index, int material_index,
                  const D3& size, bool sphere) {
        put(name + " stand", box_metal, metal, {x, top / 2, z}, {0.05, top, 0.05});
        const double centre = top + (sphere ? size[0] : size[1] / 2);
        put(name, mesh_index, material_index, {x, centre, z}, size);
    }
    // A box or a sphere hanging from the ceiling by a thin rod down to `bottom`, its top.
    void hanging(const std::string& name, double x, double z, double bottom, int mesh_index, int material_index,
                 const D3& size, bool sphere) {
        put(name + " rod", box_metal, metal, {x, (kHeight + bottom) / 2, z}, {0.03, kHeight - bottom, 0.03});
        const double centre = bottom - (sphere ? size[0] : size[1] / 2);
        put(name, mesh_index, material_index, {x, centre, z}, size);
    }
};

}  // namespace

Scene make_bulb_room_scene() {
    Room b;
    const int floor_mat = b.material("floor boards", 0.55, 0.42, 0.3);
    const int wall_mat = b.material("wall paint", 0.8, 0.78, 0.72);
    const int ceiling_mat = b.material("ceiling paint", 0.9, 0.9, 0.9);
    b.red = b.material("red", 0.8, 0.2, 0.15);
    b.blue = b.material("blue", 0.2, 0.35, 0.8);
    b.green = b.material("green", 0.25, 0.65, 0.3);
    b.metal = b.material("metal", 0.4, 0.4, 0.45);

    // The meshes in the order the loader makes them: as the nodes first use them.
    const int floor = b.mesh(panel("floor panel"));
    const int ceiling = b.mesh(panel("ceiling panel"));
    const int wall = b.mesh(panel("wall panel"));
    b.box_red = b.mesh(box_mesh("box", {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}));
    b.sphere_green = b.mesh(uv_sphere_mesh("sphere", 1.0, 32, 16));
    b.box_blue = b.mesh(box_mesh("box", {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}));
    b.box_metal = b.mesh(box_mesh("box", {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}));
    b.sphere_red = b.mesh(uv_sphere_mesh("sphere", 1.0, 32, 16));

    // The room: six panels facing inwards, each sized before it turns (T * R * S).
    const double w = kWidth, h = kHeight, d = kDepth;
    const D4 ceiling_turn = quat_axis_angle({1, 0, 0}, 180.0);
    const D4 wall_nz = quat_axis_angle({1, 0, 0}, 90.0), wall_pz = quat_axis_angle({1, 0, 0}, -90.0);
    const D4 wall_nx = quat_axis_angle({0, 0, 1}, -90.0), wall_px = quat_axis_angle({0, 0, 1}, 90.0);
    const D3 floor_size = {w, 1.0, d}, z_wall = {w, 1.0, h}, x_wall = {h, 1.0, d};
    b.place("floor", floor, floor_mat, {0.0, 0.0, 0.0}, nullptr, &floor_size);
    b.place("ceiling", ceiling, ceiling_mat, {0.0, h, 0.0}, &ceiling_turn, &floor_size);
    b.place("wall -z", wall, wall_mat, {0.0, h / 2, -d / 2}, &wall_nz, &z_wall);
    b.place("wall +z", wall, wall_mat, {0.0, h / 2, d / 2}, &wall_pz, &z_wall);
    b.place("wall -x", wall, wall_mat, {-w / 2, h / 2, 0.0}, &wall_nx, &x_wall);
    b.place("wall +x", wall, wall_mat, {w / 2, h / 2, 0.0}, &wall_px, &x_wall);

    // On the floor.
    const D4 crate_turn = quat_axis_angle({0, 1, 0}, 20.0), stool_turn = quat_axis_angle({0, 1, 0}, -15.0),
             cabinet_turn = quat_axis_angle({0, 1, 0}, 10.0);
    const D3 crate = {0.8, 0.8, 0.8}, ball = {0.35, 0.35, 0.35}, stool = {0.6, 0.5, 0.6}, cabinet = {0.6, 2.2, 0.5};
    b.place("crate", b.box_red, b.red, {1.5, 0.4, 1.0}, &crate_turn, &crate);
    b.place("ball", b.sphere_green, b.green, {-1.2, 0.35, 1.2}, nullptr, &ball);
    b.place("footstool", b.box_blue, b.blue, {0.9, 0.25, -1.5}, &stool_turn, &stool);
    b.place("cabinet", b.box_blue, b.blue, {-2.4, 1.1, -1.6}, &cabinet_turn, &cabinet);
    // At the bulb's height: one shadow on each wall.
    b.on_stand("box on stand +x", 2.3, 0.0, 1.5, b.box_red, b.red, {0.4, 0.4, 0.4}, false);
    b.on_stand("sphere on stand -x", -2.0, 0.5, 1.3, b.sphere_red, b.red, {0.25, 0.25, 0.25}, true);
    b.on_stand("box on stand +z", 0.5, 1.8, 1.7, b.box_blue, b.blue, {0.5, 0.3, 0.3}, false);
    b.on_stand("sphere on stand -z", -0.4, -1.9, 1.4, b.sphere_green, b.green, {0.2, 0.2, 0.2}, true);
    // Above the bulb: shadows on the ceiling.
    b.hanging("hanging sphere", 0.9, 0.6, 2.55, b.sphere_red, b.red, {0.15, 0.15, 0.15}, true);
    b.hanging("hanging box", -0.7, -0.7, 2.6, b.box_metal, b.metal, {0.5, 0.12, 0.35}, false);

    Scene& s = b.scene;
    // The camera in the +x +z corner under the ceiling, looking across the room.
    s.camera.view = camera_view({3.7, 2.6, 2.7}, {-1.5, 1.1, -1.3});
    s.camera.yfov = static_cast<float>(radians(75.0));
    s.camera.znear = 0.05f;
    s.camera.zfar = 20.0f;
    s.camera.aspect = 0.0f;
    // The bulb: a point light, aimed (the loader's rule for a point light) at the scene's centre.
    s.light = Light{};
    s.light.type = LightType::Point;
    s.light.position = to_float(kBulb);
    s.light.direction = glm::normalize(scene_bounds(s).center() - s.light.position);
    s.light.color = glm::vec3(1.0f, 0.9f, 0.75f);
    s.light.intensity = 20.0f;
    s.light.radius = 0.0f;
    // The floor is the ground (the loader finds a flat object named "floor").
    s.ground_object = 0;
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, -object_bounds(s, s.objects[0]).center().y);
    return s;
}

}  // namespace penumbra::scene
