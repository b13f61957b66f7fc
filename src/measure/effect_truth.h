// The ground truth of a frame with the stencil effects that show surfaces (--effects mirror,
// portal): what the camera sees in the mirror and through the portal's opening, and whether the
// light reaches it, ray traced by the same tracer (ray_tracer.h) on scenes built for the purpose.
// The renderer's visibility AOV shows the same thing (the surface seen in the mirror or through
// the opening, its visibility whole whatever the reflectivity), so the two can be scored like any
// frame. Native builds only (PENUMBRA_TRUTH).
//
//  - the frame: the scene with the portal's frame and opening added as objects that cast no
//    shadow (the renderer draws the frame after the scene's shadows are made); without a portal,
//    the scene alone;
//  - the mirror (the scene's ground object in its ground plane): where the frame's trace sees the
//    ground, the trace of the mirrored scene takes over: every other object reflected about the
//    plane (winding turned, so front faces stay front faces), the light reflected, the ground
//    left out. The reflection of what is shadowed is what is shadowed in the reflection, so this
//    is the shadows of the reflected ray's hit point. The renderer does not reflect the portal:
//    where the mirror would show the frame or the opening, or an object from the mirror's far side
//    (which the renderer clips away), the pixel is NotModelled;
//  - the portal: where the frame's trace sees the opening, the trace of the other scene through
//    the same camera takes over (its own light and shadows); a hit on the camera's side of the
//    opening's plane (which the renderer clips away) is NotModelled.
// Pixels whose frame trace is a silhouette stay silhouettes: the edges of the mirror and of the
// opening are left out of a comparison as every object's edge is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "measure/ray_tracer.h"
#include "scene/scene.h"

namespace penumbra::measure {

struct EffectTruth {
    TruthImage image;                  // the merged truth (object: the frame trace's, -1 background)
    std::vector<std::uint8_t> region;  // 1 where the mirror or the opening is seen (their pixels)
    std::size_t mirror_pixels = 0, opening_pixels = 0;
};

// mirror: the scene needs a ground plane and object; portal: scene.portal with its other scene.
// Throws std::invalid_argument when an effect asked for has nothing to work on.
EffectTruth trace_effects(const scene::Scene& scene, bool mirror, bool portal, const TruthOptions& options);

// The mirrored scene the mirror's truth traces: every object but the ground reflected about the
// ground plane (its meshes' triangles turned), the light reflected, the ground left out.
scene::Scene mirrored_scene(const scene::Scene& scene);

}  // namespace penumbra::measure
