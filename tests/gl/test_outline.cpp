// --effects outline on a context: its width in pixels, measured on a sphere at two depths; it never
// covers the object's own pixels; with every technique (and the soft settings) it leaves the
// technique's image alone outside the outline and makes no GL error.
#include "gl_fixture.h"

#include <glm/gtc/matrix_transform.hpp>

#include "plan/options.h"
#include "scenes/course_scene.h"
#include "scene/primitives.h"

using namespace penumbra;

namespace {

class OutlineGl : public test::GlTest {};

constexpr int kSize = 160;
const glm::vec3 kGreen{0.0f, 1.0f, 0.0f};

// One red sphere of radius 1 straight ahead of the camera at `distance`, nothing else.
scene::Scene sphere_scene(float distance) {
    scene::Scene s;
    s.meshes.push_back(scene::make_sphere(1.0f, 96, 48));
    scene::Material m;
    m.base_color = glm::vec4(0.8f, 0.1f, 0.1f, 1.0f);
    s.materials.push_back(m);
    s.objects.push_back(test::object("sphere", 0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -distance))));
    s.light.position = glm::vec3(2.0f, 4.0f, 2.0f);
    s.camera.view = glm::mat4(1.0f);
    s.camera.yfov = 0.6f;
    s.camera.znear = 0.1f;
    s.camera.zfar = 100.0f;
    return s;
}

struct Rgb {
    int r, g, b;
};
Rgb at(const std::vector<std::uint8_t>& px, int x, int y, int width) {
    const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 4u;
    return {px[i], px[i + 1], px[i + 2]};
}
bool is_green(const Rgb& c) { return c.r == 0 && c.g == 255 && c.b == 0; }

struct Row {
    int left = 0, right = 0;  // outline pixels left and right of the object
    int object = 0;           // object pixels between them
};

// The outline-coloured pixels of row y, on each side of the run of object pixels in the middle.
Row measure_row(const std::vector<std::uint8_t>& with, const std::vector<std::uint8_t>& without, int y, int width) {
    Row r;
    const Rgb bg = at(without, 0, y, width);
    int first = -1, last = -1;
    for (int x = 0; x < width; ++x) {
        const Rgb c = at(without, x, y, width);
        if (c.r != bg.r || c.g != bg.g || c.b != bg.b) {
            if (first < 0) first = x;
            last = x;
        }
    }
    if (first < 0) return r;
    r.object = last - first + 1;
    for (int x = 0; x < width; ++x)
        if (is_green(at(with, x, y, width))) ++(x < first ? r.left : x > last ? r.right : r.object);
    return r;
}

std::vector<std::uint8_t> render(render::Renderer& rr, const scene::Scene& sc, const render::Settings& s, int w, int h) {
    rr.render(sc, s, render::offscreen(w, h));
    return rr.read_image("camera");
}

TEST_F(OutlineGl, WidthInPixelsIsTheSameAtTwoDepths) {
    render::Settings plain;
    plain.technique = render::Technique::None;
    render::Settings s = plain;
    s.effects = {render::Effect::Outline};
    s.outline_color = kGreen;
    int radius_near = 0, radius_far = 0;
    for (float distance : {4.0f, 8.0f}) {
        const scene::Scene sc = sphere_scene(distance);
        const auto without = render(*renderer, sc, plain, kSize, kSize);
        for (float width : {1.0f, 3.0f, 8.0f}) {
            s.outline_width = width;
            const auto with = render(*renderer, sc, s, kSize, kSize);
            const Row row = measure_row(with, without, kSize / 2, kSize);
            (distance < 5.0f ? radius_near : radius_far) = row.object / 2;
            EXPECT_NEAR(row.left, width, 1.0) << "distance " << distance << ", width " << width;
            EXPECT_NEAR(row.right, width, 1.0) << "distance " << distance << ", width " << width;
            EXPECT_EQ(row.object, measure_row(without, without, kSize / 2, kSize).object) << "no outline on the sphere";
        }
    }
    // The sphere is half as big at twice the distance; the outline is not.
    EXPECT_NEAR(radius_far * 2, radius_near, 2);
    EXPECT_GT(radius_near, 20);
}

TEST_F(OutlineGl, NeverCoversTheObjectsOwnPixels) {
    render::Settings plain;
    plain.technique = render::Technique::None;
    render::Settings s = plain;
    s.effects = {render::Effect::Outline};
    s.outline_color = kGreen;
    s.outline_width = 6.0f;
    const scene::Scene sc = sphere_scene(4.0f);
    const auto without = render(*renderer, sc, plain, kSize, kSize);
    const auto with = render(*renderer, sc, s, kSize, kSize);
    const Rgb bg = at(without, 0, 0, kSize);
    int outline = 0, object = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Rgb a = at(without, x, y, kSize), b = at(with, x, y, kSize);
            const bool background = a.r == bg.r && a.g == bg.g && a.b == bg.b;
            if (!background) {
                ++object;
                ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b) << "object pixel (" << x << ", " << y << ") changed";
            } else if (is_green(b)) {
                ++outline;
            } else {
                ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b) << "background (" << x << ", " << y << ") changed";
            }
        }
    EXPECT_GT(object, 1000);
    EXPECT_GT(outline, 200);
}

// Every technique (and the soft settings) with and without the outline on the course scene: no
// GL error (the renderer checks after every pass and throws), outline pixels exist, and every
// pixel that differs is the outline's colour: the technique's image is untouched elsewhere (its
// stencil now shares the buffer with the outline's bit).
TEST_F(OutlineGl, WithEveryTechniqueTheImageChangesOnlyByTheOutline) {
    auto course = scene::make_course_scene(8);
    scene::animate_course(course, 0.6, 0.6);
    const auto cases = test::every_technique_case();
    const int w = 128, h = 96;
    for (auto& [name, plain] : cases) {
        SCOPED_TRACE(name);
        ASSERT_EQ(renderer->check(course.scene, plain, render::offscreen(w, h)), "");
        render::Settings s = plain;
        s.effects = {render::Effect::Outline};
        s.outline_color = kGreen;
        s.outline_width = 2.0f;
        ASSERT_EQ(renderer->check(course.scene, s, render::offscreen(w, h)), "");
        std::vector<std::uint8_t> without, with;
        ASSERT_NO_THROW(without = render(*renderer, course.scene, plain, w, h));
        ASSERT_NO_THROW(with = render(*renderer, course.scene, s, w, h));
        int outline = 0, other = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const Rgb a = at(without, x, y, w), b = at(with, x, y, w);
                if (a.r == b.r && a.g == b.g && a.b == b.b) continue;
                ++(is_green(b) ? outline : other);
            }
        EXPECT_GT(outline, 50);
        EXPECT_EQ(other, 0) << "pixels changed other than to the outline's colour";
        gl::check_errors("the outline test");
    }
}

}  // namespace
