// Shadow volumes (seed 000, "Shadow volume"): the camera pass draws the receivers with ambient
// light only; each caster's volume (shadow/volumes.h, made this frame on the CPU) is counted into
// the stencil buffer with two-sided stencil, depth-pass (front faces +1, back faces -1 where the
// depth test passes) or depth-fail (back +1, front -1 where it fails, with near and far caps);
// then the receivers are drawn again, lit, where the count is 0. Exact up to rasterisation: no
// bias, no texels. The camera's far plane is moved to infinity, so volumes extruded to infinity
// are never clipped (GLES 2 has no depth clamp).
//
// --volume-method auto picks per caster: depth-pass when the caster cannot put the eye's near
// plane in its shadow (shadow::may_shadow_near_plane), depth-fail otherwise. Counts add up, so
// the two methods mix in one stencil buffer.
//
// A still volume is not made again: the plan's VolumeStats carries each caster's triangles with
// what made them (VolumeCache: the object, its world matrix and mesh, the light, depth-fail or
// not), and the next plan keeps the same triangles (the same shared pointer, which the renderer
// keeps uploaded) for a caster whose key is unchanged; only moved casters, or all under a moved
// light, are extruded again. The fill statistic is kept with them while the camera is still too.
#include <algorithm>
#include <memory>
#include <string>
#include <unordered_map>

#include "plan/techniques/reports.h"
#include "plan/techniques/technique.h"
#include "shadow/volumes.h"

namespace penumbra::render {

using Triangles = std::shared_ptr<const std::vector<glm::vec4>>;

// The volumes of a plan, for the next plan to keep (VolumeStats::cache).
struct VolumeCache {
    // Everything a caster's volume depends on, compared exactly (its hash finds it). Its mesh is
    // named by index, as ContentKey::add_placement names it: the renderer gives a plan the
    // previous one only for the scene it drew (Renderer::fingerprint); the counts are a check.
    struct Key {
        std::string prefix;  // the context's (a portal's other scene: its own objects)
        bool beyond = false;
        int object = -1, mesh = -1;
        std::size_t vertices = 0, indices = 0;
        glm::mat4 world{1.0f};
        glm::vec4 light{0.0f};
        bool closed = false, fail = false;  // the caps follow: fail || !closed
        bool operator==(const Key& o) const {
            return prefix == o.prefix && beyond == o.beyond && object == o.object && mesh == o.mesh &&
                   vertices == o.vertices && indices == o.indices && world == o.world && light == o.light &&
                   closed == o.closed && fail == o.fail;
        }
        std::string hash() const {
            ContentKey k;
            k.add(prefix.data(), prefix.size());
            for (const int v : {int(beyond), object, mesh, int(closed), int(fail)}) k.add(v);
            k.add(vertices);
            k.add(indices);
            k.add(world);
            k.add(light);
            return k.str();
        }
    };
    // One caster's volume: its draws' triangles, its share of the statistics, and its fill with
    // the camera it was counted for.
    struct Kept {
        Key key;
        // Sides (and far caps at infinity: depth-fail), null when the volume is empty; near caps,
        // null when there are none.
        Triangles body, cap;
        int silhouette_edges = 0, triangles = 0;
        double fill = 0.0;
        bool has_fill = false;
        glm::mat4 fill_view_proj{1.0f};
        int fill_width = 0, fill_height = 0;
    };

    std::unordered_multimap<std::string, Kept> volumes;  // by Key::hash()
    // --show-volumes: every face, and the triangle lists it was made of, in order.
    Triangles shown;
    std::vector<Triangles> shown_from;

