// Alpha-tested cut-outs (glTF alphaMode MASK) cast cut-out shadows: tests/data/alpha_cutouts.gltf
// (a fence of slats with alpha-0 gaps, a double-sided leafy quad, a BLEND pane; make_alpha_gltf.py)
// rendered as the visibility AOV and scored against the ray-traced truth, which honours the cutoff
// too; and, with no golden, the fence's shadow map shadow has its gaps where the texture has them.
#include "gl_fixture.h"

#include <cstdio>

#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "plan/options.h"
#include "scene/gltf_loader.h"

using namespace penumbra;

namespace {

constexpr int kSize = 256;

scene::Scene alpha_scene() {
    const scene::LoadResult r = scene::load_gltf(test::test_data_dir() + "/alpha_cutouts.gltf");
    EXPECT_TRUE(r.ok) << r.error;
    return r.scene;
}

class AlphaCutouts : public test::GlTest {
protected:
    // The visibility AOV's red channel.
    std::vector<std::uint8_t> visibility(const scene::Scene& sc, render::Settings s, glm::mat4* view_proj = nullptr) {
        s.aov = render::Aov::Visibility;
        const auto& plan = renderer->render(sc, s, render::offscreen(kSize, kSize));
        if (view_proj) *view_proj = plan.camera.view_proj;
        const auto rgba = renderer->read_image();
        std::vector<std::uint8_t> v(rgba.size() / 4);
        for (size_t i = 0; i < v.size(); ++i) v[i] = rgba[i * 4];
        gl::check_errors("the alpha frame");
        return v;
    }

