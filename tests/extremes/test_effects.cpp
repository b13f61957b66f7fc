// The shadows seen in the mirror and through the portal (--effects mirror, portal) against the
// ray-traced truth of the same frame (measure/effect_truth.h): the visibility AOV shows the
// surface seen in the mirror or through the opening, the truth traces the mirrored scene and the
// other scene; scored in the effects' own pixels and over the frame.
#include "gl_fixture.h"

#include <cstdio>

#include "measure/effect_truth.h"
#include "measure/metrics.h"
#include "plan/options.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

constexpr int kSize = 256;

// The course scene at t (the light and the jump both at t), as penumbra render draws it.
scene::Scene course_at(double t) {
    scene::CourseScene c = scene::make_course_scene();
    scene::animate_course(c, t, t);
    return c.scene;
}

struct Scored {
    measure::Score frame, region;
    std::size_t mirror_pixels = 0, opening_pixels = 0, not_modelled = 0;
};

class EffectsTruth : public test::GlTest {
protected:
    Scored score(double t, const char* technique, const char* effects) {
        const scene::Scene sc = course_at(t);
        render::Settings s;
        EXPECT_EQ(render::parse_option(s, "technique", technique), "");
        EXPECT_EQ(render::parse_option(s, "effects", effects), "");
        s.aov = render::Aov::Visibility;
        const render::FrameInputs in = render::offscreen(kSize, kSize);
        renderer->render(sc, s, in);
        const auto rgba = renderer->read_image();
        gl::check_errors("the effects' visibility frame");
        std::vector<std::uint8_t> v(rgba.size() / 4);
        for (size_t i = 0; i < v.size(); ++i) v[i] = rgba[i * 4];

        const std::string e = effects;
        measure::TruthOptions to;
        to.width = to.height = kSize;
        // The scene camera's (volumes move the far plane to infinity: the same pixels, no depth range).
        to.view_proj = render::camera_view(sc, in).view_proj;
        const measure::EffectTruth truth =
            measure::trace_effects(sc, e.find("mirror") != std::string::npos, e.find("portal") != std::string::npos, to);
        const auto valid = truth.image.valid_mask();
        std::vector<std::uint8_t> in_region(valid.size());
        for (size_t i = 0; i < valid.size(); ++i) in_region[i] = valid[i] && truth.region[i];
        Scored out;
        out.frame = measure::score(v, truth.image.lit, valid);
        out.region = measure::score(v, truth.image.lit, in_region);
        out.mirror_pixels = truth.mirror_pixels;
        out.opening_pixels = truth.opening_pixels;
        out.not_modelled = truth.image.count(measure::PixelClass::NotModelled);
        std::printf("course@%.2f %dx%d %-10s --effects %-14s frame error %.3f %% (%zu px), in the effects' pixels %.3f %% "
                    "(%zu px; mirror %zu, opening %zu, not modelled %zu)\n",
                    t, kSize, kSize, technique, effects, out.frame.error_pct, out.frame.valid, out.region.error_pct,
                    out.region.valid, out.mirror_pixels, out.opening_pixels, out.not_modelled);
        return out;
    }
};

TEST_F(EffectsTruth, TheMirrorsShadowsMatchTheMirroredScenesTruth) {
    for (double t : {0.0, 0.6}) {
        const Scored r = score(t, "shadowmap", "mirror");
        // Most of the mirror shows the background, and most of the reflected teapot its underside,
        // which faces away from the light: the rest is lit or in the teapot's own shadow.
        EXPECT_GT(r.mirror_pixels, 20000u);
        EXPECT_GT(r.region.valid, 300u);
        EXPECT_GT(r.region.truth_shadowed, 15u) << "the reflection shows shadows";
        EXPECT_LT(r.region.error_pct, 1.0);
        EXPECT_LT(r.frame.error_pct, 1.0);
    }
}

TEST_F(EffectsTruth, ThePortalsShadowsMatchTheOtherScenesTruth) {
    for (double t : {0.0, 0.6}) {
        const Scored r = score(t, "shadowmap", "portal");
        EXPECT_GT(r.opening_pixels, 2000u);
        EXPECT_GT(r.region.valid, 1000u);
        EXPECT_GT(r.region.truth_shadowed, 50u) << "the other scene's shadows are in view";
        EXPECT_LT(r.region.error_pct, 1.5);
        EXPECT_LT(r.frame.error_pct, 1.0);
    }
}

TEST_F(EffectsTruth, BothTogetherLeaveOutOnlyWhatTheMirrorDoesNotReflect) {
    const Scored r = score(0.6, "shadowmap", "mirror,portal");
    EXPECT_GT(r.mirror_pixels, 20000u);
    EXPECT_GT(r.opening_pixels, 2000u);
    EXPECT_LT(r.region.error_pct, 1.5);
    // The portal's reflection (about 12 % of the mirror's pixels at t 0.6) is left out, nothing more.
    EXPECT_GT(r.not_modelled, 0u);
    EXPECT_LT(r.not_modelled, r.mirror_pixels / 5);
}

// Shadow volumes are made for the camera's pixels: the reflection is lit without them (documented),
// so the mirror's pixels miss every reflected shadow, and the truth says so.
TEST_F(EffectsTruth, TheVolumesUnshadowedReflectionIsMeasuredAsSuch) {
    const Scored r = score(0.6, "volumes", "mirror");
    EXPECT_GT(r.region.valid, 300u);
    EXPECT_GT(r.region.false_lit_pct, 1.0);
    EXPECT_LT(r.region.false_shadow_pct, 0.5);
}

}  // namespace
