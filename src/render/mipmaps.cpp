#include "render/mipmaps.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "gl/device.h"
#include "gl/objects.h"
#include "render/renderer.h"
#include "plan/variants.h"

namespace penumbra::render {

std::string to_string(MipFilter f) { return f == MipFilter::Normal ? "normal" : "box"; }

std::string to_string(MipPath p) {
    switch (p) {
        case MipPath::Auto: return "auto";
        case MipPath::Levels: return "levels";
        case MipPath::Textures: return "textures";
    }
    return "?";
}

std::string mip_size_problem(int size, int max_size) {
    if (size < 1 || (size & (size - 1)) != 0)
        return std::to_string(size) + " is not a power of two (GLES 2 mipmaps only power-of-two textures)";
    if (size > max_size)
        return std::to_string(size) + " is larger than this context's largest texture (" + std::to_string(max_size) + ")";
    return {};
}

int mip_level_count(int size) {
    int n = 1;
    while (size > 1) size /= 2, ++n;
    return n;
}

namespace {

// floor(v * 255 + 0.5), as mip_down.frag rounds.
std::uint8_t to_byte(double v) { return static_cast<std::uint8_t>(std::clamp(std::floor(v * 255.0 + 0.5), 0.0, 255.0)); }

}  // namespace

MipImage cpu_mip_down(const MipImage& above, MipFilter f) {
    MipImage out;
    out.size = std::max(1, above.size / 2);
    out.rgba.resize(static_cast<size_t>(out.size) * static_cast<size_t>(out.size) * 4u);
    const auto at = [&](int x, int y, int c) {
        // A 1x1 level above: its one texel four times (no level below a 1x1 one is ever asked for).
        x = std::min(x, above.size - 1), y = std::min(y, above.size - 1);
        return int(above.rgba[(static_cast<size_t>(y) * static_cast<size_t>(above.size) + static_cast<size_t>(x)) * 4u +
                              static_cast<size_t>(c)]);
    };
    for (int y = 0; y < out.size; ++y)
        for (int x = 0; x < out.size; ++x) {
            int sum[4];
            for (int c = 0; c < 4; ++c)
                sum[c] = at(2 * x, 2 * y, c) + at(2 * x + 1, 2 * y, c) + at(2 * x, 2 * y + 1, c) + at(2 * x + 1, 2 * y + 1, c);
            std::uint8_t* px = &out.rgba[(static_cast<size_t>(y) * static_cast<size_t>(out.size) + static_cast<size_t>(x)) * 4u];
            // The rounded mean, ties up: mip_down.frag's arithmetic on whole bytes.
            for (int c = 0; c < 4; ++c) px[c] = static_cast<std::uint8_t>((sum[c] + 2) / 4);
            if (f == MipFilter::Normal) {
                glm::dvec3 n(sum[0], sum[1], sum[2]);
                n = n * (2.0 / (4.0 * 255.0)) - 1.0;
                const double len = glm::length(n);
                n = len > 1e-4 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
                for (int c = 0; c < 3; ++c) px[c] = to_byte(n[c] * 0.5 + 0.5);
            }
        }
    return out;
}

std::vector<MipImage> cpu_mip_chain(const MipImage& level0, MipFilter f) {
    std::vector<MipImage> chain{level0};
    while (chain.back().size > 1) chain.push_back(cpu_mip_down(chain.back(), f));
    return chain;
}

MipPathChoice choose_mip_path(const gl::Caps& caps, MipPath asked) {
    MipPathChoice c;
    const bool webgl = caps.api == gl::Api::WebGL1;
    const std::string cannot = webgl ? "WebGL 1 renders into level 0 only"
                                     : "this context has no OES_fbo_render_mipmap (GLES 2 renders into level 0 only)";
    switch (asked) {
        case MipPath::Levels:
            c.path = MipPath::Levels;
            if (!caps.render_mipmap) c.problem = "--path levels: " + cannot + "; use --path textures or auto";
            else c.reason = "asked for; OES_fbo_render_mipmap renders into each level";
            break;
        case MipPath::Textures:
            c.path = MipPath::Textures;
            c.reason = "asked for: each level rendered into a texture of its own, then copied into the chain's level";
            break;
        case MipPath::Auto:
            c.path = caps.render_mipmap ? MipPath::Levels : MipPath::Textures;
            c.reason = caps.render_mipmap
                           ? "OES_fbo_render_mipmap: each level rendered into the texture's own level"
                           : cannot + ": each level rendered into a texture of its own, then copied into the chain's level";
            break;
    }
    return c;
}

// ---- the GPU chain ------------------------------------------------------------------------------

struct GpuMipChain::State {
    int size = 0;
    int levels = 0;
    gl::Texture chain;
    std::vector<gl::Framebuffer> level_fbs;  // a framebuffer on each level (Levels path), made on first use
};

namespace {

int level_size(int size, int level) { return std::max(1, size >> level); }

gl::PipelineState screen_state() {
    gl::PipelineState st;
    st.depth_test = false;
    st.depth_write = false;
    st.cull = gl::Cull::None;
    return st;
}

}  // namespace

GpuMipChain::GpuMipChain(Renderer& r, const MipImage& level0) : r_(r), s_(std::make_unique<State>()) {
    s_->size = level0.size;
    s_->levels = mip_level_count(level0.size);
    gl::TextureDesc d;
    d.width = d.height = level0.size;
    d.rgba = level0.rgba.data();
    d.label = "mip chain";
    s_->chain = gl::Texture(d);
    for (int l = 1; l < s_->levels; ++l) {
        const int n = level_size(s_->size, l);
        s_->chain.set_level(l, n, n, nullptr);
    }
    r_.device().forget_textures();
}

GpuMipChain::~GpuMipChain() { r_.device().forget_textures(); }

int GpuMipChain::levels() const { return s_->levels; }

namespace {

const gl::Framebuffer& level_fb(std::vector<gl::Framebuffer>& fbs, const gl::Texture& chain, int level) {
    if (fbs.size() <= static_cast<size_t>(level)) fbs.resize(static_cast<size_t>(level) + 1);
    gl::Framebuffer& fb = fbs[static_cast<size_t>(level)];
    if (fb.id() == 0) {
        gl::FramebufferDesc d;
        d.color = &chain;
        d.color_level = level;
        d.label = "mip level";
        fb = gl::Framebuffer(d);
    }
    return fb;
}

// One draw of `program` sampling `source` on unit 0 into `target`; u_texel (one texel of the
// source) unless the program only reads a level (MIP_READ).
void draw_from(gl::Device& dev, const gl::Program& program, const gl::Texture& source, int source_size,
               const gl::Target& target, bool texel = true) {
    dev.bind_target(target);
    dev.apply(screen_state());
    dev.use(program);
    program.set("u_image", 0);
    if (texel) {
        const float t = 1.0f / static_cast<float>(source_size);
        program.set("u_texel", glm::vec2(t, t));
    }
    dev.bind_texture(0, source);
    dev.draw_fullscreen();
}

}  // namespace

void GpuMipChain::render(MipFilter f, MipPath path) {
    gl::Device& dev = r_.device();
    const gl::Program& program = r_.shaders().get(mip_down_variant(f == MipFilter::Normal));
    // The level above, as a texture of its own (level 0's copy to start with).
    gl::TextureDesc d;
    d.width = d.height = s_->size;
    d.label = "mip source";
    gl::Texture above(d);
    {
        const gl::Framebuffer& fb0 = level_fb(s_->level_fbs, s_->chain, 0);
        dev.bind_target({&fb0, s_->size, s_->size});
        above.copy_framebuffer(0, 0, 0, s_->size, s_->size, true);
    }
    for (int l = 1; l < s_->levels; ++l) {
        const int n = level_size(s_->size, l), n_above = level_size(s_->size, l - 1);
        if (path == MipPath::Levels) {
            // Drawn into the chain's own level; then the level is the next one's source (a copy:
            // GLES 2 cannot sample one level of a texture while another of it is drawn).
            const gl::Framebuffer& fb = level_fb(s_->level_fbs, s_->chain, l);
            draw_from(dev, program, above, n_above, {&fb, n, n});
            if (l + 1 < s_->levels) above.copy_framebuffer(0, 0, 0, n, n, true);
        } else {
            // Drawn into a texture of its own (level 0 of it), copied into the chain's level; that
            // texture is the next level's source.
            gl::TextureDesc t;
            t.width = t.height = n;
            t.label = "mip level texture";
            gl::Texture own(t);
            gl::FramebufferDesc fd;
            fd.color = &own;
            fd.label = "mip level texture";
            const gl::Framebuffer fb(fd);
            dev.forget_textures();
            draw_from(dev, program, above, n_above, {&fb, n, n});
            s_->chain.copy_framebuffer(l, 0, 0, n, n, true);
            above = std::move(own);
        }
        dev.forget_textures();
    }
    dev.bind_target({nullptr, 1, 1});
}

void GpuMipChain::generate() {
    s_->chain.generate_mipmap();
    r_.device().forget_textures();
}

std::vector<MipImage> GpuMipChain::read(MipPath path) {
    gl::Device& dev = r_.device();
    std::vector<MipImage> out;
    const bool by_drawing = path != MipPath::Levels && s_->levels > 1;
    if (by_drawing) s_->chain.set_sampling(gl::Sampling::NearestMipmap);
    for (int l = 0; l < s_->levels; ++l) {
        const int n = level_size(s_->size, l);
        MipImage img;
        img.size = n;
        if (l == 0 || path == MipPath::Levels) {
            const gl::Framebuffer& fb = level_fb(s_->level_fbs, s_->chain, l);
            dev.bind_target({&fb, n, n});
            img.rgba = dev.read_rgba(n, n);
        } else {
            // Drawn at the level's size, the chain sampled nearest-mipmap-nearest: that level.
            gl::TextureDesc t;
            t.width = t.height = n;
            t.label = "mip read";
            const gl::Texture own(t);
            gl::FramebufferDesc fd;
            fd.color = &own;
            fd.label = "mip read";
            const gl::Framebuffer fb(fd);
            dev.forget_textures();
            draw_from(dev, r_.shaders().get(mip_read_variant()), s_->chain, s_->size, {&fb, n, n}, false);
            img.rgba = dev.read_rgba(n, n);
        }
        out.push_back(std::move(img));
    }
    if (by_drawing) s_->chain.set_sampling(gl::Sampling::Nearest);
    dev.forget_textures();
    dev.bind_target({nullptr, 1, 1});
    return out;
}

// ---- comparisons --------------------------------------------------------------------------------

MipDiff mip_diff(const MipImage& a, const MipImage& b, bool alpha) {
    MipDiff d;
    if (a.size != b.size || a.rgba.size() != b.rgba.size()) {
        d.max = 255;
        d.mean = 255.0;
        return d;
    }
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        if (!alpha && i % 4 == 3) continue;
        const int diff = std::abs(int(a.rgba[i]) - int(b.rgba[i]));
        d.max = std::max(d.max, diff);
        sum += diff;
        ++count;
    }
    d.mean = count ? sum / static_cast<double>(count) : 0.0;
    return d;
}

double mean_normal_length(const MipImage& level) {
    double sum = 0.0;
    const size_t n = level.rgba.size() / 4u;
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 v(level.rgba[4 * i] / 255.0 * 2.0 - 1.0, level.rgba[4 * i + 1] / 255.0 * 2.0 - 1.0,
                           level.rgba[4 * i + 2] / 255.0 * 2.0 - 1.0);
        sum += glm::length(v);
    }
    return n ? sum / static_cast<double>(n) : 0.0;
}

}  // namespace penumbra::render
