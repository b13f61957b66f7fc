// The course scene's portal (--effects portal): a frame standing at the back of the table top,
// and the scene seen through it: a lawn in an evening sun (a directional light low on the left)
// with a sphere, a box and a pillar that cast long shadows to the right.
#pragma once

#include "scene/scene.h"

namespace penumbra::scene {

// The portal of the course scene (its table top is a 4 x 4 square at y = 0, the camera looks
// at it from +z): the opening 1.4 wide and 1.4 high, its frame 0.1 wide, standing at z = -1.2.
Portal make_course_portal();

}  // namespace penumbra::scene
