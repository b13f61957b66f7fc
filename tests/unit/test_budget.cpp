// --budget-ms (issue 56): the controller against synthetic frame times, a frame's cost a function
// of the map size (and of the frame, where the scene changes). No GL: the controller sees only
// the times it is handed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "plan/budget.h"
#include "plan/options.h"
#include "plan/techniques/technique.h"

using namespace penumbra;
using render::BudgetController;

namespace {

// A frame's time: a fixed part and a part that grows with the map's texels, as on llvmpipe
// (the clear and the fill of the map).
double llvmpipe_like(int size) { return 4.0 + 4.0 * (size / 1024.0) * (size / 1024.0); }
// A GPU: the map's size hardly shows; the bench's llvmpipe model overrates its cost.
double gpu_like(int size) { return 2.0 + 0.1 * size / 1024.0; }

struct Frames {
    std::vector<int> sizes;  // the map of each frame
    std::vector<double> ms;
    int changes = 0;
};

Frames run(BudgetController& b, int frames, const std::function<double(int size, int frame)>& cost) {
    Frames r;
    for (int i = 0; i < frames; ++i) {
        const int size = b.settings().technique == render::Technique::Volumes ? BudgetController::kVolumes : b.settings().map_size;
        const double ms = cost(size, i);
        r.sizes.push_back(size);
        r.ms.push_back(ms);
        r.changes += b.observe(ms) ? 1 : 0;
    }
    return r;
}

double median_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

BudgetController controller(double budget, bool depth_texture = true, int largest = 4096) {
    return BudgetController(budget, render::Settings{}, depth_texture, largest);
}

TEST(Budget, SettlesOnTheLargestMapThatFits) {
    // Costs: 128 4.06, 256 4.25, 512 5, 1024 8, 2048 20, 4096 68 ms.
    for (const auto& bw : std::vector<std::pair<double, int>>{{6.0, 512}, {10.0, 1024}, {22.0, 2048}, {80.0, 4096}}) {
        const double budget = bw.first;
        const int want = bw.second;  // a plain variable: C++17 lambdas cannot capture a structured binding
        BudgetController b = controller(budget);
        const Frames r = run(b, 300, [](int size, int) { return llvmpipe_like(size); });
        EXPECT_EQ(b.settings().map_size, want) << "budget " << budget << ": " << b.why();
        // The last 200 frames: the median within the budget, and no change.
        const std::vector<double> tail(r.ms.end() - 200, r.ms.end());
        EXPECT_LE(median_of(tail), budget * 1.1) << budget;
        EXPECT_TRUE(std::all_of(r.sizes.end() - 200, r.sizes.end(), [&](int s) { return s == want; })) << budget;
    }
}

TEST(Budget, ALargerBudgetIsNeverASmallerMap) {
    int last = 0;
    for (double budget = 3.0; budget <= 100.0; budget *= 1.15) {
        BudgetController b = controller(budget);
        run(b, 400, [](int size, int) { return llvmpipe_like(size); });
        EXPECT_GE(b.settings().map_size, last) << "budget " << budget;
        last = b.settings().map_size;
    }
    EXPECT_EQ(last, 4096);
}

TEST(Budget, DoesNotFlickerAtTheEdgeOfABudget) {
    // 1024 takes 8 ms give or take 4 %, frame by frame; the budget is 8: 1024 is over the budget on
    // some frames and 2048 never fits. At most one change down once it settles, no return.
    BudgetController b = controller(8.0);
    const Frames r = run(b, 1000, [](int size, int frame) { return llvmpipe_like(size) * (frame % 2 ? 1.04 : 0.96); });
    int changes_late = 0;
    for (size_t i = 201; i < r.sizes.size(); ++i) changes_late += r.sizes[i] != r.sizes[i - 1] ? 1 : 0;
    EXPECT_LE(changes_late, 1) << b.why();
    EXPECT_LE(r.changes, 8);
}

TEST(Budget, AStallOfAFewFramesDoesNotMoveIt) {
    // The machine stalls now and then: 4 frames in a row at 1.8x, every 40 frames (as llvmpipe on
    // 2 cores does: docs/budget.md). 1024 takes 8 ms and fits 10; the stalls are under half the
    // window, so it stays.
    BudgetController b = controller(10.0);
    const auto stall = [](int frame) { return frame % 40 >= 36 ? 1.8 : 1.0; };
    const Frames r = run(b, 1200, [&](int size, int frame) { return llvmpipe_like(size) * stall(frame); });
    EXPECT_TRUE(std::all_of(r.sizes.end() - 800, r.sizes.end(), [](int s) { return s == 1024; })) << b.why();
}

TEST(Budget, ARungOverTheBudgetIsTriedAgainLessAndLessOften) {
    // The model (llvmpipe's ratios) says 2048 fits, the device says not: each retry is blocked
    // twice as long as the one before, so the frames over the budget are few.
    BudgetController b = controller(10.0);
    const auto cost = [](int size, int) { return size >= 2048 ? 30.0 : 3.0 + 0.5 * size / 1024.0; };
    const Frames r = run(b, 2000, cost);
    const long over = std::count_if(r.ms.begin(), r.ms.end(), [](double ms) { return ms > 10.0 * 1.05; });
    EXPECT_LT(over, 60) << b.why();
    EXPECT_EQ(b.settings().map_size, 1024);
}

TEST(Budget, MeasuresPastAPessimisticModel) {
    // On a GPU-like device every map fits 4 ms although llvmpipe's model says 4096 costs 3.4x 1024:
    // measured ratios replace the model's as the controller climbs.
    BudgetController b = controller(4.0);
    run(b, 400, [](int size, int) { return gpu_like(size); });
    EXPECT_EQ(b.settings().map_size, 4096) << b.why();
}

TEST(Budget, FollowsASceneThatGetsHeavier) {
    // From frame 300 every frame costs 2x (1024 takes 16 ms), from 600 3x (128 takes 12.2 ms).
    BudgetController b = controller(10.0);
    const auto factor = [](int frame) { return frame >= 600 ? 3.0 : frame >= 300 ? 2.0 : 1.0; };
    const Frames r = run(b, 900, [&](int size, int frame) { return llvmpipe_like(size) * factor(frame); });
    EXPECT_EQ(r.sizes[299], 1024);
    // 2x: a smaller map, the frames back within the budget a few frames after the change.
    EXPECT_LT(r.sizes[599], 1024);
    EXPECT_LE(median_of(std::vector<double>(r.ms.begin() + 320, r.ms.begin() + 600)), 10.0 * 1.1);
    // 3x: nothing fits; the smallest map, said so.
    EXPECT_EQ(b.settings().map_size, 128);
    EXPECT_NE(b.why().find("over the budget at the smallest map"), std::string::npos) << b.why();
}

TEST(Budget, StepsDownToTheLargestMapPredictedToFit) {
    // From frame 300 every frame costs 1.35x: 512 takes 6.75 ms, over 6; 256 takes 5.74 and fits
    // (predicted 5.59 by the model's ratio, never measured beside 512). Down to 256, not past it.
    BudgetController b = controller(6.0);
    const Frames r = run(b, 600, [](int size, int frame) { return llvmpipe_like(size) * (frame >= 300 ? 1.35 : 1.0); });
    EXPECT_EQ(r.sizes[299], 512);
    EXPECT_TRUE(std::none_of(r.sizes.begin() + 300, r.sizes.end(), [](int s) { return s < 256; })) << b.why();
    EXPECT_EQ(b.settings().map_size, 256) << b.why();
}

TEST(Budget, ShadowVolumesAreTheTopRungTriedPastAMapThatDidNotFit) {
    // Volumes take 9 ms here, a 2048 map 20: at 12 ms the volumes, at 6 a map (512 takes 5).
    const auto cost = [](int size, int) { return size == BudgetController::kVolumes ? 9.0 : llvmpipe_like(size); };
    BudgetController b(12.0, render::Settings{}, true, 4096, true);
    EXPECT_EQ(b.map_size(b.rungs() - 1), BudgetController::kVolumes);
    const Frames r = run(b, 400, cost);
    EXPECT_EQ(b.settings().technique, render::Technique::Volumes) << b.why();
    EXPECT_NE(b.why().find("shadow volumes"), std::string::npos) << b.why();
    EXPECT_LE(median_of(std::vector<double>(r.ms.end() - 200, r.ms.end())), 12.0 * 1.1);
    BudgetController small(6.0, render::Settings{}, true, 4096, true);
    run(small, 400, cost);
    EXPECT_EQ(small.settings().technique, render::Technique::ShadowMap) << small.why();
    EXPECT_EQ(small.settings().map_size, 512) << small.why();
    // Over the budget, back to the map they were tried from.
    BudgetController heavy(12.0, render::Settings{}, true, 4096, true);
    run(heavy, 400, [](int size, int) { return size == BudgetController::kVolumes ? 30.0 : llvmpipe_like(size); });
    EXPECT_EQ(heavy.settings().technique, render::Technique::ShadowMap) << heavy.why();
    EXPECT_EQ(heavy.settings().map_size, 1024) << heavy.why();
    // Volumes far dearer than the model says (40 ms where it predicts 18.5 from the 2048 map's 20):
    // tried once (5 frames: one skipped, four measured, each far over), then their measured ratio predicts 40,
    // past the probe's 1.5x, and keeps them out (the model's alone would try them a second time).
    BudgetController dear(22.0, render::Settings{}, true, 4096, true);
    const Frames d = run(dear, 3000, [](int size, int) { return size == BudgetController::kVolumes ? 40.0 : llvmpipe_like(size); });
    EXPECT_LE(std::count(d.ms.begin(), d.ms.end(), 40.0), 5) << dear.why();
    EXPECT_EQ(dear.settings().map_size, 2048) << dear.why();
    // Not with a soft filter (volumes have no penumbra), nor where the caller cannot draw them.
    render::Settings soft;
    soft.filter = shadow::Filter::PCSS;
    EXPECT_NE(BudgetController(12.0, soft, true, 4096, true).map_size(5), BudgetController::kVolumes);
    EXPECT_EQ(BudgetController(12.0, soft, true, 4096, true).rungs(), 6);
    EXPECT_EQ(BudgetController(12.0, render::Settings{}, true, 4096, false).rungs(), 6);
}

TEST(Budget, StaysWithinTheContextsLargestTarget) {
    BudgetController b = controller(1000.0, true, 2048);
    run(b, 300, [](int size, int) { return llvmpipe_like(size); });
    EXPECT_EQ(b.settings().map_size, 2048);
    EXPECT_EQ(b.rungs(), 5);  // 128 .. 2048
}

TEST(Budget, PicksTheEncodingAndFilterForAPointLightAndKeepsASoftOne) {
    render::Settings s;
    s.encoding = shadow::Encoding::R8;
    s.filter = shadow::Filter::PCF4x4;
    EXPECT_EQ(BudgetController(8.0, s, true, 4096).settings().encoding, shadow::Encoding::DepthTex);
    EXPECT_EQ(BudgetController(8.0, s, false, 4096).settings().encoding, shadow::Encoding::RGBA);
    EXPECT_EQ(BudgetController(8.0, s, true, 4096).settings().filter, shadow::Filter::Hard);
    s.filter = shadow::Filter::PCSS;
    EXPECT_EQ(BudgetController(8.0, s, true, 4096).settings().filter, shadow::Filter::PCSS);
}

TEST(Budget, RefusesATechniqueWithoutAMap) {
    render::Settings s;
    EXPECT_EQ(render::budget_refusal(s), "");
    s.technique = render::technique_named("volumes");
    EXPECT_NE(render::budget_refusal(s).find("--technique volumes has none"), std::string::npos) << render::budget_refusal(s);
}

TEST(Budget, TheOptionTakesMillisecondsAndZeroForOff) {
    render::Options o;
    EXPECT_EQ(render::parse_option(o, "budget-ms", "8"), "");
    EXPECT_DOUBLE_EQ(o.job.budget_ms, 8.0);
    EXPECT_NE(render::parse_option(o, "budget-ms", "-1"), "");
    EXPECT_NE(render::parse_option(o, "budget-ms", "fast"), "");
    EXPECT_EQ(render::parse_option(o, "budget-ms", "0"), "");
    EXPECT_DOUBLE_EQ(o.job.budget_ms, 0.0);
}

}  // namespace
