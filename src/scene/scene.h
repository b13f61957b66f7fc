// Plain scene data: what the renderer draws, with no GL in sight.
// Everything here is a value type; animation is a pure function of time (see course_scene.h),
// so any frame can be rebuilt exactly from its t.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::scene {

// Indexed triangle mesh. normals has one entry per position; uvs is empty or one per position.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;  // three per triangle
    // A closed surface (is_closed below): its back faces alone hold its silhouette from any light,
    // so a shadow map may take them instead of both sides. Set where the mesh is made.
    bool closed = false;
    // A surface that cannot shadow itself beyond what its own facing already darkens (is_convex
    // below): flat, or closed and convex. A shadow map need not hold it for its own sake. Set
    // with `closed` by seal().
    bool convex = false;
    // Every triangle's vertex normals are its plane's normal (is_faceted below): a box, a floor,
    // not a smooth teapot. The auto bias's slope is then the same over each triangle, and the
    // camera pass takes it per vertex (lit.vert). Set with `closed` by seal().
    bool faceted = false;
    // Its triangles over welded positions (weld below): what shadow volumes find silhouette edges
    // in. Set with `closed` by seal(); absent in a mesh made by hand (weld() it when needed).
    std::shared_ptr<const struct Topology> topology;
};

// A mesh's triangles over welded positions: positions within 1e-6 of the mesh's size are one
// vertex (a sphere's duplicated seam, a box's split corners), so an edge is the same edge in
// every triangle that uses it. Degenerate triangles (two corners welded) are dropped.
struct Topology {
    std::vector<glm::vec3> positions;      // one per welded vertex
    std::vector<std::uint32_t> triangles;  // three per triangle, into positions, the mesh's winding
    // The edge table (index_edges; weld makes it): each edge once, as its two vertices, lower index
    // first; and for each triangle corner k, the edge from corner k to corner k + 1 (mod 3).
    std::vector<std::uint32_t> edges;
    std::vector<std::uint32_t> corner_edges;
    std::size_t edge_count() const { return edges.size() / 2; }
};
Topology weld(const Mesh& mesh);  // with its edge table
// Fills topology.edges and corner_edges from its triangles (a topology made by hand has none).
void index_edges(Topology& topology);
// `topology` if it has its edge table, else a copy given one in `storage`.
const Topology& with_edge_table(const Topology& topology, Topology& storage);

// Whether the triangles enclose a volume: with positions welded, every edge is shared by exactly
// two triangles that run it in opposite directions (consistent winding).
bool is_closed(const Mesh& mesh);
bool is_closed(const Topology& topology);

// Whether no point of the surface can hide another point of it from a light that the second
// point faces: every welded vertex lies in one plane (a flat quad, lit from either side), or the
// surface is closed and every vertex lies on or behind every triangle's plane (a box, a sphere;
// consistent outward winding). Decided edge by edge in time linear in the mesh (convexity.cpp);
// within 1e-5 of the mesh's size of a plane, or 1e-5 radians of fold at an edge, counts as on it.
bool is_convex(const Topology& topology, bool closed);

// Whether every triangle's three vertex normals lie along the triangle's own normal (either way
// round; within 1e-3 radians). Degenerate triangles are not asked; no triangle at all: false.
bool is_faceted(const Mesh& mesh);

// Sets mesh.topology, mesh.closed, mesh.convex and mesh.faceted from the mesh's triangles: call where a mesh is made.
void seal(Mesh& mesh);

// 8-bit RGBA image, rows stored top row first.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// glTF's alphaMode: how a material's alpha (base_color.a times the base texture's alpha) is used.
// Opaque ignores it; Mask keeps only what has alpha >= alpha_cutoff (a fence, a leaf: in the camera
// pass and in every shadow pass); Blend is drawn over the opaque objects, sorted back to front, and
// casts no shadow unless the settings say so (docs/alpha.md).
enum class AlphaMode { Opaque, Mask, Blend };
const char* to_string(AlphaMode m);  // "OPAQUE", "MASK", "BLEND": glTF's spelling

struct Material {
    std::string name;
    glm::vec4 base_color{1.0f};
    int base_color_texture = -1;  // index into Scene::images, -1 when none
    float specular = 0.25f;       // Phong specular strength
    float shininess = 32.0f;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f;    // Mask: alpha below it is cut away
    bool double_sided = false;    // glTF doubleSided: both faces drawn, the back one lit as seen
};

// One drawable instance: a mesh with a material placed in the world.
struct Object {
    std::string name;
    int mesh = -1;
    int material = -1;
    glm::mat4 world{1.0f};
    bool casts_shadow = true;
    bool receives_shadow = true;
};

