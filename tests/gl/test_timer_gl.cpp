// GPU time per pass (gl/timer.h) on the headless context: one non-negative time per pass that
// draws, named as the plan names it; some GPU time over several frames; the frames read back all
// there when the ring is full; nothing (and "not available", never numbers) on a context without
// EXT_disjoint_timer_query, simulated by the caps flag turned off. Behaviour only, never timings.
// llvmpipe has the extension; a context without it skips the tests that need it.
#include "gl_fixture.h"

#include <string>
#include <vector>

#include "gl/timer.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

class TimerGl : public test::GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (!renderer->caps().timer_query) GTEST_SKIP() << "no EXT_disjoint_timer_query on this context";
    }
    scene::CourseScene course = scene::make_course_scene(6);

    // The course scene at frame i (the light circling, so the map is redrawn every frame).
    const scene::Scene& frame(int i) {
        scene::animate_course(course, 0.6 + i / 60.0, 0.6 + i / 60.0);
        return course.scene;
    }
};

std::vector<std::string> drawn_passes(const render::FramePlan& plan) {
    std::vector<std::string> names;
    for (const render::Pass& p : plan.passes)
        if (!p.skipped) names.push_back(p.name);
    return names;
}

TEST_F(TimerGl, OneNonNegativeTimePerPassThatDraws) {
    gl::PassTimer& timer = renderer->gpu_timer();
    ASSERT_TRUE(timer.available());
    EXPECT_FALSE(timer.enabled());  // off until asked for
    render::Settings s;
    ASSERT_EQ(render::parse_option(s, "post", "blur:2"), "");  // a few more passes than the map and the camera
    const int frames = 5;
    std::vector<std::vector<std::string>> planned;
    timer.enable(true);
    for (int i = 0; i < frames; ++i) planned.push_back(drawn_passes(renderer->render(frame(i), s, render::offscreen(64, 64))));
    timer.enable(false);
    const std::vector<gl::GpuFrame> got = timer.take(true);
    EXPECT_EQ(timer.pending(), 0);
    // Every frame read, or dropped for a disjoint clock (never on llvmpipe, allowed by the extension).
    ASSERT_EQ(static_cast<int>(got.size()) + timer.discarded(), frames);
    ASSERT_FALSE(got.empty());
    const size_t first = static_cast<size_t>(frames) - got.size();  // a discard drops the oldest first
    double total = 0.0;
    for (size_t f = 0; f < got.size(); ++f) {
        const auto& want = planned[first + f];
        ASSERT_GE(want.size(), 3u);
        ASSERT_EQ(got[f].passes.size(), want.size()) << "frame " << f;
        for (size_t p = 0; p < want.size(); ++p) {
            EXPECT_EQ(got[f].passes[p].name, want[p]);
            EXPECT_GE(got[f].passes[p].ms, 0.0) << want[p];
        }
        total += got[f].total_ms();
    }
    EXPECT_GT(total, 0.0);
    // Nothing more once read, and nothing while it is off.
    renderer->render(frame(frames), s, render::offscreen(64, 64));
    EXPECT_TRUE(timer.take(true).empty());

    const gl::GpuSummary sum = gl::summarize(got);
    EXPECT_EQ(sum.frames, static_cast<int>(got.size()));
    ASSERT_EQ(sum.passes.size(), planned.back().size());
    EXPECT_GT(sum.total_ms, 0.0);
    const std::string text = gl::describe(sum, true);
    EXPECT_NE(text.find("GPU time per pass"), std::string::npos) << text;
    EXPECT_NE(text.find(sum.passes.front().name), std::string::npos) << text;
}

TEST_F(TimerGl, SkippedPassesAreNotTimed) {
    // The same still frame twice: the second reuses the map, so only its camera pass is timed.
    gl::PassTimer& timer = renderer->gpu_timer();
    render::Settings s;
    timer.enable(true);
    const auto a = drawn_passes(renderer->render(frame(0), s, render::offscreen(64, 64)));
    const auto b = drawn_passes(renderer->render(frame(0), s, render::offscreen(64, 64)));
    timer.enable(false);
    ASSERT_LT(b.size(), a.size());
    const auto got = timer.take(true);
    ASSERT_EQ(static_cast<int>(got.size()) + timer.discarded(), 2);
    if (got.size() == 2) {
        EXPECT_EQ(got[0].passes.size(), a.size());
        EXPECT_EQ(got[1].passes.size(), b.size());
    }
}

