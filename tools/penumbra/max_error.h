// --max-error P in the commands (render, plan, bench; issue 56): the least work predicted to keep
// a frame within P % of the hard truth (render/error_target.h), chosen once, on the frame at
// --time, from --budget-ms's ladder with shadow volumes on top where they can draw the scene.
#pragma once

#include <optional>
#include <string>

#include "plan/options.h"
#include "plan/settings.h"
#include "render/error_target.h"
#include "render/renderer.h"

namespace penumbra::tools {

using render::ErrorChoice;
using render::ErrorRung;
using render::pick_rung;

// The choice for `max_pct` on `scene`'s frame; none, with `refusal` set, when it cannot be made.
std::optional<ErrorChoice> choose_for_error(double max_pct, const render::Settings& s, render::Renderer& r,
                                            const scene::Scene& scene, const render::FrameInputs& in, std::string& refusal);

// The options' --max-error choice (none when it is 0), refusing it beside --budget-ms.
std::optional<ErrorChoice> make_error_choice(const render::Options& o, render::Renderer& r, const scene::Scene& scene,
                                             const render::FrameInputs& in, std::string& refusal);

}  // namespace penumbra::tools
