// --lights and --shading: the point lights beside the scene's light, forward or deferred.
//
// Forward: the camera pass adds the first kLightsPerPass lights in its shader (POINT_LIGHTS), and
// each further batch is a pass over the same draws (POINTS_ONLY), depth equal, added.
//
// Deferred: the objects drawn once into a G-buffer (shaders_gles2/include/gbuffer.glsl: colour and
// specular, an octahedral normal in 2 x 16 bits, the depth along the pixel's ray in 24 bits with
// shininess and the receives-shadows flag) -- three colour attachments of one target in one pass
// where the context has EXT_draw_buffers / WEBGL_draw_buffers, else one pass per target, the same
// bytes either way. Then the lighting: the main light with its shadow map in one full-screen pass
// that reads the G-buffer (the same lit.frag, GBUFFER_READ), each point light over the screen
// square its range covers, added; into an RGBA16F target where the context renders half floats
// (then copied to the output), else straight into the output. --aov gbuffer-* shows a target.
#pragma once

#include <string>
#include <vector>

#include "plan/lights.h"
#include "plan/techniques/technique.h"

namespace penumbra::render {

// "" or why --lights or --shading cannot light this frame (check()).
std::string shading_problem(const PlanContext& c);

// Forward: the camera pass's first batch of point lights (with --lights and --aov color).
void forward_lights(PlanContext& c, Pass& cam, std::vector<CameraItem>& items);
// Forward: the batches after the first, as passes after `cam` (the plan's: copied first where
// there are batches to add, since adding passes moves the plan's).
void add_forward_light_passes(PlanContext& c, const Pass& cam);

// Deferred: the frame from the technique's passes before the camera's to the lit image in
// c.camera_target.
void plan_deferred(PlanContext& c, const Module& module);

// The NDC square (x0, y0, x1, y1) a sphere covers in a view-projection, clamped to the screen;
// the whole screen where the camera is inside the sphere's box or it reaches behind the camera;
// x0 >= x1 when it is off screen.
glm::vec4 screen_square(const glm::mat4& view_proj, const glm::vec3& centre, float radius);

// Shared by the forward lights (forward_lights.cpp) and the deferred frame (deferred.cpp).
// The camera's near and far distances (along its view axis) from its projection; false when the
// far plane is at infinity or the projection is degenerate.
bool near_far(const glm::mat4& proj, float& n, float& f);
// "N what" or "N whats".
std::string count_text(int n, const char* what);
// The u_point_lights uniforms of lights[first .. first + count).
std::vector<Uniform> light_uniforms(const std::vector<PointLight>& lights, size_t first, size_t count);

}  // namespace penumbra::render
