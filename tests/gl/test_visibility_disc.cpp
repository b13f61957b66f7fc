// The visibility AOV against an analytic answer: a sphere of radius r floating above a plane,
// lit by a directional light straight down, shadows exactly the disc of radius r below it.
// Every plane pixel (found by casting the pixel's ray on the CPU) must agree on >= 99% of them.
#include "gl_fixture.h"
#include "plan/options.h"

#include "scenes/probe_scenes.h"

using namespace penumbra;

namespace {

constexpr float kRadius = 1.0f;
constexpr float kHeight = 2.0f;
constexpr float kPlane = 10.0f;

// scene::make_sphere_over_plane: radius 1 at height 2 over a 10 x 10 ground, light straight down.
scene::Scene sphere_over_plane() { return scene::make_sphere_over_plane(); }

struct Tally {
    int plane_pixels = 0;
    int agree = 0;
    int shadow_expected = 0;
};

Tally score(const scene::Scene& s, const glm::mat4& view_proj, const std::vector<std::uint8_t>& rgba, int w, int h) {
    const glm::mat4 inv = glm::inverse(view_proj);
    const glm::vec3 centre(0.0f, kHeight, 0.0f);
    Tally t;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Pixel centre in NDC; images are top row first.
            const float nx = (static_cast<float>(x) + 0.5f) / static_cast<float>(w) * 2.0f - 1.0f;
            const float ny = 1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(h) * 2.0f;
            glm::vec4 a = inv * glm::vec4(nx, ny, -1.0f, 1.0f);
            glm::vec4 b = inv * glm::vec4(nx, ny, 0.0f, 1.0f);  // not the far plane: it may be at infinity
            const glm::vec3 o = glm::vec3(a) / a.w;
            const glm::vec3 d = glm::normalize(glm::vec3(b) / b.w - o);
            // Hidden behind the sphere? Then it is not a plane pixel.
            const glm::vec3 oc = o - centre;
            const float bq = glm::dot(oc, d);
            const float disc = bq * bq - (glm::dot(oc, oc) - kRadius * kRadius);
            if (disc >= 0.0f) continue;
            if (d.y >= 0.0f) continue;
            const float tp = -o.y / d.y;
            const glm::vec3 p = o + tp * d;
            if (std::fabs(p.x) > kPlane * 0.5f || std::fabs(p.z) > kPlane * 0.5f) continue;
            const bool shadowed = p.x * p.x + p.z * p.z < kRadius * kRadius;
            const std::uint8_t v = rgba[(static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * 4];
            ++t.plane_pixels;
            t.shadow_expected += shadowed;
            t.agree += shadowed == (v < 128);
        }
    (void)s;
    return t;
}

struct DiscCase {
    render::Technique technique;
    shadow::Encoding encoding;
    shadow::Filter filter;
    render::VolumeMethod method = render::VolumeMethod::Auto;  // technique volumes
};

void PrintTo(const DiscCase& c, std::ostream* os) {
    *os << render::to_string(c.technique) << "/" << shadow::to_string(c.encoding) << "/" << shadow::to_string(c.filter);
}

class VisibilityDisc : public test::GlTest, public ::testing::WithParamInterface<DiscCase> {};

TEST_P(VisibilityDisc, MatchesTheAnalyticDisc) {
    const auto c = GetParam();
    const scene::Scene s = sphere_over_plane();
    constexpr int kSize = 256;
    render::Settings set;
    set.map_size = 1024;
    set.technique = c.technique;
    set.encoding = c.encoding;
    set.filter = c.filter;
    set.volume_method = c.method;
    set.aov = render::Aov::Visibility;
    const render::FrameInputs in = render::offscreen(kSize, kSize);
    ASSERT_EQ(renderer->check(s, set, in), "");
    const render::FramePlan& plan = renderer->render(s, set, in);
    const Tally t = score(s, plan.camera.view_proj, renderer->read_image(), kSize, kSize);
    ASSERT_GT(t.plane_pixels, kSize * kSize / 3) << "the plane should fill much of the view";
    ASSERT_GT(t.shadow_expected, 500) << "the disc should cover a real area";
    const double rate = static_cast<double>(t.agree) / t.plane_pixels;
    EXPECT_GE(rate, 0.99) << render::to_args(set) << ": " << t.agree << " of " << t.plane_pixels
                          << " plane pixels agree with the analytic disc";
}

using E = shadow::Encoding;
using F = shadow::Filter;
using T = render::Technique;
using M = render::VolumeMethod;
INSTANTIATE_TEST_SUITE_P(
    All, VisibilityDisc,
    ::testing::Values(DiscCase{T::ShadowMap, E::R8, F::Hard}, DiscCase{T::ShadowMap, E::R8, F::PCF4x4},
                      DiscCase{T::ShadowMap, E::RGBA, F::Hard}, DiscCase{T::ShadowMap, E::RGBA, F::PCF2x2},
                      DiscCase{T::ShadowMap, E::RGBA, F::PCF4x4}, DiscCase{T::ShadowMap, E::DepthTex, F::Hard},
                      DiscCase{T::ShadowMap, E::DepthTex, F::PCF4x4}, DiscCase{T::Planar, E::RGBA, F::Hard},
                      DiscCase{T::Volumes, E::RGBA, F::Hard, M::Auto}, DiscCase{T::Volumes, E::RGBA, F::Hard, M::ZPass},
                      DiscCase{T::Volumes, E::RGBA, F::Hard, M::ZFail}),
    [](const ::testing::TestParamInfo<DiscCase>& i) {
        if (i.param.technique == T::Volumes)
            return std::string("volumes_") + std::string(render::to_string(i.param.method));
        return std::string(render::to_string(i.param.technique)) + "_" +
               std::string(shadow::to_string(i.param.encoding)) + "_" + std::string(shadow::to_string(i.param.filter));
    });

// The check must be able to fail: with no shadows at all, the disc is missed.
class VisibilityDiscControl : public test::GlTest {};

TEST_F(VisibilityDiscControl, FailsWithoutShadows) {
    const scene::Scene s = sphere_over_plane();
    render::Settings set;
    set.technique = render::Technique::None;
    set.aov = render::Aov::Visibility;
    const render::FramePlan& plan = renderer->render(s, set, render::offscreen(256, 256));
    const Tally t = score(s, plan.camera.view_proj, renderer->read_image(), 256, 256);
    EXPECT_LT(static_cast<double>(t.agree) / t.plane_pixels, 0.99);
}

}  // namespace
