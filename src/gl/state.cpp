#include "gl/state.h"

#include <cstdio>

namespace penumbra::gl {

bool StencilState::operator==(const StencilState& o) const {
    return enabled == o.enabled && func == o.func && ref == o.ref && read_mask == o.read_mask &&
           write_mask == o.write_mask && fail == o.fail && depth_fail == o.depth_fail && pass == o.pass &&
           two_sided == o.two_sided && back_fail == o.back_fail && back_depth_fail == o.back_depth_fail &&
           back_pass == o.back_pass;
}

bool PipelineState::operator==(const PipelineState& o) const {
    return depth_test == o.depth_test && depth_func == o.depth_func && depth_write == o.depth_write &&
           color_write == o.color_write && cull == o.cull && stencil == o.stencil && blend == o.blend &&
           offset_factor == o.offset_factor && offset_units == o.offset_units;
}

std::string to_string(Compare c) {
    switch (c) {
        case Compare::Never: return "never";
        case Compare::Less: return "less";
        case Compare::LEqual: return "lequal";
        case Compare::Equal: return "equal";
        case Compare::GEqual: return "gequal";
        case Compare::Greater: return "greater";
        case Compare::NotEqual: return "notequal";
        case Compare::Always: return "always";
    }
    return "?";
}

std::string to_string(StencilOp o) {
    switch (o) {
        case StencilOp::Keep: return "keep";
        case StencilOp::Zero: return "zero";
        case StencilOp::Replace: return "replace";
        case StencilOp::Incr: return "incr";
        case StencilOp::Decr: return "decr";
        case StencilOp::IncrWrap: return "incr-wrap";
        case StencilOp::DecrWrap: return "decr-wrap";
    }
    return "?";
}

std::string to_string(Cull c) {
    switch (c) {
        case Cull::None: return "none";
        case Cull::Back: return "back";
        case Cull::Front: return "front";
    }
    return "?";
}

int state_calls(const PipelineState& from, const PipelineState& to) {
    int n = 0;
    n += from.depth_test != to.depth_test;
    n += from.depth_func != to.depth_func;
    n += from.depth_write != to.depth_write;
    n += from.color_write != to.color_write;
    if (from.cull != to.cull) n += (to.cull != Cull::None) + ((from.cull == Cull::None) != (to.cull == Cull::None));
    const StencilState& a = to.stencil;
    const StencilState& b = from.stencil;
    n += a.enabled != b.enabled;
    n += a.func != b.func || a.ref != b.ref || a.read_mask != b.read_mask;
    n += a.write_mask != b.write_mask;
    if (a.fail != b.fail || a.depth_fail != b.depth_fail || a.pass != b.pass || a.two_sided != b.two_sided ||
        a.back_fail != b.back_fail || a.back_depth_fail != b.back_depth_fail || a.back_pass != b.back_pass)
        n += a.two_sided ? 2 : 1;
    n += from.blend != to.blend;
    const bool offset_from = from.offset_factor != 0.0f || from.offset_units != 0.0f;
    const bool offset_to = to.offset_factor != 0.0f || to.offset_units != 0.0f;
    n += offset_from != offset_to;
    n += offset_to && (from.offset_factor != to.offset_factor || from.offset_units != to.offset_units);
    return n;
}

std::string to_string(const PipelineState& s) {
    std::string out = s.depth_test ? "depth " + to_string(s.depth_func) : std::string("depth off");
    out += s.depth_write ? ", write" : ", no write";
    out += s.color_write ? "; colour on" : "; colour off";
    out += "; cull " + to_string(s.cull);
    if (s.blend == Blend::Alpha) out += "; blend alpha";
    if (s.blend == Blend::Add) out += "; blend add";
    if (s.blend == Blend::Over) out += "; blend over (premultiplied)";
    if (s.offset_factor != 0.0f || s.offset_units != 0.0f) {
        char offset[64];
        std::snprintf(offset, sizeof offset, "; depth offset %g, %g", static_cast<double>(s.offset_factor),
                      static_cast<double>(s.offset_units));
        out += offset;
    }
    const StencilState& st = s.stencil;
    if (!st.enabled) return out + "; stencil off";
    char masks[48];
    std::snprintf(masks, sizeof masks, " (read %02x, write %02x)", static_cast<unsigned>(st.read_mask),
                  static_cast<unsigned>(st.write_mask));
    out += "; stencil " + to_string(st.func) + " " + std::to_string(st.ref) + masks;
    const auto ops = [](StencilOp f, StencilOp z, StencilOp p) {
        return "fail " + to_string(f) + ", depth fail " + to_string(z) + ", pass " + to_string(p);
    };
    if (st.two_sided)
        return out + ", front: " + ops(st.fail, st.depth_fail, st.pass) + "; back: " +
               ops(st.back_fail, st.back_depth_fail, st.back_pass);
    out += ", " + ops(st.fail, st.depth_fail, st.pass);
    return out;
}

std::string to_string(Sampling s) {
    switch (s) {
        case Sampling::Nearest: return "nearest";
        case Sampling::Linear: return "linear";
        case Sampling::LinearMipmap: return "linear-mipmap";
        case Sampling::NearestMipmap: return "nearest-mipmap";
    }
    return "?";
}

std::string to_string(Wrap w) { return w == Wrap::Repeat ? "repeat" : "clamp"; }

std::string to_string(RenderbufferFormat f) {
    switch (f) {
        case RenderbufferFormat::Depth16: return "depth16";
        case RenderbufferFormat::Depth24: return "depth24";
        case RenderbufferFormat::Depth24Stencil8: return "depth24-stencil8";
        case RenderbufferFormat::DepthStencil: return "depth-stencil";
        case RenderbufferFormat::Stencil8: return "stencil8";
    }
    return "?";
}

int bytes_per_pixel(TextureFormat f) { return f == TextureFormat::RGBA16F ? 8 : 4; }

int bytes_per_pixel(RenderbufferFormat f) {
    switch (f) {
        case RenderbufferFormat::Depth16: return 2;
        case RenderbufferFormat::Stencil8: return 1;
        default: return 4;
    }
}

}  // namespace penumbra::gl
