// The mirror's truth (measure/effect_truth.h) on a sphere over a mirror: the mirrored scene keeps
// its faces' fronts outward after the reflection turned them, the light is reflected, the ground
// left out; through the camera, the mirror's pixels see the sphere's reflection where geometry
// puts it, and the rest of the frame is the plain truth.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "measure/effect_truth.h"
#include "scene/primitives.h"

using namespace penumbra;
using measure::PixelClass;

namespace {

constexpr int kSize = 160;

scene::Scene sphere_over_mirror() {
    scene::Scene s;
    s.meshes = {scene::make_quad(10.0f), scene::make_sphere(1.0f, 48, 24)};
    s.materials.resize(1);
    scene::Object ground;
    ground.name = "mirror";
    ground.mesh = 0;
    scene::Object ball;
    ball.name = "sphere";
    ball.mesh = 1;
    ball.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 0.0f));
    s.objects = {ground, ball};
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = 0;
    s.light.type = scene::LightType::Point;
    s.light.position = glm::vec3(3.0f, 6.0f, 1.0f);
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 3.0f, 8.0f), glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(50.0f);
    s.camera.znear = 0.5f;
    s.camera.zfar = 40.0f;
    return s;
}

measure::TruthOptions options(const scene::Scene& s) {
    measure::TruthOptions o;
    o.width = o.height = kSize;
    o.view_proj = glm::perspective(s.camera.yfov, 1.0f, s.camera.znear, s.camera.zfar) * s.camera.view;
    return o;
}

TEST(EffectTruth, TheMirroredSceneTurnsTheWindingAndReflectsTheLight) {
    const scene::Scene s = sphere_over_mirror();
    const scene::Scene m = measure::mirrored_scene(s);
    ASSERT_EQ(m.objects.size(), 1u);  // the ground left out
    const scene::Object& o = m.objects[0];
    const glm::vec3 centre(o.world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_NEAR(centre.y, -2.0f, 1e-5f);
    EXPECT_NEAR(m.light.position.y, -6.0f, 1e-5f);
    EXPECT_NEAR(m.light.position.x, 3.0f, 1e-5f);
    // Every triangle's counter-clockwise normal, in the world, points away from the centre.
    const scene::Mesh& mesh = m.meshes[static_cast<size_t>(o.mesh)];
    int inward = 0, outward = 0;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) p[k] = glm::vec3(o.world * glm::vec4(mesh.positions[mesh.indices[t + static_cast<size_t>(k)]], 1.0f));
        const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        if (glm::length(n) < 1e-9f) continue;
        (glm::dot(n, (p[0] + p[1] + p[2]) / 3.0f - centre) > 0.0f ? outward : inward) += 1;
    }
    EXPECT_EQ(inward, 0);
    EXPECT_GT(outward, 1000);
}

TEST(EffectTruth, TheMirrorsPixelsSeeTheSpheresReflection) {
    const scene::Scene s = sphere_over_mirror();
    const measure::TruthOptions o = options(s);
    const measure::TruthImage plain = measure::RayTracer(s).render(o);
    const measure::EffectTruth t = measure::trace_effects(s, true, false, o);
    EXPECT_EQ(t.opening_pixels, 0u);
    size_t ground = 0, reflected = 0, changed_outside = 0;
    for (size_t i = 0; i < plain.lit.size(); ++i) {
        if (plain.object[i] == 0) {
            ++ground;
            EXPECT_EQ(t.region[i], 1);
            if (t.image.pixel_class[i] == static_cast<std::uint8_t>(PixelClass::Background) ||
                t.image.pixel_class[i] == static_cast<std::uint8_t>(PixelClass::Silhouette))
                continue;
            // A surface seen in the mirror: on the reflected sphere, below the mirror.
            ++reflected;
            EXPECT_NEAR(glm::length(t.image.position[i] - glm::vec3(0.0f, -2.0f, 0.0f)), 1.0f, 0.01f);  // a tessellated sphere
        } else {
            EXPECT_EQ(t.region[i], 0);
            changed_outside += t.image.pixel_class[i] != plain.pixel_class[i] || t.image.lit[i] != plain.lit[i];
        }
    }
    EXPECT_EQ(t.mirror_pixels, ground);
    EXPECT_GT(reflected, 300u);
    EXPECT_EQ(changed_outside, 0u);
    // The reflected sphere is lit on the light's side and dark away from it, as the sphere is.
    EXPECT_GT(t.image.count(PixelClass::Valid), 0u);
    EXPECT_GT(t.image.count(PixelClass::FacingAway), plain.count(PixelClass::FacingAway));
}

TEST(EffectTruth, AnEffectWithNothingToWorkOnIsRefused) {
    scene::Scene s = sphere_over_mirror();
    const measure::TruthOptions o = options(s);
    EXPECT_THROW(measure::trace_effects(s, false, true, o), std::invalid_argument);  // no portal
    s.ground_plane.reset();
    EXPECT_THROW(measure::trace_effects(s, true, false, o), std::invalid_argument);
}

}  // namespace
