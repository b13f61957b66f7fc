// Omnidirectional shadows: the six faces of a cube around a point light, which of them see what
// the camera sees, and the casters inside each face's pyramid.
#include "shadow/cube.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "shadow/convex.h"

namespace penumbra::shadow {

namespace {

// Each face's axis and up vector (glm::lookAt's): the usual cube-map orientation turned so that
// every face is a right-handed view (a face's triangles keep their winding).
const glm::vec3 kForward[kCubeFaces] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const glm::vec3 kUp[kCubeFaces] = {{0, 1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};

// The four side planes of a face's pyramid (apex at the light, half-extent `t` in tangent
// units) and its front, in the face's eye space: a point e is inside when dot(h.xyz, e) <= 0
// for every h (the eye looks down -z).
std::array<glm::vec3, 5> pyramid(float t) {
    return {glm::vec3(1.0f, 0.0f, t), glm::vec3(-1.0f, 0.0f, t), glm::vec3(0.0f, 1.0f, t), glm::vec3(0.0f, -1.0f, t),
            glm::vec3(0.0f, 0.0f, 1.0f)};
}

// Whether the convex hull of `points` (directions from the light, world) can reach into face
// `face`'s pyramid: no side plane has them all outside. Conservative: it may say yes for a hull
// that misses the pyramid near an edge, never no for one that reaches in.
bool reaches(int face, float t, const std::vector<glm::vec3>& points) {
    if (points.empty()) return false;
    const glm::mat3 r = cube_face_rotation(face);
    for (const glm::vec3& h : pyramid(t)) {
        bool all_out = true;
        for (const glm::vec3& p : points)
            if (glm::dot(h, r * p) <= 0.0f) {
                all_out = false;
                break;
            }
        if (all_out) return false;
    }
    return true;
}

std::vector<glm::vec3> corners(const scene::Bounds& b, const glm::vec3& origin) {
    std::vector<glm::vec3> out;
    for (int i = 0; i < 8; ++i)
        out.push_back(glm::vec3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z) - origin);
    return out;
}

// The least depth (along any face's axis) of a point of box `b` seen from `p`: its per-axis gap's
// largest component (0 when `p` is inside).
float depth_to_box(const scene::Bounds& b, const glm::vec3& p) {
    const glm::vec3 gap = glm::max(glm::max(b.min - p, p - b.max), glm::vec3(0.0f));
    return std::max({gap.x, gap.y, gap.z});
}

float max_norm(const glm::vec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

bool inside(const scene::Bounds& b, const glm::vec3& p) {
    return !b.empty() && glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max));
}

}  // namespace

glm::mat3 cube_face_rotation(int face) {
    return glm::mat3(glm::lookAt(glm::vec3(0.0f), kForward[face], kUp[face]));
}

int cube_face_of(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
    return d.z >= 0.0f ? 4 : 5;
}

const char* cube_face_name(int face) {
    static const char* const names[kCubeFaces] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    return names[face];
}

int CubeFit::drawn() const {
    return static_cast<int>(std::count_if(faces.begin(), faces.end(), [](const CubeFace& f) { return f.drawn; }));
}

