// Shared by the extremes tests that score a frame against the ray-traced truth.
#pragma once

#include <glm/glm.hpp>

#include "measure/ray_tracer.h"
#include "scene/scene.h"

namespace penumbra::test {

// The truth of `scene` seen through `view_proj` (a frame plan's camera), size x size.
inline measure::TruthImage truth_frame(const scene::Scene& scene, const glm::mat4& view_proj, int size) {
    measure::TruthOptions to;
    to.width = size;
    to.height = size;
    to.view_proj = view_proj;
    return measure::RayTracer(scene).render(to);
}

}  // namespace penumbra::test