    const Kept* find(const std::string& hash, const Key& key) const {
        const auto [from, to] = volumes.equal_range(hash);
        for (auto it = from; it != to; ++it)
            if (it->second.key == key) return &it->second;
        return nullptr;
    }
    const Kept& put(const std::string& hash, Kept v) {
        const auto [from, to] = volumes.equal_range(hash);
        for (auto it = from; it != to; ++it)
            if (it->second.key == v.key) return it->second = std::move(v);
        return volumes.emplace(hash, std::move(v))->second;
    }
};

namespace {

// Stencil values this technique reads: 0 lit, anything else in a shadow (a count, wrapping in its
// use's bits: at least 4, so the count view tells 1..6 from a negative count; every bit the other
// uses of the frame leave).
constexpr int kLit = 0;
constexpr const char* kUse = "volumes: shadow count";
constexpr int kMinBits = 4;
// Near caps of depth-fail are pushed this far from the eye so that a lit open surface, its own
// cap, counts as behind itself (they lie in one plane); slope-scaled for grazing views.
constexpr float kCapOffsetFactor = 1.0f, kCapOffsetUnits = 4.0f;
// The false colours of the stencil-count view: counts 1..6, then "negative" (wrapped below 0).
constexpr int kCountColours = 6;

Pass volume_pass(const PlanContext& c, const char* name) {
    Pass p;
    p.name = name;
    p.module = "volumes";
    p.target = c.camera_target;
    p.state.depth_write = false;
    p.state.color_write = false;
    p.state.cull = gl::Cull::None;
    p.object_uniforms = ObjectUniforms::Mvp;
    p.view_proj = c.plan.camera.view_proj;
    return p;
}

Draw volume_draw(const std::string& label, Triangles tris) {
    Draw d;
    d.label = label;
    d.variant = volume_variant();
    d.triangles = std::move(tris);
    return d;
}

Triangles shared(std::vector<glm::vec4> tris) {
    return tris.empty() ? nullptr : std::make_shared<const std::vector<glm::vec4>>(std::move(tris));
}

// The caster's volume as the key says: extruded from its mesh's topology (once per key; the caller
// keeps it).
VolumeCache::Kept extrude(const PlanContext& c, const VolumeCache::Key& key) {
    const scene::Object& o = c.scene.objects[static_cast<size_t>(key.object)];
    const scene::Mesh& mesh = c.scene.meshes[static_cast<size_t>(o.mesh)];
    scene::Topology own;
    const scene::Topology& topo = mesh.topology ? *mesh.topology : (own = scene::weld(mesh));
    shadow::ShadowVolume v = shadow::extrude_volume(topo, key.world, key.light, key.closed, key.fail || !key.closed);
    if (!key.fail) v.far_cap.clear();  // at infinity: never in front of what the eye sees
    VolumeCache::Kept k;
    k.key = key;
    k.silhouette_edges = v.silhouette_edges;
    k.triangles = v.triangles();
    std::vector<glm::vec4> body = std::move(v.sides);
    body.insert(body.end(), v.far_cap.begin(), v.far_cap.end());
    // The sides' draw is there whenever the volume is (an empty list too); the caps' only when
    // there are caps.
    if (!body.empty() || !v.near_cap.empty()) k.body = std::make_shared<const std::vector<glm::vec4>>(std::move(body));
    k.cap = shared(std::move(v.near_cap));
    return k;
}

double covered(const Triangles& t, const glm::mat4& view_proj, int w, int h) {
    static const std::vector<glm::vec4> none;
    return shadow::covered_pixels(t ? *t : none, view_proj, w, h);
}

class VolumesModule : public Module {
public:
    std::string_view name() const override { return "volumes"; }
    bool own_aov(Aov a) const override { return a == Aov::StencilCount; }
    std::string label(const Settings& s) const override { return "volumes " + std::string(to_string(s.volume_method)); }
    bool representative(const Settings& s) const override { return s.volume_method == VolumeMethod::Auto; }
    std::string_view later_pass_problem() const override { return "shadow volumes are counted for the camera pass's view"; }

    std::string check(const PlanContext& c) const override {
        if (std::string p = stencil_buffer_problem(c, "--technique volumes"); !p.empty()) return p;
        glm::mat4 p = camera_view(c.scene, c.inputs).proj;
        if (!shadow::infinite_far(p))
            return "--technique volumes: needs a perspective camera (its far plane is moved to infinity)";
        return {};
    }

