// --effects portal: a frame stands in the scene (scene::Portal: the course scene's at the back of
// the table) and through its opening another scene is seen, with its own objects, light and
// shadows. Through the stencil, as the course notes teach, after the technique's passes (the
// opaque image is whole) and before the translucent objects' pass:
//
//   portal-frame       the frame lit in this scene's light (and its shadow lookup, where the
//                      technique has one), depth tested and written like any object
//   portal-mark        the opening drawn where it is seen (depth test against this scene: what
//                      stands in front of the opening hides it), no colour or depth writes,
//                      marking its pixels 1 in the portal's stencil bit
//   portal-far         in the marked pixels the other scene's sky, and the depth set to the far
//                      plane (a full-screen triangle at depth 1 through the stencil)
//   portal shadow-map  the other scene's shadow map from its own light (a nested plan context:
//                      the shadow map module with the names prefixed "portal ")
//   portal-scene       the other scene's objects lit by its light, looking its shadows up, through
//                      this frame's camera, in the marked pixels only, depth tested among themselves
//   portal-restore     the opening's depth written back in the marked pixels, so that what this
//                      scene draws later (its translucent objects, an outline) meets the opening
//                      as a surface
//
// The other scene lies where the opening looks: it is drawn with the camera's own view, and what
// of it lies on the camera's side of the opening's plane is discarded (CLIPPED: u_clip_plane, as
// the mirror's reflection is; GLES2 has no user clip planes), so an object of the other scene
// never pokes out of the opening towards the viewer.
//
// The other scene is shadow-mapped whatever this scene's technique (its own map, with this
// frame's encoding, filter, bias and precision, rgba where the context has no depth texture);
// --technique none leaves it unshadowed too. The frame is the effect's, not a scene object:
// it is drawn after this scene's shadows were made and casts none (the effects' truth,
// measure/effect_truth.h, adds it as an object that casts none).
#include <cstdio>

#include "plan/techniques/reports.h"
#include "plan/techniques/technique.h"

namespace penumbra::render {

namespace {

constexpr const char* kUse = "portal: the opening's pixels";
constexpr int kMarked = 1;
constexpr const char* kPrefix = "portal ";

const scene::Scene* beyond(const PlanContext& c) {
    const auto& p = c.scene.portal;
    if (!p || !p->beyond) return nullptr;
    const scene::Scene& b = *p->beyond;
    const auto mesh_ok = [&](int m) { return m >= 0 && m < static_cast<int>(b.meshes.size()); };
    return mesh_ok(p->opening_mesh) && mesh_ok(p->frame_mesh) ? &b : nullptr;
}

// The opening's plane (n, d) in the world with |n| = 1, turned so that the camera is on its
// negative side (the other scene, kept where n.p + d >= 0, is the far side); zero when the camera
// lies in the plane.
glm::vec4 far_side(const PlanContext& c) {
    const glm::mat4& w = c.scene.portal->world;
    const glm::vec3 n = glm::normalize(glm::transpose(glm::inverse(glm::mat3(w))) * glm::vec3(0.0f, 0.0f, 1.0f));
    const glm::vec4 p(n, -glm::dot(n, glm::vec3(w[3])));
    const float side = glm::dot(p, glm::vec4(c.plan.camera.position, 1.0f));
    if (!(side * side > 0.0f)) return glm::vec4(0.0f);
    return side > 0.0f ? -p : p;
}

class PortalModule : public Module {
public:
    std::string_view name() const override { return "portal"; }

    std::string check(const PlanContext& c) const override {
        if (!beyond(c))
            return "--effects portal: the scene has no portal to draw (the course scene, --scene teapot, has one; "
                   "a glTF scene has none)";
        return stencil_buffer_problem(c, "--effects portal");
    }

    std::vector<StencilUse> stencil_uses(const PlanContext& c) const override {
        if (!beyond(c)) return {};
        return {marking_use(kUse, "portal")};
    }

