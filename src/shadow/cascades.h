// Cascaded shadow maps for a directional light (course notes 004: "higher resolution of the depth
// texture near the viewer and lower resolution far away ... splitting the camera view frustum and
// creating a separate depth-map for each partition"). The camera's depth range over the receivers
// it sees is split into N slices; each gets an orthographic map of its own, a tile of one atlas
// texture (WebGL 1 has no texture arrays), fitted around the slice's bounding sphere (its size
// depends only on the slice and the camera's projection, not on where the camera looks), with the
// window's origin snapped to whole texels of the light's fixed axes so that a moving camera does
// not move the texel grid over the world (no shimmer). No GL here.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "shadow/light_frustum.h"

namespace penumbra::shadow {

inline constexpr int kMaxCascades = 4;

struct CascadeOptions {
    int count = 4;        // slices, 1..kMaxCascades
    float split = 0.95f;  // the split distances' blend: 0 uniform, 1 logarithmic (the practical scheme)
    bool snap = true;     // each window's origin on whole texels of the light's axes
    float blend = 0.1f;   // the share of each slice (but the last) at its far end blended into the next, 0..0.5
    int tile = 1024;      // texels per side of each cascade's map
};

struct Cascade {
    LightFrustum frustum;      // orthographic, the light's fixed axes (eye at the world's origin)
    // The camera view depths it serves: [begin, end]; over [end - band, end] its lookup is blended
    // into the next cascade's (band 0: the last). fit_begin: where its sphere starts, the previous
    // cascade's band included (that cascade blends into this one there).
    float begin = 0.0f, end = 0.0f, band = 0.0f, fit_begin = 0.0f;
    glm::vec3 centre{0.0f};    // the slice's bounding sphere, world space
    float radius = 0.0f;
    float texel = 0.0f;        // the world size of one texel of its map
    int tile_x = 0, tile_y = 0;  // its tile's lower-left texel in the atlas
    std::vector<int> casters;  // indices into fit_cascades' `casters`: those that can shadow its window
};

struct CascadeFit {
    std::vector<Cascade> cascades;
    float near = 0.0f, far = 0.0f;  // the camera view depths split (the visible receivers', quantised)
    int columns = 1, rows = 1;      // the atlas in tiles
    int atlas_width = 0, atlas_height = 0;
    glm::vec4 depth_axis{0.0f};     // camera view depth of a world point p: dot(xyz, p) + w
    std::vector<glm::vec3> visible; // the receivers' points the camera sees (visible_receiver_points)
};

// The practical split scheme: count + 1 depths from near to far, each a blend (lambda) of the
// logarithmic split near (far/near)^(i/count) and the uniform one near + (far - near) i / count.
std::vector<float> cascade_splits(float near, float far, int count, float lambda);

// The smallest sphere centred on the camera's view axis around the corners of the slice between
// view depths a and b (a < b), for the projection `proj` (perspective): the centre's view depth
// and the radius. Depends on a, b and the projection alone.
void slice_sphere(const glm::mat4& proj, float a, float b, float& centre_depth, float& radius);

// The perspective projection `proj` with its near and far planes moved to the view depths a and
// b (0 < a < b): the same image (x and y do not depend on them), clipped to the slice between.
glm::mat4 slice_projection(const glm::mat4& proj, float a, float b);

// The light's view with fixed axes: the eye at the world's origin looking along `direction`, up
// +y (or +z when the light is within 8 degrees of vertical).
glm::mat4 light_axes(const glm::vec3& direction);

// The atlas layout of `count` tiles: 2 side by side, 3 or 4 in two rows of two.
void atlas_layout(int count, int& columns, int& rows);

// The cascades of this frame, or "" in `why` and no cascades when they cannot be made: the light
// is not directional, the camera is not perspective, or it sees no receiver.
CascadeFit fit_cascades(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                        const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view,
                        const glm::mat4& camera_proj, const CascadeOptions& options, std::string* why);

// --cascades auto: how many cascades this view wants, and why (one line). A directional light
// whose receivers in view span a depth ratio far/near of R gets ceil(log8 R) cascades, 1..4 (one
// map per factor of 8 in depth: one texel per pixel stays within that factor across a slice);
// any other light, or no receiver in view, one map.
int auto_cascade_count(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                       const glm::mat4& camera_view, const glm::mat4& camera_proj, std::string& why);

}  // namespace penumbra::shadow
