#include "scene/scene_source.h"

#include "scene/gltf_loader.h"

namespace penumbra::scene {

bool SceneSource::open(const std::string& name, std::string& error, std::vector<std::string>& warnings,
                       int teapot_level) {
    course_.reset();
    if (name == "teapot") {
        course_ = make_course_scene(teapot_level);
        return true;
    }
    LoadResult r = load_gltf(name);
    warnings = r.warnings;
    if (!r.ok) {
        error = r.error;
        return false;
    }
    static_ = std::move(r.scene);
    return true;
}

const Scene& SceneSource::at(double t) {
    if (!course_) return static_;
    animate_course(*course_, t, t);
    return course_->scene;
}

}  // namespace penumbra::scene
