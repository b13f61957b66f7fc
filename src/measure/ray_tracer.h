// The ground truth for the shadow renderer: an independent CPU ray tracer on Embree 3. For the
// same camera and pixels as the renderer (its view-projection, pixel centres, top row first) it
// finds the surface first hit from the camera and whether the light reaches it, and says which
// pixels a comparison may use. It shares only the scene data (scene::Scene) with the renderer,
// never its shadow code. Native builds only (CMake option PENUMBRA_TRUTH).
//
// Definitions (docs/tradeoffs.md repeats them):
//  - camera ray: the pixel centre (x + 0.5, y + 0.5) unprojected through inverse(view_proj) at
//    NDC z = -1 and z = +1; it runs from the near plane to the far plane. Back faces are skipped,
//    as the renderer's camera pass culls them (counter-clockwise triangles are front faces).
//  - geometric normal: the triangle's face normal in world space (from its world-space vertices),
//    turned towards the camera.
//  - shadow ray: from the hit point towards the point light's position (spot lights alike) or
//    against a directional light's direction, starting on its own line epsilon / dot(normal, ray)
//    from the hit point (at most 10 x epsilon), epsilon = 1e-4 x the diagonal of the scene's
//    bounds: off its own triangle, and on the exact line to the light, so that no shadow edge
//    moves (a start moved along the normal would move each by epsilon x cot(the light's
//    elevation)); any shadow-casting triangle, front or back, blocks it (the renderer's shadow
//    pass does not cull either). The area light's rays alike, each on its own line.
//  - pixel classes, the first that applies wins:
//      Background  no surface within the camera's depth range;
//      Silhouette  a 4-neighbour is discontinuous with the pixel (see below): a one-pixel band on
//                  both sides of every silhouette, where a rasteriser and a ray may see different
//                  surfaces through the same pixel centre;
//      NotReceiver the object does not receive shadows (the renderer leaves it lit on purpose);
//      FacingAway  the geometric normal faces away from the light (dot(n, L) <= 0): shadowed by
//                  itself, where the renderer's lighting is dark whatever its shadow test says;
//      OutsideCone a spot light's outer cone does not reach the point: no direct light whatever
//                  the shadow test says (the renderer fits its map to the scene, not to the cone);
//      Valid       used by the metrics.
//    Two 4-neighbours p and q are discontinuous when they hit different objects (background
//    counts as one), or when either one's tangent plane, intersected with the other's camera ray,
//    predicts a ray distance off by more than `discontinuity` (relative) from the distance found.
//    Creases on one object are continuous; depth jumps (a handle in front of the body) are not.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::measure {

enum class PixelClass : std::uint8_t {
    Valid = 0,
    Background = 1,
    Silhouette = 2,
    NotReceiver = 3,
    FacingAway = 4,
    OutsideCone = 5,
    NotModelled = 6  // only in an effect's truth (effect_truth.h): what the renderer leaves out there on purpose
};
inline constexpr int kPixelClassCount = 7;
const char* to_string(PixelClass c);

struct TruthOptions {
    int width = 512;
    int height = 512;
    glm::mat4 view_proj{1.0f};  // the renderer's camera_view_proj() for this frame and size
    // Area light (optional, for comparing filtered shadows with a penumbra): visibility averaged
    // over this many stratified samples on a disc facing the surface point, of radius light_radius
    // (world units) at a point or spot light's position, or of angular radius light_radius
    // (radians) around a directional light's direction. 0 samples: no area-light image.
    int soft_samples = 0;
    float light_radius = 0.0f;
    float discontinuity = 0.01f;  // relative ray-distance jump that makes a silhouette
    int threads = 0;              // 0: one per hardware thread
};

struct TruthImage {
    int width = 0;
    int height = 0;
    // Per pixel, top row first:
    std::vector<std::uint8_t> lit;           // 1 where the light reaches the first hit (point light), else 0
    std::vector<float> soft;                 // area-light visibility in [0, 1]; empty without soft samples
    std::vector<std::uint8_t> pixel_class;   // PixelClass
    std::vector<std::int32_t> object;        // the scene object hit, -1 for background
    std::vector<float> distance;             // camera ray distance from the near plane, 0 for background
    std::vector<glm::vec3> position;         // world-space hit point (zero for background)

    bool valid(size_t i) const { return pixel_class[i] == static_cast<std::uint8_t>(PixelClass::Valid); }
    std::vector<std::uint8_t> valid_mask() const;  // 1 where valid
    // The camera's view depth of each hit (distance along its view axis; 0 for background), for
    // the camera `view` the image was traced with.
    std::vector<float> view_depth(const glm::mat4& view) const;
    size_t count(PixelClass c) const;
};

class RayTracer {
public:
    // Builds the acceleration structures from the scene's world-space triangles (objects' meshes
    // under their world matrices) and keeps a copy of its light.
    // Alpha (scene::AlphaMode): a MASK material's texels with alpha below its cutoff (the base
    // texture's alpha, bilinear at the base level, scene::sample_alpha, times the base colour's)
    // stop neither camera nor shadow rays; a double-sided one is hit from behind too. BLEND objects
    // are not seen by camera rays and block shadow rays only with blend_shadows (cut out at their
    // cutoff), as the renderer's --blend-shadows.
    explicit RayTracer(const scene::Scene& scene, bool blend_shadows = false);
    ~RayTracer();
    RayTracer(const RayTracer&) = delete;
    RayTracer& operator=(const RayTracer&) = delete;

    TruthImage render(const TruthOptions& options) const;

    // The offset off the surface for shadow-ray origins (1e-4 x the scene's diagonal).
    float epsilon() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace penumbra::measure
