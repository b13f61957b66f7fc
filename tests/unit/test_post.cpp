// --post as data: the option's forms and errors, the Gaussian's weights, and the passes and
// resources a plan gets for blur, bloom and shadow-blur (ping-pong, formats, where each writes).
// No GL context.
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <gtest/gtest.h>

#include "full_caps.h"
#include "plan_names.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "plan/post.h"
#include "scenes/course_scene.h"

using namespace penumbra;
using render::FramePlan;
using render::PostKind;

namespace {

using penumbra::testing::full_caps;

render::Settings with_post(const char* post) {
    render::Settings s;
    const std::string err = render::parse_option(s, "post", post);
    if (!err.empty()) throw std::runtime_error(err);
    return s;
}

using penumbra::testing::pass_named;
using penumbra::testing::pass_names;

std::string target_name(const FramePlan& p, const render::Pass& pass) {
    return pass.target.resource < 0 ? "window" : p.resources[static_cast<size_t>(pass.target.resource)].desc.name;
}

std::string read_name(const FramePlan& p, const render::Pass& pass) {
    const std::vector<int> r = pass.reads();
    return r.empty() ? "" : p.resources[static_cast<size_t>(r.front())].desc.name;
}

gl::Caps half_float_caps() {
    gl::Caps c = full_caps();
    c.half_float_target = true;
    return c;
}

}  // namespace

TEST(Post, TheOptionTakesAnOrderedListAndNamesWhatIsWrong) {
    EXPECT_TRUE(with_post("none").post.empty());
    const render::Settings s = with_post("bloom:0.6,blur:4,shadow-blur:6");
    ASSERT_EQ(s.post.size(), 3u);
    EXPECT_EQ(s.post[0].kind, PostKind::Bloom);  // the list's order, not a fixed one
    EXPECT_FLOAT_EQ(s.post[0].value, 0.6f);
    EXPECT_EQ(s.post[1].kind, PostKind::Blur);
    EXPECT_EQ(s.post[2].kind, PostKind::ShadowBlur);
    EXPECT_EQ(render::post_text(s.post), "bloom:0.6,blur:4,shadow-blur:6");
    EXPECT_EQ(with_post(render::post_text(s.post).c_str()), s);  // printed, parsed back

    render::Settings t;
    const auto error = [&](const char* v) { return render::parse_option(t, "post", v); };
    EXPECT_NE(error("blur:0").find("whole number of pixels, 1..32"), std::string::npos);
    EXPECT_NE(error("blur:2.5").find("whole number"), std::string::npos);
    EXPECT_NE(error("blur:33").find("1..32"), std::string::npos);
    EXPECT_NE(error("bloom:1.5").find("[0, 1]"), std::string::npos);
    EXPECT_NE(error("bloom").find("after a colon"), std::string::npos);
    EXPECT_NE(error("blur:x").find("not a number"), std::string::npos);
    EXPECT_NE(error("sharpen:2").find("not blur:R, bloom:T or shadow-blur:R"), std::string::npos);
    EXPECT_NE(error("blur:2,blur:3").find("listed twice"), std::string::npos);
    EXPECT_NE(error("blur:2,").find("''"), std::string::npos);  // an empty item
    EXPECT_TRUE(t.post.empty());  // nothing half-set by the refusals
}

TEST(Post, TheGaussianWeightsSumToOneAndFallOffAtThreeSigma) {
    for (int r : {1, 2, 4, 8, 32}) {
        const std::vector<float> w = render::gaussian_weights(r);
        ASSERT_EQ(w.size(), static_cast<size_t>(r) + 1);
        double sum = w[0];
        for (size_t i = 1; i < w.size(); ++i) {
            sum += 2.0 * w[i];
            EXPECT_LT(w[i], w[i - 1]);
        }
        EXPECT_NEAR(sum, 1.0, 1e-6) << r;
        // sigma = R / 3: the last tap is exp(-4.5) of the centre's.
        EXPECT_NEAR(w.back() / w[0], std::exp(-4.5), 1e-5) << r;
    }
}

