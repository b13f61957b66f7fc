// Gooch's soft shadow (seed 001): the offset planes' matrices, their offsets and spread, the
// averaging weights. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include <glm/glm.hpp>

#include "shadow/gooch.h"
#include "shadow/planar.h"

using namespace penumbra::shadow;

namespace {

const glm::vec4 kGround(0.0f, 1.0f, 0.0f, 0.0f);
const glm::vec4 kPoint(1.0f, 6.0f, 0.5f, 1.0f);
const glm::vec4 kSun(glm::normalize(glm::vec3(0.5f, 1.0f, 0.3f)), 0.0f);  // towards the light

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 s = m * glm::vec4(p, 1.0f);
    EXPECT_GT(s.w, 0.0f);
    return glm::vec3(s) / s.w;
}

}  // namespace

TEST(Gooch, OffsetZeroIsExactlyThePlanarProjection) {
    for (const glm::vec4& light : {kPoint, kSun}) {
        const glm::mat4 g = gooch_projection(kGround, light, 0.0f);
        const glm::mat4 p = planar_projection(kGround, light);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_EQ(g[c][r], p[c][r]);
    }
}

TEST(Gooch, RadiusZeroGivesNoSpreadAndOnlyThePlanarProjection) {
    const glm::vec3 caster(0.3f, 1.0f, -0.2f);
    EXPECT_EQ(gooch_spread(kGround, kPoint, 0.0f, caster), 0.0f);
    EXPECT_EQ(gooch_spread(kGround, kSun, 0.0f, caster), 0.0f);
    for (float o : gooch_offsets(8, 0.0f)) {
        EXPECT_EQ(o, 0.0f);
        const glm::mat4 g = gooch_projection(kGround, kPoint, o);
        EXPECT_EQ(g, planar_projection(kGround, kPoint));
    }
}

TEST(Gooch, OffsetsAreSymmetricAndSpanTheSpread) {
    EXPECT_EQ(gooch_offsets(1, 0.7f), std::vector<float>{0.0f});
    for (int k = 2; k <= 16; ++k) {
        const std::vector<float> o = gooch_offsets(k, 0.7f);
        ASSERT_EQ(o.size(), static_cast<size_t>(k));
        EXPECT_FLOAT_EQ(o.front(), -0.7f);
        EXPECT_FLOAT_EQ(o.back(), 0.7f);
        for (int i = 0; i < k; ++i) {
            EXPECT_EQ(o[static_cast<size_t>(i)], -o[static_cast<size_t>(k - 1 - i)]) << k << " " << i;
            if (i) {
                EXPECT_GT(o[static_cast<size_t>(i)], o[static_cast<size_t>(i - 1)]);
            }
        }
    }
}

TEST(Gooch, EveryProjectionEndsOnTheGround) {
    const std::vector<glm::vec3> points = {{0.2f, 1.0f, 0.1f}, {-1.0f, 2.5f, 0.7f}, {0.8f, 0.3f, -1.2f}};
    for (const glm::vec4& light : {kPoint, kSun})
        for (float o : {-0.8f, -0.3f, 0.3f, 0.8f})
            for (const glm::vec3& p : points) EXPECT_NEAR(apply(gooch_projection(kGround, light, o), p).y, 0.0f, 1e-5f);
}

