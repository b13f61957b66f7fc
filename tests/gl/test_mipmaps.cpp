// Mipmaps by rendering (render/mipmaps.h) on a context: every level rendered from the level above
// equals the CPU reference within 1 level, through the texture's own levels (OES_fbo_render_mipmap)
// and through textures of their own (WebGL 1's way), the two byte for byte; the normal filter keeps
// the normals unit length where glGenerateMipmap's box shortens them; a level read back by drawing
// equals the level read through a framebuffer. No GL errors (the fixture's teardown).
#include "gl_fixture.h"

#include "render/mipmaps.h"
#include "scene/marble.h"

using namespace penumbra;
using render::MipFilter;
using render::MipImage;
using render::MipPath;

namespace {

MipImage source(bool normals, int size) {
    const scene::Image s = normals ? scene::make_tile_normal_map(size) : scene::make_marble(size);
    return {size, s.rgba};
}

class MipmapsGl : public test::GlTest {};

TEST(MipmapsCpu, BoxRoundsTheMeanOfFourAndNormalsAreRenormalised) {
    MipImage above{2, {0, 10, 255, 255, /**/ 1, 10, 255, 255, /**/ 2, 11, 0, 255, /**/ 3, 11, 0, 255}};
    const MipImage box = render::cpu_mip_down(above, MipFilter::Box);
    ASSERT_EQ(box.size, 1);
    EXPECT_EQ(box.rgba, (std::vector<std::uint8_t>{2, 11, 128, 255}));  // (6 + 2) / 4, (42 + 2) / 4, ties up
    // Two normals tilted left and two tilted right: their box mean is short and points up; the
    // normal filter makes it unit length again.
    const auto enc = [](double v) { return static_cast<std::uint8_t>(v * 127.5 + 127.5 + 0.5); };
    const std::uint8_t l = enc(-0.6), r = enc(0.6), up = enc(0.8), mid = enc(0.0);
    MipImage normals{2, {l, mid, up, 255, r, mid, up, 255, l, mid, up, 255, r, mid, up, 255}};
    EXPECT_LT(render::mean_normal_length(render::cpu_mip_down(normals, MipFilter::Box)), 0.81);
    const MipImage n = render::cpu_mip_down(normals, MipFilter::Normal);
    EXPECT_NEAR(render::mean_normal_length(n), 1.0, 0.01);
    EXPECT_EQ(n.rgba[2], 255);  // straight up
}

TEST(MipmapsCpu, PathChoiceNamesTheReason) {
    gl::Caps caps;
    caps.render_mipmap = true;
    EXPECT_EQ(render::choose_mip_path(caps, MipPath::Auto).path, MipPath::Levels);
    caps.render_mipmap = false;
    caps.api = gl::Api::WebGL1;
    const render::MipPathChoice c = render::choose_mip_path(caps, MipPath::Auto);
    EXPECT_EQ(c.path, MipPath::Textures);
    EXPECT_NE(c.reason.find("WebGL 1 renders into level 0 only"), std::string::npos) << c.reason;
    EXPECT_NE(render::choose_mip_path(caps, MipPath::Levels).problem.find("--path levels"), std::string::npos);
    EXPECT_NE(render::mip_size_problem(96, 4096).find("not a power of two"), std::string::npos);
    EXPECT_EQ(render::mip_size_problem(64, 4096), "");
    EXPECT_EQ(render::mip_level_count(64), 7);
}

TEST_F(MipmapsGl, EveryLevelEqualsTheCpuReferenceOnBothPaths) {
    ASSERT_TRUE(renderer->caps().render_mipmap) << "llvmpipe renders into mip levels (OES_fbo_render_mipmap)";
    for (bool normals : {false, true})
        for (MipFilter f : {MipFilter::Box, MipFilter::Normal}) {
            const MipImage level0 = source(normals, 64);
            const std::vector<MipImage> cpu = render::cpu_mip_chain(level0, f);
            std::vector<MipImage> by_path[2];
            int i = 0;
            for (MipPath p : {MipPath::Levels, MipPath::Textures}) {
                render::GpuMipChain chain(*renderer, level0);
                chain.render(f, p);
                by_path[i] = chain.read(p);
                const std::vector<MipImage>& got = by_path[i++];
                ASSERT_EQ(got.size(), cpu.size());
                for (size_t l = 0; l < got.size(); ++l) {
                    SCOPED_TRACE((normals ? "normals " : "marble ") + render::to_string(f) + " " + render::to_string(p) +
                                 " level " + std::to_string(l));
                    EXPECT_EQ(got[l].size, 64 >> l);
                    EXPECT_LE(render::mip_diff(got[l], cpu[l]).max, 1);
                    if (l > 0) {
                        EXPECT_LE(render::mip_diff(got[l], render::cpu_mip_down(got[l - 1], f)).max, 1);
                    }
                }
            }
            for (size_t l = 0; l < cpu.size(); ++l) EXPECT_EQ(by_path[0][l].rgba, by_path[1][l].rgba) << "level " << l;
        }
}

TEST_F(MipmapsGl, TheComparisonSeesAWrongFilter) {
    // The box chain of the normal map against the normal filter's reference: the check above
    // would fail (the renormalisation moves the coarse levels by far more than 1 level).
    const MipImage level0 = source(true, 64);
    render::GpuMipChain chain(*renderer, level0);
    chain.render(MipFilter::Box, MipPath::Levels);
    const std::vector<MipImage> got = chain.read(MipPath::Levels);
    const std::vector<MipImage> cpu = render::cpu_mip_chain(level0, MipFilter::Normal);
    int worst = 0;
    for (size_t l = 0; l < got.size(); ++l) worst = std::max(worst, render::mip_diff(got[l], cpu[l]).max);
    EXPECT_GT(worst, 10);
}

TEST_F(MipmapsGl, GenerateMipmapShortensNormalsTheNormalFilterDoesNot) {
    const MipImage level0 = source(true, 64);
    render::GpuMipChain generated(*renderer, level0), rendered(*renderer, level0);
    generated.generate();
    rendered.render(MipFilter::Normal, MipPath::Levels);
    const std::vector<MipImage> g = generated.read(MipPath::Levels), r = rendered.read(MipPath::Levels);
    // Level 3 (8x8): one texel per tile of the map, where a box mean of a dome's normals is short.
    EXPECT_LT(render::mean_normal_length(g[3]), 0.9);
    EXPECT_GT(render::mean_normal_length(r[3]), 0.99);
    // glGenerateMipmap is a box filter too: within a few levels of the CPU box chain.
    const std::vector<MipImage> box = render::cpu_mip_chain(level0, MipFilter::Box);
    for (size_t l = 0; l < g.size(); ++l) EXPECT_LE(render::mip_diff(g[l], box[l]).max, 8) << "level " << l;
}

TEST_F(MipmapsGl, ALevelReadByDrawingEqualsTheLevelReadThroughAFramebuffer) {
    render::GpuMipChain chain(*renderer, source(false, 32));
    chain.generate();
    const std::vector<MipImage> attached = chain.read(MipPath::Levels), drawn = chain.read(MipPath::Textures);
    ASSERT_EQ(attached.size(), drawn.size());
    for (size_t l = 0; l < attached.size(); ++l) EXPECT_EQ(attached[l].rgba, drawn[l].rgba) << "level " << l;
}

}  // namespace
