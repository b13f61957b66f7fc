// Omnidirectional shadows for a point light (course notes 000: one shadow map is "not
// omnidirectional"): six perspective maps, the faces of a cube around the light, tiles of one
// atlas texture 3 x 2 (an unfolded cube, read with texture2D like every other map: docs/cube.md).
// Each face looks along one axis with a field of view a little over 90 degrees, so the tile holds
// a guard band of texels beyond the face's edge: a filter's taps near the edge read real depth
// from the neighbouring face's directions and a shadow crossing the edge stays continuous. Only
// the faces that see a receiver the camera sees are drawn, each with the casters inside its
// pyramid. No GL here.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "shadow/light_frustum.h"

namespace penumbra::shadow {

inline constexpr int kCubeFaces = 6;

// Face i looks along +x, -x, +y, -y, +z, -z (i = 0..5): its view's rotation (world directions
// into the face's eye space, the face looking down -z). The shader's cubeFaceEye is this by hand.
glm::mat3 cube_face_rotation(int face);
// The face a direction from the light falls in: its largest component's axis and sign (ties: x
// before y before z). The shader's cubeFace.
int cube_face_of(const glm::vec3& direction);
const char* cube_face_name(int face);  // "+x"

struct CubeFace {
    LightFrustum frustum;     // perspective, the guard band included
    int tile_x = 0, tile_y = 0;  // its tile's lower-left texel in the atlas
    bool drawn = false;       // it sees a receiver the camera sees
    std::vector<int> casters; // indices into fit_cube's `casters` inside its pyramid (drawn faces only)
};

struct CubeFit {
    std::array<CubeFace, kCubeFaces> faces;
    float znear = 0.0f, zfar = 0.0f;  // along each face's axis, the same for all
    float tangent = 1.0f;   // the half-extent of each face's window in tangent units (1: exactly 90 degrees)
    // The half-extent of the pyramid a face is drawn for (a visible receiver in it) and draws the
    // casters of: `tangent` in an atlas; in a cube map, the guard band's (the filter's taps past a
    // face's edge read the next face, which must hold that depth).
    float reach = 1.0f;
    int tile = 0;           // texels per side of each face
    int guard = 0;          // texels of each tile beyond the face's 90 degrees, per side (a cube map's: read from the next face)
    bool cube_map = false;  // the faces of a GL cube map (each exactly 90 degrees), not tiles of an atlas
    int atlas_width = 0, atlas_height = 0;  // 3 x 2 tiles (a cube map: one face's size)
    std::vector<glm::vec3> visible;  // the receivers' points the camera sees (visible_receiver_points)
    int drawn() const;
};

// The cube of this frame, or no drawn face and "" in `why` when it cannot be made: the light is
// not a point light, or the camera sees no receiver. `tile`: texels per side of a face; `guard`:
// texels of it beyond the face's edge, per side (at least a filter's reach). `cube_map`: the faces
// of a GL cube map instead, exactly 90 degrees each, a face drawn when a visible receiver is within
// `guard` texels of it.
CubeFit fit_cube(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                 const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj, int tile, int guard,
                 std::string* why, bool cube_map = false);

// --cascades auto for a point light: a cube when the light is inside the receivers' bounds (a bulb
// in a room) or inside the casters' (they surround it), where one frustum cannot hold what it
// lights; otherwise one map. `why`: one line.
bool cube_wanted(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                 const std::vector<scene::Bounds>& casters, std::string& why);

}  // namespace penumbra::shadow
