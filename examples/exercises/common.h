// What the exercise modules (examples/exercises/*.cpp) share: the registry's types and the
// controls of the course scene's animation. Each module is one function returning its Exercise,
// named as its line in list.h names it.
#pragma once

#include <algorithm>
#include <string>

#include "../exercise_list.h"
#include "gl/caps.h"
#include "plan/settings.h"
#include "scenes/course_scene.h"

namespace penumbra::examples::exercises {

using K = ControlKind;

// The course scene's light circling the table and the teapot's jump, as buttons.
inline Control light_toggle() { return {"light", "Animation", K::Toggle}; }
inline Control jump_toggle() { return {"jump", "Animation", K::Toggle}; }

}  // namespace penumbra::examples::exercises