    void after_opaque(PlanContext& c) const override {
        const scene::Scene* other = beyond(c);
        if (!other) return;
        const scene::Portal& portal = *c.scene.portal;
        const glm::vec4 plane = far_side(c);
        if (plane == glm::vec4(0.0f)) {
            c.plan.notes.push_back("--effects portal: the camera lies in the opening's plane; nothing seen through it");
            return;
        }
        const StencilUse& use = c.stencil(kUse);

        // The frame and the opening: draws of the portal's meshes in this scene (no scene object).
        const auto portal_draw = [&](int mesh, const char* label) {
            Draw d;
            d.label = label;
            d.mesh = mesh;
            d.material = portal.frame_material;
            d.world = portal.world;
            d.beyond = true;
            return d;
        };

        Pass frame;
        frame.name = "portal-frame";
        frame.module = "portal";
        frame.target = c.camera_target;
        frame.bindings = c.lit_bindings();
        Draw fd = portal_draw(portal.frame_mesh, "portal frame");
        std::vector<CameraItem> items{{-1, c.base_features(fd), (1u << frame.bindings.size()) - 1u}};
        // Lit as the camera pass lights an object, with its shadow lookup (shadow map, Gooch's
        // texture; planar shadows fall on the ground only).
        frame.draws.push_back(fd);
        const std::string unshadowed = shade_after_camera(c, frame, items);
        set_lit_draws(frame, items);
        frame.detail = "the frame in this scene's light" + frame.detail +
                       (unshadowed.empty() ? "" : " (unshadowed: " + unshadowed + ")");
        c.add_pass(std::move(frame));

        // The opening as the frame's vertex shader places it, no colour, both faces.
        const auto opening_pass = [&](const char* name) {
            Pass p;
            p.name = name;
            p.module = "portal";
            p.target = c.camera_target;
            p.state.color_write = false;
            p.state.depth_write = false;
            p.state.cull = gl::Cull::None;
            p.bindings = c.lit_bindings();
            Draw d = portal_draw(portal.opening_mesh, "portal opening");
            d.variant = lit_variant(c.base_features(d));
            d.bindings = (1u << p.bindings.size()) - 1u;
            p.draws.push_back(d);
            return p;
        };
        Pass mark = opening_pass("portal-mark");
        mark.state.depth_func = gl::Compare::LEqual;
        mark.state.stencil = use.test(gl::Compare::Always, kMarked, gl::StencilOp::Replace);
        mark.detail = "the opening's seen pixels marked in the stencil (" + use.describe() +
                      "), depth tested against this scene, colour and depth writes off";
        c.add_pass(std::move(mark));

        // The visibility AOV's background is white (the camera pass's clear), the sky's too.
        const glm::vec4 sky = c.settings.aov == Aov::Visibility ? glm::vec4(1.0f) : glm::vec4(portal.sky, 1.0f);
        Pass far = far_plane_pass(c, "portal-far", "portal", use, kMarked, sky);
        far.detail = "the other scene's sky in the marked pixels, their depth set to the far plane (depth 1)";
        c.add_pass(std::move(far));

        plan_other_scene(c, *other, plane, use);

        Pass restore = opening_pass("portal-restore");
        restore.state.depth_func = gl::Compare::Always;
        restore.state.depth_write = true;
        restore.state.stencil = use.test(gl::Compare::Equal, kMarked);
        restore.detail = "the opening's depth written back in the marked pixels";
        c.add_pass(std::move(restore));
    }

private:
    // The other scene's shadow map and its objects through the opening: a plan context of its
    // own (its objects, its light, names prefixed) on this frame's plan, camera and target.
    static void plan_other_scene(PlanContext& c, const scene::Scene& other, const glm::vec4& plane,
                                 const StencilUse& use) {
        Settings s = c.settings;
        const bool shadows = s.technique != Technique::None;
        s.technique = Technique::ShadowMap;
        s.aov = c.settings.aov == Aov::Visibility ? Aov::Visibility : Aov::Color;  // its own shadows' visibility
        s.area_samples = 1;
        if (s.encoding == shadow::Encoding::DepthTex && !c.caps.depth_texture) s.encoding = shadow::Encoding::RGBA;
        FrameInputs in = c.inputs;  // the camera and the output; the overrides name this scene's objects
        in.objects.clear();
        in.images.clear();
        in.light.reset();
        PlanContext o = PlanContext::of(other, s, c.caps, in, c.previous, c.plan, other.light);
        o.depth_path = c.depth_path;
        o.camera_target = c.camera_target;
        o.prefix = kPrefix;
        o.beyond = true;
        for (size_t i = 0; i < other.objects.size(); ++i) {
            const scene::Object& ob = other.objects[i];
            if (ob.mesh < 0 || ob.mesh >= static_cast<int>(other.meshes.size())) continue;
            if (material_of(other, ob.material).alpha_mode == scene::AlphaMode::Blend) continue;
            o.drawable.push_back(static_cast<int>(i));
            if (casts(other, ob, false)) o.casters.push_back(static_cast<int>(i));
        }
        // The shadow map module records its light's frustum in the plan: that of this scene's
        // light stays the plan's (what penumbra plan prints, what the bench reads).
        std::optional<LightViewReport> light_view;
        if (const LightViewReport* r = c.plan.find<LightViewReport>()) light_view = *r;
        // So is its map size; the other scene's map (a resource of its own) is matched to what it
        // serves, not held to this scene's size as a second map into the same target would be.
        std::optional<MapSizeReport> map_size;
        if (const MapSizeReport* r = c.plan.find<MapSizeReport>()) map_size = *r;
        c.plan.drop(MapSizeReport::kKey);
        const Module& sm = technique_module(Technique::ShadowMap);
        if (shadows) sm.before_camera(o);

        Pass p;
        p.name = "portal-scene";
        p.module = "portal";
        p.target = c.camera_target;
        p.state.stencil = use.test(gl::Compare::Equal, kMarked);
        p.bindings = o.lit_bindings();
        p.bindings.push_back({"portal", {{"u_clip_plane", plane}}, {}});
        std::vector<CameraItem> items;
        const std::uint32_t all = (1u << p.bindings.size()) - 1u;
        for (int i : o.drawable) {
            p.draws.push_back(o.object_draw(i));
            LitFeatures f = o.base_features(p.draws.back());
            f.clipped = true;
            items.push_back({i, f, all});
        }
        p.detail = std::to_string(items.size()) + " object(s) of the other scene in its own light, in the marked pixels, "
                   "clipped at the opening's plane";
        if (shadows) sm.shade(o, p, items);
        else p.detail += ", no shadows (--technique none)";
        set_lit_draws(p, items);
        c.add_pass(std::move(p));
        if (light_view) c.plan.put(*light_view);
        else c.plan.drop(LightViewReport::kKey);
        if (map_size) c.plan.put(*map_size);
        else c.plan.drop(MapSizeReport::kKey);
    }
};

}  // namespace

const Module& portal_module() {
    static const PortalModule m;
    return m;
}

}  // namespace penumbra::render
