#include "scene/scene_source.h"

#include "scene/gltf_loader.h"
#include "scenes/scale_scenes.h"

namespace penumbra::scene {

bool SceneSource::open(const std::string& name, std::string& error, std::vector<std::string>& warnings,
                       int teapot_level, const LoadOptions& load) {
    course_.reset();
    if (name == "teapot") {
        course_ = make_course_scene(teapot_level);
        return true;
    }
    if (is_scale_name(name)) {
        ScaleSpec spec;
        if (!parse_scale_name(name, spec, error)) return false;
        static_ = make_scale_scene(spec);
        return true;
    }
    LoadResult r = load_gltf(name, load);
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
    if (eye_ == Eye::InShadow) place_eye_in_shadow(course_->scene);
    return course_->scene;
}

void SceneSource::set_eye(Eye eye) {
    Scene& s = course_ ? course_->scene : static_;
    if (eye_ == Eye::Scene) camera_ = s.camera;
    eye_ = eye;
    s.camera = camera_;
    if (eye == Eye::InShadow && !course_) place_eye_in_shadow(static_);
}

}  // namespace penumbra::scene