TEST(Post, BlurIsTwoPassesThroughASecondTargetIntoTheOutput) {
    const scene::Scene scene = scene::make_course_scene(4).scene;
    const FramePlan p = render::plan(scene, with_post("blur:4"), full_caps(), render::offscreen(64, 48));
    EXPECT_EQ(pass_names(p), (std::vector<std::string>{"shadow-map", "camera", "post-blur-h", "post-blur-v"}));
    EXPECT_EQ(target_name(p, pass_named(p, "camera")), "post-scene");
    const render::Pass& h = pass_named(p, "post-blur-h");
    const render::Pass& v = pass_named(p, "post-blur-v");
    EXPECT_EQ(read_name(p, h), "post-scene");
    EXPECT_EQ(target_name(p, h), "post-a");
    EXPECT_EQ(read_name(p, v), "post-a");
    EXPECT_EQ(target_name(p, v), "camera");  // the frame's output
    EXPECT_EQ(p.resource("post-b"), nullptr) << "one ping-pong target is enough for one blur";
    ASSERT_EQ(h.draws.size(), 1u);
    EXPECT_TRUE(h.draws[0].fullscreen);
    EXPECT_EQ(h.draws[0].variant, render::blur_variant(4));
    EXPECT_FALSE(h.state.depth_test);
    // One texel along each direction.
    const auto step = [](const render::Pass& pass) {
        for (const auto& u : pass.bindings.at(0).uniforms)
            if (u.name == "u_step") return std::get<glm::vec2>(u.value);
        return glm::vec2(-1.0f);
    };
    EXPECT_EQ(step(h), glm::vec2(1.0f / 64.0f, 0.0f));
    EXPECT_EQ(step(v), glm::vec2(0.0f, 1.0f / 48.0f));
    // RGBA8 intermediates without half floats, RGBA16F with them (and a note that says which).
    EXPECT_FALSE(p.resource("post-a")->desc.half_float);
    const FramePlan hf = render::plan(scene, with_post("blur:4"), half_float_caps(), render::offscreen(64, 48));
    EXPECT_TRUE(hf.resource("post-a")->desc.half_float);
    EXPECT_EQ(hf.resource("post-a")->desc.bytes(), 64u * 48u * 8u);
    EXPECT_FALSE(hf.resource("post-scene")->desc.half_float);  // what the effects blend into stays RGBA8
    bool said = false;
    for (const std::string& n : hf.notes) said = said || n.find("rgba16f") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST(Post, ChainedStepsPingPongAndNeverWriteWhatTheyRead) {
    const scene::Scene scene = scene::make_course_scene(4).scene;
    const FramePlan p = render::plan(scene, with_post("blur:2,bloom:0.5"), full_caps(), render::offscreen(64, 64));
    for (const render::Pass& pass : p.passes)
        for (int r : pass.reads()) EXPECT_NE(r, pass.target.resource) << pass.name;
    EXPECT_EQ(target_name(p, pass_named(p, "post-blur-v")), "post-b");  // not the RGBA8 camera image
    EXPECT_EQ(read_name(p, pass_named(p, "bloom-bright")), "post-b");
    EXPECT_EQ(p.resource("bloom-half")->desc.width, 32);
    EXPECT_EQ(p.resource("bloom-quarter")->desc.width, 16);
    EXPECT_EQ(target_name(p, pass_named(p, "bloom-add")), "camera");
    EXPECT_EQ(p.passes.back().name, "bloom-add");
    // Bloom first, then blur: the order of the list.
    const FramePlan q = render::plan(scene, with_post("bloom:0.5,blur:2"), full_caps(), render::offscreen(64, 64));
    EXPECT_EQ(q.passes.back().name, "post-blur-v");
    EXPECT_EQ(target_name(q, pass_named(q, "bloom-add")), "post-a");
    EXPECT_EQ(read_name(q, pass_named(q, "post-blur-h")), "post-a");
}

TEST(Post, ShadowBlurShadesWithTheBlurredVisibility) {
    const scene::Scene scene = scene::make_course_scene(4).scene;
    const FramePlan p = render::plan(scene, with_post("shadow-blur:5"), full_caps(), render::offscreen(64, 64));
    EXPECT_EQ(pass_names(p), (std::vector<std::string>{"shadow-map", "shadow-visibility", "shadow-blur-h",
                                                       "shadow-blur-v", "camera"}));
    EXPECT_EQ(target_name(p, pass_named(p, "shadow-visibility")), "shadow-visibility");
    EXPECT_EQ(target_name(p, pass_named(p, "shadow-blur-v")), "shadow-visibility");
    const render::Pass& cam = pass_named(p, "camera");
    EXPECT_EQ(target_name(p, cam), "camera");
    EXPECT_EQ(read_name(p, cam), "shadow-visibility");
    // The receivers read the blurred visibility, not the map.
    bool table = false;
    for (const render::Draw& d : cam.draws)
        if (d.label == "table") {
            table = true;
            EXPECT_NE(d.variant.key().find("AREA_LOOKUP"), std::string::npos);
            EXPECT_EQ(d.variant.key().find("SHADOW_MAP"), std::string::npos);
        }
    EXPECT_TRUE(table);
    // Where it cannot apply, a note says why and the frame is the technique's own.
    render::Settings none = with_post("shadow-blur:5");
    none.technique = render::Technique::None;
    const FramePlan n = render::plan(scene, none, full_caps(), render::offscreen(64, 64));
    EXPECT_FALSE(n.has_pass("shadow-blur-h"));
    bool noted = false;
    for (const std::string& note : n.notes) noted = noted || note.find("no shadows to blur") != std::string::npos;
    EXPECT_TRUE(noted);
    // With volumes, its stencil passes draw into the visibility image.
    render::Settings vol = with_post("shadow-blur:5");
    vol.technique = render::Technique::Volumes;
    const FramePlan v = render::plan(scene, vol, full_caps(), render::offscreen(64, 64));
    EXPECT_TRUE(v.has_pass("shadow-blur-h"));
    for (const render::Pass& pass : v.passes)
        if (pass.module == "volumes") {
            EXPECT_EQ(target_name(v, pass), "shadow-visibility") << pass.name;
        }
}

TEST(Post, AWindowsStencilIsNotThePostImagesOne) {
    // Without OES_packed_depth_stencil an offscreen target has no stencil: a window's has. With
    // --post blur the camera draws into a texture even for a window, so the outline is refused there.
    const scene::Scene scene = scene::make_course_scene(4).scene;
    gl::Caps caps = full_caps();
    caps.packed_depth_stencil = false;
    render::FrameInputs window;
    window.output = render::Output::to_window(64, 64);
    render::Settings s = with_post("none");
    s.effects = {render::Effect::Outline};
    EXPECT_EQ(render::check(scene, s, caps, window), "");
    s.post = with_post("blur:2").post;
    EXPECT_NE(render::check(scene, s, caps, window).find("OES_packed_depth_stencil"), std::string::npos);
}
