#include "plan/post.h"

#include <cmath>
#include <cstdio>

#include "plan/options.h"
#include "plan/techniques/technique.h"
#include "scene/printable.h"

namespace penumbra::render {

std::string_view to_string(PostKind k) {
    switch (k) {
        case PostKind::Blur: return "blur";
        case PostKind::Bloom: return "bloom";
        case PostKind::ShadowBlur: return "shadow-blur";
    }
    return "?";
}

namespace {

constexpr PostKind kAllPostKinds[] = {PostKind::Blur, PostKind::Bloom, PostKind::ShadowBlur};

// One item "kind:value": "" and the step, or what is wrong with it.
std::string parse_item(std::string_view item, PostStep& step) {
    const std::string shown = "'" + scene::printable(item) + "'";
    const size_t colon = item.find(':');
    const std::string_view kind = item.substr(0, colon);
    bool known = false;
    for (PostKind k : kAllPostKinds)
        if (kind == to_string(k)) {
            step.kind = k;
            known = true;
        }
    if (!known) return shown + " is not blur:R, bloom:T or shadow-blur:R";
    if (colon == std::string_view::npos) return shown + " needs its value after a colon (" + std::string(kind) +
                                                (step.kind == PostKind::Bloom ? ":T)" : ":R)");
    double v = 0.0;
    if (!parse_number(item.substr(colon + 1), v)) return shown + ": the value is not a number";
    if (step.kind == PostKind::Bloom) {
        if (v < 0.0 || v > 1.0) return shown + ": the threshold T must be in [0, 1]";
    } else if (v != std::floor(v) || v < 1.0 || v > kMaxBlurRadius) {
        return shown + ": the radius R must be a whole number of pixels, 1.." + std::to_string(kMaxBlurRadius);
    }
    step.value = static_cast<float>(v);
    return {};
}

std::string parse_steps(std::string_view text, std::vector<PostStep>& out) {
    out.clear();
    if (text == "none") return {};
    size_t start = 0;
    while (true) {
        const size_t end = std::min(text.find(',', start), text.size());
        PostStep step;
        if (std::string why = parse_item(text.substr(start, end - start), step); !why.empty()) return why;
        for (const PostStep& s : out)
            if (s.kind == step.kind) return "'" + std::string(to_string(step.kind)) + "' is listed twice";
        out.push_back(step);
        if (end == text.size()) return {};
        start = end + 1;
    }
}

}  // namespace

std::string post_form(std::string_view text) {
    std::vector<PostStep> steps;
    return parse_steps(text, steps);
}

std::vector<PostStep> parse_post(std::string_view text) {
    std::vector<PostStep> steps;
    if (!parse_steps(text, steps).empty()) steps.clear();
    return steps;
}

std::string post_text(const std::vector<PostStep>& steps) {
    std::string s;
    for (const PostStep& p : steps) s += (s.empty() ? "" : ",") + std::string(to_string(p.kind)) + ":" + shortest_float(p.value);
    return s.empty() ? "none" : s;
}

std::vector<float> gaussian_weights(int radius) {
    std::vector<float> w(static_cast<size_t>(std::max(radius, 0)) + 1);
    const double sigma = std::max(radius, 1) / 3.0;
    double sum = 0.0;
    std::vector<double> d(w.size());
    for (size_t i = 0; i < d.size(); ++i) {
        const double x = static_cast<double>(i);
        d[i] = std::exp(-x * x / (2.0 * sigma * sigma));
        sum += i == 0 ? d[i] : 2.0 * d[i];
    }
    for (size_t i = 0; i < d.size(); ++i) w[i] = static_cast<float>(d[i] / sum);
    return w;
}

bool image_post(const Settings& s) { return s.post_step(PostKind::Blur) || s.post_step(PostKind::Bloom); }

std::string post_format(const gl::Caps& caps) {
    return caps.half_float_target ? "rgba16f (OES_texture_half_float, _linear and EXT_color_buffer_half_float)"
                                  : "rgba8 (this context renders into no half-float texture)";
}

}  // namespace penumbra::render
