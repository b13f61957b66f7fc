#include "scene/scene.h"

namespace penumbra::scene {

Bounds mesh_bounds(const Mesh& mesh) {
    Bounds b;
    for (const auto& p : mesh.positions) b.add(p);
    return b;
}

std::vector<glm::vec3> corners(const Bounds& b) {
    std::vector<glm::vec3> out;
    out.reserve(8);
    for (int i = 0; i < 8; ++i)
        out.emplace_back((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    return out;
}

Bounds object_bounds(const Scene& scene, const Object& object) {
    Bounds out;
    if (object.mesh < 0 || object.mesh >= static_cast<int>(scene.meshes.size())) return out;
    const Bounds local = mesh_bounds(scene.meshes[static_cast<size_t>(object.mesh)]);
    if (local.empty()) return out;
    for (const auto& c : corners(local)) out.add(glm::vec3(object.world * glm::vec4(c, 1.0f)));
    return out;
}

Bounds scene_bounds(const Scene& scene, bool casters_only) {
    Bounds out;
    for (const auto& o : scene.objects)
        if (!casters_only || o.casts_shadow) out.add(object_bounds(scene, o));
    return out;
}

}  // namespace penumbra::scene
