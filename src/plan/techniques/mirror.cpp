// --effects mirror: the scene's ground object (the course's table top) becomes a planar mirror; a
// share of its colour (--reflectivity) is the scene seen in it. Through the stencil, as the course
// notes teach, after the technique's passes (the opaque image is whole) and before the translucent
// objects' pass:
//
//   mirror-mark     the ground drawn where it is seen (depth test, no depth or colour writes),
//                   marking its pixels 1 in the mirror's stencil bit
//   mirror-far      in the marked pixels the depth set to the far plane (a full-screen triangle at
//                   depth 1 through the stencil: glClear ignores the stencil test), colour kept
//   mirror-depth    every object but the ground through the reflected camera, depth only, in the
//                   marked pixels: the nearest reflected surface of each pixel
//   mirror-sky      the background, r x its colour over (1 - r) x the table's, where nothing was
//                   reflected (depth still 1: depth test equal)
//   mirror-reflect  the reflected objects lit, depth test equal (one fragment a pixel: each pixel
//                   is blended once), r x their colour over (1 - r) x the table's
//   mirror-restore  the ground's depth written back in the marked pixels (depth test always)
//
// The reflected camera is the camera times the reflection R about the mirror's plane: the objects
// stay where they are in the world, so their lighting, the light and the shadow map's lookup are
// the scene's own (the reflection of a shadow is the shadow of the reflection); only the eye moves
// (to R eye) and the triangles' winding turns (culling the front faces instead of the back).
// What lies on the mirror's far side (a teapot sinking into the table; anything below it) would be
// seen in front of the mirror: GLES2 has no user clip planes, so the lit shader discards it
// (REFLECTED: u_clip_plane), per fragment and exact at the plane. An oblique near plane (Lengyel's
// projection whose near plane is the mirror's) would clip without a discard, but it bends the
// depth range of the reflected view (the far plane meets the near one at the mirror's horizon:
// a sky pixel would no longer sit at depth 1, which mirror-sky's depth-equal test needs).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plan/techniques/technique.h"

namespace penumbra::render {

namespace {

constexpr const char* kUse = "mirror: the mirror's pixels";
constexpr int kMarked = 1;

bool has_mirror(const PlanContext& c) {
    const int g = c.scene.ground_object;
    return c.scene.ground_plane && g >= 0 && g < static_cast<int>(c.scene.objects.size()) &&
           c.scene.objects[static_cast<size_t>(g)].mesh >= 0 &&
           c.scene.objects[static_cast<size_t>(g)].mesh < static_cast<int>(c.scene.meshes.size());
}

// The mirror's plane (n, d) with |n| = 1, turned so that the camera is on its positive side; a
// zero vector when the camera lies in the plane (it sees the mirror edge-on: nothing to reflect).
glm::vec4 facing_plane(const PlanContext& c) {
    glm::vec4 p = *c.scene.ground_plane;
    const float len = glm::length(glm::vec3(p));
    if (!(len > 0.0f)) return glm::vec4(0.0f);
    p /= len;
    const float side = glm::dot(p, glm::vec4(c.plan.camera.position, 1.0f));
    if (side == 0.0f) return glm::vec4(0.0f);
    return side > 0.0f ? p : -p;
}

gl::Cull turned(gl::Cull c) {
    return c == gl::Cull::Back ? gl::Cull::Front : c == gl::Cull::Front ? gl::Cull::Back : gl::Cull::None;
}

class MirrorModule : public Module {
public:
    std::string_view name() const override { return "mirror"; }

    std::string check(const PlanContext& c) const override {
        if (!has_mirror(c))
            return "--effects mirror: the scene has no ground plane with an object in it to make a mirror of";
        return stencil_buffer_problem(c, "--effects mirror");
    }

    std::vector<StencilUse> stencil_uses(const PlanContext& c) const override {
        if (!has_mirror(c)) return {};
        return {marking_use(kUse, "mirror")};
    }

