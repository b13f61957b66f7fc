// Mipmaps by rendering (penumbra mipmaps; the course notes' "generating mipmaps by rendering into
// each level"): a square power-of-two RGBA8 texture's chain made level by level on the GPU, each
// level drawn from the level above with a box filter or a normal map's renormalising filter
// (mip_down.frag), compared with glGenerateMipmap and with the same filters on the CPU.
//
// Two ways to build it, the same bytes either way:
//   levels    each level rendered into the texture's own level (a framebuffer with that level
//             attached: OES_fbo_render_mipmap). GLES 2 has no base level, so a texture cannot be
//             sampled at one level while another of it is drawn (a feedback loop): the level above
//             is read through a copy of it (glCopyTexImage2D into a scratch texture).
//   textures  WebGL 1 and GLES 2 without the extension render into level 0 only: each level is
//             rendered into a texture of its own from the previous one, read back and uploaded
//             into the chain's level (glTexImage2D).
// Reading a level back: through a framebuffer on it (levels), or by drawing the chain sampled
// nearest-mipmap-nearest at the level's size (textures; what WebGL 1 can do).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl/caps.h"

namespace penumbra::render {

class Renderer;

enum class MipFilter { Box, Normal };
enum class MipPath { Auto, Levels, Textures };
std::string to_string(MipFilter f);  // "box", "normal"
std::string to_string(MipPath p);    // "auto", "levels", "textures"

// One square level: size x size RGBA8, rows bottom first.
struct MipImage {
    int size = 0;
    std::vector<std::uint8_t> rgba;
};

// "" when `size` can be a chain's level 0 (a power of two, 1..max_size), else the problem.
std::string mip_size_problem(int size, int max_size);
int mip_level_count(int size);  // log2(size) + 1

// The filter applied once on the CPU: level L+1 from level L (its size halved), each byte the
// rounded value of the filtered float, as a context that rounds writes it.
MipImage cpu_mip_down(const MipImage& above, MipFilter f);
// Level 0 and every level below it, each from the one above.
std::vector<MipImage> cpu_mip_chain(const MipImage& level0, MipFilter f);

// The path used for `asked` on this context: Auto takes levels where the context can render into
// them, else textures. `reason` says why in one line; Levels without OES_fbo_render_mipmap is a
// problem (returned non-empty, path unchanged).
struct MipPathChoice {
    MipPath path = MipPath::Textures;
    std::string reason;
    std::string problem;
};
MipPathChoice choose_mip_path(const gl::Caps& caps, MipPath asked);

// A chain on the GPU: level 0 uploaded, the levels below defined (contents undefined until
// built). Owns its GL objects; works through the renderer's device and shader library, on the
// renderer's context.
class GpuMipChain {
public:
    GpuMipChain(Renderer& r, const MipImage& level0);
    ~GpuMipChain();
    GpuMipChain(const GpuMipChain&) = delete;
    GpuMipChain& operator=(const GpuMipChain&) = delete;

    // Levels 1.. rendered from the level above along `path` (Levels or Textures: chosen already).
    // Throws gl::Error on a GL failure.
    void render(MipFilter f, MipPath path);
    // Levels 1.. made by glGenerateMipmap instead.
    void generate();
    // Every level (0 included) read back: through a framebuffer on each level with `path` Levels,
    // else by drawing (MIP_READ).
    std::vector<MipImage> read(MipPath path);
    int levels() const;

private:
    struct State;
    Renderer& r_;
    std::unique_ptr<State> s_;
};

// Per-channel differences of two levels of one size: the largest and the mean over RGB (alpha too
// with `alpha`).
struct MipDiff {
    int max = 0;
    double mean = 0.0;
};
MipDiff mip_diff(const MipImage& a, const MipImage& b, bool alpha = true);
// The mean length of a normal map level's decoded normals (1 for unit normals; a box filter
// shortens them where they differ).
double mean_normal_length(const MipImage& level);

}  // namespace penumbra::render
