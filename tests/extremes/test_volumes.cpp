// Shadow volumes on a GL context, scored against the ray-traced truth: open meshes (a tube, a bowl,
// a tilted quad, a box missing a face) and a closed sphere under point, spot and directional
// lights; the course scene and the bench scenes; the eye inside a shadow, where depth-pass fails
// as the course notes say and depth-fail (and auto) hold; and the stencil left so that another
// technique drawn next with the same renderer is unaffected.
#include "gl_fixture.h"

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "measure/image_io.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "plan/techniques/reports.h"
#include "plan/options.h"
#include "scenes/course_scene.h"
#include "scene/gltf_loader.h"
#include "scene/primitives.h"
#include "scene/scene_source.h"

using namespace penumbra;

namespace {

constexpr int kSize = 256;
constexpr double kExact = 0.05;  // % of the valid pixels: exact up to rasterisation

using test::object;

// An open tube along y: radius r, height h, no ends.
scene::Mesh tube(float r, float h, int segments) {
    scene::Mesh m;
    for (int i = 0; i < segments; ++i) {
        const float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(segments);
        const glm::vec3 n(std::cos(a), 0.0f, std::sin(a));
        m.positions.push_back(n * r);
        m.positions.push_back(n * r + glm::vec3(0.0f, h, 0.0f));
        m.normals.insert(m.normals.end(), {n, n});
    }
    const auto u = [&](int i) { return static_cast<std::uint32_t>(i % (2 * segments)); };
    for (int i = 0; i < segments; ++i) {
        const int b = 2 * i;
        // Counter-clockwise seen from outside.
        m.indices.insert(m.indices.end(), {u(b), u(b + 1), u(b + 2), u(b + 2), u(b + 1), u(b + 3)});
    }
    scene::seal(m);
    return m;
}

scene::Mesh open_box() {
    scene::Mesh m = scene::make_box(glm::vec3(0.45f, 0.35f, 0.45f));
    m.indices.erase(m.indices.begin() + 12, m.indices.begin() + 18);  // the top face (+y) gone
    scene::seal(m);
    return m;
}

enum class LightKind { Point, Spot, Directional };

// The four open casters and a closed sphere over a ground quad.
scene::Scene open_meshes(LightKind kind) {
    scene::Scene s;
    s.meshes = {scene::make_quad(12.0f), tube(0.35f, 1.4f, 20), scene::make_bowl(0.7f, 24, 12), scene::make_quad(1.4f), open_box(),
                scene::make_sphere(0.4f, 16, 8)};
    s.materials.resize(1);
    const auto at = [](float x, float y, float z) { return glm::translate(glm::mat4(1.0f), glm::vec3(x, y, z)); };
    s.objects = {object("ground", 0, glm::mat4(1.0f)),
                 object("tube", 1, at(-1.8f, 0.6f, 0.6f) * glm::rotate(glm::mat4(1.0f), 1.2f, glm::vec3(0.3f, 0.0f, 1.0f))),
                 object("bowl", 2, at(0.0f, 1.3f, -1.2f)),
                 object("quad", 3, at(1.6f, 1.1f, 0.4f) * glm::rotate(glm::mat4(1.0f), 2.4f, glm::vec3(1.0f, 0.0f, 0.4f))),
                 object("open box", 4, at(0.2f, 0.9f, 1.4f) * glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(0.2f, 1.0f, 0.5f))),
                 object("sphere", 5, at(-0.6f, 2.2f, 0.2f))};
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = 0;
    switch (kind) {
        case LightKind::Point:
            s.light.type = scene::LightType::Point;
            s.light.position = glm::vec3(2.5f, 6.0f, 1.5f);
            break;
        case LightKind::Spot:
            s.light.type = scene::LightType::Spot;
            s.light.position = glm::vec3(-2.0f, 6.5f, 2.0f);
            s.light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.3f));
            s.light.spot_inner_cone = 0.5f;
            s.light.spot_outer_cone = 0.7f;
            break;
        case LightKind::Directional:
            s.light.type = scene::LightType::Directional;
            s.light.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, 0.3f));
            break;
    }
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 6.0f, 7.0f), glm::vec3(0.0f, 0.6f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(55.0f);
    s.camera.znear = 0.1f;
    s.camera.zfar = 40.0f;
    return s;
}

// The visibility image `rgba` (red channel) of a frame of `sc` scored against the truth, traced with
// the camera's finite projection: the same pixels as the renderer's infinite one (only depth differs).
measure::Score score_frame(const scene::Scene& sc, const std::vector<std::uint8_t>& rgba) {
    const render::FrameInputs in = render::offscreen(kSize, kSize);
    measure::TruthOptions to;
    to.width = kSize;
    to.height = kSize;
    to.view_proj = render::camera_view(sc, in).view_proj;
    const measure::TruthImage t = measure::RayTracer(sc).render(to);
    return measure::score(measure::from_rgba(rgba, kSize, kSize, 1).data, t.lit, t.valid_mask());
}

class Volumes : public test::GlTest {
protected:
    struct Result {
        measure::Score score;
        render::VolumeStats stats;
    };

