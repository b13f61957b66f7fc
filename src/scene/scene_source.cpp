#include "scene/scene_source.h"

#include "scene/gltf_loader.h"
#include "scene/memory_budget.h"
#include "scenes/scale_scenes.h"

namespace penumbra::scene {

namespace {

// "pile:100000: 100001 objects, 600002 triangles": what the memory budget's refusal names.
std::string describe_size(const std::string& name, const Scene& s) {
    std::size_t triangles = 0;
    for (const Object& o : s.objects)
        if (o.mesh >= 0 && o.mesh < static_cast<int>(s.meshes.size())) triangles += s.meshes[static_cast<size_t>(o.mesh)].indices.size() / 3;
    return name + ": " + std::to_string(s.objects.size()) + " objects, " + std::to_string(triangles) + " triangles";
}

}  // namespace

bool SceneSource::open(const std::string& name, std::string& error, std::vector<std::string>& warnings,
                       int teapot_level, const LoadOptions& load) {
    memory::Guard guard("loading the scene");
    memory::set_subject(name);
    course_.reset();
    if (name == "teapot") {
        course_ = make_course_scene(teapot_level);
        return true;
    }
    if (is_scale_name(name)) {
        ScaleSpec spec;
        if (!parse_scale_name(name, spec, error)) return false;
        static_ = make_scale_scene(spec);
        memory::set_subject(describe_size(name, static_));
        return true;
    }
    LoadResult r = load_gltf(name, load);
    warnings = r.warnings;
    if (!r.ok) {
        error = r.error;
        return false;
    }
    static_ = std::move(r.scene);
    memory::set_subject(describe_size(name, static_));
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
