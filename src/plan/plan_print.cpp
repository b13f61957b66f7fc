// A plan for people (describe: one line per pass; to_text: everything) and for programs (to_json).
// `penumbra render -v` prints describe(), `penumbra plan` to_text() or to_json() of the same plan.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

#include "plan/json.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "shadow/cube.h"

namespace penumbra::render {

namespace {

std::string bytes_str(std::size_t b) {
    char buf[32];
    if (b >= (1u << 20)) std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(b) / (1u << 20));
    else std::snprintf(buf, sizeof buf, "%.1f KiB", static_cast<double>(b) / 1024.0);
    return buf;
}

std::string resource_name(const FramePlan& p, int r) {
    return r < 0 ? std::string("window") : p.resources[static_cast<size_t>(r)].desc.name;
}

std::string target_str(const FramePlan& p, const TargetRef& t) {
    std::string s = resource_name(p, t.resource) + " " + std::to_string(t.width) + "x" + std::to_string(t.height);
    if (t.resource >= 0 && p.resources[static_cast<size_t>(t.resource)].desc.cube)
        return s + " face " + shadow::cube_face_name(t.face);
    if (t.x || t.y || t.clip) s += " at (" + std::to_string(t.x) + ", " + std::to_string(t.y) + ")" + (t.clip ? ", clipped" : "");
    return s;
}

std::string object_uniforms_str(ObjectUniforms u) {
    switch (u) {
        case ObjectUniforms::None: return "none";
        case ObjectUniforms::Mvp: return "mvp";
        case ObjectUniforms::Lit: return "lit";
        case ObjectUniforms::Model: return "model";
    }
    return "?";
}

std::string clear_str(const Clear& c) {
    std::string s;
    if (c.color) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "colour (%.2f, %.2f, %.2f, %.2f)", static_cast<double>(c.color->r),
                      static_cast<double>(c.color->g), static_cast<double>(c.color->b), static_cast<double>(c.color->a));
        s = buf;
    }
    if (c.depth) s += std::string(s.empty() ? "" : ", ") + "depth";
    if (c.stencil) s += std::string(s.empty() ? "" : ", ") + "stencil";
    return s;
}

std::string binding_names(const Pass& pass, std::uint32_t bits) {
    std::string s;
    for (size_t i = 0; i < pass.bindings.size(); ++i)
        if (bits & (1u << i)) s += (s.empty() ? "" : ", ") + pass.bindings[i].name;
    return s.empty() ? "-" : s;
}

// Each report in the registry's order (report_slots(): a slot with r null where no module reported
// it), then any other in the order reported.
template <typename F>
void for_each_report(const FramePlan& p, F f) {
    const std::vector<ReportSlot>& slots = report_slots();
    for (const ReportSlot& slot : slots) {
        const Report* found = nullptr;
        for (const Report& r : p.reports)
            if (r.key == slot.key) found = &r;
        f(&slot, found);
    }
    for (const Report& r : p.reports)
        if (std::none_of(slots.begin(), slots.end(), [&](const ReportSlot& s) { return s.key == r.key; })) f(nullptr, &r);
}

// ---- JSON -----------------------------------------------------------------------------------

std::string json_value(const UniformValue& v) {
    return std::visit(
        [](const auto& x) -> std::string {
            using X = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<X, int>) return std::to_string(x);
            else if constexpr (std::is_same_v<X, float>) return json_number(static_cast<double>(x));
            else return json_floats(x);
        },
        v);
}

std::string json_strings(const std::vector<std::string>& v) {
    std::string s = "[";
    for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + json_quote(v[i]);
    return s + "]";
}

