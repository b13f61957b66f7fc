// --effects portal on a context. The reference for the opening is the other scene rendered by
// itself through the same camera with the same settings (its own light, its own shadow map fitted
// the same way): in the opening's pixels the portal shows exactly that, within 1 level; where the
// teapot stands in front of the opening the teapot is seen (the opening is depth tested against
// the course scene); outside the frame the image is the one without the portal, byte for byte.
// With every technique (and the outline and the mirror) the frame makes no GL error and changes
// only the pixels around the frame.
#include "gl_fixture.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

class PortalGl : public test::GlTest {};

constexpr int kW = 256, kH = 256;

using Image = std::vector<std::uint8_t>;

Image render(render::Renderer& rr, const scene::Scene& sc, const render::Settings& s) {
    rr.render(sc, s, render::offscreen(kW, kH));
    return rr.read_image("camera");
}

void save(const std::string& name, const Image& img) {
    std::filesystem::create_directories("test-output/portal");
    measure::write_png("test-output/portal/" + name + ".png", measure::from_rgba(img, kW, kH, 4));
}

int channel_diff(const Image& a, const Image& b, size_t px) {
    int d = 0;
    for (size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[px * 4 + c]) - int(b[px * 4 + c])));
    return d;
}

// A pixel's centre in the world's clip space, projected: x right, y down in pixels.
glm::vec2 to_pixel(const glm::mat4& view_proj, const glm::vec3& p) {
    const glm::vec4 c = view_proj * glm::vec4(p, 1.0f);
    return {(c.x / c.w * 0.5f + 0.5f) * kW, (0.5f - c.y / c.w * 0.5f) * kH};
}

// Whether the pixel centre (x + 0.5, y + 0.5) lies inside the convex quad q (screen space, any
// winding) at least `margin` pixels from its edges.
bool inside(const glm::vec2 (&q)[4], int x, int y, float margin) {
    const glm::vec2 p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    float sign = 0.0f;
    for (int i = 0; i < 4; ++i) {
        const glm::vec2 a = q[i], b = q[(i + 1) % 4];
        const glm::vec2 e = b - a;
        const float cross = e.x * (p.y - a.y) - e.y * (p.x - a.x);
        const float dist = cross / glm::length(e);
        if (sign == 0.0f) sign = dist < 0.0f ? -1.0f : 1.0f;
        if (dist * sign < margin) return false;
    }
    return true;
}

// The opening's corners (local: x +-0.7, y 0.1..1.5, z 0; scenes/portal_scene.cpp) on the screen.
void opening_quad(const scene::Scene& sc, glm::vec2 (&q)[4], float grow = 0.0f) {
    const glm::mat4 vp = render::camera_view(sc, render::offscreen(kW, kH)).view_proj;
    const glm::mat4& w = sc.portal->world;
    const float h = 0.7f + grow;
    const glm::vec3 local[4] = {{-h, 0.1f - grow, 0.0f}, {h, 0.1f - grow, 0.0f}, {h, 1.5f + grow, 0.0f}, {-h, 1.5f + grow, 0.0f}};
    for (int i = 0; i < 4; ++i) q[i] = to_pixel(vp, glm::vec3(w * glm::vec4(local[i], 1.0f)));
}

// The course scene at t, with a teapot of level 16.
scene::CourseScene course_at(double t) {
    scene::CourseScene c = scene::make_course_scene(16);
    scene::animate_course(c, t, t);
    return c;
}

// The other scene alone, seen by the course scene's camera.
scene::Scene other_scene(const scene::Scene& course) {
    scene::Scene o = *course.portal->beyond;
    o.camera = course.camera;
    return o;
}

