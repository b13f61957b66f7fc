// --effects outline: the objects outlined in a colour (--outline-color) and a width in pixels
// (--outline-width), the same width at any depth. The outlined objects are every shadow caster but
// the ground and alpha-tested cut-outs (in the course scene: the teapot). After the technique's passes:
//
//   outline-mark  the objects' pixels marked 1 in the outline's stencil bit (colour and depth
//                 writes off, no depth test, both faces: every pixel the object covers, seen or not)
//   outline-draw  the objects pushed out along their screen-space normals by the width (outline.vert)
//                 in the colour, where the bit is NOT set: only around the object, never on it
//
// No depth test in either: the outline is whole where the teapot stands in the table (its lower
// rim would sink into the table top otherwise) and shows through what stands in front of it, like a
// selection highlight.
//
// The course notes scale the model instead. A scale about the object's centre moves each point by
// (s - 1) times its distance from the centre: the outline is as wide as the object is big (thin at
// the spout, wide at the body), and in pixels it shrinks with distance (1/z) like the object does;
// where the centre is not inside (a torus, an L) it even leaves a gap. Here the move is made after
// the projection, in pixels.
#include <algorithm>
#include <cstdio>

#include "plan/techniques/technique.h"

namespace penumbra::render {

namespace {

constexpr const char* kUse = "outline: the model's pixels";
constexpr int kMarked = 1;

// A caster whose material is not opaque (a glTF MASK cut-out, or BLEND casting under
// --blend-shadows): its edge is where the texture's alpha crosses the cutoff, which geometry pushed
// out along its normals cannot follow (a fence would get the outline of its whole quad).
bool cut_out(const PlanContext& c, int object) {
    const int m = c.scene.objects[static_cast<size_t>(object)].material;
    return m >= 0 && static_cast<size_t>(m) < c.scene.materials.size() &&
           c.scene.materials[static_cast<size_t>(m)].alpha_mode != scene::AlphaMode::Opaque;
}

// Every shadow caster but the ground object and the cut-outs, in scene order.
std::vector<int> outlined(const PlanContext& c) {
    std::vector<int> out;
    for (int i : c.casters)
        if (i != c.scene.ground_object && !cut_out(c, i)) out.push_back(i);
    return out;
}

class OutlineModule : public Module {
public:
    std::string_view name() const override { return "outline"; }

    std::string check(const PlanContext& c) const override {
        return stencil_buffer_problem(c, "--effects outline");
    }

    std::vector<StencilUse> stencil_uses(const PlanContext& c) const override {
        if (outlined(c).empty()) return {};
        return {marking_use(kUse, "outline")};
    }

    void after_camera(PlanContext& c) const override {
        const std::vector<int> objects = outlined(c);
        std::string left_out;
        for (int i : c.casters)
            if (cut_out(c, i)) left_out += (left_out.empty() ? "" : ", ") + c.scene.objects[static_cast<size_t>(i)].name;
        if (!left_out.empty())
            c.plan.notes.push_back("--effects outline: the alpha-tested caster(s) " + left_out +
                                   " are not outlined (an outline pushed out from the geometry cannot follow a cut-out's edge)");
        if (objects.empty()) {
            c.plan.notes.push_back("--effects outline: nothing to outline (no shadow caster but the ground and cut-outs)");
            return;
        }
        const StencilUse& use = c.stencil(kUse);
        const Settings& s = c.settings;
        const TargetRef& t = c.camera_target;
        const glm::vec2 viewport(static_cast<float>(t.width), static_cast<float>(t.height));
        const auto pass = [&](const char* name, float width) {
            Pass p;
            p.name = name;
            p.module = "outline";
            p.target = t;
            p.state.depth_test = false;
            p.state.depth_write = false;
            p.state.cull = gl::Cull::None;
            p.object_uniforms = ObjectUniforms::Model;  // u_model, u_normal_matrix
            p.bindings.push_back({"outline",
                                  {{"u_view_proj", c.plan.camera.view_proj},
                                   {"u_viewport", viewport},
                                   {"u_outline_width", width},
                                   {"u_value", glm::vec4(s.outline_color, 1.0f)}},
                                  {}});
            for (int i : objects) {
                Draw d = c.mesh_draw(i);
                d.variant = outline_variant();
                d.bindings = 1u;
                p.draws.push_back(d);
            }
            return p;
        };

        Pass mark = pass("outline-mark", 0.0f);
        mark.state.color_write = false;
        mark.state.stencil = use.test(gl::Compare::Always, kMarked, gl::StencilOp::Replace);
        mark.detail = std::to_string(objects.size()) + " object(s)' pixels marked in the stencil (" + use.describe() +
                      "), colour and depth off";
        c.add_pass(std::move(mark));

        Pass draw = pass("outline-draw", s.outline_width);
        draw.state.stencil = use.test(gl::Compare::NotEqual, kMarked);
        char buf[160];
        std::snprintf(buf, sizeof buf, "the object(s) pushed out %g px along their screen-space normals, drawn where "
                      "the stencil is not marked",
                      static_cast<double>(s.outline_width));
        draw.detail = buf;
        c.add_pass(std::move(draw));
    }
};

}  // namespace

const Module& outline_module() {
    static const OutlineModule m;
    return m;
}

}  // namespace penumbra::render
