// CourseApp's scenes: the course scene, made on first use, and the scenes of the exercises that
// fly (the bulb room, the terrain), each with its fly camera, made the first time it is shown.
#include "exercises.h"

#include <cstddef>
#include <memory>

namespace penumbra::examples {

scene::CourseScene& CourseApp::made_course() const {
    if (course_) return *course_;
    course_ = scene::make_course_scene(10, false, !defer_marble_);
    scene_camera_ = course_->scene.camera;
    // What any exercise's frames add to the course scene (W09P2b's ground), before a GL object is made.
    for (const Exercise& x : exercise_list())
        if (x.extend_course) x.extend_course(course_->scene);
    return *course_;
}

bool CourseApp::complete_scene() {
    const bool made = !course_;
    scene::CourseScene& course = made_course();
    if (!scene::complete_marble(course)) return made;
    // The texture changed in place: uploaded again where the course scene is the renderer's (a
    // scene not loaded is uploaded whole, marble and all, by the first frame that draws it).
    if (renderer_ && renderer_->has_loaded(course.scene))
        renderer_->update_image(static_cast<std::size_t>(course.marble), course.scene.images[static_cast<std::size_t>(course.marble)]);
    return true;
}

bool CourseApp::scene_complete() const { return course_ && scene::marble_complete(*course_); }

CourseApp::OwnScene* CourseApp::own_scene() {
    const Exercise& x = *exercise_;
    if (!flies(x)) return nullptr;
    auto it = own_.find(x.name);
    if (it == own_.end()) {
        auto made = std::make_unique<scene::Scene>(x.make_scene());
        const scene::Camera camera = made->camera;
        it = own_.emplace(x.name, OwnScene{std::move(made), camera, FlyRig(camera.view, x.fly_bounds())}).first;
    }
    return &it->second;
}

const CourseApp::OwnScene* CourseApp::own_scene() const {
    const auto it = own_.find(exercise_->name);
    return it != own_.end() ? &it->second : nullptr;
}

const scene::Scene& CourseApp::scene() const {
    const OwnScene* o = own_scene();
    return o ? *o->scene : made_course().scene;
}

bool CourseApp::fly(double forward, double right, double up, double yaw, double pitch) {
    OwnScene* o = own_scene();
    return o && o->fly.move(forward, right, up, yaw, pitch);
}

void CourseApp::reset_camera() {
    if (OwnScene* o = own_scene()) o->fly.reset();
}

bool CourseApp::camera_moved() const {
    const OwnScene* o = own_scene();
    return o && o->fly.moved;
}

const FlyCamera& CourseApp::camera() const {
    static const FlyCamera none;
    const OwnScene* o = own_scene();
    return o ? o->fly.at : none;
}

double CourseApp::fly_step() const { return own_scene() ? exercise_->fly_bounds().step : 0.0; }

}  // namespace penumbra::examples
