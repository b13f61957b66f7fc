// --map-size auto in the plan (map_size.cpp): each returns the size and puts the plan's
// MapSizeReport (the size and why).
#pragma once

#include "plan/techniques/technique.h"
#include "shadow/cascades.h"
#include "shadow/cube.h"

namespace penumbra::render {

// One map of frustum `f` serving the receivers in view, the camera pass's pixels.
int auto_map_size(PlanContext& c, const ShadowBounds& b, const shadow::LightFrustum& f);
// A cube: each drawn face matched to the receivers it serves (those in view inside its frustum),
// the largest size any face asks for. A face that sees much of the image in little of its map
// would be under-sampled by a mean over the faces (bulb_room.gltf at 512x512: faces of 512 and
// 0.130 % of error by the mean, 1024 and 0.056 % by the largest).
int auto_map_size(PlanContext& c, const ShadowBounds& b, const shadow::CubeFit& fit);
// Cascades: each matched to the receivers in view within its slice of the camera's depth range,
// in its window; the largest size any asks for (the atlas's tiles share one size), as for a cube.
int auto_map_size(PlanContext& c, const ShadowBounds& b, const shadow::CascadeFit& fit);
// The size a cascades' fit starts from under auto: the previous plan's match where it made one
// (so a frame that keeps its size fits once), else the fixed default's.
int auto_first_guess(const PlanContext& c);

}  // namespace penumbra::render
