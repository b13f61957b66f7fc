// --post: passes over finished images (the course notes' multipass rendering: render to a texture,
// then draw a full-screen triangle that reads it into another, ping-pong). No GL here: the passes
// are planned like every other (plan/plan.h) and the renderer runs them.
//
//   blur:R         a separable Gaussian of radius R pixels (taps -R..R, sigma R/3, weights summing
//                  to 1), one horizontal pass into a second target and one vertical pass back
//   bloom:T        what is brighter than T (each channel minus T) into a half-size target (a 2x2 box
//                  by linear sampling), blurred there and again at quarter size, both added back
//   shadow-blur:R  the technique's visibility AOV blurred with the same passes, and the camera pass
//                  shading with it (plan/plan.cpp): a cheap soft shadow that knows no depth
//
// The intermediate targets are RGBA16F where the context renders into half floats
// (gl::Caps::half_float_target), else RGBA8; the camera's image before them stays RGBA8 (what the
// effects blend into), and the last pass writes the frame's output.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "plan/plan.h"
#include "plan/settings.h"

namespace penumbra::render {

struct PlanContext;

// "" when `text` is a --post value ("none", or a comma list of kind:value, each kind once), else
// what is wrong with it (the option table's check).
std::string post_form(std::string_view text);
// The steps of a value post_form accepts, in its order.
std::vector<PostStep> parse_post(std::string_view text);
// "none", or "blur:4,bloom:0.6".
std::string post_text(const std::vector<PostStep>& steps);

// The blur's weights for offsets 0..radius: exp(-x^2 / (2 sigma^2)), sigma = radius / 3,
// normalised so that w[0] + 2 (w[1] + ... + w[R]) = 1.
std::vector<float> gaussian_weights(int radius);

// Whether the settings have passes over the camera's image (blur or bloom).
bool image_post(const Settings& s);
// The format of the post passes' intermediate targets on this context, in words.
std::string post_format(const gl::Caps& caps);

// The separable blur of resource `src` (sampled) into `dst`, through resource `tmp` (the
// horizontal pass's target, the size of dst): two passes named NAME-h and NAME-v.
void add_blur_passes(PlanContext& c, const std::string& name, int src, int tmp, const TargetRef& dst, int radius);
// A pass of full-screen draws (no depth test or writes, no culling, no object uniforms) into `target`.
Pass screen_pass(std::string name, std::string module, const TargetRef& target);
// A pass of one full-screen draw reading resource `src` at unit 0 as u_image, with `more`
// uniforms, into `dst` (the bloom's bright pass with u_threshold 0 is a copy).
Pass image_pass(const PlanContext& c, std::string name, int src, const TargetRef& dst, Variant v,
                std::vector<Uniform> more, std::string detail);
// The resource of the intermediate targets: `name` at width x height (linear, clamp), colour only.
int add_post_target(PlanContext& c, const std::string& name, int width, int height, const std::string& purpose);

// The blur and bloom passes of c.settings.post from the camera's image (resource `image`) into
// `out`, the frame's output.
void add_post_passes(PlanContext& c, int image, const TargetRef& out);

}  // namespace penumbra::render