    void after_opaque(PlanContext& c) const override {
        if (!has_mirror(c)) return;
        const glm::vec4 plane = facing_plane(c);
        if (plane == glm::vec4(0.0f)) {
            c.plan.notes.push_back("--effects mirror: the camera lies in the mirror's plane; nothing reflected");
            return;
        }
        const Settings& s = c.settings;
        const StencilUse& use = c.stencil(kUse);
        const int ground = c.scene.ground_object;
        // The visibility AOV shows the reflected surfaces' visibility whole (the reflectivity blends colours).
        const bool visibility = s.aov == Aov::Visibility;
        const float r = visibility ? 1.0f : std::clamp(s.reflectivity, 0.0f, 1.0f);

        // The ground as the camera pass shades it (the same vertex shader: the same depths), no colour.
        const auto ground_pass = [&](const char* name) {
            Pass p;
            p.name = name;
            p.module = "mirror";
            p.target = c.camera_target;
            p.state.color_write = false;
            p.state.depth_write = false;
            p.bindings = c.lit_bindings();
            Draw g = c.object_draw(ground);
            g.variant = lit_variant(c.base_features(g));
            g.bindings = (1u << p.bindings.size()) - 1u;
            p.draws.push_back(g);
            return p;
        };
        Pass mark = ground_pass("mirror-mark");
        mark.state.depth_func = gl::Compare::LEqual;
        mark.state.stencil = use.test(gl::Compare::Always, kMarked, gl::StencilOp::Replace);
        mark.detail = "the mirror's seen pixels marked in the stencil (" + use.describe() + "), colour and depth writes off";
        c.add_pass(std::move(mark));

        Pass far = far_plane_pass(c, "mirror-far", "mirror", use, kMarked, glm::vec4(0.0f));
        far.state.color_write = false;
        far.detail = "the depth of the marked pixels set to the far plane (depth 1)";
        c.add_pass(std::move(far));

        // The reflected view: the camera's uniforms with the reflected eye, and the clip plane.
        const glm::mat4 R = scene::reflection(plane);
        std::vector<Binding> bindings = c.lit_bindings();
        for (Uniform& u : bindings[0].uniforms) {
            if (u.name == "u_view_proj") u.value = c.plan.camera.view_proj * R;
            if (u.name == "u_camera_pos") u.value = glm::vec3(R * glm::vec4(c.plan.camera.position, 1.0f));
        }
        bindings.push_back({"mirror", {{"u_clip_plane", plane}, {"u_reflectivity", r}}, {}});
        Pass reflect;
        reflect.name = "mirror-reflect";
        reflect.module = "mirror";
        reflect.target = c.camera_target;
        reflect.state.cull = gl::Cull::Front;
        reflect.state.stencil = use.test(gl::Compare::Equal, kMarked);
        reflect.bindings = std::move(bindings);
        std::vector<CameraItem> items;
        const std::uint32_t all = (1u << reflect.bindings.size()) - 1u;
        for (int i : c.drawable) {
            if (i == ground) continue;
            Draw d = c.object_draw(i);
            d.cull = turned(d.cull.value_or(gl::Cull::Back));
            LitFeatures f = c.base_features(d);
            f.reflected = true;
            reflect.draws.push_back(d);
            items.push_back({i, f, all});
        }
        if (items.empty()) {
            c.plan.notes.push_back("--effects mirror: nothing but the mirror to reflect");
        }
        // Shadows in the reflection: what the technique reads by a lookup (the shadow map, Gooch's
        // texture). The stencil techniques' shadows fall on the mirror itself (planar), or are made
        // for the camera's view only (volumes: the reflection is lit without them), as are the
        // light samples of --area-samples (averaged per pixel of the camera's image).
        if (const std::string unshadowed = shade_after_camera(c, reflect, items); !unshadowed.empty()) {
            c.plan.notes.push_back("--effects mirror: the reflection is lit without shadows (" + unshadowed + ")");
            reflect.detail = ", no shadows";
        }
        set_lit_draws(reflect, items);
        const std::string shading = reflect.detail;

        Pass depth = reflect;
        depth.name = "mirror-depth";
        depth.state.color_write = false;
        depth.detail = std::to_string(items.size()) +
                       " object(s) through the reflected camera (culling front faces, clipped at the mirror's plane), "
                       "depth only, in the marked pixels";
        c.add_pass(std::move(depth));

        const glm::vec3 background = visibility ? glm::vec3(1.0f) : glm::vec3(kBackground);  // the camera pass's clear
        Pass sky = far_plane_pass(c, "mirror-sky", "mirror", use, kMarked, glm::vec4(background * r, r));
        sky.state.depth_func = gl::Compare::Equal;
        sky.state.depth_write = false;
        sky.state.blend = gl::Blend::Over;
        char buf[192];
        std::snprintf(buf, sizeof buf, "the background reflected where nothing else is (depth still 1): %.3g of it over the mirror", static_cast<double>(r));
        sky.detail = buf;
        c.add_pass(std::move(sky));

        reflect.state.depth_func = gl::Compare::Equal;
        reflect.state.depth_write = false;
        reflect.state.blend = gl::Blend::Over;
        std::snprintf(buf, sizeof buf, "the nearest reflected surfaces lit (depth equal), %.3g of their colour over the mirror's",
                      static_cast<double>(r));
        reflect.detail = buf + shading;
        c.add_pass(std::move(reflect));

        Pass restore = ground_pass("mirror-restore");
        restore.state.depth_func = gl::Compare::Always;
        restore.state.depth_write = true;
        restore.state.stencil = use.test(gl::Compare::Equal, kMarked);
        restore.detail = "the mirror's depth written back in the marked pixels";
        c.add_pass(std::move(restore));
    }
};

}  // namespace

const Module& mirror_module() {
    static const MirrorModule m;
    return m;
}

}  // namespace penumbra::render