    Result run(const scene::Scene& sc, const char* method, const std::string& what) {
        render::Settings s;
        s.technique = render::Technique::Volumes;
        EXPECT_EQ(render::parse_option(s, "volume-method", method), "");
        s.aov = render::Aov::Visibility;
        const render::FrameInputs in = render::offscreen(kSize, kSize);
        EXPECT_EQ(renderer->check(sc, s, in), "");
        const auto& plan = renderer->render(sc, s, in);
        Result r;
        if (render::volumes_of(plan)) r.stats = *render::volumes_of(plan);
        r.score = score_frame(sc, renderer->read_image());
        std::printf("%-34s --volume-method %-5s error %.3f%% (false shadow %.3f%%, false lit %.3f%%), %d depth-pass, "
                    "%d depth-fail caster(s), %d silhouette edge(s), fill %.2f per pixel\n",
                    what.c_str(), method, r.score.error_pct, r.score.false_shadow_pct, r.score.false_lit_pct,
                    r.stats.zpass_casters, r.stats.zfail_casters, r.stats.silhouette_edges, r.stats.fill_per_pixel);
        return r;
    }
};

TEST_F(Volumes, OpenMeshesCastExactShadowsUnderEveryLight) {
    const std::pair<const char*, LightKind> lights[] = {
        {"point", LightKind::Point}, {"spot", LightKind::Spot}, {"directional", LightKind::Directional}};
    for (const auto& [name, kind] : lights) {
        const scene::Scene sc = open_meshes(kind);
        for (int m = 1; m <= 4; ++m) ASSERT_FALSE(sc.meshes[static_cast<size_t>(m)].closed) << sc.objects[static_cast<size_t>(m)].name;
        ASSERT_TRUE(sc.meshes[5].closed);
        for (const char* method : {"auto", "zpass", "zfail"}) {
            const Result r = run(sc, method, std::string("open meshes, ") + name + " light,");
            EXPECT_LE(r.score.error_pct, kExact) << name << " light, " << method;
            EXPECT_GT(r.score.valid, static_cast<std::size_t>(kSize * kSize / 4));
        }
    }
}

// The score must be able to fail: with no shadows at all it is far off.
TEST_F(Volumes, TheScoreCanFail) {
    const scene::Scene sc = open_meshes(LightKind::Point);
    render::Settings s;
    s.technique = render::Technique::None;
    s.aov = render::Aov::Visibility;
    renderer->render(sc, s, render::offscreen(kSize, kSize));
    EXPECT_GT(score_frame(sc, renderer->read_image()).error_pct, 1.0);
}

TEST_F(Volumes, TheCourseSceneIsExact) {
    scene::CourseScene course = scene::make_course_scene(10);
    for (double t : {0.0, 1.3, 2.9}) {
        scene::animate_course(course, t, t);
        for (const char* method : {"auto", "zpass", "zfail"}) {
            const Result r = run(course.scene, method, "course scene at t = " + std::to_string(t).substr(0, 3) + ",");
            EXPECT_LE(r.score.error_pct, kExact) << "t = " << t << ", " << method;
        }
    }
}

TEST_F(Volumes, TheBenchScenesAreExact) {
    // bench_hard's light grazes a grating of thin slats: its shadow edges run nearly parallel to
    // the ground, and a pixel on either side of each edge disagrees with the truth (0.37 % here;
    // the shadow map at 2048 misses 0.60 % of the same frame). Held to 0.5 %, not to kExact.
    const std::pair<const char*, double> scenes[] = {{"bench_easy", kExact},  {"bench_medium", kExact}, {"bench_hard", 0.5},
                                                     {"bench_curved", kExact}, {"sphere_over_plane", kExact}};
    for (const auto& [name, bound] : scenes) {
        const scene::LoadResult l = scene::load_gltf(test::test_data_dir() + "/" + name + ".gltf");
        ASSERT_TRUE(l.ok) << l.error;
        const Result r = run(l.scene, "auto", name);
        EXPECT_LE(r.score.error_pct, bound) << name;
    }
}

TEST_F(Volumes, WithTheEyeInAShadowDepthPassFailsAndDepthFailHolds) {
    scene::CourseScene course = scene::make_course_scene(10);
    scene::animate_course(course, 0.0, 0.0);
    ASSERT_TRUE(scene::place_eye_in_shadow(course.scene));
    const Result pass = run(course.scene, "zpass", "eye in the teapot's shadow,");
    const Result fail = run(course.scene, "zfail", "eye in the teapot's shadow,");
    const Result automatic = run(course.scene, "auto", "eye in the teapot's shadow,");
    // Depth-pass starts counting at 0 where the eye's count is not 0: the lit ground beyond the
    // shadow turns dark (7.97 % of the pixels here).
    EXPECT_GT(pass.score.error_pct, 2.0) << "depth-pass should fail with the eye inside a volume";
    EXPECT_GT(pass.score.error_pct, 100.0 * fail.score.error_pct);
    EXPECT_LE(fail.score.error_pct, kExact);
    EXPECT_LE(automatic.score.error_pct, kExact);
    EXPECT_GE(automatic.stats.zfail_casters, 1);
}

TEST_F(Volumes, TheStencilIsLeftAsOtherTechniquesNeedIt) {
    scene::CourseScene course = scene::make_course_scene(10);
    scene::animate_course(course, 0.7, 0.7);
    const render::FrameInputs in = render::offscreen(kSize, kSize);
    render::Settings planar;
    planar.technique = render::Technique::Planar;
    render::Settings volumes;
    volumes.technique = render::Technique::Volumes;
    volumes.show_volumes = true;
    renderer->render(course.scene, planar, in);
    const auto before = renderer->read_image();
    renderer->render(course.scene, volumes, in);
    const auto with_volumes = renderer->read_image();
    renderer->render(course.scene, planar, in);
    const auto after = renderer->read_image();
    EXPECT_NE(before, with_volumes);
    EXPECT_EQ(before, after) << "planar shadows drawn after shadow volumes must not see their stencil or state";
    // And in one target, one after the other, the default state comes back after every frame.
    gl::check_errors("after the volumes");
}

}  // namespace
