// A technique is a module of the frame plan: it adds passes, resources and shader features to a
// plan and owns nothing else (no GL objects, no state between frames: what it needs from an
// earlier frame, it finds in the previous plan). plan() (plan/plan.cpp) calls the technique in
// use at fixed points of every frame:
//
//   check         "" or why it cannot run on this scene and context
//   before_camera passes before the camera's: the shadow map from the light
//   own_view      an AOV of its own instead of the camera pass (the light's depth)
//   camera pass   built by plan(); the technique keeps objects out of it (keeps_out_of_camera) and
//                 adds its bindings and each draw's shader features (shade)
//   after_camera  passes after it: planar shadows and shadow volumes through the stencil buffer
//
// A module that uses the stencil declares each use (stencil_uses: a name, the bits it needs,
// whether it counts); plan() allocates bits to all the frame's uses before any pass is added, and
// the module makes its passes' stencil state through its use (PlanContext::stencil(name).test(...)),
// never with raw values and masks.
//
// Effects (--effects: outline, mirror, portal) are modules too, beside the technique:
// plan() asks each for check and stencil_uses, and calls its after_opaque after the technique's
// after_camera (the opaque image is whole: the mirror draws its reflection there, before the
// translucent objects' pass) and its after_camera after that pass, so an effect draws over whatever
// the technique made of the image.
//
// Adding a technique: a file here with a Module subclass, its entry in techniques.cpp, its value in
// render::Technique and the option table's choices (plan/option_table.cpp). An effect: the same with
// render::Effect and effect_module.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "plan/plan.h"
#include "plan/weak_in_pages.h"

namespace penumbra::render {

// A resource's content key: every value its passes depend on, hashed (FNV-1a, 64 bits) and
// printed in hex. Equal keys in two plans mean the resource need not be drawn again.
class ContentKey {
public:
    void add(const void* data, std::size_t bytes);
    template <typename T>
    void add(const T& value) {
        add(&value, sizeof value);
    }
    // Where scene object `object` stands and what it is: its index, world matrix and mesh.
    void add_placement(const scene::Scene& scene, int object) {
        add(object);
        add(scene.objects[static_cast<size_t>(object)].world);
        add(scene.objects[static_cast<size_t>(object)].mesh);
    }
    std::string str() const;

private:
    std::uint64_t h_ = 1469598103934665603ull;
};

// One object the camera pass will draw, while the techniques add their features to it.
struct CameraItem {
    int object = -1;
    LitFeatures features;
    std::uint32_t bindings = 0;  // bits of the camera pass's bindings
};

struct PlanContext;
// The light's frustum for this frame's camera, as --light-fit says: receivers and casters by their
// world bounds; TightFit::casters indexes PlanContext::casters (both in scene order). `soft`: the
// shadows' penumbrae reach beyond the casters' outlines, so the shadows fit leaves out the casters
// that shadow nothing but does not cut the window to the others.
shadow::TightFit fit_to_view(const PlanContext& c, bool soft);
// One flag per PlanContext::casters entry: 0 where --light-fit shadows leaves that caster out of
// every map, cascade, cube face and volume, as it can shadow no receiver the camera sees
// (shadow::ReceiverIndex::shadows_any); all 1 under the other fits.
std::vector<char> shadowing_casters(const PlanContext& c);

// What a module sees of the frame being planned, and the helpers it adds with.
struct PlanContext {
    const scene::Scene& scene;
    const Settings& settings;
    const gl::Caps& caps;
    const FrameInputs& inputs;
    const FramePlan* previous;
    FramePlan& plan;

    scene::Light light;           // the scene's, or the inputs'
    std::vector<int> drawable;    // objects with a mesh, in scene order, but glTF BLEND ones
    std::vector<int> casters;     // objects that cast shadows (render::casts: BLEND under --blend-shadows only)
    DepthPath depth_path;         // how depth is packed on this context
    TargetRef camera_target;      // where the camera pass draws
    std::vector<int> translucent; // objects with a mesh and a BLEND material: the blend pass's, after all else
    // A nested scene's context (the portal's other scene): its resources' and passes' names start
    // with `prefix`, and its draws' meshes are the portal's (Draw::beyond).
    std::string prefix;
    bool beyond = false;
    // One point of an area light (a Heckbert-Herf sample, `light` moved there): the lit passes
    // count only what faces it (LitFeatures::horizon with a light size of 0).
    bool light_sample = false;

