// The light's view and projection, fitted tightly around the points that must be in the map
// (exercise W09P2a): perspective for point and spot lights, orthographic for directional ones.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "shadow/casting.h"
#include "shadow/convex.h"

namespace penumbra::shadow {

struct LightFrustum {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    float znear = 0.1f;  // distances along the light's view axis (eye space -z)
    float zfar = 1.0f;
    bool perspective = true;
    glm::mat4 view_proj() const { return proj * view; }
};

// Fit the light's frustum around `points` (world space: the corners of every caster's and
// receiver's bounds). A point or spot light looks from its position towards `aim` (the scene's
// centre, as the exercise does); a directional light looks along its direction. The view's up
// vector is chosen so that it is never parallel to the view axis (a light straight overhead).
// Every point lies inside the returned clip volume, with a small margin.
LightFrustum fit_light_frustum(const scene::Light& light, const std::vector<glm::vec3>& points,
                               const glm::vec3& aim);

// The tight fit: the light's frustum around what the camera can see shadowed, not the whole scene.
struct TightFit {
    LightFrustum frustum;
    // The share of the map (0..1) covered by the receivers in view: the area of the convex hull
    // of the visible receiver points in the light's NDC, clipped to [-1,1]^2, over 4.
    float texel_use = 0.0f;
    // Indices into the `casters` argument of those the map must hold (inside the fitted window,
    // no farther from the light than the farthest visible receiver point); every one in the
    // fallback.
    std::vector<int> casters;
    // The points of the receivers inside the camera's view (and a spot light's cone), world space.
    std::vector<glm::vec3> visible;
    // false: the fallback, fit_light_frustum over every caster's and receiver's bounds (no
    // receiver in view, or a point or spot light inside a caster's or receiver's bounds).
    bool tight = false;
    // The shadows fit (fit_light_frustum_shadows): the casters inside the window left out because
    // they shadow no receiver in view, and whether the window was cut to the drawn casters.
    int culled = 0;
    bool cut = false;
    // A perspective fit whose window the 75-degree cap cut: some visible receiver points are
    // outside the map and would count as lit (a wide spot cone, a light low over a long receiver).
    bool capped = false;
};

// The vertices of each receiver box clipped to the camera's clip volume (camera_view_proj) and,
// for a spot light, to the four planes of the pyramid around its outer cone (when under 90
// degrees): every point of a receiver the camera can see lit lies in their convex hulls. Each
// point at least once: a box in view whole gives its eight corners.
std::vector<glm::vec3> visible_receiver_points(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                               const glm::mat4& camera_view_proj);
// The same, one list per receiver (in the order of `receivers`); a box in view whole gives its
// eight corners and a 1 in `whole` (clip_box_by). `also`: further half-spaces to clip by (a cube
// face's frustum, for what that face serves).
std::vector<std::vector<glm::vec3>> visible_points_each(const scene::Light& light,
                                                      const std::vector<scene::Bounds>& receivers,
                                                      const glm::mat4& camera_view_proj, std::vector<char>& whole,
                                                      const std::vector<glm::vec4>& also = {});
// The half-spaces visible_points_each clips each receiver by: the camera's clip volume, the
// pyramid around a spot light's cone, and `also`.
ClipPlanes visible_clip_planes(const scene::Light& light, const glm::mat4& camera_view_proj, const std::vector<glm::vec4>& also = {});
// Where the fits aim: the mean of the receivers' visible points, a box in view whole counted as
// its six faces' 24 corners (in clip_box's order, as the fits counted them before boxes were kept
// whole: the aim, and so every plan, stays the same to the bit).
glm::vec3 visible_centroid(const std::vector<SeenReceiver>& seen);

// The light as a homogeneous point: (position, 1), or (direction towards it, 0); what shadow volumes
// extrude away from and shadow::may_shadow takes.
glm::vec4 light_vector(const scene::Light& light);

// The share of the map of frustum `f` covered by the convex hull of `points` (see TightFit);
// points at or behind a perspective light's eye plane are left out.
float texel_use(const LightFrustum& f, const std::vector<glm::vec3>& points);
// The share of clip space's square (0..1) covered by the convex hull of `points` projected through
// `view_proj`, clipped to [-1,1]^2; points at or behind its eye plane left out. texel_use's, and
// the screen's share the receivers cover (shadow/resolution.h).
float hull_share(const glm::mat4& view_proj, const std::vector<glm::vec3>& points);

// Fit the light's projection to what matters: the visible receiver points, looked at from the
// light (point, spot) towards their centroid or along the light (directional), with an asymmetric
// frustum (tangents) or box around their projected extent (1% margin), the far plane just beyond
// the farthest of them and the near plane just before the nearest of them and of the casters that
// reach into that window (each caster box clipped to the window and the far plane). Every visible
// receiver point, and every point of a caster between the light and one, is inside the returned
// clip volume, except where a perspective window would pass the 75 degree half-angle cap (as in
// fit_light_frustum). Degenerate input falls back to fit_light_frustum (see TightFit::tight).
TightFit fit_light_frustum_tight(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                 const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj);

// What the shadows fit knows beyond the boxes: the scene object of each receiver and caster box,
// which casters cannot shadow themselves (scene::Mesh::convex), and whether to cut the window to
// the casters (false for soft shadows: their penumbrae reach beyond the casters' outlines).
struct CastingInfo {
    std::vector<int> receiver_objects;
    std::vector<int> caster_objects;
    std::vector<char> caster_convex;
    bool fit_window = true;
    // Ask every caster of every receiver in turn, without the index (ReceiverIndex's `linear`):
    // the pairwise rule the tests hold the index to. Casters x receivers: for tests only.
    bool pairwise = false;
};

// The shadows fit (--light-fit shadows): the tight fit, drawing only the casters that can shadow
// a receiver in view (ReceiverIndex::shadows_any; the rest counted in TightFit::culled), with the window
// cut to where their shadows can fall: seen from the light, each drawn caster's part inside the
// window, cut to the visible receivers it may shadow (ReceiverIndex::cut_to_reach; a ground plane under a plank
// that dips below it shadows only the plank's tip, not the whole ground). A visible receiver
// point outside the window can be shadowed by no caster (the lookup reads it as lit). The window
// keeps the tight fit's margin around them.
TightFit fit_light_frustum_shadows(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                   const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj,
                                   const CastingInfo& info);

// The receivers the camera sees (visible_points_each), each with its scene object (`info`); and
// caster box k with its object and convexity: what ReceiverIndex (receiver_index.h) is asked.
std::vector<SeenReceiver> seen_receivers(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                         const glm::mat4& camera_view_proj, const CastingInfo& info);
CasterBox caster_box(const std::vector<scene::Bounds>& casters, const CastingInfo& info, size_t k);

// One flag per caster box: 1 where it can shadow a receiver the camera sees (ReceiverIndex::shadows_any
// over visible_points_each), 0 where a plane proves it cannot: what the shadows fit leaves out.
std::vector<char> shadowing_flags(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                  const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj,
                                  const CastingInfo& info);

// The fit before the tight one (--light-fit scene), also the tight fit's fallback:
// fit_light_frustum around the bounds of every receiver and caster, every caster drawn; `visible`
// and `texel_use` as the tight fit reports them, `tight` false.
TightFit fit_light_frustum_scene(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                                 const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj);

// Matrix that maps clip space [-1,1] to texture space [0,1] (the sheet's B).
glm::mat4 clip_to_texture();

}  // namespace penumbra::shadow
