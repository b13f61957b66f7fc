// The shadow map's lookup uniforms for cascades and a cube's faces (shadow_lookup.cpp).
#pragma once

#include "plan/techniques/technique.h"
#include "shadow/cube.h"

namespace penumbra::render {

void add_cascade_uniforms(const PlanContext& c, Binding& b, const ResourceDesc& map);
// Texels of each cube face's tile beyond its 90 degrees, per side, for the filter in use.
int cube_guard(const Settings& s, int size);
void add_cube_uniforms(const shadow::CubeFit& fit, const scene::Light& light, Binding& b, const ResourceDesc& map);

}  // namespace penumbra::render
