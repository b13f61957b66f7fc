// The fly camera of the exercises with a scene of their own (the cascades exercise over the
// kilometre of terrain, the bulb exercise in the room): where the eye stands and where it looks,
// moved by the page's buttons, keys and drags and the desktop's keys (CourseApp::fly), kept in the
// URL as camera=X,Y,Z,YAW,PITCH, and kept within its scene's bounds. No GL here.
#pragma once

#include <string>
#include <string_view>

#include <glm/glm.hpp>

namespace penumbra::examples {

// Where the eye stands (world metres) and where it looks (degrees: yaw clockwise from north, -z,
// seen from above; pitch up from the horizon, within +-89).
struct FlyCamera {
    glm::vec3 eye{0.0f};
    float yaw = 0.0f;
    float pitch = 0.0f;
};

// Where a fly camera may go in a scene: a camera= value with its eye outside `allowed` is refused
// (`where` says the rule); a move or a value is kept within `keep` and, where the scene has a
// ground, `above` metres over it. `step`: metres a button or key press moves (turns are degrees).
struct FlyBounds {
    glm::vec3 allowed_min{0.0f}, allowed_max{0.0f};
    glm::vec3 keep_min{0.0f}, keep_max{0.0f};
    float (*ground)(float x, float z) = nullptr;
    float above = 0.0f;
    double step = 1.0;
    std::string_view where;
};
// Over the kilometre of terrain: within 2 km of the centre, 0.3 m above the ground, 2 m a step.
const FlyBounds& terrain_fly_bounds();
// In the bulb room: the eye 0.2 m inside the walls, the floor and the ceiling, 0.25 m a step.
const FlyBounds& room_fly_bounds();

// The unit vector the camera looks along.
glm::vec3 fly_forward(const FlyCamera& c);
// Its view matrix (world -> eye, +y up).
glm::mat4 fly_view(const FlyCamera& c);
// The camera where a view matrix puts the eye.
FlyCamera fly_from_view(const glm::mat4& view);
// Moves `forward` metres along the view, `right` metres to the side and `up` metres upwards, then
// turns by `yaw` degrees (to the right) and `pitch` degrees (up), and keeps it within the bounds.
// False (and nothing changed) on a number that is not finite.
bool fly_move(FlyCamera& c, const FlyBounds& b, double forward, double right, double up, double yaw, double pitch);
// "X,Y,Z,YAW,PITCH": millimetres and hundredths of a degree, trailing zeros off.
std::string fly_value(const FlyCamera& c);
// Reads fly_value's form into `out` (kept within the bounds): "" or one line naming the problem
// (out unchanged).
std::string parse_fly(std::string_view text, const FlyBounds& b, FlyCamera& out);

// A scene's fly camera: where it stands, where the scene's own camera stood (the start), whether
// it has left it, and the bounds it is kept in.
struct FlyRig {
    FlyCamera at, start;
    bool moved = false;
    const FlyBounds* bounds = nullptr;

    // At the scene camera's `view`, unmoved, kept in `b`.
    FlyRig(const glm::mat4& view, const FlyBounds& b) : at(fly_from_view(view)), start(at), bounds(&b) {}
    // fly_move within the bounds; false (nothing changed) on a number that is not finite.
    bool move(double forward, double right, double up, double yaw, double pitch);
    void reset();  // back to the start
    // camera=...: "" or the problem (nothing changed).
    std::string set(std::string_view value);
    // The view: the scene camera's `scene_view` exactly until moved, then the fly camera's.
    glm::mat4 view(const glm::mat4& scene_view) const { return moved ? fly_view(at) : scene_view; }
};

}  // namespace penumbra::examples