enum class LightType { Directional, Point, Spot };

struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f, 5.0f, 0.0f};    // point and spot
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // directional and spot: where the light travels (unit)
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float spot_inner_cone = 0.0f;             // radians
    float spot_outer_cone = 0.7853982f;       // radians
    // The light's size, for soft shadows: a sphere of this radius (world units) for point and spot
    // lights, a sun of this angular radius (radians) for a directional one. 0: a point (hard
    // shadows). glTF: the light's extras {"penumbra": {"radius": R}}.
    float radius = 0.0f;
};

struct Camera {
    glm::mat4 view{1.0f};    // world -> eye
    float yfov = 0.7853982f; // radians
    float znear = 0.1f;
    float zfar = 100.0f;
    float aspect = 0.0f;     // 0: take the viewport's
};

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    bool empty() const { return min.x > max.x; }
    void add(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void add(const Bounds& b) { if (!b.empty()) { add(b.min); add(b.max); } }
    glm::vec3 center() const { return 0.5f * (min + max); }
    // The box around two corners, in any order.
    static Bounds around(const glm::vec3& a, const glm::vec3& b) {
        Bounds r;
        r.add(a);
        r.add(b);
        return r;
    }
};

struct Scene;

// A portal (--effects portal, plan/techniques/portal.cpp): a rectangular opening standing in
// the scene through which another scene is seen, with its own objects, light and shadows, in the
// camera's view (the other scene lies where the opening looks, clipped at the opening's plane).
// The opening and its frame are the effect's, not the scene's objects: the scene's truth and the
// shadow techniques do not see them (the effects' truth, measure/effect_truth.h, adds them as
// objects that cast no shadow). Their meshes and material are kept with the other
// scene's (`beyond`), so this scene's own lists are what they are without the portal.
struct Portal {
    int opening_mesh = -1;    // in beyond's meshes: the opening, facing +z in its local z = 0 plane
    int frame_mesh = -1;      // in beyond's meshes: the frame around it, drawn in this scene's light
    int frame_material = -1;  // in beyond's materials
    glm::mat4 world{1.0f};    // places the opening and its frame in this scene
    glm::vec3 sky{0.0f};      // the other scene's background
    std::shared_ptr<const Scene> beyond;  // the scene seen through the opening
};

struct Scene {
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<Object> objects;
    Light light;
    Camera camera;
    // The plane that planar projected shadows fall on (n.x, n.y, n.z, d with n.p + d = 0),
    // and the object that lies in it; absent when the scene has no such ground.
    std::optional<glm::vec4> ground_plane;
    int ground_object = -1;
    // An opening into another scene, drawn only under --effects portal (the course scene has one).
    std::optional<Portal> portal;
};

// Bilinear filtering of an image's alpha at texture coordinate uv, as GL samples a texture at its
// base level (texel centres at (i + 0.5) / size; repeat or clamp to edge at the borders; rows top
// first, glTF's uv origin at the top-left). An empty image reads 1.
float sample_alpha(const Image& image, glm::vec2 uv, bool repeat);
// What GL does with a scene image (Renderer::load): repeat for power-of-two sizes, else clamp.
bool repeats(const Image& image);

// Local-space bounds of a mesh, and world-space bounds of an object (its mesh's corners transformed).
Bounds mesh_bounds(const Mesh& mesh);
Bounds object_bounds(const Scene& scene, const Object& object);
// Every mesh's local bounds, once: many nodes share a mesh, and its vertices need reading once,
// not once a node. object_bounds from them is the same box as from the scene.
std::vector<Bounds> all_mesh_bounds(const Scene& scene);
Bounds object_bounds(const std::vector<Bounds>& mesh_bounds, const Object& object);
// World-space bounds of every object (casters_only: only those that cast shadows).
Bounds scene_bounds(const Scene& scene, bool casters_only = false);
// A camera node's world matrix made rigid: its z axis and y axis made orthonormal (x from them),
// its position kept, any scale dropped (a scaled view would distort depth and lighting). Not
// finite when the node is scaled to zero or flattened.
glm::mat4 rigid_frame(const glm::mat4& world);
// The eight corners of a box.
std::vector<glm::vec3> corners(const Bounds& b);

// The reflection about the plane (n, d) with |n| = 1: x -> x - 2 (n.x + d) n (a mirror's; it turns
// the triangles' winding).
glm::mat4 reflection(const glm::vec4& plane);

}  // namespace penumbra::scene
