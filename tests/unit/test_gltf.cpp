// The glTF loader against the files tests/data/make_gltf.py writes: node transforms, lights,
// cameras, materials and textures, the defaults for what a file leaves out, and a clean
// one-line error (never a crash) for every malformed file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/gltf_loader.h"
#include "../test_paths.h"

using namespace penumbra::scene;

namespace {

std::string data(const std::string& name) { return penumbra::test::test_data_dir() + "/" + name; }

LoadResult load_ok(const std::string& name) {
    LoadResult r = load_gltf(data(name));
    EXPECT_TRUE(r.ok) << r.error;
    return r;
}

bool has_warning(const LoadResult& r, const std::string& text) {
    for (const auto& w : r.warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

void expect_vec3(const glm::vec3& got, const glm::vec3& want, float tol = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

void expect_bounds(const Bounds& b, const glm::vec3& min, const glm::vec3& max, float tol = 1e-5f) {
    SCOPED_TRACE("bounds");
    expect_vec3(b.min, min, tol);
    expect_vec3(b.max, max, tol);
}

const Object* find_object(const Scene& s, const std::string& name) {
    for (const auto& o : s.objects)
        if (o.name == name) return &o;
    return nullptr;
}

void expect_unit_normals(const Scene& s) {
    for (const auto& m : s.meshes) {
        ASSERT_EQ(m.normals.size(), m.positions.size()) << m.name;
        for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f) << m.name;
    }
}

// Every malformed file must fail with a single line that names the file and the problem.
void expect_error(const std::string& name, const std::string& problem) {
    const LoadResult r = load_gltf(data(name));
    EXPECT_FALSE(r.ok) << name;
    EXPECT_NE(r.error.find(name), std::string::npos) << r.error;
    EXPECT_NE(r.error.find(problem), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
    EXPECT_TRUE(r.scene.objects.empty());
}

}  // namespace

// ---- sphere_over_plane.gltf ---------------------------------------------------------------------

TEST(GltfSphereOverPlane, ObjectsAndWorldBounds) {
    const LoadResult r = load_ok("sphere_over_plane.gltf");
    ASSERT_EQ(r.scene.objects.size(), 2u);
    const Object* sphere = find_object(r.scene, "sphere");
    const Object* ground = find_object(r.scene, "ground");
    ASSERT_NE(sphere, nullptr);
    ASSERT_NE(ground, nullptr);
    // Radius 1 around (0, 2, 0); 32 slices put vertices exactly on +-x and +-z.
    expect_bounds(object_bounds(r.scene, *sphere), {-1, 1, -1}, {1, 3, 1});
    expect_bounds(object_bounds(r.scene, *ground), {-5, 0, -5}, {5, 0, 5});
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST(GltfSphereOverPlane, GroundPlaneFound) {
    const LoadResult r = load_ok("sphere_over_plane.gltf");
    ASSERT_GE(r.scene.ground_object, 0);
    EXPECT_EQ(r.scene.objects[static_cast<size_t>(r.scene.ground_object)].name, "ground");
    ASSERT_TRUE(r.scene.ground_plane.has_value());
    const glm::vec4 p = *r.scene.ground_plane;
    EXPECT_FLOAT_EQ(p.x, 0.0f);
    EXPECT_FLOAT_EQ(p.y, 1.0f);
    EXPECT_FLOAT_EQ(p.z, 0.0f);
    EXPECT_NEAR(p.w, 0.0f, 1e-6f);
}

TEST(GltfSphereOverPlane, DirectionalLightPointsDown) {
    const LoadResult r = load_ok("sphere_over_plane.gltf");
    const Light& l = r.scene.light;
    EXPECT_EQ(l.type, LightType::Directional);
    expect_vec3(l.direction, {0, -1, 0});
    expect_vec3(l.position, {0, 10, 0});
    expect_vec3(l.color, {1.0f, 0.9f, 0.8f});
    EXPECT_FLOAT_EQ(l.intensity, 3.0f);
}

TEST(GltfSphereOverPlane, CameraViewFromNode) {
    const LoadResult r = load_ok("sphere_over_plane.gltf");
    const Camera& c = r.scene.camera;
    const glm::mat4 eye_to_world = glm::inverse(c.view);
    expect_vec3(glm::vec3(eye_to_world[3]), {0, 4, 12});
    // The node is pitched 10 degrees down: it looks along (0, -sin 10, -cos 10).
    const float a = glm::radians(10.0f);
    expect_vec3(glm::vec3(eye_to_world * glm::vec4(0, 0, -1, 0)), {0, -std::sin(a), -std::cos(a)});
    expect_vec3(glm::vec3(c.view * glm::vec4(0, 4, 12, 1)), {0, 0, 0});
    EXPECT_FLOAT_EQ(c.yfov, 0.8f);
    EXPECT_FLOAT_EQ(c.znear, 0.1f);
    EXPECT_FLOAT_EQ(c.zfar, 100.0f);
    EXPECT_FLOAT_EQ(c.aspect, 1.5f);
}

TEST(GltfSphereOverPlane, MaterialsAndNormals) {
    const LoadResult r = load_ok("sphere_over_plane.gltf");
    const Object* sphere = find_object(r.scene, "sphere");
    ASSERT_NE(sphere, nullptr);
    const Material& m = r.scene.materials.at(static_cast<size_t>(sphere->material));
    EXPECT_EQ(m.name, "red");
    EXPECT_FLOAT_EQ(m.base_color.r, 0.8f);
    EXPECT_FLOAT_EQ(m.base_color.g, 0.1f);
    EXPECT_FLOAT_EQ(m.base_color.b, 0.1f);
    EXPECT_EQ(m.base_color_texture, -1);
    expect_unit_normals(r.scene);
    // A sphere's normals point away from its centre.
    const Mesh& mesh = r.scene.meshes.at(static_cast<size_t>(sphere->mesh));
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        ASSERT_GT(glm::dot(mesh.normals[i], glm::normalize(mesh.positions[i])), 0.999f);
    EXPECT_EQ(mesh.indices.size() % 3, 0u);
}

// ---- boxes_no_camera_no_light.gltf / .glb ---------------------------------------------------------

TEST(GltfBoxes, NodeTransformsCompose) {
    const LoadResult r = load_ok("boxes_no_camera_no_light.gltf");
    ASSERT_EQ(r.scene.objects.size(), 2u);
    const Object* a = find_object(r.scene, "box_a");
    const Object* b = find_object(r.scene, "box_b");
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    // box_a: unit cube, scaled (2,1,1) -> x in [-1,1]; rotated 90 deg about y -> (x,z) = (z,-x):
    // x in [-0.5,0.5], z in [-1,1]; then the parent's matrix moves it by (1,2,3).
    expect_bounds(object_bounds(r.scene, *a), {0.5f, 1.5f, 2.0f}, {1.5f, 2.5f, 4.0f});
    // box_b: half size around (-3, 0.5, 0).
    expect_bounds(object_bounds(r.scene, *b), {-3.25f, 0.25f, -0.25f}, {-2.75f, 0.75f, 0.25f});
    // Order matters: T * R * S, not T * S * R, so a corner lands exactly here.
    const glm::vec3 corner = glm::vec3(a->world * glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    expect_vec3(corner, {1.5f, 2.5f, 2.0f});
}

TEST(GltfBoxes, DefaultCameraFramesBoundsWithWarning) {
    const LoadResult r = load_ok("boxes_no_camera_no_light.gltf");
    EXPECT_TRUE(has_warning(r, "no camera in " + data("boxes_no_camera_no_light.gltf") +
                                   ": using a default view of the scene's bounds"));
    const Camera& c = r.scene.camera;
    EXPECT_NEAR(c.yfov, glm::radians(45.0f), 1e-6f);
    EXPECT_EQ(c.aspect, 0.0f);
    const Bounds bounds = scene_bounds(r.scene);
    // The centre lies straight ahead; the eye is in front (+z) and above.
    const glm::vec3 centre_eye = glm::vec3(c.view * glm::vec4(bounds.center(), 1.0f));
    EXPECT_NEAR(centre_eye.x, 0.0f, 1e-4f);
    EXPECT_NEAR(centre_eye.y, 0.0f, 1e-4f);
    EXPECT_LT(centre_eye.z, 0.0f);
    const glm::vec3 eye = glm::vec3(glm::inverse(c.view)[3]);
    EXPECT_GT(eye.y, bounds.center().y);
    EXPECT_GT(eye.z, bounds.center().z);
    // Every corner of the bounds is inside the frustum (square viewport).
    const float t = std::tan(0.5f * c.yfov);
    for (const auto& p : corners(bounds)) {
        const glm::vec3 e = glm::vec3(c.view * glm::vec4(p, 1.0f));
        EXPECT_GT(-e.z, c.znear);
        EXPECT_LT(-e.z, c.zfar);
        EXPECT_LE(std::abs(e.x), -e.z * t);
        EXPECT_LE(std::abs(e.y), -e.z * t);
    }
}

TEST(GltfBoxes, DefaultLightWithWarning) {
    const LoadResult r = load_ok("boxes_no_camera_no_light.gltf");
    EXPECT_TRUE(has_warning(r, "no light in " + data("boxes_no_camera_no_light.gltf") +
                                   ": using a default directional light"));
    EXPECT_EQ(r.scene.light.type, LightType::Directional);
    expect_vec3(r.scene.light.direction, glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f)));
    EXPECT_LT(r.scene.light.direction.y, 0.0f);
}

TEST(GltfBoxes, DefaultMaterialAndNoGround) {
    const LoadResult r = load_ok("boxes_no_camera_no_light.gltf");
    const Object* a = find_object(r.scene, "box_a");
    const Object* b = find_object(r.scene, "box_b");
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    const Material& ma = r.scene.materials.at(static_cast<size_t>(a->material));
    EXPECT_FLOAT_EQ(ma.base_color.b, 0.9f);
    const Material& mb = r.scene.materials.at(static_cast<size_t>(b->material));
    EXPECT_FLOAT_EQ(mb.base_color.r, 0.8f);
    EXPECT_FLOAT_EQ(mb.base_color.g, 0.8f);
    EXPECT_FLOAT_EQ(mb.base_color.b, 0.8f);
    EXPECT_FLOAT_EQ(mb.base_color.a, 1.0f);
    EXPECT_EQ(r.scene.ground_object, -1);
    EXPECT_FALSE(r.scene.ground_plane.has_value());
}

TEST(GltfBoxes, ComputedNormalsAndGeneratedIndices) {
    const LoadResult r = load_ok("boxes_no_camera_no_light.gltf");
    expect_unit_normals(r.scene);
    // box_a shares its 8 corners: smooth normals point outwards.
    const Mesh& a = r.scene.meshes.at(static_cast<size_t>(find_object(r.scene, "box_a")->mesh));
    ASSERT_EQ(a.positions.size(), 8u);
    ASSERT_EQ(a.indices.size(), 36u);
    for (size_t i = 0; i < a.positions.size(); ++i) EXPECT_GT(glm::dot(a.normals[i], a.positions[i]), 0.0f);
    // box_b has no indices (0..35 generated) and no shared vertices: flat, axis-aligned normals.
    const Mesh& b = r.scene.meshes.at(static_cast<size_t>(find_object(r.scene, "box_b")->mesh));
    ASSERT_EQ(b.indices.size(), 36u);
    for (std::uint32_t i = 0; i < 36; ++i) EXPECT_EQ(b.indices[i], i);
    for (size_t t = 0; t < 36; t += 3) {
        const glm::vec3 face = glm::normalize(
            glm::cross(b.positions[t + 1] - b.positions[t], b.positions[t + 2] - b.positions[t]));
        for (size_t k = 0; k < 3; ++k) expect_vec3(b.normals[t + k], face);
        EXPECT_NEAR(std::abs(face.x) + std::abs(face.y) + std::abs(face.z), 1.0f, 1e-6f);
        EXPECT_GT(glm::dot(face, b.positions[t]), 0.0f);  // wound outwards
    }
}

TEST(GltfBoxes, BinaryGlbMatchesText) {
    const LoadResult text = load_ok("boxes_no_camera_no_light.gltf");
    const LoadResult glb = load_ok("boxes_no_camera_no_light.glb");
    ASSERT_EQ(glb.scene.objects.size(), text.scene.objects.size());
    ASSERT_EQ(glb.scene.meshes.size(), text.scene.meshes.size());
    for (size_t i = 0; i < text.scene.objects.size(); ++i) {
        EXPECT_EQ(glb.scene.objects[i].name, text.scene.objects[i].name);
        const Bounds bt = object_bounds(text.scene, text.scene.objects[i]);
        expect_bounds(object_bounds(glb.scene, glb.scene.objects[i]), bt.min, bt.max, 0.0f);
    }
    for (size_t i = 0; i < text.scene.meshes.size(); ++i) {
        EXPECT_EQ(glb.scene.meshes[i].positions, text.scene.meshes[i].positions);
        EXPECT_EQ(glb.scene.meshes[i].indices, text.scene.meshes[i].indices);
    }
}

// ---- textured_quad.gltf -------------------------------------------------------------------------

TEST(GltfTexturedQuad, TextureAndBaseColorFactor) {
    const LoadResult r = load_ok("textured_quad.gltf");
    ASSERT_EQ(r.scene.objects.size(), 1u);
    const Object& quad = r.scene.objects[0];
    const Material& m = r.scene.materials.at(static_cast<size_t>(quad.material));
    EXPECT_FLOAT_EQ(m.base_color.r, 1.0f);
    EXPECT_FLOAT_EQ(m.base_color.g, 0.5f);
    EXPECT_FLOAT_EQ(m.base_color.b, 0.25f);
    EXPECT_FLOAT_EQ(m.base_color.a, 1.0f);
    ASSERT_EQ(m.base_color_texture, 0);
    ASSERT_EQ(r.scene.images.size(), 1u);
    const Image& img = r.scene.images[0];
    EXPECT_EQ(img.width, 4);
    EXPECT_EQ(img.height, 4);
    ASSERT_EQ(img.rgba.size(), 4u * 4u * 4u);
    // The RGB PNG's pixel (x, y) = (64x, 64y, 200); alpha is filled in as opaque.
    const size_t at = (1 * 4 + 2) * 4;  // x = 2, y = 1 (row 1 from the top)
    EXPECT_EQ(img.rgba[at + 0], 128);
    EXPECT_EQ(img.rgba[at + 1], 64);
    EXPECT_EQ(img.rgba[at + 2], 200);
    EXPECT_EQ(img.rgba[at + 3], 255);
}

TEST(GltfTexturedQuad, SixteenBitGreyBecomesEightBitRgba) {
    const LoadResult r = load_ok("quad_grey16.gltf");
    ASSERT_EQ(r.scene.images.size(), 1u);
    const Image& img = r.scene.images[0];
    ASSERT_EQ(img.width, 4);
    ASSERT_EQ(img.height, 1);
    ASSERT_EQ(img.rgba.size(), 16u);
    // 16-bit samples 0, 0x4000, 0x8000, 0xffff, rounded to 8 bits and copied to r, g and b.
    const std::uint8_t want[4] = {0, 64, 128, 255};
    for (size_t x = 0; x < 4; ++x) {
        for (size_t c = 0; c < 3; ++c) EXPECT_EQ(img.rgba[x * 4 + c], want[x]) << "x " << x;
        EXPECT_EQ(img.rgba[x * 4 + 3], 255);
    }
}

TEST(GltfTexturedQuad, NormalizedByteUvsThroughStride) {
    const LoadResult r = load_ok("textured_quad.gltf");
    const Mesh& mesh = r.scene.meshes.at(static_cast<size_t>(r.scene.objects[0].mesh));
    ASSERT_EQ(mesh.uvs.size(), 4u);
    const std::vector<glm::vec2> want = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_FLOAT_EQ(mesh.uvs[i].x, want[i].x);
        EXPECT_FLOAT_EQ(mesh.uvs[i].y, want[i].y);
    }
    expect_unit_normals(r.scene);
    // Flat, but named "quad": not taken for a ground plane.
    EXPECT_EQ(r.scene.ground_object, -1);
}

TEST(GltfTexturedQuad, FirstLightIsTheSpot) {
    const LoadResult r = load_ok("textured_quad.gltf");
    const Light& l = r.scene.light;
    EXPECT_EQ(l.type, LightType::Spot);
    expect_vec3(l.position, {0, 3, 0});
    expect_vec3(l.direction, {0, -1, 0});
    EXPECT_FLOAT_EQ(l.spot_inner_cone, 0.2f);
    EXPECT_FLOAT_EQ(l.spot_outer_cone, 0.6f);
    expect_vec3(l.color, {0.5f, 1.0f, 0.25f});
    EXPECT_FLOAT_EQ(l.intensity, 20.0f);
    EXPECT_FALSE(has_warning(r, "no light"));
    EXPECT_TRUE(has_warning(r, "no camera"));
}

TEST(GltfTexturedQuad, PointLightAimsAtSceneCentre) {
    const LoadResult r = load_ok("quad_point_light.gltf");
    const Light& l = r.scene.light;
    EXPECT_EQ(l.type, LightType::Point);
    expect_vec3(l.position, {2, 4, 1});
    // The quad is centred on the origin.
    expect_vec3(l.direction, glm::normalize(glm::vec3(-2, -4, -1)));
    EXPECT_FLOAT_EQ(l.intensity, 5.0f);
}

// ---- malformed input ----------------------------------------------------------------------------

TEST(GltfErrors, BrokenJson) { expect_error("bad_json.gltf", "invalid glTF"); }

TEST(GltfErrors, AccessorPastItsBuffer) { expect_error("bad_accessor_range.gltf", "reads past the end"); }

TEST(GltfErrors, MeshWithoutPosition) { expect_error("bad_no_position.gltf", "no POSITION"); }

TEST(GltfErrors, LinesAreUnsupported) { expect_error("bad_mode_lines.gltf", "only TRIANGLES"); }

TEST(GltfErrors, IndexOutOfRange) { expect_error("bad_index_range.gltf", "index 7"); }

TEST(GltfErrors, StrideTooSmall) { expect_error("bad_stride.gltf", "byteStride 4"); }

TEST(GltfErrors, MissingFileNamesThePath) {
    const std::string path = data("does_not_exist.gltf");
    const LoadResult r = load_gltf(path);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("cannot open"), std::string::npos) << r.error;
}

TEST(GltfErrors, UnknownExtension) {
    const LoadResult r = load_gltf(data("make_gltf.py"));
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("unknown file extension '.py'"), std::string::npos) << r.error;
}

// Every truncation of a valid .glb is rejected with an error: no crash, no exception escapes.
TEST(GltfErrors, TruncatedGlbNeverCrashes) {
    std::ifstream in(data("boxes_no_camera_no_light.glb"), std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 100u);
    const std::string path = ::testing::TempDir() + "penumbra_truncated.glb";
    for (size_t n = 0; n < bytes.size(); n += 7) {
        {
            std::ofstream out(path, std::ios::binary | std::ios::trunc);
            out.write(bytes.data(), static_cast<std::streamsize>(n));
        }
        const LoadResult r = load_gltf(path);
        EXPECT_FALSE(r.ok) << "length " << n;
        EXPECT_FALSE(r.error.empty()) << "length " << n;
    }
    std::remove(path.c_str());
}
