// --effects mirror on a context. The reference is made without the effect: the course scene
// mirrored by hand (every object but the table moved by the reflection R about the table's plane,
// its triangles' winding turned back, the light moved by R, the table taken away), rendered by the
// same camera. In the mirror's pixels a perfect mirror (reflectivity 1) shows that reference
// within 1 level; everywhere else the image is the one without the mirror, byte for byte;
// reflectivity 0 changes nothing. With every technique (and the soft settings, and the outline)
// the frame makes no GL error and changes only the table's pixels (or the outline's).
#include "gl_fixture.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"
#include "scene/primitives.h"

using namespace penumbra;

namespace {

class MirrorGl : public test::GlTest {};

constexpr int kW = 256, kH = 192;

using Image = std::vector<std::uint8_t>;

std::vector<std::uint8_t> render(render::Renderer& rr, const scene::Scene& sc, const render::Settings& s) {
    rr.render(sc, s, render::offscreen(kW, kH));
    return rr.read_image("camera");
}

// Written under the tests' output folder (mirror/) when a comparison fails, to look at.
void save(const std::string& name, const Image& img) {
    const std::filesystem::path dir = std::filesystem::path(test::test_out_dir()) / "mirror";
    std::filesystem::create_directories(dir);
    measure::write_png((dir / (name + ".png")).string(), measure::from_rgba(img, kW, kH, 4));
}

// Within 1.5 levels of the background (render::kBackground) in each channel.
bool background_at(const Image& img, size_t px) {
    const glm::vec4 bg = render::kBackground * 255.0f;
    for (size_t c = 0; c < 3; ++c)
        if (std::abs(img[px * 4 + c] - bg[static_cast<glm::length_t>(c)]) > 1.5f) return false;
    return true;
}

int channel_diff(const Image& a, const Image& b, size_t px) {
    int d = 0;
    for (size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[px * 4 + c]) - int(b[px * 4 + c])));
    return d;
}

glm::mat4 reflection_about(const glm::vec4& plane) {
    const glm::vec3 n = glm::normalize(glm::vec3(plane));
    const float d = plane.w / glm::length(glm::vec3(plane));
    glm::mat4 r(1.0f);
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) r[col][row] -= 2.0f * n[row] * n[col];
    r[3] = glm::vec4(-2.0f * d * n, 1.0f);
    return r;
}

// The scene as seen in its table, made by moving the objects: what a perfect mirror must show.
scene::Scene mirrored(const scene::Scene& s) {
    scene::Scene m = s;
    const glm::mat4 R = reflection_about(*s.ground_plane);
    for (scene::Mesh& mesh : m.meshes) {
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
        mesh.topology.reset();
        mesh.closed = false;
    }
    for (scene::Object& o : m.objects) o.world = R * o.world;
    m.objects[static_cast<size_t>(s.ground_object)].mesh = -1;  // the mirror shows no table
    m.ground_object = -1;
    m.ground_plane.reset();
    m.light.position = glm::vec3(R * glm::vec4(s.light.position, 1.0f));
    m.light.direction = glm::vec3(R * glm::vec4(s.light.direction, 0.0f));
    return m;
}

struct Course {
    scene::CourseScene course = scene::make_course_scene(16);
    scene::Scene table_only;
    explicit Course(double t) {
        scene::animate_course(course, t, t);
        table_only = course.scene;
        for (size_t i = 0; i < table_only.objects.size(); ++i)
            if (static_cast<int>(i) != table_only.ground_object) table_only.objects[i].mesh = -1;
    }
};

// The pixels where the table is seen: it differs from the background there in the table-only
// image, and the full image (no shadows) is the same as the table-only one (nothing in front).
std::vector<bool> mirror_pixels(const Image& table_only, const Image& plain) {
    std::vector<bool> m(static_cast<size_t>(kW * kH));
    for (size_t p = 0; p < m.size(); ++p) m[p] = !background_at(table_only, p) && channel_diff(table_only, plain, p) == 0;
    return m;
}