TEST_F(PortalGl, TheOpeningShowsOnlyTheOtherSceneWithItsOwnShadows) {
    for (double t : {0.0, 0.75}) {  // the teapot on the table, and at the top of its jump in front of the opening
        SCOPED_TRACE("t = " + std::to_string(t));
        const scene::CourseScene c = course_at(t);
        render::Settings plain;  // the shadow map, as the defaults have it
        render::Settings s = plain;
        s.effects = {render::Effect::Portal};
        render::Settings none = plain;
        none.technique = render::Technique::None;
        scene::Scene no_teapot = c.scene;
        no_teapot.objects[static_cast<size_t>(c.teapot)].mesh = -1;

        const Image without = render(*renderer, c.scene, plain);
        const Image with = render(*renderer, c.scene, s);
        const Image other = render(*renderer, other_scene(c.scene), plain);
        const Image other_unshadowed = render(*renderer, other_scene(c.scene), none);
        // The teapot's pixels: where it changes the unshadowed image.
        const Image teapot_on = render(*renderer, c.scene, none), teapot_off = render(*renderer, no_teapot, none);

        glm::vec2 opening[4], frame[4];
        opening_quad(c.scene, opening);
        opening_quad(c.scene, frame, 0.1f + 0.08f);  // the frame's outer edge and its thickness
        int in_opening = 0, off = 0, worst = 0, shadowed = 0, teapot_in_front = 0, teapot_hidden = 0, outside = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const size_t p = static_cast<size_t>(y * kW + x);
                const bool teapot = channel_diff(teapot_on, teapot_off, p) > 0;
                if (inside(opening, x, y, 1.0f)) {
                    if (teapot) {
                        ++teapot_in_front;
                        teapot_hidden += channel_diff(with, without, p) != 0;
                        continue;
                    }
                    ++in_opening;
                    const int d = channel_diff(with, other, p);
                    worst = std::max(worst, d);
                    off += d > 1;
                    shadowed += channel_diff(other, other_unshadowed, p) > 16;
                } else if (!inside(frame, x, y, -1.5f)) {
                    outside += channel_diff(with, without, p) != 0;
                }
            }
        std::printf("t %.2f: %d opening pixels (%d in the other scene's shadows), %d differ from the other scene "
                    "alone by more than 1 level (worst %d); the teapot in front of %d of them (%d hidden); %d pixels "
                    "changed outside the frame\n",
                    t, in_opening, shadowed, off, worst, teapot_in_front, teapot_hidden, outside);
        EXPECT_GT(in_opening, 2000);
        EXPECT_GT(shadowed, 100) << "the other scene's own shadows are seen";
        EXPECT_EQ(off, 0) << "the opening shows the other scene alone";
        EXPECT_EQ(teapot_hidden, 0) << "the opening is drawn over the teapot in front of it";
        if (t > 0.5) {
            EXPECT_GT(teapot_in_front, 100) << "the teapot jumps in front of the opening";
        }
        EXPECT_EQ(outside, 0) << "pixels changed outside the frame";
        if (off || teapot_hidden || outside) {
            const std::string n = std::to_string(static_cast<int>(t * 100));
            save("opening-" + n + ".with", with);
            save("opening-" + n + ".other", other);
        }
        gl::check_errors("the portal test");
    }
}

TEST_F(PortalGl, TechniqueNoneLeavesTheOtherSceneUnshadowedToo) {
    const scene::CourseScene c = course_at(0.0);
    render::Settings none;
    none.technique = render::Technique::None;
    render::Settings s = none;
    s.effects = {render::Effect::Portal};
    const Image with = render(*renderer, c.scene, s);
    const Image other = render(*renderer, other_scene(c.scene), none);
    glm::vec2 opening[4];
    opening_quad(c.scene, opening);
    int n = 0, off = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            if (inside(opening, x, y, 1.0f) && y < kH / 3) {  // above the teapot
                ++n;
                off += channel_diff(with, other, static_cast<size_t>(y * kW + x)) > 1;
            }
    EXPECT_GT(n, 1000);
    EXPECT_EQ(off, 0);
    const render::FramePlan* plan = renderer->last_plan();
    ASSERT_NE(plan, nullptr);
    EXPECT_EQ(plan->resource_index("portal shadow-map"), -1);
}

TEST_F(PortalGl, TheOtherScenesMapIsDrawnOnceWhileNothingInItMoves) {
    scene::CourseScene c = course_at(0.0);
    render::Settings s;
    s.effects = {render::Effect::Portal};
    render(*renderer, c.scene, s);
    scene::animate_course(c, 0.5, 0.5);  // this scene's light and teapot move; the other scene stands still
    render(*renderer, c.scene, s);
    const render::FramePlan& plan = *renderer->last_plan();
    int ran = 0, skipped = 0;
    for (const render::Pass& p : plan.passes) {
        if (p.name == "portal shadow-map") (p.skipped ? skipped : ran) += 1;
        if (p.name == "shadow-map") {
            EXPECT_FALSE(p.skipped) << "this scene's map is redrawn: its light moved";
        }
    }
    EXPECT_EQ(ran, 0);
    EXPECT_EQ(skipped, 1);
}

TEST_F(PortalGl, WithEveryTechniqueOnlyTheFramesPixelsChange) {
    const scene::CourseScene c = course_at(0.6);
    glm::vec2 frame[4];
    opening_quad(c.scene, frame, 0.1f + 0.08f);
    for (auto& [name, plain] : test::every_technique_case()) {
        for (render::Effect other : {render::Effect::Outline, render::Effect::Mirror, render::Effect::Portal}) {
            SCOPED_TRACE(name + " + " + std::string(render::to_string(other)));
            render::Settings base = plain;
            if (other != render::Effect::Portal) base.effects = {other};
            render::Settings s = base;
            s.effects.push_back(render::Effect::Portal);
            std::sort(s.effects.begin(), s.effects.end());  // kAllEffects' order, as the option table keeps it
            ASSERT_EQ(renderer->check(c.scene, s, render::offscreen(kW, kH)), "");
            Image without, with;
            ASSERT_NO_THROW(without = render(*renderer, c.scene, base));
            ASSERT_NO_THROW(with = render(*renderer, c.scene, s));
            int changed = 0, elsewhere = 0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    if (channel_diff(with, without, static_cast<size_t>(y * kW + x)) == 0) continue;
                    ++changed;
                    elsewhere += !inside(frame, x, y, -1.5f);
                }
            EXPECT_GT(changed, 2000);
            // The outline is drawn after the portal: where it crosses the frame it is the same.
            EXPECT_EQ(elsewhere, 0) << "pixels changed away from the frame";
            gl::check_errors("the portal with every technique");
        }
    }
}

}  // namespace