    // A context of `scene` on `plan`: no objects yet (the caller lists them), no target.
    static PlanContext of(const scene::Scene& scene, const Settings& settings, const gl::Caps& caps,
                          const FrameInputs& inputs, const FramePlan* previous, FramePlan& plan, scene::Light light) {
        return {scene, settings, caps, inputs, previous, plan, std::move(light), {}, {}, {}, {}, {}, {}, false};
    }
    // The same frame's opaque objects and casters with other settings into another target (a
    // hard visibility the frame then uses: a light sample's, the one to blur); no translucent
    // objects (they are drawn once, into the frame's image).
    PlanContext with(const Settings& s, TargetRef target) const {
        return {scene, s, caps, inputs, previous, plan, light, drawable, casters, depth_path, target, {}, {}, false};
    }

    // Declares a resource (once per name) and returns its index. With a non-empty `content` key
    // equal to the previous plan's for the same description, it is marked reused.
    int add_resource(ResourceDesc desc, std::string content, std::string purpose);
    // Appends a pass; a pass into a reused resource is marked skipped.
    Pass& add_pass(Pass pass);
    // A resource's or pass's name in this context: prefix + name.
    std::string named(std::string_view name) const { return prefix + std::string(name); }
    // Whether `object` receives shadows; -1 (a draw an effect adds, not a scene object) does.
    bool receives(int object) const {
        return object < 0 || scene.objects[static_cast<size_t>(object)].receives_shadow;
    }
    // A draw of `object`'s mesh where it stands (no material: for depth-only and stencil passes).
    Draw mesh_draw(int object) const;
    // The same draw of a caster, alpha-tested where its material is MASK (or BLEND casting under
    // --blend-shadows): the material and base texture set, Draw::alpha on. What the pass's
    // variant needs (depth_variant, flat_variant) is returned.
    AlphaTest caster_alpha(Draw& d) const;
    // A Lit draw of `object`: its mesh and material (after the inputs' overrides), world matrix
    // and base-colour texture (a scene image, or the resource an ImageOverride names).
    Draw object_draw(int object);
    // The lit shader's features every draw has: the light's kind, the AOV, the texture.
    LitFeatures base_features(const Draw& d) const;
    // The light as the lit shader takes it: (position, 1) or (direction towards the light, 0).
    glm::vec4 light_vector() const;
    // The camera's uniforms (view, light, ambient) and the spot light's, for a Lit pass.
    std::vector<Binding> lit_bindings() const;
    // The frame's stencil use of that name, with its allocated bits (a module asks only for the
    // uses it declared; std::logic_error otherwise).
    const StencilUse& stencil(std::string_view name) const;
};

class Module {
public:
    virtual ~Module() = default;
    virtual std::string_view name() const = 0;
    virtual std::string check(const PlanContext&) const { return {}; }
    // The stencil uses of this frame (none: the module leaves the stencil alone).
    virtual std::vector<StencilUse> stencil_uses(const PlanContext&) const { return {}; }
    virtual void before_camera(PlanContext&) const {}
    virtual bool own_view(PlanContext&) const { return false; }
    virtual bool keeps_out_of_camera(const PlanContext&, int /*object*/) const { return false; }
    virtual void shade(PlanContext&, Pass& /*camera*/, std::vector<CameraItem>& /*items*/) const {}
    virtual void after_camera(PlanContext&) const {}
    // Effects: after the technique's passes, before the translucent (glTF BLEND) objects' pass.
    virtual void after_opaque(PlanContext&) const {}