TEST_F(MirrorGl, APerfectMirrorShowsTheSceneRenderedWithTheReflectionMatrix) {
    for (double t : {0.6, 1.2}) {
        SCOPED_TRACE("t = " + std::to_string(t));
        Course c(t);
        render::Settings plain;
        plain.technique = render::Technique::None;
        render::Settings s = plain;
        s.effects = {render::Effect::Mirror};
        s.reflectivity = 1.0f;
        const Image table = render(*renderer, c.table_only, plain);
        const Image without = render(*renderer, c.course.scene, plain);
        const Image with = render(*renderer, c.course.scene, s);
        const Image reference = render(*renderer, mirrored(c.course.scene), plain);
        const std::vector<bool> mirror = mirror_pixels(table, without);
        int in_mirror = 0, off = 0, worst = 0, outside_changed = 0, teapot_seen = 0;
        for (size_t p = 0; p < mirror.size(); ++p) {
            if (!mirror[p]) {
                outside_changed += channel_diff(with, without, p) != 0;
                continue;
            }
            ++in_mirror;
            const int d = channel_diff(with, reference, p);
            worst = std::max(worst, d);
            off += d > 1;
            teapot_seen += channel_diff(reference, table, p) > 0 && std::abs(reference[p * 4] - 31) > 2;
        }
        std::printf("t %.1f: %d mirror pixels, %d of them show the teapot; %d differ from the reference by more than "
                    "1 level (worst %d); %d pixels changed outside the mirror\n",
                    t, in_mirror, teapot_seen, off, worst, outside_changed);
        EXPECT_GT(in_mirror, kW * kH / 8);
        EXPECT_GT(teapot_seen, 200) << "the teapot is seen in the mirror";
        // Pixels whose centres lie on a triangle's edge may fall on either side in the two renders
        // (R M p against (R M) p): at most 1 in 2000 of the mirror's pixels.
        EXPECT_LE(off, in_mirror / 2000);
        if (off > in_mirror / 2000) {
            const std::string t_name = std::to_string(static_cast<int>(t * 10));
            save("perfect-" + t_name + ".with", with);
            save("perfect-" + t_name + ".reference", reference);
        }
        EXPECT_EQ(outside_changed, 0) << "nothing changes outside the mirror";
        gl::check_errors("the mirror test");
    }
}

TEST_F(MirrorGl, ReflectivityZeroChangesNothingAndHalfIsBetween) {
    Course c(0.6);
    render::Settings plain;
    render::Settings s = plain;
    s.effects = {render::Effect::Mirror};
    s.reflectivity = 0.0f;
    const Image without = render(*renderer, c.course.scene, plain);
    EXPECT_EQ(render(*renderer, c.course.scene, s), without);
    s.reflectivity = 1.0f;
    const Image full = render(*renderer, c.course.scene, s);
    s.reflectivity = 0.5f;
    const Image half = render(*renderer, c.course.scene, s);
    int between = 0, changed = 0;
    for (size_t p = 0; p < static_cast<size_t>(kW * kH); ++p) {
        if (channel_diff(full, without, p) == 0) continue;
        ++changed;
        bool ok = true;
        for (size_t ch = 0; ch < 3; ++ch) {
            const double want = 0.5 * full[p * 4 + ch] + 0.5 * without[p * 4 + ch];
            ok = ok && std::abs(half[p * 4 + ch] - want) <= 1.5;
        }
        between += ok;
    }
    EXPECT_GT(changed, kW * kH / 8);
    EXPECT_GE(between, changed - changed / 1000) << "reflectivity 0.5 is the mean of 0 and 1";
}

// A wall standing on a mirror floor, a ball between it and the light: the ball's shadow on the
// wall is seen in the mirror, below the wall's foot, as the shadow map casts it.
scene::Scene wall_scene() {
    scene::Scene s;
    s.meshes.push_back(scene::make_quad(8.0f));
    s.meshes.push_back(scene::make_box(glm::vec3(1.6f, 1.0f, 0.1f)));
    s.meshes.push_back(scene::make_sphere(0.35f, 48, 24));
    scene::Material grey;
    grey.base_color = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
    scene::Material light_wall;
    light_wall.base_color = glm::vec4(0.9f, 0.85f, 0.7f, 1.0f);
    s.materials = {grey, light_wall};
    s.objects.push_back(test::object("floor", 0, glm::mat4(1.0f)));
    scene::Object wall = test::object("wall", 1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, -1.0f)));
    wall.material = 1;
    s.objects.push_back(wall);
    s.objects.push_back(test::object("ball", 2, glm::translate(glm::mat4(1.0f), glm::vec3(0.2f, 0.9f, 0.2f))));
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = 0;
    s.light.position = glm::vec3(0.6f, 2.2f, 3.0f);
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 1.3f, 5.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = 0.9f;
    s.camera.znear = 0.1f;
    s.camera.zfar = 50.0f;
    return s;
}

