// The frame shapes: how plan() arranges the technique's passes around the camera's. Each shape is
// a file of its own behind one entry (plan_frame_shape), tried in order, the first that applies
// planning the frame:
//
//   deferred      --shading deferred: a G-buffer, then its pixels lit (deferred.cpp)
//   area light    --area-samples N: the technique run from N points on the light, averaged
//                 (Heckbert and Herf; area_light.cpp)
//   shadow blur   --post shadow-blur:R: the technique's visibility blurred in screen space before
//                 shading (shadow_blur.cpp)
//   forward       one hard shadow: the technique's passes, the camera's, the technique's after it
//                 (forward.cpp)
//
// A shape asks the technique only what Module declares (shadows(), soft_by_itself(),
// later_pass_problem(), shades_deferred(), own_aov()): none names a technique. No GL here.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "plan/techniques/technique.h"

namespace penumbra::render {

// Everything plan() and check() share: the context with the scene's requirements gathered, the
// technique's module, the effects drawn, and the frame's stencil after allocate().
struct Planning {
    FramePlan plan;
    PlanContext ctx;
    const Module& module;
    std::vector<const Module*> effects;  // drawn on the colour image (the mirror and portal on visibility too)
    size_t technique_uses = 0;           // plan.stencil's first uses are the technique's (allocate)

    Planning(const scene::Scene& scene, const Settings& s, const gl::Caps& caps, const FrameInputs& in,
             const FramePlan* previous);
    // Declares every use of the frame in the plan and gives each its bits: "" or why they do not fit.
    std::string allocate();
    bool stencil() const { return !plan.stencil.empty(); }
    bool technique_stencil() const { return technique_uses > 0; }
    bool effect_stencil() const { return plan.stencil.size() > technique_uses; }
};

// A frame shape: whether this frame takes it (if not but it was asked for, why: a note), and its
// passes.
struct FrameShape {
    const char* name;
    bool (*applies)(const PlanContext& c, std::string* why);
    void (*plan)(Planning& p);
};

// Plans the frame with the first shape that applies (each shape asked for but not taken notes why).
void plan_frame_shape(Planning& p);

// ---- what the shapes share (forward.cpp) --------------------------------------------------------

// The resource behind a texture output: colour, and depth (with stencil where a technique needs it).
ResourceDesc texture_desc(const Output& o, const gl::Caps& caps, bool stencil);
// The camera pass into c.camera_target: every drawable object the module leaves in, shaded with
// the module's features; `extra` (may be null) adds features and bindings after the module's.
Pass camera_pass(PlanContext& c, const Module& module, bool stencil,
                 void (*extra)(PlanContext&, Pass&, std::vector<CameraItem>&) = nullptr);
// The glTF BLEND objects after everything else, back to front, blended (forward.cpp says more).
void blend_pass(PlanContext& c, const Module& module);
// The texture unit of the screen-space visibility (the light samples' sum, the blurred visibility).
inline constexpr int kAreaUnit = 0;
// The lit shader's screen-space visibility (AREA_LOOKUP) for every receiver of the camera pass:
// dot(the texel of `resource` under the pixel, `weights`), bound as `binding`.
void screen_lookup(PlanContext& c, Pass& cam, std::vector<CameraItem>& items, const char* resource,
                   const glm::vec4& weights, const char* binding);
// The technique's passes before and after a camera pass into `target` with `settings` (a hard
// visibility: a light sample's, the visibility to blur): `light` its light, `previous` the plan
// whose resources it may reuse. The camera pass is named `name`. `light_sample`: `light` is one
// point of an area light (PlanContext::light_sample).
void plan_hard_visibility(Planning& p, const Settings& settings, const scene::Light& light, const FramePlan* previous,
                          TargetRef target, const char* name, bool light_sample = false);

// The shapes (each file's). A native program has all of them; a browser page's module only the
// forward shape and those its exercise names (Exercise::frames): plan_frame_shape's references to
// the others are weak there, as techniques.cpp's to the technique modules.
const FrameShape& deferred_shape();      // deferred.cpp
const FrameShape& area_light_shape();    // area_light.cpp
const FrameShape& shadow_blur_shape();   // shadow_blur.cpp
extern const FrameShape kForwardShape;   // forward.cpp
// --post blur and bloom (post_passes.cpp): not one of plan_frame_shape's, plan() adds their
// passes after the frame's; reached the same way.
const FrameShape& image_post_shape();
// Whether the shape of that name ("deferred", "area light", "shadow blur", "image post") is in
// this program.
bool frame_shape_linked(std::string_view name);

}  // namespace penumbra::render