std::string json_state(const gl::PipelineState& st) {
    const gl::StencilState& s = st.stencil;
    return "{\"depth_test\":" + json_bool(st.depth_test) + ",\"depth_func\":" + json_quote(gl::to_string(st.depth_func)) +
           ",\"depth_write\":" + json_bool(st.depth_write) + ",\"color_write\":" + json_bool(st.color_write) +
           ",\"cull\":" + json_quote(gl::to_string(st.cull)) + ",\"stencil\":{\"enabled\":" + json_bool(s.enabled) +
           ",\"func\":" + json_quote(gl::to_string(s.func)) + ",\"ref\":" + std::to_string(s.ref) +
           ",\"read_mask\":" + std::to_string(s.read_mask) + ",\"write_mask\":" + std::to_string(s.write_mask) +
           ",\"fail\":" + json_quote(gl::to_string(s.fail)) + ",\"depth_fail\":" + json_quote(gl::to_string(s.depth_fail)) +
           ",\"pass\":" + json_quote(gl::to_string(s.pass)) + ",\"two_sided\":" + json_bool(s.two_sided) +
           ",\"back_fail\":" + json_quote(gl::to_string(s.back_fail)) +
           ",\"back_depth_fail\":" + json_quote(gl::to_string(s.back_depth_fail)) +
           ",\"back_pass\":" + json_quote(gl::to_string(s.back_pass)) + "},\"blend\":" +
           json_bool(st.blend != gl::Blend::Off) + ",\"depth_offset\":[" + json_number(static_cast<double>(st.offset_factor)) +
           "," + json_number(static_cast<double>(st.offset_units)) + "],\"text\":" + json_quote(gl::to_string(st)) + "}";
}

std::string json_pass(const FramePlan& p, const Pass& pass) {
    std::string j = "{\"name\":" + json_quote(pass.name) + ",\"module\":" + json_quote(pass.module);
    const TargetRef& t = pass.target;
    j += ",\"target\":{\"resource\":" + json_quote(resource_name(p, t.resource)) + ",\"width\":" + std::to_string(t.width) +
         ",\"height\":" + std::to_string(t.height) + ",\"x\":" + std::to_string(t.x) + ",\"y\":" + std::to_string(t.y) +
         ",\"clip\":" + json_bool(t.clip) +
         (t.resource >= 0 && p.resources[static_cast<size_t>(t.resource)].desc.cube
              ? ",\"face\":" + json_quote(shadow::cube_face_name(t.face))
              : std::string()) +
         "}";
    if (pass.clear) {
        const Clear& c = *pass.clear;
        j += ",\"clear\":{\"color\":" + (c.color ? json_floats(*c.color) : std::string("null")) + ",\"depth\":" +
             json_bool(c.depth) + ",\"stencil\":" + json_bool(c.stencil) + "}";
    } else {
        j += ",\"clear\":null";
    }
    j += ",\"state\":" + json_state(pass.state);
    j += ",\"object_uniforms\":" + json_quote(object_uniforms_str(pass.object_uniforms));
    j += ",\"bindings\":[";
    for (size_t i = 0; i < pass.bindings.size(); ++i) {
        const Binding& b = pass.bindings[i];
        j += std::string(i ? "," : "") + "{\"name\":" + json_quote(b.name) + ",\"uniforms\":{";
        for (size_t u = 0; u < b.uniforms.size(); ++u)
            j += std::string(u ? "," : "") + json_quote(b.uniforms[u].name) + ":" + json_value(b.uniforms[u].value);
        j += "},\"textures\":[";
        for (size_t k = 0; k < b.textures.size(); ++k)
            j += std::string(k ? "," : "") + "{\"unit\":" + std::to_string(b.textures[k].unit) +
                 ",\"resource\":" + json_quote(resource_name(p, b.textures[k].resource)) +
                 ",\"attachment\":" + std::to_string(b.textures[k].attachment) + "}";
        j += "]}";
    }
    j += "],\"draws\":[";
    for (size_t i = 0; i < pass.draws.size(); ++i) {
        const Draw& d = pass.draws[i];
        std::vector<std::string> names;
        for (const auto& def : d.variant.defines) names.push_back(def.substr(0, def.find(' ')));
        std::vector<std::string> binds;
        for (size_t b = 0; b < pass.bindings.size(); ++b)
            if (d.bindings & (1u << b)) binds.push_back(pass.bindings[b].name);
        j += std::string(i ? "," : "") + "{\"object\":" + (d.fullscreen ? std::string("null") : json_quote(d.label)) +
             ",\"triangles\":" + (d.triangles ? std::to_string(d.triangles->size() / 3) : std::string("null")) +
             ",\"fullscreen\":" + json_bool(d.fullscreen) + ",\"mesh\":" + std::to_string(d.mesh) +
             ",\"material\":" + std::to_string(d.material) + ",\"variant\":" + json_quote(d.variant.name()) +
             ",\"vertex\":" + json_quote(d.variant.vertex) + ",\"fragment\":" + json_quote(d.variant.fragment) +
             ",\"defines\":" + json_strings(names) + ",\"bindings\":" + json_strings(binds) +
             ",\"texture\":" + (d.image_resource >= 0 ? json_quote(resource_name(p, d.image_resource))
                                : d.image >= 0       ? json_quote("image " + std::to_string(d.image))
                                                     : std::string("null")) +
             ",\"cull\":" + json_quote(gl::to_string(d.cull.value_or(pass.state.cull))) + "}";
    }
    std::vector<std::string> reads;
    for (int r : pass.reads()) reads.push_back(resource_name(p, r));
    j += "],\"reads\":" + json_strings(reads) +
         ",\"copy_to\":" + (pass.copy_to >= 0 ? json_quote(resource_name(p, pass.copy_to)) : std::string("null")) +
         ",\"skipped\":" + json_bool(pass.skipped) +
         ",\"detail\":" + json_quote(pass.detail) + "}";
    return j;
}

}  // namespace

