// The Newell teapot, tessellated from its 32 bicubic Bezier patches (public-domain control points).
#pragma once

#include "scene/scene.h"

namespace penumbra::scene {

// Tessellate each patch into level x level quads. The teapot stands on y = 0 with +y up,
// its original units (about 3.15 tall, rim to spout about 6.4 wide on x), centred on x/z.
// Normals are unit length (the degenerate patch corners at the lid knob and the bottom get
// a proper normal), and triangles that collapse at those poles are left out.
Mesh make_teapot(int level);

}  // namespace penumbra::scene
