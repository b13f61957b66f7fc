// The truth of a frame with the mirror and the portal (effect_truth.h): three traces merged.
#include "measure/effect_truth.h"

#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace penumbra::measure {

namespace {

// (n, d) with |n| = 1; throws on a degenerate plane.
glm::vec4 unit_plane(glm::vec4 p, const char* what) {
    const float len = glm::length(glm::vec3(p));
    if (!(len > 0.0f)) throw std::invalid_argument(std::string(what) + ": a plane without a normal");
    return p / len;
}

// A point in front of the camera's centre pixel, on its near plane: which side of a plane the
// camera is on.
glm::vec3 near_point(const TruthOptions& o) {
    const glm::vec4 p = glm::inverse(o.view_proj) * glm::vec4(0.0f, 0.0f, -1.0f, 1.0f);
    return glm::vec3(p) / p.w;
}

float side(const glm::vec4& plane, const glm::vec3& p) { return glm::dot(glm::vec3(plane), p) + plane.w; }

// Adds the portal's frame and opening to a copy of the scene as objects that cast no shadow;
// returns their indices (frame, opening).
std::pair<int, int> add_portal_objects(scene::Scene& s, const scene::Portal& portal) {
    const scene::Scene& other = *portal.beyond;
    const auto add = [&](int mesh, bool receives, const char* name) {
        scene::Object o;
        o.name = name;
        o.mesh = static_cast<int>(s.meshes.size());
        s.meshes.push_back(other.meshes[static_cast<size_t>(mesh)]);
        o.material = -1;
        if (portal.frame_material >= 0 && portal.frame_material < static_cast<int>(other.materials.size())) {
            scene::Material m = other.materials[static_cast<size_t>(portal.frame_material)];
            m.base_color_texture = -1;  // the truth needs its alpha only: the frame is opaque
            m.alpha_mode = scene::AlphaMode::Opaque;
            o.material = static_cast<int>(s.materials.size());
            s.materials.push_back(m);
        }
        o.world = portal.world;
        o.casts_shadow = false;
        o.receives_shadow = receives;
        s.objects.push_back(o);
        return static_cast<int>(s.objects.size()) - 1;
    };
    const int frame = add(portal.frame_mesh, true, "portal frame");
    const int opening = add(portal.opening_mesh, false, "portal opening");
    return {frame, opening};
}

// Copies pixel i of `from` into `to` (class, light, area light; the object stays the frame's).
void take(TruthImage& to, const TruthImage& from, size_t i) {
    to.lit[i] = from.lit[i];
    to.pixel_class[i] = from.pixel_class[i];
    to.distance[i] = from.distance[i];
    to.position[i] = from.position[i];
    if (!to.soft.empty() && !from.soft.empty()) to.soft[i] = from.soft[i];
}

void not_modelled(TruthImage& t, size_t i) {
    t.lit[i] = 1;
    t.pixel_class[i] = static_cast<std::uint8_t>(PixelClass::NotModelled);
}

}  // namespace

scene::Scene mirrored_scene(const scene::Scene& scene) {
    if (!scene.ground_plane || scene.ground_object < 0 || scene.ground_object >= static_cast<int>(scene.objects.size()))
        throw std::invalid_argument("the mirror's truth: the scene has no ground plane with an object in it");
    const glm::vec4 plane = unit_plane(*scene.ground_plane, "the mirror's truth");
    const glm::mat4 R = scene::reflection(plane);
    scene::Scene m;
    m.materials = scene.materials;
    m.images = scene.images;
    m.camera = scene.camera;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (static_cast<int>(i) == scene.ground_object) continue;
        scene::Object o = scene.objects[i];
        if (o.mesh < 0 || o.mesh >= static_cast<int>(scene.meshes.size())) continue;
        scene::Mesh mesh = scene.meshes[static_cast<size_t>(o.mesh)];
        // R turns the winding: swap two corners of every triangle so its front stays its front.
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
        mesh.topology.reset();
        o.mesh = static_cast<int>(m.meshes.size());
        m.meshes.push_back(std::move(mesh));
        o.world = R * o.world;
        m.objects.push_back(o);
    }
    m.light = scene.light;
    m.light.position = glm::vec3(R * glm::vec4(scene.light.position, 1.0f));
    m.light.direction = glm::vec3(R * glm::vec4(scene.light.direction, 0.0f));
    return m;
}

