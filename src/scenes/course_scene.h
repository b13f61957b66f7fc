// The course's scene (exercise sheet W09): the Newell teapot jumping on a marble table top,
// lit by a point light circling above the table. Everything animated is a pure function of time,
// with separate clocks for the light and the jump so the pages' on/off buttons can freeze either.
#pragma once

#include "scene/scene.h"

namespace penumbra::scene {

struct CourseScene {
    Scene scene;
    int teapot = -1;  // object indices
    int table = -1;
    int marble = -1;  // the table's texture (Scene::images)
};

// Geometry, materials and the marble texture; the animated parts at t = 0. With `portal` the
// scene's portal (--effects portal's frame and the other scene seen through it, portal_scene.h);
// without it Scene::portal is empty: a page that may never draw it adds it when a frame asks for
// it (CourseApp::course_scene_for). Without `marble` the table is untextured, in the colour of
// marble_placeholder() (the image the marble's index holds), until complete_marble() makes the
// marble and puts it on the table (the pages draw their first frame before the marble's noise).
CourseScene make_course_scene(int teapot_level = 10, bool portal = true, bool marble = true);
// Whether the table has its marble texture, and the marble (make_marble(512, 7)) made in place of
// the placeholder: false if it was there already.
bool marble_complete(const CourseScene& course);
bool complete_marble(CourseScene& course);

// Places the light at light_time and the teapot at jump_time (seconds).
void animate_course(CourseScene& course, double light_time, double jump_time);

// The light's position on its circle, and the teapot's lift above the table, at time t.
glm::vec3 course_light_position(double t);
float course_teapot_lift(double t);
// The first time at or after t when the teapot touches the table (where a jump switched off lets it land).
double course_teapot_landing(double t);

}  // namespace penumbra::scene
