// --shading deferred against --shading forward on a context, with the same --lights: every pixel
// within 2 levels, through the G-buffer drawn in one pass (EXT_draw_buffers) and one pass per
// target (a renderer told the context has no draw buffers); the two G-buffer paths give the same
// bytes. With a shadow map the only pixels allowed further apart are those where the shadow test
// itself flips between the two programs (a surface point within float rounding of the map's depth:
// the visibility AOVs differ there), and those must be rare. The G-buffer views show what the
// G-buffer holds. No GL errors (the fixture's teardown).
#include "gl_fixture.h"

#include <algorithm>
#include <filesystem>

#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

constexpr int kW = 200, kH = 150;

using Image = std::vector<std::uint8_t>;

class DeferredGl : public test::GlTest {
protected:
    scene::CourseScene course = scene::make_course_scene(8);

    // A renderer on the same context that believes it has no draw buffers: one pass per target.
    std::unique_ptr<render::Renderer> without_draw_buffers() {
        gl::Caps caps = gl::probe_caps(test::context());
        caps.draw_buffers = false;
        return std::make_unique<render::Renderer>(caps);
    }

    Image render(render::Renderer& r, const char* technique, const char* shading, int lights,
                 const char* aov = "color") {
        render::Settings s;
        EXPECT_EQ(render::parse_option(s, "technique", technique), "");
        EXPECT_EQ(render::parse_option(s, "shading", shading), "");
        EXPECT_EQ(render::parse_option(s, "aov", aov), "");
        s.lights = lights;
        const render::FramePlan& plan = r.render(course.scene, s, render::offscreen(kW, kH));
        last_mrt = plan.has_pass("gbuffer");
        last_per_target = plan.has_pass("gbuffer-color") && plan.has_pass("gbuffer-normal") && plan.has_pass("gbuffer-depth");
        return r.read_image("camera");
    }
    bool last_mrt = false, last_per_target = false;
};

void save(const std::string& name, const Image& img) {
    const std::filesystem::path dir = std::filesystem::path(test::test_out_dir()) / "deferred";
    std::filesystem::create_directories(dir);
    measure::write_png((dir / (name + ".png")).string(), measure::from_rgba(img, kW, kH, 4));
}

// The largest RGB difference over the pixels not excluded.
int worst(const Image& a, const Image& b, const std::vector<bool>& excluded = {}) {
    int w = 0;
    for (size_t p = 0; p < a.size() / 4; ++p) {
        if (!excluded.empty() && excluded[p]) continue;
        for (size_t c = 0; c < 3; ++c) w = std::max(w, std::abs(int(a[p * 4 + c]) - int(b[p * 4 + c])));
    }
    return w;
}

TEST_F(DeferredGl, EqualsForwardWithinTwoLevelsOnEveryPixelThroughBothGbufferPaths) {
    if (!renderer->caps().draw_buffers) GTEST_SKIP() << "no EXT_draw_buffers on this context: the MRT path is untested";
    auto per_target = without_draw_buffers();
    for (int lights : {0, 8, 40}) {
        SCOPED_TRACE("lights " + std::to_string(lights));
        const Image forward = render(*renderer, "none", "forward", lights);
        const Image mrt = render(*renderer, "none", "deferred", lights);
        EXPECT_TRUE(last_mrt);
        const Image passes = render(*per_target, "none", "deferred", lights);
        EXPECT_TRUE(last_per_target);
        EXPECT_FALSE(last_mrt);
        save("forward-" + std::to_string(lights), forward);
        save("deferred-" + std::to_string(lights), mrt);
        EXPECT_LE(worst(forward, mrt), 2);
        EXPECT_EQ(mrt, passes) << "the G-buffer drawn at once and target by target differ";
        // The lights do something: 40 of them brighten much of the table.
        if (lights == 40) {
            int brighter = 0;
            const Image dark = render(*renderer, "none", "deferred", 0);
            for (size_t p = 0; p < dark.size() / 4; ++p)
                if (int(mrt[p * 4]) + mrt[p * 4 + 1] + mrt[p * 4 + 2] > int(dark[p * 4]) + dark[p * 4 + 1] + dark[p * 4 + 2] + 30)
                    ++brighter;
            EXPECT_GT(brighter, kW * kH / 20);
        }
    }
}

TEST_F(DeferredGl, WithTheShadowMapOnlyTheShadowTestsFlipsDifferAndThoseAreRare) {
    auto per_target = without_draw_buffers();
    for (render::Renderer* r : {renderer.get(), per_target.get()}) {
        const Image fwd_vis = render(*r, "shadowmap", "forward", 0, "visibility");
        const Image def_vis = render(*r, "shadowmap", "deferred", 0, "visibility");
        std::vector<bool> flipped(fwd_vis.size() / 4, false);
        int flips = 0;
        for (size_t p = 0; p < flipped.size(); ++p)
            if (std::abs(int(fwd_vis[p * 4]) - int(def_vis[p * 4])) > 2) {
                flipped[p] = true;
                ++flips;
            }
        EXPECT_LE(flips, kW * kH / 2000) << "the visibility differs on more than 0.05% of the pixels";
        // The shadow is there in both: a good share of shadowed pixels.
        int shadowed = 0;
        for (size_t p = 0; p < flipped.size(); ++p) shadowed += def_vis[p * 4] < 128;
        EXPECT_GT(shadowed, kW * kH / 50);
        const Image forward = render(*r, "shadowmap", "forward", 8);
        const Image deferred = render(*r, "shadowmap", "deferred", 8);
        EXPECT_LE(worst(forward, deferred, flipped), 2);
    }
}

TEST_F(DeferredGl, GbufferViewsShowWhatItHolds) {
    // The table's top faces up: its normal view is (0.5, 1, 0.5); where nothing is, the clear
    // colour; the depth view is darker farther away; the colour view is the teapot's orange on
    // its body (red well above blue) and the material's colour, not lit, on the table.
    const auto at = [](int x, int y) { return (static_cast<size_t>(y) * kW + static_cast<size_t>(x)) * 4; };
    const size_t table_near = at(kW / 2, kH - 20), table_far = at(kW / 2, 52), teapot = at(kW / 2, 75), sky = at(kW / 2, 5);
    const Image normal = render(*renderer, "shadowmap", "deferred", 0, "gbuffer-normal");
    save("gbuffer-normal", normal);
    EXPECT_NEAR(normal[table_near], 128, 2);
    EXPECT_NEAR(normal[table_near + 1], 255, 1);
    EXPECT_NEAR(normal[table_near + 2], 128, 2);
    EXPECT_NEAR(normal[sky], std::round(render::kBackground.r * 255.0f), 1);
    const Image depth = render(*renderer, "shadowmap", "deferred", 0, "gbuffer-depth");
    save("gbuffer-depth", depth);
    EXPECT_GT(int(depth[table_near]), int(depth[table_far]) + 40);
    const Image color = render(*renderer, "shadowmap", "deferred", 0, "gbuffer-color");
    save("gbuffer-color", color);
    EXPECT_GT(int(color[teapot]), int(color[teapot + 2]) + 80);
    const Image position = render(*renderer, "shadowmap", "deferred", 0, "gbuffer-position");
    save("gbuffer-position", position);
    // z (blue) grows towards the camera: the near table is bluer than the far.
    EXPECT_GT(int(position[table_near + 2]), int(position[table_far + 2]) + 40);
}

}  // namespace
