// What the exercise modules (examples/exercises/*.cpp) share: the registry's types and the
// controls of the course scene's animation. Each module is one function returning its Exercise,
// named as its line in list.h names it.
#pragma once

#include <algorithm>
#include <string>

#include "../exercise_list.h"
#include "gl/caps.h"
#include "plan/frames/frame.h"
#include "plan/settings.h"
#include "plan/techniques/technique.h"
#include "scenes/course_scene.h"

namespace penumbra::examples::exercises {

using K = ControlKind;

// The course scene's light circling the table and the teapot's jump, as buttons.
inline Control light_toggle() { return {"light", "Animation", K::Toggle}; }
inline Control jump_toggle() { return {"jump", "Animation", K::Toggle}; }

// The draws several exercises share (Exercise::draw).
// The course scene's colour image: the exercise offers no other view.
inline void draw_colour(Host& host, render::Settings s, render::FrameInputs in) {
    s.aov = render::Aov::Color;
    host.render(s, in);
}
// The exercise's own scene from the fly camera: colour, visibility, or the cascades' (the cube's
// faces') tints.
inline void draw_own_scene(Host& host, render::Settings s, render::FrameInputs in) {
    if (s.aov != render::Aov::Visibility && s.aov != render::Aov::Cascades) s.aov = render::Aov::Color;
    host.render_own_scene(s, in);
}

}  // namespace penumbra::examples::exercises
