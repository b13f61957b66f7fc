// The post passes' planning (post.h): the screen and image passes, the blurs, --post blur and
// bloom after the frame. A file of its own so that a browser page links it only where its exercise
// takes the image post (frame.h: image_post_shape) or a shape that draws such passes (deferred,
// the shadow blur); the option's parsing stays in post.cpp.
#include <algorithm>
#include <cstdio>

#include "plan/frames/frame.h"
#include "plan/options.h"
#include "plan/post.h"

namespace penumbra::render {

namespace {

// Bloom's blurs, in pixels of the half- and quarter-size targets.
constexpr int kBloomRadius = 4;
constexpr int kImageUnit = 0;

bool image_post_applies(const PlanContext& c, std::string*) { return image_post(c.settings); }

}  // namespace

Pass screen_pass(std::string name, std::string module, const TargetRef& target) {
    Pass p;
    p.name = std::move(name);
    p.module = std::move(module);
    p.target = target;
    p.state.depth_test = p.state.depth_write = false;
    p.state.cull = gl::Cull::None;
    p.object_uniforms = ObjectUniforms::None;
    return p;
}

int add_post_target(PlanContext& c, const std::string& name, int width, int height, const std::string& purpose) {
    ResourceDesc d;
    d.name = c.named(name);
    d.width = std::max(width, 1);
    d.height = std::max(height, 1);
    d.half_float = c.caps.half_float_target;
    d.sampling = gl::Sampling::Linear;
    return c.add_resource(d, "", purpose);
}

namespace {

Pass post_pass(std::string name, const TargetRef& target) { return screen_pass(std::move(name), "post", target); }

Draw fullscreen(Variant v) {
    Draw d;
    d.fullscreen = true;
    d.variant = std::move(v);
    d.bindings = 1u;
    return d;
}

TargetRef whole(const PlanContext& c, int resource) {
    const ResourceDesc& d = c.plan.resources[static_cast<size_t>(resource)].desc;
    return {resource, d.width, d.height, 0, 0, false};
}

const std::string& name_of(const PlanContext& c, int resource) {
    return c.plan.resources[static_cast<size_t>(resource)].desc.name;
}

}  // namespace

// A pass of one full-screen draw reading `src` at unit 0 as u_image, with `more` uniforms.
Pass image_pass(const PlanContext& c, std::string name, int src, const TargetRef& dst, Variant v,
                std::vector<Uniform> more, std::string detail) {
    Pass p = post_pass(std::move(name), dst);
    more.insert(more.begin(), Uniform{"u_image", kImageUnit});
    p.bindings.push_back({"image", std::move(more), {{kImageUnit, src}}});
    p.draws.push_back(fullscreen(std::move(v)));
    std::string into = "the window";
    if (dst.resource >= 0) {
        const ResourceDesc& d = c.plan.resources[static_cast<size_t>(dst.resource)].desc;
        into = d.name + (d.half_float ? " (rgba16f)" : " (rgba8)");
    }
    p.detail = name_of(c, src) + " -> " + into + ": " + std::move(detail);
    return p;
}

void add_blur_passes(PlanContext& c, const std::string& name, int src, int tmp, const TargetRef& dst, int radius) {
    const TargetRef t = whole(c, tmp);
    char what[64];
    std::snprintf(what, sizeof what, "Gaussian, %d taps (sigma %.3g px), ", 2 * radius + 1, radius / 3.0);
    c.add_pass(image_pass(c, name + "-h", src, t, blur_variant(radius),
                          {{"u_step", glm::vec2(1.0f / static_cast<float>(t.width), 0.0f)}}, std::string(what) + "horizontal"));
    c.add_pass(image_pass(c, name + "-v", tmp, dst, blur_variant(radius),
                          {{"u_step", glm::vec2(0.0f, 1.0f / static_cast<float>(t.height))}}, std::string(what) + "vertical"));
}

void add_post_passes(PlanContext& c, int image, const TargetRef& out) {
    std::vector<const PostStep*> steps;
    for (const PostStep& s : c.settings.post)
        if (s.kind != PostKind::ShadowBlur) steps.push_back(&s);
    if (steps.empty()) return;
    const int w = c.inputs.output.width, h = c.inputs.output.height;
    c.plan.notes.push_back("--post " + post_text(c.settings.post) + ": intermediate targets " + post_format(c.caps));
    int ping[2] = {-1, -1};  // "post-a", "post-b", declared when first needed
    // A full-size intermediate target other than `busy`.
    const auto other = [&](int busy) {
        const int k = busy == ping[0] ? 1 : 0;
        if (ping[k] < 0)
            ping[k] = add_post_target(c, k == 0 ? "post-a" : "post-b", w, h, "--post: ping-pong between passes");
        return ping[k];
    };
    int current = image;
    for (size_t i = 0; i < steps.size(); ++i) {
        const bool last = i + 1 == steps.size();
        const PostStep& s = *steps[i];
        if (s.kind == PostKind::Blur) {
            // Into the ping-pong target the horizontal pass did not use (or back where it read: the
            // vertical pass reads only the other one), never into the RGBA8 camera image.
            const int tmp = other(current);
            const int dst = last ? -1 : current == image ? other(tmp) : current;
            add_blur_passes(c, "post-blur", current, tmp, last ? out : whole(c, dst), static_cast<int>(s.value));
            if (!last) current = dst;
            continue;
        }
        // Bloom: the bright part at half size, blurred; again at quarter size; both added back.
        const int half = add_post_target(c, "bloom-half", w / 2, h / 2, "--post bloom: the bright part at half size");
        const int half_tmp = add_post_target(c, "bloom-half-tmp", w / 2, h / 2, "--post bloom: its blur's first pass");
        const int quarter = add_post_target(c, "bloom-quarter", w / 4, h / 4, "--post bloom: at quarter size");
        const int quarter_tmp = add_post_target(c, "bloom-quarter-tmp", w / 4, h / 4, "--post bloom: its blur's first pass");
        c.add_pass(image_pass(c, "bloom-bright", current, whole(c, half), bright_variant(), {{"u_threshold", s.value}},
                              "each channel minus " + shortest_float(s.value) + ", a 2x2 box by linear sampling"));
        add_blur_passes(c, "bloom-half-blur", half, half_tmp, whole(c, half), kBloomRadius);
        c.add_pass(image_pass(c, "bloom-down", half, whole(c, quarter), bright_variant(), {{"u_threshold", 0.0f}},
                              "a 2x2 box by linear sampling"));
        add_blur_passes(c, "bloom-quarter-blur", quarter, quarter_tmp, whole(c, quarter), kBloomRadius);
        const TargetRef dst = last ? out : whole(c, other(current));
        Pass add = image_pass(c, "bloom-add", current, dst, bloom_add_variant(),
                              {{"u_bloom_half", kImageUnit + 1}, {"u_bloom_quarter", kImageUnit + 2}},
                              "the image plus the mean of its bright part blurred at 1/2 and at 1/4 size");
        add.bindings.front().textures.push_back({kImageUnit + 1, half});
        add.bindings.front().textures.push_back({kImageUnit + 2, quarter});
        c.add_pass(std::move(add));
        current = dst.resource;
    }
}

const FrameShape& image_post_shape() {
    // Not one of plan_frame_shape's: plan() adds its passes after the frame's (add_post_passes).
    static const FrameShape shape{"image post", image_post_applies, nullptr};
    return shape;
}

}  // namespace penumbra::render
