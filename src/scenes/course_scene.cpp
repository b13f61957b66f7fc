#include "scenes/course_scene.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "plan/weak_in_pages.h"
#include "scene/marble.h"
#include "scenes/portal_scene.h"
#include "scene/primitives.h"
#include "scene/teapot.h"

namespace penumbra::scene {

// The pages make the course scene without its portal, and a page's module has the portal's scene
// only where its exercise names it (examples/exercise_list.h: Exercise::portal); null there otherwise.
PENUMBRA_WEAK_IN_PAGES Portal make_course_portal();

namespace {

Portal (*portal_getter())() { return &make_course_portal; }

constexpr float kTableSize = 4.0f;       // the table top is a 4 x 4 square at y = 0
constexpr float kTeapotScale = 0.25f;    // the Newell teapot is about 3.15 units tall: 0.79 here
constexpr float kLightRadius = 2.0f;     // the light circles the table's centre...
constexpr float kLightHeight = 3.0f;     // ...this high above it
constexpr double kLightPeriod = 12.0;    // seconds per turn
constexpr float kJumpHeight = 0.6f;
constexpr double kJumpPeriod = 1.5;      // seconds per bounce
constexpr double kTwoPi = 6.283185307179586;
constexpr int kMarbleSize = 512;
constexpr std::uint32_t kMarbleSeed = 7;

// The angle of a turn of `period` seconds at t, in [0, 2 pi): the turns counted in double, so a
// clock that has run for hours keeps its phase, and the sine taken in float, as the positions are
// floats. The pages' modules then hold no double-precision sine or cosine (docs/payload.md).
float turn_angle(double t, double period) {
    const double turns = t / period;
    return static_cast<float>(kTwoPi * (turns - std::floor(turns)));
}

}  // namespace

bool marble_complete(const CourseScene& course) {
    return course.marble < 0 || course.scene.images[static_cast<size_t>(course.marble)].width == kMarbleSize;
}

namespace {

// The table's material with the marble, or (while it is deferred) in the placeholder's colour and
// untextured: then the first frame's table and teapot share one program, and a software rasteriser
// compiles one pipeline for that frame instead of two (docs/payload.md).
void dress_table(CourseScene& c, bool marble) {
    Material& m = c.scene.materials[static_cast<size_t>(c.scene.objects[static_cast<size_t>(c.table)].material)];
    const Image& img = c.scene.images[static_cast<size_t>(c.marble)];
    m.base_color = marble ? glm::vec4(1.0f)
                          : glm::vec4(img.rgba[0], img.rgba[1], img.rgba[2], img.rgba[3]) / 255.0f;
    m.base_color_texture = marble ? c.marble : -1;
}

}  // namespace

bool complete_marble(CourseScene& course) {
    if (marble_complete(course)) return false;
    course.scene.images[static_cast<size_t>(course.marble)] = make_marble(kMarbleSize, kMarbleSeed);
    dress_table(course, true);
    return true;
}

glm::vec3 course_light_position(double t) {
    const float a = turn_angle(t, kLightPeriod);
    return {kLightRadius * std::cos(a), kLightHeight, kLightRadius * std::sin(a)};
}

float course_teapot_lift(double t) {
    // |sin| bounces: the teapot touches the table at t = 0, 1.5, 3, ... and is highest in between.
    return kJumpHeight * std::fabs(std::sin(turn_angle(t, 2.0 * kJumpPeriod)));
}

double course_teapot_landing(double t) {
    // A clock a hair past a landing (sums of frame times) counts as on the table.
    return std::ceil(t / kJumpPeriod - 1e-6) * kJumpPeriod;
}

CourseScene make_course_scene(int teapot_level, bool portal, bool marble_now) {
    CourseScene c;
    Scene& s = c.scene;

    s.meshes.push_back(make_quad(kTableSize, 2.0f));
    s.meshes.push_back(make_teapot(teapot_level));
    c.marble = static_cast<int>(s.images.size());
    s.images.push_back(marble_now ? make_marble(kMarbleSize, kMarbleSeed) : marble_placeholder());

    Material marble;
    marble.name = "marble";
    marble.specular = 0.35f;
    marble.shininess = 48.0f;
    Material porcelain;
    porcelain.name = "teapot";
    porcelain.base_color = glm::vec4(0.85f, 0.45f, 0.25f, 1.0f);
    porcelain.specular = 0.5f;
    porcelain.shininess = 64.0f;
    s.materials = {marble, porcelain};

    Object table;
    table.name = "table";
    table.mesh = 0;
    table.material = 0;
    // The table is drawn into the shadow map too, as in the exercise: the view from the light
    // shows it, and its own self-shadowing is where the encodings' bias thresholds show.
    Object teapot;
    teapot.name = "teapot";
    teapot.mesh = 1;
    teapot.material = 1;
    s.objects = {table, teapot};
    c.table = 0;
    c.teapot = 1;
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = c.table;

    s.light.type = LightType::Point;
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 2.6f, 4.4f), glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(45.0f);
    s.camera.znear = 0.1f;
    s.camera.zfar = 30.0f;
    if (portal)  // drawn only under --effects portal
        if (const auto make = portal_getter()) s.portal = make();

    dress_table(c, marble_now);
    animate_course(c, 0.0, 0.0);
    return c;
}

void animate_course(CourseScene& c, double light_time, double jump_time) {
    Scene& s = c.scene;
    s.light.position = course_light_position(light_time);
    // A point light is aimed at the scene's centre, as the exercise does.
    s.light.direction = glm::normalize(glm::vec3(0.0f) - s.light.position);
    const glm::mat4 lift = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, course_teapot_lift(jump_time), 0.0f));
    s.objects[static_cast<size_t>(c.teapot)].world = glm::scale(lift, glm::vec3(kTeapotScale));
}

}  // namespace penumbra::scene