TEST_F(TimerGl, TheRingWaitsAndKeepsEveryFrame) {
    // More frames than the ring holds, none finished nor read in between: the timer waits for the
    // oldest when the ring is full, and every frame comes back.
    gl::PassTimer& timer = renderer->gpu_timer();
    render::Settings s;
    const int frames = 3 * gl::PassTimer::kRing;
    timer.enable(true);
    for (int i = 0; i < frames; ++i) {
        renderer->render(frame(i), s, render::offscreen(32, 32));
        EXPECT_LE(timer.pending(), gl::PassTimer::kRing);
    }
    timer.enable(false);
    EXPECT_EQ(static_cast<int>(timer.take(true).size()) + timer.discarded(), frames);
}

TEST_F(TimerGl, AnUnfinishedFrameIsDropped) {
    // A pass that throws leaves its frame open with a query active: the next frame drops it and
    // runs its own queries without a GL error (the fixture checks for one).
    gl::PassTimer timer(true);
    timer.enable(true);
    timer.begin_frame();
    timer.begin_pass("thrown");
    timer.begin_frame();
    timer.begin_pass("a");
    timer.begin_pass("b");  // ends "a": one query active at a time
    timer.end_frame();
    const auto got = timer.take(true);
    ASSERT_EQ(static_cast<int>(got.size()) + timer.discarded(), 1);
    if (!got.empty()) {
        ASSERT_EQ(got[0].passes.size(), 2u);
        EXPECT_EQ(got[0].passes[0].name, "a");
        EXPECT_EQ(got[0].passes[1].name, "b");
    }
}

// A context without the extension: the caps flag off, as probe_caps leaves it there.
TEST(TimerGlNoExtension, NotAvailableRatherThanNumbers) {
    test::context();
    gl::Caps caps = gl::probe_caps(test::context());
    caps.timer_query = false;
    render::Renderer r(caps);
    gl::PassTimer& timer = r.gpu_timer();
    EXPECT_FALSE(timer.available());
    timer.enable(true);
    EXPECT_FALSE(timer.enabled());
    scene::CourseScene course = scene::make_course_scene(6);
    for (int i = 0; i < 3; ++i) r.render(course.scene, render::Settings{}, render::offscreen(32, 32));
    EXPECT_TRUE(timer.take(true).empty());
    EXPECT_EQ(timer.pending(), 0);
    const std::string text = gl::describe(gl::summarize({}), timer.available());
    EXPECT_EQ(text, "GPU timer: not available on this context (no EXT_disjoint_timer_query)\n");
    gl::check_errors("no timer");
}

// The summary's arithmetic: medians per pass, a second pass of one name apart, the frames' totals.
TEST(TimerSummary, MediansPerPassAndPerFrame) {
    const std::vector<gl::GpuFrame> frames = {
        {{{"shadow-map", 1.0}, {"camera", 2.0}}},
        {{{"shadow-map", 3.0}, {"camera", 4.0}, {"camera", 0.5}}},
        {{{"camera", 6.0}}},
    };
    const gl::GpuSummary s = gl::summarize(frames);
    EXPECT_EQ(s.frames, 3);
    ASSERT_EQ(s.passes.size(), 3u);
    EXPECT_EQ(s.passes[0].name, "shadow-map");
    EXPECT_DOUBLE_EQ(s.passes[0].ms, 2.0);
    EXPECT_EQ(s.passes[0].frames, 2);
    EXPECT_EQ(s.passes[1].name, "camera");
    EXPECT_DOUBLE_EQ(s.passes[1].ms, 4.0);
    EXPECT_EQ(s.passes[2].name, "camera #2");
    EXPECT_DOUBLE_EQ(s.total_ms, 6.0);  // totals 3, 7.5, 6
    EXPECT_EQ(gl::pass_list(s), "shadow-map: 2.000; camera: 4.000; camera #2: 0.500");
    EXPECT_NE(gl::describe(s, true).find("(in 2 of 3 frames)"), std::string::npos);
    EXPECT_EQ(gl::describe(gl::summarize({}), true, 2), "GPU timer: no frame measured, 2 discarded for GL_GPU_DISJOINT_EXT\n");
}

}  // namespace
