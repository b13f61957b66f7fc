// A scene by name, as every front end names it: "teapot" is the course scene (animated by t),
// anything else a glTF 2.0 file (static).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/course_scene.h"
#include "scene/scene.h"

namespace penumbra::scene {

class SceneSource {
public:
    // Returns false with `error` set (one line) when the scene cannot be loaded; warnings are
    // the loader's notes (a missing camera or light replaced by a default).
    bool open(const std::string& name, std::string& error, std::vector<std::string>& warnings,
              int teapot_level = 10);
    // The scene at time t (both the light's and the jump's clocks at t).
    const Scene& at(double t);
    bool animated() const { return course_.has_value(); }

private:
    std::optional<CourseScene> course_;
    Scene static_;
};

}  // namespace penumbra::scene
