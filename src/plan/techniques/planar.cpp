// Planar projected shadows (seed 001, exercise W09P1), drawn once per pixel through the stencil
// buffer: the ground marks its visible pixels 1, the casters flattened onto the ground plane from
// the light turn 1 into 2 (never twice, so overlapping triangles darken once), and the ground is
// drawn again, unlit, where the stencil is 2. The shadow is never depth-tested against the ground,
// so there is nothing to fight.
#include <algorithm>

#include "plan/techniques/technique.h"
#include "shadow/planar.h"

namespace penumbra::render {

namespace {

// The stencil values this technique writes into its use's bits of the camera target (cleared to
// 0 each frame): 2 bits, counting (1 -> 2 by incr).
constexpr int kGroundVisible = 1;
constexpr int kInShadow = 2;
constexpr const char* kUse = "planar: shadowed ground";

bool has_ground(const PlanContext& c) {
    const int g = c.scene.ground_object;
    return c.scene.ground_plane && g >= 0 &&
           std::find(c.drawable.begin(), c.drawable.end(), g) != c.drawable.end();
}

// A pass of this technique into the camera's target; `overlay` passes neither test nor write depth.
Pass camera_pass(const PlanContext& c, const char* name, bool overlay) {
    Pass p;
    p.name = name;
    p.module = "planar";
    p.target = c.camera_target;
    if (overlay) p.state.depth_test = p.state.depth_write = false;
    return p;
}

class PlanarModule : public Module {
public:
    std::string_view name() const override { return "planar"; }

    std::string check(const PlanContext& c) const override {
        if (!has_ground(c))
            return "--technique planar: the scene has no ground plane (a flat object named ground, floor, plane or "
                   "table)";
        if (!c.caps.packed_depth_stencil)
            return "--technique planar: this context has no OES_packed_depth_stencil for the stencil buffer";
        return {};
    }

    std::vector<StencilUse> stencil_uses(const PlanContext& c) const override {
        if (!has_ground(c)) return {};
        StencilUse u;
        u.name = kUse;
        u.module = "planar";
        u.bits = 2;  // 0 outside the ground, 1 the ground, 2 in the shadow
        u.counts = true;
        return {u};
    }

    bool keeps_out_of_camera(const PlanContext& c, int object) const override {
        return has_ground(c) && object == c.scene.ground_object;
    }

    void after_camera(PlanContext& c) const override {
        if (!has_ground(c)) return;
        const int ground = c.scene.ground_object;
        const StencilUse& use = c.stencil(kUse);

        Pass mark = camera_pass(c, "planar-ground", false);
        mark.state.stencil = use.test(gl::Compare::Always, kGroundVisible, gl::StencilOp::Replace);
        mark.bindings = c.lit_bindings();
        const std::uint32_t all = (1u << mark.bindings.size()) - 1u;
        Draw g = c.object_draw(ground);
        g.variant = lit_variant(c.base_features(g));
        g.bindings = all;
        mark.draws.push_back(g);
        mark.detail = "the ground, lit, marking its pixels " + std::to_string(kGroundVisible) + " in the stencil";
        c.add_pass(std::move(mark));

        Pass project = camera_pass(c, "planar-stencil", true);
        project.state.color_write = false;
        project.state.cull = gl::Cull::None;
        project.state.stencil = use.test(gl::Compare::Equal, kGroundVisible, gl::StencilOp::Incr);
        project.object_uniforms = ObjectUniforms::Mvp;
        project.view_proj = c.plan.camera.view_proj * shadow::planar_projection(*c.scene.ground_plane, c.light_vector());
        for (int i : c.casters) {
            if (i == ground) continue;
            project.draws.push_back(c.mesh_draw(i));
            // A cut-out's uvs survive the flattening: its gaps leave the stencil alone.
            const AlphaTest alpha = c.caster_alpha(project.draws.back());
            project.draws.back().variant = depth_variant(shadow::Encoding::DepthTex, c.depth_path, alpha);
        }
        project.detail = std::to_string(project.draws.size()) + " caster(s) flattened onto the ground, stencil " +
                         std::to_string(kGroundVisible) + " -> " + std::to_string(kInShadow) + ", colour and depth off";
        c.add_pass(std::move(project));

        Pass shade = camera_pass(c, "planar-shadow", true);
        shade.state.stencil = use.test(gl::Compare::Equal, kInShadow);
        shade.bindings = c.lit_bindings();
        LitFeatures f = c.base_features(g);
        f.in_shadow = true;
        g.variant = lit_variant(f);
        shade.draws.push_back(g);
        shade.detail = "the ground again, unlit, where stencil = " + std::to_string(kInShadow);
        c.add_pass(std::move(shade));
    }
};

}  // namespace

const Module& planar_module() {
    static const PlanarModule m;
    return m;
}

}  // namespace penumbra::render