    std::vector<StencilUse> stencil_uses(const PlanContext&) const override {
        StencilUse u;
        u.name = kUse;
        u.module = "volumes";
        u.bits = kMinBits;
        u.counts = true;
        return {u};
    }

    void before_camera(PlanContext& c) const override {
        // Silhouettes come from the triangles, not from the texture: a cut-out casts its whole quad.
        std::string cut;
        int n = 0;
        for (int i : c.casters)
            if (material_of(c.scene, c.scene.objects[static_cast<size_t>(i)].material).alpha_mode !=
                scene::AlphaMode::Opaque)
                cut += (n++ ? ", " : "") + c.scene.objects[static_cast<size_t>(i)].name;
        if (n)
            c.plan.notes.push_back("--technique volumes: " + std::to_string(n) + " alpha-tested caster(s) (" + cut +
                                   ") cast the shadow of their whole geometry: volumes are extruded from triangles, "
                                   "the alpha cutoff cannot cut them (use shadowmap, planar or gooch for cut-outs)");
        CameraView& cam = c.plan.camera;
        if (shadow::infinite_far(cam.proj)) cam.view_proj = cam.proj * cam.view;
    }

    void shade(PlanContext& c, Pass& cam, std::vector<CameraItem>& items) const override {
        int dark = 0;
        for (CameraItem& item : items)
            if (c.scene.objects[static_cast<size_t>(item.object)].receives_shadow) {
                item.features.in_shadow = true;
                ++dark;
            }
        cam.detail += ", " + std::to_string(dark) + " receiver(s) with ambient light only, infinite far plane";
    }

