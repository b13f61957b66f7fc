// `penumbra export`'s promise: every file the glTF writer writes loads back with scene::load_gltf,
// without a warning: the course scene at many times (odd ones too) and each good file of
// tests/data (not bad_*). And what it cannot write it refuses, naming the value, and writes nothing:
// a number that is not finite (JSON has no NaN; nlohmann would write null) or a camera glTF cannot hold.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "scenes/course_scene.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_writer.h"
#include "scene/printable.h"
#include "../test_paths.h"

using namespace penumbra::scene;
namespace fs = std::filesystem;

namespace {

std::string temp_path(const std::string& name) {
    return (fs::temp_directory_path() / ("penumbra_loads_back_" + std::to_string(::getpid()) + "_" + name)).string();
}

size_t triangles(const Scene& s) {
    size_t n = 0;
    for (const auto& o : s.objects)
        if (o.mesh >= 0 && o.mesh < static_cast<int>(s.meshes.size())) n += s.meshes[static_cast<size_t>(o.mesh)].indices.size() / 3;
    return n;
}

// Writes `s`, loads the file back: it must load, without warnings, with the same objects and triangles.
void expect_loads_back(const Scene& s, const std::string& label) {
    const std::string path = temp_path("scene.gltf");
    GltfWriteOptions wo;
    wo.aspect = 1.5f;
    wo.generator = "test " + label;
    ASSERT_EQ(write_gltf(path, s, wo), "") << label;
    const LoadResult r = load_gltf(path);
    fs::remove(path);
    ASSERT_TRUE(r.ok) << label << ": " << r.error;
    for (const auto& w : r.warnings) ADD_FAILURE() << label << ": warning on loading the export back: " << w;
    EXPECT_EQ(r.scene.objects.size(), s.objects.size()) << label;
    EXPECT_EQ(triangles(r.scene), triangles(s)) << label;
    EXPECT_TRUE(std::isfinite(r.scene.camera.znear) && r.scene.camera.znear > 0.0f) << label;
}

std::string to_gltf_error(const Scene& s) {
    std::string error;
    const std::string text = to_gltf(s, {}, error);
    EXPECT_TRUE(text.empty() || error.empty());
    EXPECT_EQ(text.find("null"), std::string::npos);
    return error;
}

TEST(ExportLoadsBack, TheCourseSceneAtManyTimes) {
    for (double t : {0.0, 0.6, 2.25, 7.0, 13.37, 59.999, 3600.0, -2.5, 1e6, -1e6}) {
        CourseScene course = make_course_scene(4);
        animate_course(course, t, t);
        expect_loads_back(course.scene, "course at t = " + std::to_string(t));
    }
}

TEST(ExportLoadsBack, EveryGoodFileOfTheTestData) {
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(penumbra::test::test_data_dir())) {
        const fs::path p = entry.path();
        const std::string name = p.filename().string();
        if (name.rfind("bad_", 0) == 0 || (p.extension() != ".gltf" && p.extension() != ".glb")) continue;
        const LoadResult in = load_gltf(p.string());
        ASSERT_TRUE(in.ok) << name << ": " << in.error;
        expect_loads_back(in.scene, name);
        ++files;
    }
    EXPECT_GE(files, 8u) << "tests/data's good files";
}

TEST(ExportLoadsBack, ANumberThatIsNotFiniteIsRefusedByName) {
    const Scene good = make_course_scene(2).scene;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    struct Case {
        const char* says;
        void (*spoil)(Scene&, float);
        float value;
    };
    const Case cases[] = {
        {"the camera's znear is not finite (nan)", [](Scene& s, float v) { s.camera.znear = v; }, nan},
        {"the camera's zfar is not finite (inf)", [](Scene& s, float v) { s.camera.zfar = v; }, inf},
        {"the camera's yfov is not finite (nan)", [](Scene& s, float v) { s.camera.yfov = v; }, nan},
        {"the camera's matrix is not finite", [](Scene& s, float v) { s.camera.view[3][0] = v; }, nan},
        {"the light's position is not finite (-inf)", [](Scene& s, float v) { s.light.position.y = v; }, -inf},
        {"the light's intensity is not finite (nan)", [](Scene& s, float v) { s.light.intensity = v; }, nan},
        {"its world matrix is not finite (nan)", [](Scene& s, float v) { s.objects[0].world[3][1] = v; }, nan},
        {"position 0 is not finite", [](Scene& s, float v) { s.meshes[static_cast<size_t>(s.objects[0].mesh)].positions[0].x = v; }, inf},
        {"base colour is not finite (nan)", [](Scene& s, float v) { s.materials[0].base_color.g = v; }, nan},
        {"the camera's znear 0.000000 is not > 0", [](Scene& s, float v) { s.camera.znear = v; }, 0.0f},
    };
    for (const Case& c : cases) {
        Scene s = good;
        c.spoil(s, c.value);
        const std::string err = to_gltf_error(s);
        EXPECT_NE(err.find(c.says), std::string::npos) << "expected '" << c.says << "' in: " << err;
        EXPECT_THROW(to_gltf(s), std::invalid_argument) << c.says;
        // write_gltf writes nothing, not even its temporary file, and says which file and why.
        const std::string path = temp_path("refused.gltf");
        const std::string werr = write_gltf(path, s);
        EXPECT_NE(werr.find(c.says), std::string::npos) << werr;
        EXPECT_NE(werr.find("refused.gltf"), std::string::npos) << werr;
        EXPECT_FALSE(fs::exists(path)) << c.says;
        EXPECT_FALSE(fs::exists(path + ".tmp")) << c.says;
    }
}

TEST(ExportLoadsBack, NamesThatAreNotUtf8GoInEscaped) {
    Scene s = make_course_scene(2).scene;
    s.objects[0].name = "teapot\xff\n";
    GltfWriteOptions wo;
    wo.generator = "penumbra export --scene a\xff.gltf";
    const std::string path = temp_path("names.gltf");
    ASSERT_EQ(write_gltf(path, s, wo), "");
    const LoadResult r = load_gltf(path);
    fs::remove(path);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_FALSE(r.scene.objects.empty());
    EXPECT_TRUE(valid_utf8(r.scene.objects[0].name)) << r.scene.objects[0].name;
    EXPECT_EQ(r.scene.objects[0].name, printable("teapot\xff\n"));
}

}  // namespace
