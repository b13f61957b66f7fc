// Planar projected shadows (seed 001): the projection that squashes casters onto a receiving
// plane, generalised to homogeneous lights so one matrix serves point and directional lights.
#include "shadow/planar.h"

namespace penumbra::shadow {

// With P = plane and L = light (both homogeneous), M = (P.L) I - L P^T. For any x:
//   P.(M x) = (P.L)(P.x) - (P.L)(P.x) = 0           -> M x lies on the plane;
//   M x = (P.L) x - (P.x) L                          -> a combination of x and L, so on their line.
// A point already on the plane (P.x = 0) maps to (P.L) x: the same point after the divide.
// The resulting w is (P.L) x.w - (P.x) L.w. For a light on the plane's positive side (P.L > 0,
// the usual case) and x between the light and the plane, w > 0, so GL clips nothing it should
// keep. For a light on the negative side the whole matrix is negated (the same projective map)
// to keep that property.
glm::mat4 planar_projection(const glm::vec4& plane, const glm::vec4& light) {
    const float pl = glm::dot(plane, light);
    // outerProduct(c, r) is c r^T: column j of L P^T is L * P[j].
    glm::mat4 m = glm::mat4(pl) - glm::outerProduct(light, plane);
    if (pl < 0.0f) m = -m;
    return m;
}

}  // namespace penumbra::shadow
