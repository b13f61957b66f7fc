// The shadows fit asks each caster which visible receivers it can shadow. ReceiverIndex answers
// through a hierarchy so that the cost grows with n log n, not n squared; these tests hold it to
// the pairwise rule (every caster asked of every receiver: ReceiverIndex's `linear`, the fit's
// CastingInfo::pairwise), answer for answer and bit for bit, on random boxes made to tie on their
// planes and on every scene file of the tests.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "plan/plan.h"
#include "scene/gltf_loader.h"
#include "scenes/course_scene.h"
#include "scenes/scale_scenes.h"
#include "shadow/light_frustum.h"
#include "shadow/receiver_index.h"
#include "../test_paths.h"

using namespace penumbra;

namespace {

bool same_bits(const glm::vec4& a, const glm::vec4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const glm::mat4& a, const glm::mat4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Coordinates on a grid of quarters, so that boxes, points and lights often share a plane: the
// ties where may_shadow's strict and non-strict comparisons decide.
float grid(std::mt19937& rng, int lo, int hi) { return static_cast<float>(std::uniform_int_distribution<int>(lo, hi)(rng)) / 4.0f; }
glm::vec3 grid3(std::mt19937& rng, int lo, int hi) { return {grid(rng, lo, hi), grid(rng, lo, hi), grid(rng, lo, hi)}; }

}  // namespace

TEST(ReceiverIndex, AnswersEveryCasterAsThePairwiseRuleDoes) {
    std::mt19937 rng(55);
    int shadowing = 0, shadowing_none = 0, cut = 0, kept_whole = 0;
    for (int round = 0; round < 12; ++round) {
        // Receivers: point sets around grid positions (some empty: nothing of them in view); the
        // objects numbered so that some casters are receivers too.
        std::vector<shadow::SeenReceiver> seen;
        for (int k = 0; k < 150; ++k) {
            shadow::SeenReceiver r;
            r.object = k;
            const glm::vec3 at = grid3(rng, -40, 40);
            if (k % 17 != 0)
                for (int p = 0; p < 4; ++p) r.points.push_back(at + grid3(rng, 0, 6));
            seen.push_back(std::move(r));
        }
        const glm::vec4 light = round % 3 == 0 ? glm::vec4(glm::normalize(grid3(rng, -8, 8) + glm::vec3(0, 0.01f, 0)), 0.0f)
                                               : glm::vec4(grid3(rng, -60, 60), 1.0f);
        const shadow::ReceiverIndex tree(seen, light), pairs(seen, light, true);
        shadow::ReceiverIndex tree_w(seen, light), pairs_w(seen, light, true);
        // An orthographic window: every point is in front, so each rect is taken.
        const glm::mat4 view = glm::lookAt(glm::vec3(0, 30, 20), glm::vec3(0), glm::vec3(0, 1, 0));
        ASSERT_TRUE(tree_w.set_window(view, false, 0.0f));
        ASSERT_TRUE(pairs_w.set_window(view, false, 0.0f));
        for (int k = 0; k < 300; ++k) {
            shadow::CasterBox caster;
            caster.object = round % 2 == 0 ? k : 1000 + k;
            const glm::vec3 at = grid3(rng, -40, 40);
            caster.bounds = scene::Bounds::around(at, at + grid3(rng, 0, k % 5 == 0 ? 40 : 8) * glm::vec3(1, k % 7 == 0 ? 0 : 1, 1));
            caster.convex = k % 3 != 0;
            const bool any = pairs.shadows_any(caster);
            ASSERT_EQ(tree.shadows_any(caster), any) << "round " << round << ", caster " << k;
            ++(any ? shadowing : shadowing_none);
            // The caster's own rect, somewhere in the window.
            const glm::vec2 c(grid(rng, -48, 40), grid(rng, -48, 40));
            const glm::vec4 own(c.x, c.x + grid(rng, 1, 24), c.y, c.y + grid(rng, 1, 24));
            glm::vec4 a = own, b = own;
            tree_w.cut_to_reach(caster, a);
            pairs_w.cut_to_reach(caster, b);
            ASSERT_TRUE(same_bits(a, b)) << "round " << round << ", caster " << k;
            ++(same_bits(a, own) ? kept_whole : cut);
        }
    }
    // Both answers come up often, or the comparison proves little.
    std::printf("%d casters shadow a receiver, %d none; %d rects cut, %d kept whole\n", shadowing, shadowing_none, cut,
                kept_whole);
    EXPECT_GT(shadowing, 500);
    EXPECT_GT(shadowing_none, 200);
    EXPECT_GT(cut, 500);
    EXPECT_GT(kept_whole, 200);
}

TEST(ReceiverIndex, TheSelfOfAConvexCasterIsNeverAReceiver) {
    // One receiver, the caster's own object: a convex caster shadows nothing, a concave one itself.
    std::vector<shadow::SeenReceiver> seen{{7, scene::corners(scene::Bounds::around({0, 0, 0}, {1, 1, 1}))}};
    const shadow::ReceiverIndex index(seen, glm::vec4(0.5f, 5.0f, 0.5f, 1.0f));
    shadow::CasterBox self{7, scene::Bounds::around({0, 0, 0}, {1, 1, 1}), true};
    EXPECT_FALSE(index.shadows_any(self));
    self.convex = false;
    EXPECT_TRUE(index.shadows_any(self)) << "control: the same box, not convex";
}

namespace {

// The fit and the flags both ways, bit for bit.
void expect_same_fits(const std::string& label, const scene::Scene& s) {
    for (const bool soft : {false, true}) {
        render::ShadowBounds b = render::shadow_bounds(s);
        b.casting.fit_window = !soft;
        const glm::mat4 vp = render::camera_view(s, render::FrameInputs{}).view_proj;
        const shadow::TightFit fast = shadow::fit_light_frustum_shadows(s.light, b.receivers, b.casters, vp, b.casting);
        b.casting.pairwise = true;
        const shadow::TightFit slow = shadow::fit_light_frustum_shadows(s.light, b.receivers, b.casters, vp, b.casting);
        SCOPED_TRACE(label + (soft ? " (soft)" : ""));
        EXPECT_TRUE(same_bits(fast.frustum.view, slow.frustum.view));
        EXPECT_TRUE(same_bits(fast.frustum.proj, slow.frustum.proj));
        EXPECT_EQ(fast.casters, slow.casters);
        EXPECT_EQ(fast.culled, slow.culled);
        EXPECT_EQ(fast.cut, slow.cut);
        EXPECT_EQ(fast.tight, slow.tight);
        EXPECT_EQ(std::memcmp(&fast.texel_use, &slow.texel_use, sizeof(float)), 0);
        const std::vector<char> flags_slow = shadow::shadowing_flags(s.light, b.receivers, b.casters, vp, b.casting);
        b.casting.pairwise = false;
        EXPECT_EQ(shadow::shadowing_flags(s.light, b.receivers, b.casters, vp, b.casting), flags_slow);
    }
}

}  // namespace

TEST(ReceiverIndex, FitsEverySceneFileAsThePairwiseRuleDoes) {
    scene::CourseScene course = scene::make_course_scene(4);
    for (const double t : {0.0, 0.3, 0.6, 1.1, 2.7}) {
        scene::animate_course(course, t, t);
        expect_same_fits("course at t = " + std::to_string(t), course.scene);
    }
    for (const char* file : {"bench_easy.gltf", "bench_medium.gltf", "bench_hard.gltf", "bench_curved.gltf",
                             "terrain_km.gltf", "bulb_room.gltf", "sphere_over_plane.gltf", "alpha_cutouts.gltf"}) {
        const scene::LoadResult r = scene::load_gltf(test::test_data_dir() + "/" + file);
        ASSERT_TRUE(r.ok) << file << ": " << r.error;
        expect_same_fits(file, r.scene);
    }
    // Many objects, each light type: the piled and the spread layouts.
    for (const char* name : {"pile:1500", "pile:1500:spot", "pile:1500:sun", "forest:1500", "forest:1500:spot",
                             "forest:1500:sun"}) {
        scene::ScaleSpec spec;
        std::string error;
        ASSERT_TRUE(scene::parse_scale_name(name, spec, error)) << error;
        expect_same_fits(name, scene::make_scale_scene(spec));
    }
}