EffectTruth trace_effects(const scene::Scene& scene, bool mirror, bool portal, const TruthOptions& options) {
    if (portal && !(scene.portal && scene.portal->beyond))
        throw std::invalid_argument("the portal's truth: the scene has no portal");
    const auto mesh_ok = [&](int m) { return m >= 0 && m < static_cast<int>(scene.portal->beyond->meshes.size()); };
    if (portal && !(mesh_ok(scene.portal->opening_mesh) && mesh_ok(scene.portal->frame_mesh)))
        throw std::invalid_argument("the portal's truth: the portal's meshes are not in its scene");

    // The frame: the scene, with the portal's frame and opening when the portal is on.
    scene::Scene framed = scene;
    framed.portal.reset();
    int frame = -1, opening = -1;
    if (portal) std::tie(frame, opening) = add_portal_objects(framed, *scene.portal);
    EffectTruth out;
    out.image = RayTracer(framed).render(options);
    TruthImage& t = out.image;
    const size_t n = t.lit.size();
    out.region.assign(n, 0);
    const glm::vec3 eye_side = near_point(options);
    const auto silhouette = [&](size_t i) { return t.pixel_class[i] == static_cast<std::uint8_t>(PixelClass::Silhouette); };

    if (mirror) {
        scene::Scene m = mirrored_scene(scene);
        // What the renderer does not reflect (the portal's frame and opening) is traced too, so
        // that the pixels where the mirror would show it are known and left out.
        int frame_m = -1, opening_m = -1;
        if (portal) {
            scene::Scene with = m;
            std::tie(frame_m, opening_m) = add_portal_objects(with, *scene.portal);
            const glm::mat4 R = scene::reflection(unit_plane(*scene.ground_plane, "the mirror's truth"));
            for (int k : {frame_m, opening_m}) {
                scene::Object& o = with.objects[static_cast<size_t>(k)];
                scene::Mesh& mesh = with.meshes[static_cast<size_t>(o.mesh)];
                for (size_t q = 0; q + 2 < mesh.indices.size(); q += 3) std::swap(mesh.indices[q + 1], mesh.indices[q + 2]);
                o.world = R * o.world;
            }
            m = std::move(with);
        }
        const TruthImage r = RayTracer(m).render(options);
        const glm::vec4 plane = unit_plane(*scene.ground_plane, "the mirror's truth");
        const float eye = side(plane, eye_side);
        for (size_t i = 0; i < n; ++i) {
            if (t.object[i] != scene.ground_object) continue;
            out.region[i] = 1;
            ++out.mirror_pixels;
            if (silhouette(i)) continue;
            take(t, r, i);
            if (r.object[i] < 0) continue;  // the background, reflected
            // The reflection of an object on the mirror's far side lies on the camera's side.
            const bool far_side = side(plane, r.position[i]) * eye > 0.0f;
            if (far_side || r.object[i] == frame_m || r.object[i] == opening_m) not_modelled(t, i);
        }
    }
    if (portal) {
        const scene::Scene& other = *scene.portal->beyond;
        const TruthImage b = RayTracer(other).render(options);
        const glm::mat4& w = scene.portal->world;
        const glm::vec3 normal = glm::normalize(glm::transpose(glm::inverse(glm::mat3(w))) * glm::vec3(0.0f, 0.0f, 1.0f));
        const glm::vec4 plane(normal, -glm::dot(normal, glm::vec3(w[3])));
        const float eye = side(plane, eye_side);
        for (size_t i = 0; i < n; ++i) {
            if (t.object[i] != opening) continue;
            out.region[i] = 1;
            ++out.opening_pixels;
            if (silhouette(i)) continue;
            take(t, b, i);
            if (b.object[i] >= 0 && side(plane, b.position[i]) * eye > 0.0f) not_modelled(t, i);
        }
    }
    return out;
}

}  // namespace penumbra::measure