// A point of the ground maps to itself under offset 0, and under every offset where the light's
// ray is the ground's normal (the foot of a point light); elsewhere Gooch's planes slide it by
// o tan t along the light's tilt (the contact shadow moves: the method's penumbra is too big).
TEST(Gooch, GroundPointsMapToThemselvesWhereTheRayIsVertical) {
    const glm::vec3 foot(kPoint.x, 0.0f, kPoint.z);
    for (float o : {-0.8f, 0.0f, 0.8f}) {
        const glm::vec3 f = apply(gooch_projection(kGround, kPoint, o), foot);
        EXPECT_NEAR(glm::distance(f, foot), 0.0f, 1e-5f) << o;
    }
    const glm::vec3 g(-0.5f, 0.0f, 1.5f);
    EXPECT_NEAR(glm::distance(apply(gooch_projection(kGround, kPoint, 0.0f), g), g), 0.0f, 1e-5f);
    // A sun: every point moves by o tan t, the same for all (a translation of the shadow).
    const glm::vec3 lateral(kSun.x, 0.0f, kSun.z);
    const float tan_t = glm::length(lateral) / kSun.y;
    const glm::vec3 moved = apply(gooch_projection(kGround, kSun, 0.5f), g);
    EXPECT_NEAR(glm::distance(moved, g), 0.5f * tan_t, 1e-5f);
    // towards the light's foot for a plane raised towards the light
    EXPECT_GT(glm::dot(moved - g, lateral), 0.0f);
}

// The outermost plane moves the shadow of the casters' centre by the half-width of the penumbra a
// light of that radius throws from the centre's height.
TEST(Gooch, SpreadMatchesTheLightsPenumbraAtTheCaster) {
    const float radius = 0.3f;
    const glm::vec3 caster(-1.5f, 1.2f, 0.5f);  // tilt = 2.5 / 4.8 > kGoochMinTilt
    const float s = gooch_spread(kGround, kPoint, radius, caster);
    ASSERT_GT(s, 0.0f);
    const glm::vec3 centre = apply(planar_projection(kGround, kPoint), caster);
    const glm::vec3 outer = apply(gooch_projection(kGround, kPoint, s), caster);
    const float H = kPoint.y, h = caster.y;
    EXPECT_NEAR(glm::distance(centre, outer), radius * h / (H - h), 1e-4f);
    const glm::vec3 inner = apply(gooch_projection(kGround, kPoint, -s), caster);
    EXPECT_NEAR(glm::distance(centre, inner), radius * h / (H - h), 1e-4f);

    const float angle = 0.05f;
    const float ss = gooch_spread(kGround, kSun, angle, caster);
    const glm::vec3 sc = apply(planar_projection(kGround, kSun), caster);
    EXPECT_NEAR(glm::distance(sc, apply(gooch_projection(kGround, kSun, ss), caster)), h * std::tan(angle), 1e-4f);
    // Straight under the light: the tilt is floored, the planes stay under the light.
    const float under = gooch_spread(kGround, kPoint, radius, glm::vec3(kPoint.x, 1.0f, kPoint.z));
    EXPECT_GT(under, 0.0f);
    EXPECT_LE(under, 0.5f * H);
    // A caster under the ground or over the light: nothing to spread.
    EXPECT_EQ(gooch_spread(kGround, kPoint, radius, glm::vec3(0.0f, -1.0f, 0.0f)), 0.0f);
    EXPECT_EQ(gooch_spread(kGround, kPoint, radius, glm::vec3(0.0f, 7.0f, 0.0f)), 0.0f);
}

TEST(Gooch, WeightsAreWholeBytesSummingTo255) {
    for (int k = 1; k <= 16; ++k) {
        const std::vector<int> w = gooch_weight_bytes(k);
        ASSERT_EQ(w.size(), static_cast<size_t>(k));
        EXPECT_EQ(std::accumulate(w.begin(), w.end(), 0), 255) << k;
        for (int b : w) EXPECT_LE(std::abs(b * k - 255), k) << k;
    }
}

TEST(Gooch, DiscTapsLieInTheUnitDisc) {
    EXPECT_EQ(gooch_disc(1), std::vector<glm::vec2>{glm::vec2(0.0f)});
    for (int k = 2; k <= 16; ++k) {
        const auto d = gooch_disc(k);
        ASSERT_EQ(d.size(), static_cast<size_t>(k));
        for (const glm::vec2& p : d) EXPECT_LE(glm::length(p), 1.0f);
    }
}