std::string FramePlan::describe() const {
    std::string out;
    for (size_t i = 0; i < passes.size(); ++i)
        out += std::to_string(i + 1) + ". " + passes[i].name + ": " +
               (passes[i].skipped ? "reused (what it draws is unchanged since the last frame): " : "") + passes[i].detail + "\n";
    return out;
}

std::string FramePlan::to_text() const {
    std::ostringstream o;
    o << "frame plan: " << to_args(settings) << " -> " << output << "\n";
    char buf[160];
    std::snprintf(buf, sizeof buf, "camera at (%.3g, %.3g, %.3g)\n", static_cast<double>(camera.position.x),
                  static_cast<double>(camera.position.y), static_cast<double>(camera.position.z));
    o << buf;
    for_each_report(*this, [&](const ReportSlot*, const Report* r) {
        if (r && r->text) o << r->text(r->value);
    });
    if (!stencil.empty()) {
        o << "stencil uses (" << stencil_bits << " bits):\n";
        for (const StencilUse& u : stencil) {
            std::snprintf(buf, sizeof buf, "  %s (%s): %s, needs %d%s; ref 1 = %d, read %02x, write %02x\n", u.name.c_str(),
                          u.module.c_str(), u.describe().c_str(), u.bits, u.counts ? ", counts" : "", u.ref(1),
                          u.mask(), u.mask());
            o << buf;
        }
    }
    std::size_t total = 0;
    o << "resources:\n";
    for (const PlannedResource& r : resources) {
        total += r.desc.bytes();
        o << "  " << r.desc.name << ": " << r.desc.describe() << ", " << bytes_str(r.desc.bytes());
        if (!r.content.empty()) o << ", content " << r.content << (r.reused ? " (reused: unchanged since the last frame)" : "");
        o << "; " << r.purpose << "\n";
    }
    o << "  total " << bytes_str(total) << "\n";
    const StateCounts sc = state_counts();
    o << "state changes: " << sc.passes << " pass(es) run, " << sc.state_calls << " pipeline-state call(s), "
      << sc.program_switches << " program switch(es), " << sc.uniform_sets << " shared uniform(s) set, "
      << sc.texture_binds << " texture bind(s) (" << sc.texture_binds_skipped << " skipped: already bound), " << sc.draws
      << " draw(s)\n";
    o << "passes:\n";
    for (size_t i = 0; i < passes.size(); ++i) {
        const Pass& p = passes[i];
        o << "  " << i + 1 << ". " << p.name << " (" << p.module << ") -> " << target_str(*this, p.target)
          << (p.skipped ? "  [skipped: reused]" : "") << "\n";
        o << "     " << p.detail << "\n";
        if (p.clear) o << "     clear: " << clear_str(*p.clear) << "\n";
        o << "     state: " << gl::to_string(p.state) << "\n";
        if (!p.draws.empty()) o << "     per draw: " << object_uniforms_str(p.object_uniforms) << " uniforms\n";
        for (const Binding& b : p.bindings) {
            o << "     binding " << b.name << ":";
            for (const Uniform& u : b.uniforms) o << " " << u.name;
            for (const TextureBinding& t : b.textures) o << " [unit " << t.unit << ": " << resource_name(*this, t.resource)
                                                            << (t.attachment ? " colour " + std::to_string(t.attachment) : "") << "]";
            o << "\n";
        }
        const std::vector<int> reads = p.reads();
        if (!reads.empty()) {
            o << "     reads:";
            for (int r : reads) o << " " << resource_name(*this, r);
            o << "\n";
        }
        // A pass of many draws has few variants and binding sets: each named once, while it repeats.
        const Draw* last = nullptr;
        std::string variant, bindings;
        for (const Draw& d : p.draws) {
            if (!last || d.variant.vertex != last->variant.vertex || d.variant.fragment != last->variant.fragment ||
                d.variant.defines != last->variant.defines)
                variant = d.variant.name();
            if (!last || d.bindings != last->bindings) bindings = binding_names(p, d.bindings);
            last = &d;
            o << "     draw " << (d.fullscreen ? std::string("full-screen triangle") : d.label)
              << (d.triangles ? " (" + std::to_string(d.triangles->size() / 3) + " triangles)" : std::string()) << ": "
              << variant << " with " << bindings << (d.cull ? ", cull " + gl::to_string(*d.cull) : std::string()) << "\n";
        }
    }
    for (const auto& n : notes) o << "note: " << n << "\n";
    return o.str();
}

