// The shadow map's lookup uniforms for its two many-map layouts, cascades and a cube's faces, and
// the cube's guard band: what the camera pass reads the atlas with (shadow.glsl). Apart from
// shadow_map.cpp, which plans the passes that fill the atlas.
#include "plan/techniques/shadow_lookup.h"

#include <algorithm>
#include <string>

#include "plan/techniques/reports.h"

namespace penumbra::render {

// The cascades' uniforms (shadow.glsl, CASCADES): the light's axes (the same view for every
// cascade), per cascade the scale and offset from the light's eye space to its own map's [0, 1]
// coordinates, its tile of the atlas and its extents for the slope bias; the slices' far ends and
// blend bands; the camera's view depth.
void add_cascade_uniforms(const PlanContext& c, Binding& b, const ResourceDesc& map) {
    const auto& cascades = cascades_of(c.plan);
    const float w = static_cast<float>(map.width), h = static_cast<float>(map.height);
    const float tile = w / 2.0f;
    glm::vec4 ends(0.0f), bands(0.0f);
    for (size_t i = 0; i < cascades.size(); ++i) {
        const shadow::Cascade& k = cascades[i];
        const std::string at = "[" + std::to_string(i) + "]";
        // Texture space = clip / 2 + 1/2, and an orthographic clip space is eye space scaled and
        // offset per axis: P[i][i] and P[3][i].
        const glm::mat4& P = k.frustum.proj;
        b.uniforms.push_back({"u_cascade_scale" + at, 0.5f * glm::vec3(P[0][0], P[1][1], P[2][2])});
        b.uniforms.push_back({"u_cascade_offset" + at, 0.5f * glm::vec3(P[3][0], P[3][1], P[3][2]) + glm::vec3(0.5f)});
        b.uniforms.push_back({"u_cascade_tile" + at, glm::vec4(static_cast<float>(k.tile_x) / w,
                                                               static_cast<float>(k.tile_y) / h, tile / w, tile / h)});
        b.uniforms.push_back({"u_cascade_slope" + at, glm::vec4(1.0f / k.frustum.proj[0][0], 1.0f / k.frustum.proj[1][1],
                                                                k.frustum.znear, k.frustum.zfar)});
        ends[static_cast<int>(i)] = k.end;
        bands[static_cast<int>(i)] = k.band;
    }
    // Beyond the last cascade: the last's end (the lookup there says lit outside its window).
    for (size_t i = cascades.size(); i < 4; ++i) ends[static_cast<int>(i)] = cascades.back().end;
    b.uniforms.push_back({"u_cascade_light", cascades.front().frustum.view});
    b.uniforms.push_back({"u_cascade_end", ends});
    b.uniforms.push_back({"u_cascade_band", bands});
    const glm::mat4& v = c.plan.camera.view;
    b.uniforms.push_back({"u_cascade_depth", -glm::vec4(v[0][2], v[1][2], v[2][2], v[3][2])});
}

// Texels of each cube face's tile beyond its 90 degrees, per side, so that a filter's taps near a
// face's edge read the depth of the directions there instead of the edge's texel again: none for
// one tap (it never leaves the face by more than half a texel, and the clamp to the tile holds
// it); PCF's reach (1.5 texels and the nearest texel's half) for PCF; PCSS's taps reach up to an
// eighth of the map, so it gets a 32nd of the tile and its widest penumbrae near an edge are
// clamped. Measured on bulb_room.gltf, PCF 4x4, within 2 pixels of a seam: 1.147 % -> 1.016 %
// of error at 128 texels, 0.443 % -> 0.382 % at 256 (docs/cube.md).
int cube_guard(const Settings& s, int size) {
    switch (s.filter) {
        case shadow::Filter::Hard: return 0;
        case shadow::Filter::PCSS: return std::max(4, size / 32);
        default: return 2;
    }
}

// The cube's uniforms (shadow.glsl, CUBE): the light's position, each face's tile (zw 0: not
// drawn), and the one projection's constants: tangent to texture, and the window depth of a depth
// d along a face's axis, f / (f - n) - (f n / (f - n)) / d.
void add_cube_uniforms(const shadow::CubeFit& fit, const scene::Light& light, Binding& b, const ResourceDesc& map) {
    const float w = static_cast<float>(map.width), h = static_cast<float>(map.height);
    const float t = static_cast<float>(fit.tile);
    for (int f = 0; f < shadow::kCubeFaces; ++f) {
        const shadow::CubeFace& face = fit.faces[static_cast<size_t>(f)];
        b.uniforms.push_back({"u_cube_tile[" + std::to_string(f) + "]",
                              face.drawn ? glm::vec4(static_cast<float>(face.tile_x) / w, static_cast<float>(face.tile_y) / h,
                                                     t / w, t / h)
                                         : glm::vec4(0.0f)});
    }
    const float n = fit.znear, f = fit.zfar;
    b.uniforms.push_back({"u_cube_light", light.position});
    b.uniforms.push_back({"u_cube_depth", glm::vec3(0.5f / fit.tangent, f / (f - n), f * n / (f - n))});
}

}  // namespace penumbra::render
