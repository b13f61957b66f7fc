// --map-size auto in the plan (map_size.cpp): each returns the size and puts the plan's
// MapSizeReport (the size and why).
#pragma once

#include "plan/techniques/technique.h"
#include "shadow/cube.h"

namespace penumbra::render {

// One map of frustum `f` serving the receivers in view, the camera pass's pixels.
int auto_map_size(PlanContext& c, const ShadowBounds& b, const shadow::LightFrustum& f);
// A cube: each drawn face matched to the receivers it serves (those in view inside its frustum),
// the largest size any face asks for. A face that sees much of the image in little of its map
// would be under-sampled by a mean over the faces (bulb_room.gltf at 512x512: faces of 512 and
// 0.130 % of error by the mean, 1024 and 0.056 % by the largest).
int auto_map_size(PlanContext& c, const ShadowBounds& b, const shadow::CubeFit& fit);

}  // namespace penumbra::render