TEST_F(MirrorGl, TheShadowMapsShadowIsReflectedToo) {
    const scene::Scene sc = wall_scene();
    scene::Scene floor_only = sc;
    for (size_t i = 1; i < floor_only.objects.size(); ++i) floor_only.objects[i].mesh = -1;
    render::Settings shadowed;
    shadowed.map_size = 2048;
    render::Settings s = shadowed;
    s.effects = {render::Effect::Mirror};
    s.reflectivity = 1.0f;
    render::Settings none = shadowed;
    none.technique = render::Technique::None;
    const Image floor = render(*renderer, floor_only, none);
    const Image unshadowed = render(*renderer, sc, none);
    const Image with = render(*renderer, sc, s);
    const scene::Scene m = mirrored(sc);
    const Image reference = render(*renderer, m, shadowed);
    const Image reference_unshadowed = render(*renderer, m, none);
    const std::vector<bool> mirror = mirror_pixels(floor, unshadowed);
    int in_mirror = 0, shadow = 0, off = 0;
    for (size_t p = 0; p < mirror.size(); ++p) {
        if (!mirror[p]) continue;
        ++in_mirror;
        shadow += channel_diff(reference, reference_unshadowed, p) > 8;
        off += channel_diff(with, reference, p) > 8;
    }
    std::printf("%d mirror pixels, %d of them in the reflected shadow; %d differ from the mirrored scene's by more "
                "than 8 levels\n", in_mirror, shadow, off);
    EXPECT_GT(shadow, 300) << "the ball's shadow on the wall is seen in the mirror";
    // The two shadow maps are fitted to two different scenes (texels land differently): only the
    // shadow's edge may differ.
    EXPECT_LE(off, shadow / 20);
    if (shadow <= 300 || off > shadow / 20) {
        save("wall.with", with);
        save("wall.reference", reference);
    }
}

// What lies below the mirror's plane is never seen in it (the shader's clip plane): a ball under
// the floor, which the reflected camera would otherwise show as if it floated above it.
TEST_F(MirrorGl, WhatLiesBelowTheMirrorIsCutAway) {
    scene::Scene sc = wall_scene();
    sc.objects[1].mesh = -1;  // no wall
    sc.objects[2].world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.4f, 0.5f));  // the ball just under the floor
    scene::Scene floor_only = sc;
    floor_only.objects[2].mesh = -1;
    render::Settings none;
    none.technique = render::Technique::None;
    render::Settings s = none;
    s.effects = {render::Effect::Mirror};
    s.reflectivity = 1.0f;
    const Image floor = render(*renderer, floor_only, none);
    const Image with = render(*renderer, sc, s);
    int in_mirror = 0, not_background = 0;
    for (size_t p = 0; p < static_cast<size_t>(kW * kH); ++p) {
        if (background_at(floor, p)) continue;
        ++in_mirror;
        not_background += !background_at(with, p);
    }
    EXPECT_GT(in_mirror, kW * kH / 4);
    EXPECT_EQ(not_background, 0) << "the ball below the floor is seen in the mirror";
    if (not_background) save("below.with", with);
}

TEST_F(MirrorGl, WithEveryTechniqueOnlyTheTableChanges) {
    Course c(0.6);
    const auto cases = test::every_technique_case();
    render::Settings none;
    none.technique = render::Technique::None;
    const Image table = render(*renderer, c.table_only, none);
    for (auto& [name, plain] : cases) {
        for (bool outline : {false, true}) {
            SCOPED_TRACE(name + (outline ? " + outline" : ""));
            render::Settings s = plain;
            s.effects = {render::Effect::Mirror};
            if (outline) s.effects.insert(s.effects.begin(), render::Effect::Outline);
            s.outline_color = glm::vec3(0.0f, 1.0f, 0.0f);
            ASSERT_EQ(renderer->check(c.course.scene, s, render::offscreen(kW, kH)), "");
            render::Settings base = s;
            base.effects.pop_back();  // the same without the mirror
            Image without, with;
            ASSERT_NO_THROW(without = render(*renderer, c.course.scene, base));
            ASSERT_NO_THROW(with = render(*renderer, c.course.scene, s));
            int changed = 0, elsewhere = 0;
            for (size_t p = 0; p < static_cast<size_t>(kW * kH); ++p) {
                if (channel_diff(with, without, p) == 0) continue;
                ++changed;
                elsewhere += background_at(table, p);
            }
            EXPECT_GT(changed, 500);
            EXPECT_EQ(elsewhere, 0) << "pixels changed where the table is not";
            gl::check_errors("the mirror with every technique");
        }
    }
}

}  // namespace