    void after_camera(PlanContext& c) const override {
        const Settings& s = c.settings;
        const glm::vec4 light = c.light_vector();
        const auto near = shadow::near_rectangle(c.plan.camera.view_proj);
        const ShadowBounds bounds = shadow_bounds(c.scene, c.settings.blend_shadows);
        VolumeStats stats;
        const StencilUse& use = c.stencil(kUse);
        Pass zpass = volume_pass(c, "volumes-zpass");
        zpass.state.stencil = use.count(false);
        Pass zfail = volume_pass(c, "volumes-zfail");
        zfail.state.stencil = use.count(true);
        // Near caps, pushed back by a depth offset (below). Depth-pass needs them for open meshes
        // only: the camera pass culls back faces, so the eye sees past the inside of a bowl or a
        // tube, through triangles whose caps then lie in front of what it sees.
        Pass zpass_caps = volume_pass(c, "volumes-zpass-caps");
        zpass_caps.state.stencil = use.count(false);
        Pass caps = volume_pass(c, "volumes-zfail-caps");
        caps.state.stencil = use.count(true);
        for (Pass* p : {&zpass_caps, &caps}) {
            p->state.offset_factor = kCapOffsetFactor;
            p->state.offset_units = kCapOffsetUnits;
        }
        const int w = c.camera_target.width, h = c.camera_target.height;
        const glm::mat4& view_proj = c.plan.camera.view_proj;
        // What the previous plan kept, and this plan's volumes of an earlier light sample.
        const VolumeStats* before = c.previous ? volumes_of(*c.previous) : nullptr;
        const VolumeCache* old = before ? before->cache.get() : nullptr;
        // One cache for all of a plan's volumes: a light sample's adds to the earlier samples'.
        std::shared_ptr<VolumeCache> next;
        if (VolumeStats* earlier = c.plan.find<VolumeStats>(); earlier && earlier->cache) next = std::move(earlier->cache);
        else next = std::make_shared<VolumeCache>();
        std::vector<Triangles> shown_from;  // every face, for --show-volumes
        double fill = 0.0;
        const std::vector<char> shadowing = shadowing_casters(c);
        for (size_t k = 0; k < c.casters.size(); ++k) {
            if (!shadowing[k]) {
                ++stats.culled;
                continue;
            }
            const int i = c.casters[k];
            const scene::Object& o = c.scene.objects[static_cast<size_t>(i)];
            VolumeCache::Key key;
            key.prefix = c.prefix;
            key.beyond = c.beyond;
            key.object = i;
            key.mesh = o.mesh;
            key.world = o.world;
            key.light = light;
            const scene::Mesh& mesh = c.scene.meshes[static_cast<size_t>(o.mesh)];
            key.vertices = mesh.positions.size();
            key.indices = mesh.indices.size();
            key.closed = mesh.closed;
            key.fail = s.volume_method == VolumeMethod::ZFail ||
                       (s.volume_method == VolumeMethod::Auto &&
                        shadow::may_shadow_near_plane(near, light, bounds.casters[k]));
            const std::string hash = key.hash();
            const VolumeCache::Kept* kept = old ? old->find(hash, key) : nullptr;
            if (!kept) kept = next->find(hash, key);
            VolumeCache::Kept v = kept ? *kept : extrude(c, key);
            ++(kept ? stats.kept : stats.extruded);
            if (v.has_fill && v.fill_view_proj == view_proj && v.fill_width == w && v.fill_height == h) {
                ++stats.fill_kept;
            } else {
                v.fill = covered(v.body, view_proj, w, h) + covered(v.cap, view_proj, w, h);
                v.has_fill = true;
                v.fill_view_proj = view_proj;
                v.fill_width = w;
                v.fill_height = h;
            }
            const VolumeCache::Kept& now = next->put(hash, std::move(v));
            if (!now.body) continue;  // nothing to count
            ++(key.fail ? stats.zfail_casters : stats.zpass_casters);
            stats.silhouette_edges += now.silhouette_edges;
            stats.triangles += now.triangles;
            fill += now.fill;
            if (s.show_volumes) shown_from.insert(shown_from.end(), {now.body, now.cap});
            (key.fail ? zfail : zpass).draws.push_back(volume_draw(o.name, now.body));
            if (now.cap) (key.fail ? caps : zpass_caps).draws.push_back(volume_draw(o.name, now.cap));
        }
        if (s.show_volumes) {
            if (old && old->shown && old->shown_from == shown_from) {
                next->shown = old->shown;
            } else {
                std::vector<glm::vec4> all;
                for (const Triangles& part : shown_from)
                    if (part) all.insert(all.end(), part->begin(), part->end());
                next->shown = shared(std::move(all));
            }
            next->shown_from = std::move(shown_from);
        }
        stats.fill = fill;
        stats.fill_per_pixel = w > 0 && h > 0 ? fill / (static_cast<double>(w) * h) : 0.0;
        const Triangles shown = next->shown;
        stats.cache = std::move(next);
        c.plan.put(stats);
        const auto describe = [&](Pass& p, const char* what) {
            int tris = 0;
            for (const Draw& d : p.draws) tris += static_cast<int>(d.triangles->size() / 3);
            p.detail = std::to_string(p.draws.size()) + " caster(s), " + std::to_string(tris) + " triangle(s): " + what;
        };
        if (!zpass.draws.empty()) {
            describe(zpass, "sides, front faces +1 / back faces -1 where the depth test passes; colour and depth off");
            c.add_pass(std::move(zpass));
        }
        if (!zpass_caps.draws.empty()) {
            describe(zpass_caps, "near caps of open meshes, depth-pass counting, pushed back by a depth offset");
            c.add_pass(std::move(zpass_caps));
        }
        if (!zfail.draws.empty()) {
            describe(zfail, "sides and far caps at infinity, back faces +1 / front faces -1 where the depth test fails");
            c.add_pass(std::move(zfail));
        }
        if (!caps.draws.empty()) {
            describe(caps, "near caps, the same counting, pushed back by a depth offset so a lit surface passes its own cap");
            c.add_pass(std::move(caps));
        }

        if (s.aov == Aov::StencilCount) {
            count_view(c);
        } else {
            lit_pass(c);
        }
        if (s.show_volumes && shown) show(c, shown);
    }

private:
    // The receivers again, lit, where the stencil count is 0.
    static void lit_pass(PlanContext& c) {
        Pass lit;
        lit.name = "volumes-lit";
        lit.module = "volumes";
        lit.target = c.camera_target;
        lit.state.depth_func = gl::Compare::LEqual;
        lit.state.depth_write = false;
        lit.state.stencil = c.stencil(kUse).test(gl::Compare::Equal, kLit);
        lit.bindings = c.lit_bindings();
        const std::uint32_t all = (1u << lit.bindings.size()) - 1u;
        for (int i : c.drawable) {
            if (!c.scene.objects[static_cast<size_t>(i)].receives_shadow) continue;
            Draw d = c.object_draw(i);
            d.variant = lit_variant(c.base_features(d));
            d.bindings = all;
            lit.draws.push_back(d);
        }
        lit.detail = std::to_string(lit.draws.size()) + " receiver(s) again, lit, where the stencil count is 0 (depth lequal)";
        c.add_pass(std::move(lit));
    }

