// Where the eye is: the scene's camera, or inside the shadow of the scene's largest caster (the
// view where shadow volumes' depth-pass fails: the near plane lies inside a volume). Used by
// SceneSource (the command line) and by the course exercises (examples/exercises.cpp).
#pragma once

#include "scene/scene.h"

namespace penumbra::scene {

enum class Eye { Scene, InShadow };

// Moves the camera of `scene` into the shadow of its largest caster (not the ground): just beyond
// it on the ray from the light through its centre, kept above the ground plane, looking along the
// shadow and down towards the ground. False (and the scene unchanged) when no such caster exists.
bool place_eye_in_shadow(Scene& scene);

}  // namespace penumbra::scene
