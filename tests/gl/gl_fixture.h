// Shared by the GL tests: one headless EGL context per test process, a renderer on it, and
// image comparison that writes actual and diff PNGs when a golden does not match.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "gl/caps.h"
#include "gl/check.h"
#include "platform/platform.h"
#include "measure/image_compare.h"
#include "measure/image_io.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "../test_paths.h"

namespace penumbra::test {

// Makes the context current once per process (tests in one process share it).
platform::Platform& context();

struct GlTest : ::testing::Test {
    void SetUp() override {
        context();
        renderer = std::make_unique<render::Renderer>(gl::probe_caps(context()));
    }
    void TearDown() override {
        renderer.reset();
        gl::check_errors("test teardown");
    }
    // One frame of `scene` with `s` (its aov the visibility's), size x size, from the scene's
    // camera or `view`: the image's red channel, top row first; the plan into `plan_out`.
    std::vector<std::uint8_t> visibility_frame(const scene::Scene& scene, const render::Settings& s, int size,
                                               const glm::mat4* view = nullptr, render::FramePlan* plan_out = nullptr);
    std::unique_ptr<render::Renderer> renderer;
};

// An object of the test scenes: `mesh` at `world`, material 0, casting and receiving shadows.
inline scene::Object object(const char* name, int mesh, const glm::mat4& world) {
    scene::Object o;
    o.name = name;
    o.mesh = mesh;
    o.material = 0;
    o.world = world;
    return o;
}

// Every technique, and the settings that plan their passes differently (PCSS, r8 light samples
// over the shadow map, volumes and planar, Gooch's planes and texture, z-fail volumes shown), each
// with a name: what the effects' tests walk.
std::vector<std::pair<std::string, render::Settings>> every_technique_case();

// Compares `actual` with tests/golden/NAME.png by measure::compare_images (what any conformant
// implementation may do differently passes: measure/image_compare.h names the rules). On a
// mismatch (or a missing golden) writes NAME.actual.png and NAME.diff.png (grey: off but within
// one pixel of the golden's colour; white: unexplained) under build/test-output/golden and fails
// with the figures and their paths.
void expect_matches_golden(const std::string& name, const measure::Pixels& actual,
                           const measure::CompareRules& rules = {});

}  // namespace penumbra::test
