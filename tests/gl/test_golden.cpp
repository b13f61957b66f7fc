// Golden images of the course scene at a fixed t for each encoding x filter (and the planar and
// no-shadow techniques), and for the stencil effects (outline, mirror, portal) over the shadow map
// and shadow volumes. The goldens were approved by looking at them (tools/approve_goldens.sh).
#include "gl_fixture.h"

#include "scene/scene_source.h"

using namespace penumbra;

namespace {

struct Case {
    const char* name;
    render::Technique technique;
    shadow::Encoding encoding;
    shadow::Filter filter;
    render::Aov aov;
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }

// Names the case in test listings instead of its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// llvmpipe is deterministic for one build and machine; the thresholds leave room for a
// different CPU's rounding on a few edge pixels, not for a shadow that moved.
constexpr int kMaxThreshold = 96;
constexpr double kMeanThreshold = 0.5;

class Golden : public test::GlTest, public ::testing::WithParamInterface<Case> {};

// The course scene at t = 0.6 s, 256x256, with settings s, against tests/golden/NAME.png.
void expect_course_golden(render::Renderer& renderer, const char* name, const render::Settings& s) {
    constexpr double kTime = 0.6;
    constexpr int kSize = 256;
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(src.open("teapot", error, warnings)) << error;
    const render::FrameInputs in = render::offscreen(kSize, kSize);
    ASSERT_EQ(renderer.check(src.at(kTime), s, in), "");
    renderer.render(src.at(kTime), s, in);
    const int channels = s.aov == render::Aov::Color ? 3 : 1;
    test::expect_matches_golden(name, measure::from_rgba(renderer.read_image(), kSize, kSize, channels),
                                kMaxThreshold, kMeanThreshold);
}

TEST_P(Golden, CourseSceneMatches) {
    const Case c = GetParam();
    render::Settings s;
    s.map_size = 512;
    s.technique = c.technique;
    s.encoding = c.encoding;
    s.filter = c.filter;
    s.aov = c.aov;
    expect_course_golden(*renderer, c.name, s);
}

struct EffectCase {
    const char* name;
    render::Technique technique;
    std::vector<render::Effect> effects;
};

void PrintTo(const EffectCase& c, std::ostream* os) { *os << c.name; }
std::string effect_case_name(const ::testing::TestParamInfo<EffectCase>& info) { return info.param.name; }

class GoldenEffects : public test::GlTest, public ::testing::WithParamInterface<EffectCase> {};

TEST_P(GoldenEffects, CourseSceneMatches) {
    const EffectCase& c = GetParam();
    render::Settings s;
    s.map_size = 512;
    s.technique = c.technique;
    s.effects = c.effects;
    expect_course_golden(*renderer, c.name, s);
}

using E = shadow::Encoding;
using F = shadow::Filter;
using T = render::Technique;
using A = render::Aov;

INSTANTIATE_TEST_SUITE_P(
    Course, Golden,
    ::testing::Values(Case{"r8_hard", T::ShadowMap, E::R8, F::Hard, A::Color},
                      Case{"r8_pcf2x2", T::ShadowMap, E::R8, F::PCF2x2, A::Color},
                      Case{"r8_pcf4x4", T::ShadowMap, E::R8, F::PCF4x4, A::Color},
                      Case{"rgba_hard", T::ShadowMap, E::RGBA, F::Hard, A::Color},
                      Case{"rgba_pcf2x2", T::ShadowMap, E::RGBA, F::PCF2x2, A::Color},
                      Case{"rgba_pcf4x4", T::ShadowMap, E::RGBA, F::PCF4x4, A::Color},
                      Case{"depthtex_hard", T::ShadowMap, E::DepthTex, F::Hard, A::Color},
                      Case{"depthtex_pcf2x2", T::ShadowMap, E::DepthTex, F::PCF2x2, A::Color},
                      Case{"depthtex_pcf4x4", T::ShadowMap, E::DepthTex, F::PCF4x4, A::Color},
                      Case{"planar", T::Planar, E::RGBA, F::Hard, A::Color},
                      Case{"none", T::None, E::RGBA, F::Hard, A::Color},
                      Case{"rgba_hard_visibility", T::ShadowMap, E::RGBA, F::Hard, A::Visibility},
                      Case{"planar_visibility", T::Planar, E::RGBA, F::Hard, A::Visibility},
                      Case{"rgba_light_depth", T::ShadowMap, E::RGBA, F::Hard, A::LightDepth}),
    case_name);

using X = render::Effect;

INSTANTIATE_TEST_SUITE_P(
    Course, GoldenEffects,
    ::testing::Values(EffectCase{"outline", T::ShadowMap, {X::Outline}}, EffectCase{"mirror", T::ShadowMap, {X::Mirror}},
                      EffectCase{"portal", T::ShadowMap, {X::Portal}},
                      EffectCase{"volumes_outline_mirror_portal", T::Volumes, {X::Outline, X::Mirror, X::Portal}}),
    effect_case_name);

}  // namespace