    // The stencil count in false colour over the unlit image: one full-screen pass per count.
    static void count_view(PlanContext& c) {
        static const glm::vec4 colours[kCountColours] = {{0.10f, 0.45f, 1.00f, 0.55f}, {0.10f, 0.85f, 0.35f, 0.55f},
                                                         {0.95f, 0.85f, 0.10f, 0.55f}, {1.00f, 0.50f, 0.05f, 0.55f},
                                                         {0.85f, 0.20f, 0.85f, 0.55f}, {1.00f, 1.00f, 1.00f, 0.55f}};
        const auto overlay = [&](const std::string& name, gl::StencilState st, const glm::vec4& colour, std::string detail) {
            Pass p;
            p.name = name;
            p.module = "volumes";
            p.target = c.camera_target;
            p.state.depth_test = false;
            p.state.depth_write = false;
            p.state.cull = gl::Cull::None;
            p.state.blend = gl::Blend::Alpha;
            p.state.stencil = st;
            p.object_uniforms = ObjectUniforms::None;
            p.bindings.push_back({"colour", {{"u_value", colour}}, {}});
            Draw d;
            d.fullscreen = true;
            d.variant = probe_variant();
            d.bindings = 1u;
            p.draws.push_back(d);
            p.detail = std::move(detail);
            c.add_pass(std::move(p));
        };
        const StencilUse& use = c.stencil(kUse);
        for (int k = 1; k <= kCountColours; ++k)
            overlay("volumes-count-" + std::to_string(k), use.test(gl::Compare::Equal, k), colours[k - 1],
                    "count " + std::to_string(k) + ": a false colour where the stencil holds it");
        // Wrapped below zero (the use's top bit set; 128..255 with all 8 bits): what depth-pass
        // leaves where the eye is inside a volume.
        gl::StencilState negative = use.test(gl::Compare::Equal, 1 << (use.width - 1));
        negative.read_mask = use.top_bit();
        overlay("volumes-count-negative", negative, {1.0f, 0.05f, 0.05f, 0.75f},
                "a negative count (wrapped past 0, top bit set): red; depth-pass's failure with the eye in a shadow");
    }

    // The volumes over the image, translucent: faces towards the eye orange, faces away blue.
    static void show(PlanContext& c, const Triangles& shared) {
        Pass p = volume_pass(c, "volumes-show");
        p.state.color_write = true;
        p.state.blend = gl::Blend::Alpha;
        p.bindings.push_back({"towards the eye", {{"u_value", glm::vec4(1.0f, 0.55f, 0.1f, 0.22f)}}, {}});
        p.bindings.push_back({"away from the eye", {{"u_value", glm::vec4(0.2f, 0.5f, 1.0f, 0.22f)}}, {}});
        Draw back = volume_draw("the volumes' back faces", {});
        back.triangles = shared;
        back.bindings = 2u;
        back.cull = gl::Cull::Front;
        Draw front = volume_draw("the volumes' front faces", {});
        front.triangles = shared;
        front.bindings = 1u;
        front.cull = gl::Cull::Back;
        p.draws = {back, front};
        p.detail = std::to_string(shared->size() / 3) + " triangle(s), translucent, depth-tested against the scene";
        c.add_pass(std::move(p));
    }
};

}  // namespace

const Module& volumes_module() {
    static const VolumesModule m;
    return m;
}

}  // namespace penumbra::render