CubeFit fit_cube(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                 const std::vector<scene::Bounds>& casters, const glm::mat4& camera_view_proj, int tile, int guard,
                 std::string* why, bool cube_map) {
    CubeFit fit;
    auto fail = [&](const char* reason) {
        if (why) *why = reason;
        return fit;
    };
    // A spot light's cube is the same cube around its position; only the faces its cone reaches
    // are drawn (the visible points below are clipped to the cone).
    if (light.type == scene::LightType::Directional) return fail("the light is directional");
    fit.tile = tile;
    fit.guard = std::clamp(guard, 0, tile / 4);
    fit.cube_map = cube_map;
    fit.reach = static_cast<float>(tile) / static_cast<float>(tile - 2 * fit.guard);
    fit.tangent = cube_map ? 1.0f : fit.reach;
    fit.atlas_width = cube_map ? tile : 3 * tile;
    fit.atlas_height = cube_map ? tile : 2 * tile;
    const glm::vec3 L = light.position;
    // Which faces see a visible receiver: each receiver's visible part (its box clipped to the
    // camera's view, as visible_receiver_points clips it for a point light) tested against each
    // face's pyramid.
    std::vector<char> whole;
    for (std::vector<glm::vec3>& part : visible_points_each(light, receivers, camera_view_proj, whole)) {
        fit.visible.insert(fit.visible.end(), part.begin(), part.end());
        for (glm::vec3& p : part) p -= L;
        for (int f = 0; f < kCubeFaces; ++f)
            if (!fit.faces[static_cast<size_t>(f)].drawn && reaches(f, fit.reach, part))
                fit.faces[static_cast<size_t>(f)].drawn = true;
    }
    if (fit.visible.empty() || fit.drawn() == 0) return fail("the camera sees no receiver");

    // Depth along a face's axis: no visible receiver point is farther than its largest component
    // (a ray from the light to it stays within that), so neither is anything that can shadow it.
    float zfar = 0.0f, znear = std::numeric_limits<float>::max();
    for (const glm::vec3& p : fit.visible) {
        zfar = std::max(zfar, max_norm(p - L));
        znear = std::min(znear, max_norm(p - L));
    }
    zfar *= 1.01f;
    for (int f = 0; f < kCubeFaces; ++f) {
        CubeFace& face = fit.faces[static_cast<size_t>(f)];
        if (!face.drawn) continue;
        for (size_t k = 0; k < casters.size(); ++k) {
            const float d = depth_to_box(casters[k], L);
            if (d >= zfar || !reaches(f, fit.reach, corners(casters[k], L))) continue;
            face.casters.push_back(static_cast<int>(k));
            znear = std::min(znear, d);
        }
    }
    // The near plane just before the nearest of them, but no nearer than 1/2000 of the far one
    // (a caster around the light itself would otherwise take all of the depth's precision).
    fit.znear = std::max(0.95f * znear, zfar / 2000.0f);
    fit.zfar = zfar;
    const glm::mat4 proj = glm::perspective(2.0f * std::atan(fit.tangent), 1.0f, fit.znear, fit.zfar);
    for (int f = 0; f < kCubeFaces; ++f) {
        CubeFace& face = fit.faces[static_cast<size_t>(f)];
        // A cube map's face turned 180 degrees about its axis: textureCube reads a face with s and
        // t against this view's x and y (the GLES 2 spec's table 3.21), for every face.
        face.frustum.view = glm::lookAt(L, L + kForward[f], cube_map ? -kUp[f] : kUp[f]);
        face.frustum.proj = proj;
        face.frustum.znear = fit.znear;
        face.frustum.zfar = fit.zfar;
        face.frustum.perspective = true;
        face.tile_x = cube_map ? 0 : (f % 3) * tile;
        face.tile_y = cube_map ? 0 : (f / 3) * tile;
    }
    if (why) why->clear();
    return fit;
}

bool cube_wanted(const scene::Light& light, const std::vector<scene::Bounds>& receivers,
                 const std::vector<scene::Bounds>& casters, std::string& why) {
    if (light.type != scene::LightType::Point) {
        why = light.type == scene::LightType::Spot ? "one map: a spot light's cone fits one frustum (a cube where the "
                                                     "map's fit finds it does not)"
                                                   : "one map: the light is not a point light";
        return false;
    }
    scene::Bounds r, c;
    for (const scene::Bounds& b : receivers) r.add(b);
    for (const scene::Bounds& b : casters) c.add(b);
    if (inside(r, light.position)) {
        why = "a cube: the point light is inside the receivers' bounds";
        return true;
    }
    if (inside(c, light.position)) {
        why = "a cube: the casters surround the point light";
        return true;
    }
    why = "one map: the point light is outside the scene's bounds";
    return false;
}

}  // namespace penumbra::shadow
