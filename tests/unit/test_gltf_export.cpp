// The glTF writer round-trips through the loader: the course scene at time t written to a file
// and read back has the same objects, the same triangles at the same world-space positions, the
// same camera and the same light; so does a glTF scene with a directional light.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/course_scene.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_writer.h"

using namespace penumbra::scene;
namespace fs = std::filesystem;

namespace {

std::string temp_path(const std::string& name) {
    return (fs::temp_directory_path() / ("penumbra_" + std::to_string(::getpid()) + "_" + name)).string();
}

void expect_near(const glm::vec3& got, const glm::vec3& want, float tol, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, tol) << what;
    EXPECT_NEAR(got.y, want.y, tol) << what;
    EXPECT_NEAR(got.z, want.z, tol) << what;
}

// Writes, reads back and checks every triangle of every object in world space.
Scene round_trip(const Scene& in, const std::string& name) {
    const std::string path = temp_path(name);
    EXPECT_EQ(write_gltf(path, in), "");
    LoadResult r = load_gltf(path);
    std::remove(path.c_str());
    EXPECT_TRUE(r.ok) << r.error;
    for (const auto& w : r.warnings) ADD_FAILURE() << "unexpected loader warning: " << w;
    const Scene& out = r.scene;
    EXPECT_EQ(out.objects.size(), in.objects.size());
    for (size_t i = 0; i < std::min(in.objects.size(), out.objects.size()); ++i) {
        const Object& a = in.objects[i];
        const Object& b = out.objects[i];
        EXPECT_EQ(a.name, b.name);
        const Mesh& ma = in.meshes[static_cast<size_t>(a.mesh)];
        const Mesh& mb = out.meshes[static_cast<size_t>(b.mesh)];
        EXPECT_EQ(ma.indices.size(), mb.indices.size()) << a.name << ": triangle count";
        EXPECT_EQ(ma.positions.size(), mb.positions.size()) << a.name;
        if (ma.indices.size() != mb.indices.size() || ma.positions.size() != mb.positions.size()) continue;
        EXPECT_EQ(ma.uvs.size(), mb.uvs.size()) << a.name;
        float worst = 0.0f;
        for (size_t k = 0; k < ma.indices.size(); ++k) {
            const glm::vec3 pa(a.world * glm::vec4(ma.positions[ma.indices[k]], 1.0f));
            const glm::vec3 pb(b.world * glm::vec4(mb.positions[mb.indices[k]], 1.0f));
            worst = std::max(worst, glm::length(pa - pb));
        }
        EXPECT_LE(worst, 1e-5f) << a.name << ": largest world-space distance between a vertex and its copy";
        const Material& mat_a = in.materials[static_cast<size_t>(a.material)];
        const Material& mat_b = out.materials[static_cast<size_t>(b.material)];
        for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(mat_a.base_color[c], mat_b.base_color[c]) << a.name;
        EXPECT_EQ(mat_a.base_color_texture >= 0, mat_b.base_color_texture >= 0) << a.name;
    }
    // The camera: the same view (re-orthonormalised by the loader) and projection.
    for (int c = 0; c < 4; ++c)
        for (int rr = 0; rr < 4; ++rr) EXPECT_NEAR(out.camera.view[c][rr], in.camera.view[c][rr], 1e-5f) << "view";
    EXPECT_FLOAT_EQ(out.camera.yfov, in.camera.yfov);
    EXPECT_FLOAT_EQ(out.camera.znear, in.camera.znear);
    EXPECT_FLOAT_EQ(out.camera.zfar, in.camera.zfar);
    EXPECT_FLOAT_EQ(out.camera.aspect, in.camera.aspect);
    // The light.
    EXPECT_EQ(out.light.type, in.light.type);
    expect_near(out.light.position, in.light.position, 1e-5f, "light position");
    expect_near(out.light.color, in.light.color, 1e-6f, "light colour");
    EXPECT_FLOAT_EQ(out.light.intensity, in.light.intensity);
    if (in.light.type != LightType::Point) expect_near(out.light.direction, in.light.direction, 1e-5f, "light direction");
    return r.scene;
}

TEST(GltfExport, CourseSceneRoundTrips) {
    for (double t : {0.0, 0.6, 2.25}) {
        CourseScene course = make_course_scene();
        animate_course(course, t, t);
        const Scene out = round_trip(course.scene, "course.gltf");
        // The marble travels as an embedded PNG and comes back pixel for pixel.
        ASSERT_EQ(out.images.size(), 1u);
        EXPECT_EQ(out.images[0].width, course.scene.images[0].width);
        EXPECT_EQ(out.images[0].rgba, course.scene.images[0].rgba);
        // The table is found as the ground again, so planar shadows work on the exported file.
        EXPECT_EQ(out.ground_object, course.table);
        // A point light is aimed at the scene's centre by both (the course and the loader).
        EXPECT_GT(glm::dot(out.light.direction, course.scene.light.direction), 0.99f);
    }
}

TEST(GltfExport, DirectionalLightAndSpotRoundTrip) {
    CourseScene course = make_course_scene(4);
    Scene s = course.scene;
    s.light.type = LightType::Directional;
    s.light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    s.light.color = glm::vec3(1.0f, 0.9f, 0.8f);
    s.light.intensity = 3.0f;
    s.camera.aspect = 1.5f;
    round_trip(s, "directional.gltf");

    s.light.type = LightType::Spot;
    s.light.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 0.0f));  // straight down: the frame's other up
    s.light.spot_inner_cone = 0.2f;
    s.light.spot_outer_cone = 0.6f;
    const Scene out = round_trip(s, "spot.gltf");
    EXPECT_FLOAT_EQ(out.light.spot_inner_cone, 0.2f);
    EXPECT_FLOAT_EQ(out.light.spot_outer_cone, 0.6f);
    EXPECT_EQ(out.light.radius, 0.0f) << "no extras: a point light";
}

TEST(GltfExport, TheLightsRadiusRoundTripsInItsExtras) {
    CourseScene course = make_course_scene(4);
    Scene s = course.scene;
    s.light.radius = 0.25f;
    EXPECT_FLOAT_EQ(round_trip(s, "radius.gltf").light.radius, 0.25f);
    s.light.type = LightType::Directional;
    s.light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.light.radius = 0.01f;  // radians: the sun's is about 0.0047
    EXPECT_FLOAT_EQ(round_trip(s, "sun_radius.gltf").light.radius, 0.01f);
}

TEST(GltfExport, WritesNothingToAMissingFolder) {
    CourseScene course = make_course_scene(2);
    const std::string err = write_gltf("/nonexistent-folder/x.gltf", course.scene);
    EXPECT_NE(err.find("/nonexistent-folder/x.gltf"), std::string::npos) << err;
}

}  // namespace
