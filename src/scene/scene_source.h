// A scene by name, as every front end names it: "teapot" is the course scene (animated by t),
// anything else a glTF 2.0 file (static).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenes/course_scene.h"
#include "scene/eye.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"

namespace penumbra::scene {

class SceneSource {
public:
    // Returns false with `error` set (one line) when the scene cannot be loaded; warnings are
    // the loader's notes (a missing camera or light replaced by a default).
    bool open(const std::string& name, std::string& error, std::vector<std::string>& warnings,
              int teapot_level = 10, const LoadOptions& load = {});
    // The scene at time t (both the light's and the jump's clocks at t), seen from the eye.
    const Scene& at(double t);
    // Where at() puts the eye from now on (Eye::Scene: the scene's own camera).
    void set_eye(Eye eye);
    bool animated() const { return course_.has_value(); }

private:
    std::optional<CourseScene> course_;
    Scene static_;
    Eye eye_ = Eye::Scene;
    Camera camera_;  // the scene's own
};

}  // namespace penumbra::scene