std::string FramePlan::to_json() const {
    std::string j = "{\"settings\":{";
    const auto pairs = to_pairs(settings);
    for (size_t i = 0; i < pairs.size(); ++i) j += std::string(i ? "," : "") + json_quote(pairs[i].first) + ":" + json_quote(pairs[i].second);
    j += "},\"output\":" + json_quote(output);
    j += ",\"camera\":{\"position\":" + json_floats(camera.position) + ",\"view_proj\":" + json_floats(camera.view_proj) + "}";
    for_each_report(*this, [&](const ReportSlot* slot, const Report* r) {
        j += ",\"" + (r ? r->key : std::string(slot->key)) + "\":" + (r ? r->json(r->value) : std::string(slot->absent_json));
    });
    j += ",\"stencil_bits\":" + std::to_string(stencil_bits) + ",\"stencil\":[";
    for (size_t i = 0; i < stencil.size(); ++i) {
        const StencilUse& u = stencil[i];
        j += std::string(i ? "," : "") + "{\"name\":" + json_quote(u.name) + ",\"module\":" + json_quote(u.module) +
             ",\"bits\":" + std::to_string(u.bits) + ",\"counts\":" + json_bool(u.counts) +
             ",\"shift\":" + std::to_string(u.shift) + ",\"width\":" + std::to_string(u.width) +
             ",\"ref_of_1\":" + std::to_string(u.ref(1)) + ",\"read_mask\":" + std::to_string(u.mask()) +
             ",\"write_mask\":" + std::to_string(u.mask()) + "}";
    }
    j += "]";
    j += ",\"resources\":[";
    std::size_t total = 0;
    for (size_t i = 0; i < resources.size(); ++i) {
        const PlannedResource& r = resources[i];
        const ResourceDesc& d = r.desc;
        total += d.bytes();
        j += std::string(i ? "," : "") + "{\"name\":" + json_quote(d.name) + ",\"width\":" + std::to_string(d.width) +
             ",\"height\":" + std::to_string(d.height) + ",\"color\":" + json_bool(d.color) + ",\"depth_buffer\":" +
             (d.depth_buffer ? json_quote(gl::to_string(*d.depth_buffer)) : std::string("null")) +
             ",\"depth_texture\":" + json_bool(d.depth_texture) + ",\"cube\":" + json_bool(d.cube) + ",\"sampling\":" + json_quote(gl::to_string(d.sampling)) +
             ",\"wrap\":" + json_quote(gl::to_string(d.wrap)) + ",\"bytes\":" + std::to_string(d.bytes()) +
             ",\"content\":" + json_quote(r.content) + ",\"reused\":" + json_bool(r.reused) +
             ",\"purpose\":" + json_quote(r.purpose) + "}";
    }
    const StateCounts n = state_counts();
    j += "],\"bytes\":" + std::to_string(total) + ",\"state_changes\":{\"passes\":" + std::to_string(n.passes) +
         ",\"state_calls\":" + std::to_string(n.state_calls) + ",\"program_switches\":" +
         std::to_string(n.program_switches) + ",\"uniform_sets\":" + std::to_string(n.uniform_sets) +
         ",\"texture_binds\":" + std::to_string(n.texture_binds) + ",\"texture_binds_skipped\":" +
         std::to_string(n.texture_binds_skipped) + ",\"draws\":" + std::to_string(n.draws) + "},\"passes\":[";
    for (size_t i = 0; i < passes.size(); ++i) j += std::string(i ? "," : "") + json_pass(*this, passes[i]);
    j += "],\"notes\":" + json_strings(notes) + "}";
    return j;
}

}  // namespace penumbra::render
