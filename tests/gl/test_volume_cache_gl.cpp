// Shadow volumes that cost what they draw, on a context: a still frame uploads no triangles and
// draws the same image; a frame after a move draws what a renderer that never saw the frame
// before draws, from a refilled buffer too; the renderer holds only the lists of the plans it ran
// last.
#include "gl_fixture.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

class VolumeCacheGl : public test::GlTest {};

const render::FrameInputs kInputs = render::offscreen(96, 64);

render::Settings volumes(bool show) {
    render::Settings s;
    s.technique = render::Technique::Volumes;
    s.show_volumes = show;
    // The table's volume too (the shadows fit leaves it out: it shadows nothing in view): two
    // casters, one still while the other moves.
    s.light_fit = render::LightFit::Tight;
    return s;
}

std::vector<std::uint8_t> frame(render::Renderer& r, const scene::Scene& scene, const render::Settings& s) {
    r.render(scene, s, kInputs);
    return r.read_image();
}

// The image of a renderer that draws this one frame and nothing before it.
std::vector<std::uint8_t> fresh(const scene::Scene& scene, const render::Settings& s) {
    render::Renderer r(gl::probe_caps(test::context()));
    return frame(r, scene, s);
}

size_t volume_draws(const render::FramePlan& p) {
    size_t n = 0;
    for (const auto& pass : p.passes)
        for (const auto& d : pass.draws) n += d.triangles && !d.triangles->empty() ? 1u : 0u;
    return n;
}

TEST_F(VolumeCacheGl, AStillFrameUploadsNothingAndDrawsTheSameImage) {
    for (bool show : {false, true}) {
        scene::CourseScene course = scene::make_course_scene(4);
        scene::animate_course(course, 0.6, 0.6);
        const render::Settings s = volumes(show);
        const auto first = frame(*renderer, course.scene, s);
        const std::uint64_t uploads = renderer->triangle_uploads();
        ASSERT_GT(uploads, 0u);
        const auto second = frame(*renderer, course.scene, s);
        EXPECT_EQ(renderer->triangle_uploads(), uploads) << "every list kept, every buffer kept";
        EXPECT_EQ(second, first);
        EXPECT_EQ(second, fresh(course.scene, s));
        gl::check_errors("a still volumes frame");
    }
}

TEST_F(VolumeCacheGl, AMovedFrameDrawsWhatAFreshRendererDraws) {
    for (bool show : {false, true}) {
        scene::CourseScene course = scene::make_course_scene(4);
        scene::animate_course(course, 0.6, 0.6);
        const render::Settings s = volumes(show);
        const auto before = frame(*renderer, course.scene, s);
        // The teapot jumps: its volume is uploaded again, the table's is not.
        std::uint64_t uploads = renderer->triangle_uploads();
        scene::animate_course(course, 0.6, 0.66);
        const auto jumped = frame(*renderer, course.scene, s);
        EXPECT_GT(renderer->triangle_uploads(), uploads);
        EXPECT_LT(renderer->triangle_uploads() - uploads, volume_draws(*renderer->last_plan()))
            << "the still table's lists were not uploaded again";
        EXPECT_NE(jumped, before) << "the control: the jump shows";
        EXPECT_EQ(jumped, fresh(course.scene, s));
        // The light moves: every volume again.
        uploads = renderer->triangle_uploads();
        scene::animate_course(course, 0.7, 0.66);
        const auto lit = frame(*renderer, course.scene, s);
        EXPECT_GE(renderer->triangle_uploads() - uploads, volume_draws(*renderer->last_plan()) - (show ? 1u : 0u));
        EXPECT_EQ(lit, fresh(course.scene, s));
    }
}

TEST_F(VolumeCacheGl, ARefilledBufferDrawsWhatANewOneDraws) {
    // The teapot jumps for 8 frames: from the third on, its new volume goes into the buffer of the
    // one two frames back (a little larger or smaller: the rest of the buffer is not drawn).
    scene::CourseScene course = scene::make_course_scene(4);
    const render::Settings s = volumes(false);
    std::vector<std::uint8_t> first, last;
    for (int i = 0; i < 8; ++i) {
        scene::animate_course(course, 0.6, 0.6 + 0.03 * i);
        last = frame(*renderer, course.scene, s);
        if (i == 0) first = last;
    }
    EXPECT_GT(renderer->triangle_refills(), 0u);
    EXPECT_NE(last, first) << "the control: the jump shows";
    EXPECT_EQ(last, fresh(course.scene, s));
    gl::check_errors("refilled volume buffers");
}

TEST_F(VolumeCacheGl, TheRendererHoldsOnlyTheListsOfItsLastPlans) {
    scene::CourseScene course = scene::make_course_scene(4);
    const render::Settings s = volumes(false);
    size_t most = 0;
    for (int i = 0; i < 12; ++i) {
        scene::animate_course(course, 0.6 + 0.02 * i, 0.6 + 0.02 * i);
        const render::FramePlan& p = renderer->render(course.scene, s, kInputs);
        most = std::max(most, volume_draws(p));
        EXPECT_LE(renderer->triangle_buffers(), 2 * most) << "frame " << i << ": this plan's and the one before";
    }
    // Without volumes the next runs let them go.
    render::Settings none;
    none.technique = render::Technique::None;
    renderer->render(course.scene, none, kInputs);
    renderer->render(course.scene, none, kInputs);
    EXPECT_EQ(renderer->triangle_buffers(), 0u);
}

}  // namespace
