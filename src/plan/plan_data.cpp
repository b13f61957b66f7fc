// The plan's value types: the caller's outputs, the resources and passes (their descriptions and
// what executing them asks of GL, counted), and the stencil's named uses with their allocation.
// No GL here; plan.cpp builds plans out of these.
#include <algorithm>
#include <cstdio>
#include <map>

#include "plan/plan.h"

namespace penumbra::render {

namespace {

std::string size_str(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

// ---- inputs ------------------------------------------------------------------------------------

Output Output::offscreen(int width, int height) {
    Output o;
    o.width = width;
    o.height = height;
    return o;
}

Output Output::to_window(int width, int height) {
    Output o;
    o.window = true;
    o.width = width;
    o.height = height;
    return o;
}

Output Output::window_region(int x, int y, int width, int height) {
    Output o = to_window(width, height);
    o.x = x;
    o.y = y;
    o.clip = true;
    return o;
}

Output Output::texture(std::string name, int width, int height, gl::Sampling sampling, gl::Wrap wrap) {
    Output o;
    o.name = std::move(name);
    o.width = width;
    o.height = height;
    o.sampling = sampling;
    o.wrap = wrap;
    return o;
}

Output Output::copied_texture(std::string name, int width, int height, gl::Sampling sampling, gl::Wrap wrap) {
    Output o = texture(std::move(name), width, height, sampling, wrap);
    o.copied = true;
    return o;
}

FrameInputs offscreen(int width, int height) {
    FrameInputs in;
    in.output = Output::offscreen(width, height);
    return in;
}

// ---- resources and passes ----------------------------------------------------------------------

std::size_t ResourceDesc::bytes() const {
    const auto px = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::size_t per = 0;
    if (color)
        per += static_cast<std::size_t>(cube ? 6 : colors) *
               static_cast<std::size_t>(
                   gl::bytes_per_pixel(half_float ? gl::TextureFormat::RGBA16F : gl::TextureFormat::RGBA8));
    if (depth_texture) per += static_cast<std::size_t>(gl::bytes_per_pixel(gl::TextureFormat::Depth));
    if (depth_buffer) per += static_cast<std::size_t>(gl::bytes_per_pixel(*depth_buffer));
    return px * per;
}

std::string ResourceDesc::describe() const {
    std::string s = (cube ? "6 x " : "") + size_str(width, height);
    std::string parts = cube ? "cube " : "";
    if (color) parts += (colors > 1 ? std::to_string(colors) + " x " : std::string()) + (half_float ? "rgba16f" : "rgba8");
    if (depth_texture) parts += std::string(parts.empty() ? "" : " + ") + "depth texture";
    if (depth_buffer) parts += std::string(parts.empty() ? "" : " + ") + gl::to_string(*depth_buffer);
    return s + " " + parts + ", " + gl::to_string(sampling) + ", " + gl::to_string(wrap);
}

bool ResourceDesc::operator==(const ResourceDesc& o) const {
    return name == o.name && width == o.width && height == o.height && color == o.color && half_float == o.half_float && colors == o.colors &&
           depth_buffer == o.depth_buffer && depth_texture == o.depth_texture && cube == o.cube && sampling == o.sampling && wrap == o.wrap;
}

std::vector<int> Pass::reads() const {
    std::vector<int> out;
    const auto add = [&](int r) {
        if (r >= 0 && std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
    };
    for (const Binding& b : bindings)
        for (const TextureBinding& t : b.textures) add(t.resource);
    for (const Draw& d : draws) add(d.image_resource);
    return out;
}

StateCounts FramePlan::state_counts() const {
    StateCounts n;
    gl::PipelineState state;  // Renderer::run leaves the defaults after every frame
    std::string program;
    std::map<int, std::string> units;  // what each texture unit holds
    const auto bind = [&](int unit, const std::string& what) {
        std::string& held = units[unit];
        ++(held == what ? n.texture_binds_skipped : n.texture_binds);
        held = what;
    };
    for (const Pass& pass : passes) {
        if (pass.skipped) continue;
        ++n.passes;
        n.state_calls += gl::state_calls(state, pass.state);
        state = pass.state;
        for (const Binding& b : pass.bindings)
            for (const TextureBinding& t : b.textures) bind(t.unit, "resource " + std::to_string(t.resource) + "." + std::to_string(t.attachment));
        bool first = true;
        std::uint32_t bound = 0;
        std::string pass_program;
        for (const Draw& d : pass.draws) {
            gl::PipelineState want = pass.state;
            want.cull = d.cull.value_or(pass.state.cull);
            n.state_calls += gl::state_calls(state, want);
            state = want;
            const std::string v = d.variant.name();
            if (first || v != pass_program || d.bindings != bound) {
                if (v != program) ++n.program_switches;
                program = pass_program = v;
                bound = d.bindings;
                first = false;
                for (size_t i = 0; i < pass.bindings.size(); ++i)
                    if (d.bindings & (1u << i)) n.uniform_sets += static_cast<int>(pass.bindings[i].uniforms.size());
            }
            if ((pass.object_uniforms == ObjectUniforms::Lit || (pass.object_uniforms == ObjectUniforms::Mvp && d.alpha)) &&
                d.image >= 0)
                bind(kBaseTextureUnit, d.image_resource >= 0 ? "resource " + std::to_string(d.image_resource)
                                                             : "image " + std::to_string(d.image));
            ++n.draws;
        }
    }
    n.state_calls += gl::state_calls(state, gl::PipelineState{});
    return n;
}

void FramePlan::drop(std::string_view key) {
    reports.erase(std::remove_if(reports.begin(), reports.end(), [&](const Report& r) { return r.key == key; }),
                  reports.end());
}

int FramePlan::resource_index(std::string_view name) const {
    for (size_t i = 0; i < resources.size(); ++i)
        if (resources[i].desc.name == name) return static_cast<int>(i);
    return -1;
}

const PlannedResource* FramePlan::resource(std::string_view name) const {
    const int i = resource_index(name);
    return i < 0 ? nullptr : &resources[static_cast<size_t>(i)];
}

bool FramePlan::has_pass(std::string_view name) const {
    return std::any_of(passes.begin(), passes.end(), [&](const Pass& p) { return p.name == name; });
}

bool FramePlan::drawn(std::string_view name) const {
    const int r = resource_index(name);
    return r >= 0 && std::any_of(passes.begin(), passes.end(),
                                 [&](const Pass& p) { return p.target.resource == r && !p.skipped; });
}

// ---- the stencil -------------------------------------------------------------------------------

std::uint32_t StencilUse::mask() const {
    if (width <= 0) return 0u;
    return ((width >= 32 ? ~0u : (1u << width) - 1u) << shift) & 0xFFu;
}

int StencilUse::ref(int value) const { return value << shift; }

std::uint32_t StencilUse::top_bit() const { return width > 0 ? 1u << (shift + width - 1) : 0u; }

gl::StencilState StencilUse::test(gl::Compare func, int value, gl::StencilOp pass) const {
    gl::StencilState s = gl::stencil_test(func, ref(value), pass);
    s.read_mask = s.write_mask = mask();
    return s;
}

gl::StencilState StencilUse::count(bool on_depth_fail) const {
    gl::StencilState s = gl::stencil_count(on_depth_fail);
    s.read_mask = s.write_mask = mask();
    return s;
}

std::string StencilUse::describe() const {
    char buf[64];
    if (width <= 1) std::snprintf(buf, sizeof buf, "bit %d (mask %02x)", shift, mask());
    else std::snprintf(buf, sizeof buf, "bits %d-%d (mask %02x)", shift, shift + width - 1, mask());
    return buf;
}

const StencilUse* FramePlan::stencil_use(std::string_view name) const {
    for (const StencilUse& u : stencil)
        if (u.name == name) return &u;
    return nullptr;
}

std::string allocate_stencil(std::vector<StencilUse>& uses, int available) {
    StencilUse* counter = nullptr;
    int needed = 0;
    std::string names;
    for (StencilUse& u : uses) {
        if (u.counts) {
            if (counter)
                return "stencil: '" + counter->name + "' and '" + u.name +
                       "' both count (incr/decr act on the stencil's lowest bits): one frame holds one";
            counter = &u;
        }
        needed += u.bits;
        names += (names.empty() ? "'" : " and '") + u.name + "' (" + std::to_string(u.bits) +
                 (u.bits == 1 ? " bit)" : " bits)");
    }
    if (needed > available)
        return "stencil: " + names + " need " + std::to_string(needed) + " bits, the target has " +
               std::to_string(available);
    int top = available;
    for (StencilUse& u : uses)
        if (!u.counts) {
            top -= u.bits;
            u.shift = top;
            u.width = u.bits;
        }
    if (counter) {
        counter->shift = 0;
        counter->width = top;
    }
    return {};
}

std::string Output::describe() const {
    const std::string copy = copy_to.empty() ? "" : ", copied into texture " + copy_to;
    if (window)
        return "window " + size_str(width, height) +
               (x || y || clip ? " at (" + std::to_string(x) + ", " + std::to_string(y) + ")" : "") + copy;
    if (name == "camera") return "offscreen " + size_str(width, height) + copy;
    return "texture " + name + " " + size_str(width, height) + (copied ? " (filled by a copy)" : "");
}

}  // namespace penumbra::render