    // ---- what the core asks a technique (the planner, the frame shapes and check() branch on
    // these answers, never on which technique it is) ----
    // It draws shadows at all (none: no; nothing to sample from light points or to blur).
    virtual bool shadows() const { return true; }
    // "" when its shadow is hard; else how it is soft by itself (gooch: "its planes take the
    // light's size"): no light samples averaged and no screen-space blur on top of it.
    virtual std::string_view soft_by_itself() const { return {}; }
    // "" when a pass after the camera's (the translucent objects', an effect's lit pass) takes its
    // shadow through shade(); else why not (volumes: counted for the camera pass's view).
    virtual std::string_view later_pass_problem() const { return {}; }
    // The AOV is a view of its own (light-depth, cascades: the shadow map's; stencil-count: the
    // volumes'): another technique's frame cannot show it.
    virtual bool own_aov(Aov) const { return false; }
    // Its shadow (or none) can be looked up by a deferred light pass, and its frame shaded again
    // by more lights (--shading deferred, --lights): the shadow map, or no shadows.
    virtual bool shades_deferred() const { return false; }
    // It draws a depth map from the light that --encoding, --filter and --map-size choose (a
    // bench row's encoding, filter and map columns; its moving frame's extra time is that map's).
    virtual bool depth_map() const { return false; }
    // Its settings in a few words, for a bench row and a plot's legend ("rgba pcf4x4",
    // "volumes zfail", "planar").
    virtual std::string label(const Settings&) const { return std::string(name()); }
    // These settings are the one of its sweep whose error picture the bench writes (the map's
    // 1024 texels, the volumes' auto).
    virtual bool representative(const Settings&) const { return true; }
};

// The module of each technique (techniques.cpp) and of each effect. A technique or effect whose
// module is not in the program (technique_linked) throws std::invalid_argument.
const Module& technique_module(Technique t);
const Module& effect_module(Effect e);
// Each module by itself (its own file). A program has the modules something in it names: every
// native program all of them (techniques.cpp names each), a browser page's module only those its
// exercise names (examples/exercise_list.h, Exercise::modules), techniques.cpp's references being
// weak there, so that a page loads only the code of what it offers.
const Module& shadow_map_module();  // shadow_map.cpp
const Module& planar_module();      // planar.cpp
const Module& volumes_module();     // volumes.cpp
const Module& gooch_module();       // gooch.cpp
const Module& outline_module();     // outline.cpp
const Module& mirror_module();      // mirror.cpp
const Module& portal_module();      // portal.cpp
// The shadow map's layouts beside one map (shadow_map_parts.h), each in its own file: cascades
// (a directional light's depth range split into several maps) and a cube (a point light's six
// faces, or those a wide spot light's cone reaches). The module reaches them by references weak
// in the browser: a page links one only where its exercise names it (Exercise::layouts), and
// elsewhere plans one map with a note.
struct MapLayout;
const MapLayout& cascades_layout();  // map_cascades.cpp
const MapLayout& cube_layout();      // map_cube.cpp
// Whether the layout named `name` ("cascades", "cube") is in this program (always, but in a page's).
bool map_layout_linked(std::string_view name);
// Whether the module of technique `t` (effect `e`) is in this program (always, but in a page's).
bool technique_linked(Technique t);
bool effect_linked(Effect e);
// "" unless `option` is "technique" or "effects" and the module of `s`'s value for it is not in
// this program, or it asks for a frame shape that is not (area-samples above 1, shading deferred,
// post shadow-blur, blur or bloom: plan/frames/frame.h): then one line naming it. (Only the option being set: a page's stored technique
// may be one its exercise's frame replaces, Exercise::frame.)
std::string unlinked_problem(const Settings& s, std::string_view option);
// The module of no shadows: the camera pass of a frame whose shadow comes from elsewhere (the
// light samples' average, the blurred visibility).
const Module& unshadowed_module();
// "" when technique `t` can show `aov`; else "--aov X: needs --technique Y", Y the technique whose
// own view it is (Module::own_aov).
std::string aov_problem(Technique t, Aov aov);
// The techniques whose modules answer yes to `question`, as "--technique a or b".
std::string techniques_that(bool (Module::*question)() const);

// Helpers of the modules' passes (techniques.cpp).
//
// Each draw of `p` gets the lit variant and the bindings of its item (items[k] is draws[k]'s).
void set_lit_draws(Pass& p, const std::vector<CameraItem>& items);
// An effect's lit pass drawn after the camera pass (the mirror's reflection, the portal's frame)
// takes the technique's shadow lookup: "" when it did, else why it is lit without shadows (the
// light samples are averaged for the camera pass's pixels, shadow volumes counted for its view).
std::string shade_after_camera(PlanContext& c, Pass& p, std::vector<CameraItem>& items);
// A full-screen triangle on the far plane (depth 1) in `colour`, into the camera's target where
// `use` holds `value`; depth test always, depth and colour written.
Pass far_plane_pass(const PlanContext& c, std::string name, std::string module, const StencilUse& use, int value,
                    const glm::vec4& colour);
// "" when the frame's target has a stencil buffer (a window's, or off screen, --post's image
// included, a packed depth-stencil: OES_packed_depth_stencil), else why `who` ("--effects
// mirror") cannot run.
std::string stencil_buffer_problem(const PlanContext& c, std::string_view who);
// A use of one stencil bit that marks pixels (the outline's, the mirror's, the portal's).
StencilUse marking_use(std::string name, std::string module);

}  // namespace penumbra::render