    measure::Score score(const scene::Scene& sc, const render::Settings& s, const char* label) {
        const auto v = visibility(sc, s);
        measure::TruthOptions to;
        to.width = to.height = kSize;
        // The scene camera's (volumes move the far plane to infinity: the same pixels, no depth range).
        to.view_proj = render::camera_view(sc, render::offscreen(kSize, kSize)).view_proj;
        const measure::TruthImage t = measure::RayTracer(sc, s.blend_shadows).render(to);
        const measure::Score r = measure::score(v, t.lit, t.valid_mask());
        std::printf("alpha_cutouts %dx%d %-40s error %.3f %% (false shadow %.3f %%, false lit %.3f %%), %zu valid px\n",
                    kSize, kSize, label, r.error_pct, r.false_shadow_pct, r.false_lit_pct, r.valid);
        return r;
    }
};

render::Settings settings(const char* technique, const char* encoding = "rgba") {
    render::Settings s;
    EXPECT_EQ(render::parse_option(s, "technique", technique), "");
    EXPECT_EQ(render::parse_option(s, "encoding", encoding), "");
    return s;
}

TEST_F(AlphaCutouts, TheirShadowsMatchTheTruthWithinOnePercent) {
    const scene::Scene sc = alpha_scene();
    for (const char* e : {"rgba", "r8", "depthtex"}) {
        const measure::Score r = score(sc, settings("shadowmap", e), (std::string("shadowmap ") + e).c_str());
        EXPECT_LT(r.error_pct, 1.0) << e;
        EXPECT_GT(r.valid, 10000u);
    }
    EXPECT_LT(score(sc, settings("planar"), "planar").error_pct, 1.0);
    render::Settings blend = settings("shadowmap");
    blend.blend_shadows = true;
    EXPECT_LT(score(sc, blend, "shadowmap --blend-shadows on").error_pct, 1.0);
    // Shadow volumes cannot cut: the whole quads' shadows (documented), far from the truth.
    EXPECT_GT(score(sc, settings("volumes"), "volumes (whole quads, as documented)").error_pct, 2.0);
}

// Where a ray from the light through the fence's texel (u, v) meets the ground, as a pixel.
glm::ivec2 ground_pixel(const scene::Scene& sc, const glm::mat4& view_proj, float u, float v) {
    // The fence: x -2.5..0.5 (u), y 1.5..0 (v), z 0 (make_alpha_gltf.py).
    const glm::vec3 f(-2.5f + 3.0f * u, 1.5f * (1.0f - v), 0.0f);
    const glm::vec3 l = sc.light.position;
    const glm::vec3 g = l + (l.y / (l.y - f.y)) * (f - l);
    const glm::vec4 c = view_proj * glm::vec4(g, 1.0f);
    const glm::vec2 ndc = glm::vec2(c) / c.w;
    return {static_cast<int>((ndc.x * 0.5f + 0.5f) * kSize), static_cast<int>((0.5f - ndc.y * 0.5f) * kSize)};
}

TEST_F(AlphaCutouts, TheFencesShadowHasGapsWhereItsTextureDoes) {
    scene::Scene sc = alpha_scene();
    glm::mat4 vp;
    const auto cut = visibility(sc, settings("shadowmap"), &vp);
    // The same fence opaque: its quad's whole shadow.
    for (auto& m : sc.materials) m.alpha_mode = scene::AlphaMode::Opaque;
    const auto whole = visibility(sc, settings("shadowmap"));
    // Below the rail (texel rows 10..13), at texel row 24: each of the 4 slats (texel columns
    // 8k..8k+4) and the gap after it (8k+5..8k+7), at their middles.
    int checked = 0;
    for (int k = 0; k < 4; ++k) {
        const glm::ivec2 slat = ground_pixel(sc, vp, (8.0f * static_cast<float>(k) + 2.5f) / 32.0f, 24.5f / 32.0f);
        const glm::ivec2 gap = ground_pixel(sc, vp, (8.0f * static_cast<float>(k) + 6.5f) / 32.0f, 24.5f / 32.0f);
        for (const glm::ivec2& p : {slat, gap}) {
            ASSERT_GE(p.x, 0);
            ASSERT_LT(p.x, kSize);
            ASSERT_GE(p.y, 0);
            ASSERT_LT(p.y, kSize);
        }
        const auto at = [](const std::vector<std::uint8_t>& img, glm::ivec2 p) {
            return img[static_cast<size_t>(p.y) * kSize + static_cast<size_t>(p.x)];
        };
        EXPECT_EQ(at(cut, slat), 0) << "behind slat " << k << " at (" << slat.x << ", " << slat.y << ")";
        EXPECT_EQ(at(whole, slat), 0) << "slat " << k;
        EXPECT_EQ(at(cut, gap), 255) << "behind gap " << k << " at (" << gap.x << ", " << gap.y << ")";
        EXPECT_EQ(at(whole, gap), 0) << "gap " << k << " without the alpha test";
        ++checked;
    }
    EXPECT_EQ(checked, 4);
}

TEST_F(AlphaCutouts, EveryTechniqueAndBlendSettingRendersWithoutGlErrors) {
    const scene::Scene sc = alpha_scene();
    for (const char* t : {"shadowmap", "planar", "volumes", "gooch", "none"})
        for (const char* b : {"off", "on"})
            for (const char* aov : {"color", "visibility"}) {
                render::Settings s = settings(t);
                ASSERT_EQ(render::parse_option(s, "blend-shadows", b), "");
                ASSERT_EQ(render::parse_option(s, "aov", aov), "");
                EXPECT_NO_THROW(renderer->render(sc, s, render::offscreen(96, 96))) << render::to_args(s);
                EXPECT_NO_THROW(gl::check_errors("after the frame")) << render::to_args(s);
            }
    render::Settings soft = settings("shadowmap");
    soft.filter = shadow::Filter::PCSS;
    soft.light_radius = 0.1f;
    EXPECT_NO_THROW(renderer->render(sc, soft, render::offscreen(96, 96)));
    soft.filter = shadow::Filter::Hard;
    soft.area_samples = 4;
    EXPECT_NO_THROW(renderer->render(sc, soft, render::offscreen(96, 96)));
    EXPECT_NO_THROW(gl::check_errors("after the soft frames"));
}

}  // namespace
