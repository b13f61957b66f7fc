// --post on a context. The blur is checked against a CPU Gaussian written here from its definition
// (taps -R..R, sigma R/3, weights normalised, the edge clamped) applied to the same frame rendered
// without it: within 1 level on every pixel, through RGBA16F intermediates and through RGBA8 ones.
// Shadow-blur's visibility equals the CPU Gaussian of the hard visibility AOV the same way. Bloom
// only adds light, and adds none above a threshold of 1. No GL errors (the fixture's teardown).
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "plan/options.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

constexpr int kW = 160, kH = 120;  // not square: the two directions' steps differ

using Image = std::vector<std::uint8_t>;

class PostGl : public test::GlTest {
protected:
    scene::CourseScene course = scene::make_course_scene(8);

    Image render_with(render::Renderer& r, const char* post, render::Aov aov = render::Aov::Color) {
        render::Settings s;
        s.aov = aov;
        EXPECT_EQ(render::parse_option(s, "post", post), "");
        r.render(course.scene, s, render::offscreen(kW, kH));
        return r.read_image("camera");
    }
};

void save(const std::string& name, const Image& img) {
    std::filesystem::create_directories("test-output/post");
    measure::write_png("test-output/post/" + name + ".png", measure::from_rgba(img, kW, kH, 4));
}

// The Gaussian of radius r, in doubles, each channel, clamped at the edges; horizontal then vertical.
std::vector<double> cpu_gaussian(const Image& img, int r) {
    const double sigma = r / 3.0;
    std::vector<double> w(static_cast<size_t>(2 * r + 1));
    double sum = 0.0;
    for (int i = -r; i <= r; ++i) sum += w[static_cast<size_t>(i + r)] = std::exp(-i * i / (2.0 * sigma * sigma));
    for (double& x : w) x /= sum;
    std::vector<double> h(img.size(), 0.0), out(img.size(), 0.0);
    const auto at = [](int x, int y, int c) { return static_cast<size_t>((y * kW + x) * 4 + c); };
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            for (int c = 0; c < 4; ++c)
                for (int i = -r; i <= r; ++i)
                    h[at(x, y, c)] += w[static_cast<size_t>(i + r)] * img[at(std::clamp(x + i, 0, kW - 1), y, c)];
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            for (int c = 0; c < 4; ++c)
                for (int i = -r; i <= r; ++i)
                    out[at(x, y, c)] += w[static_cast<size_t>(i + r)] * h[at(x, std::clamp(y + i, 0, kH - 1), c)];
    return out;
}

struct Diff {
    int worst = 0;     // the largest difference in levels, over the compared pixels' RGB
    int changed = 0;   // pixels the blur moved by more than 4 levels from the unblurred frame
};

// `got` against the reference (rounded), over the pixels where `mask` is true (all when empty).
Diff compare(const Image& got, const std::vector<double>& ref, const Image& before, const std::vector<bool>& mask = {}) {
    Diff d;
    for (size_t p = 0; p < got.size() / 4; ++p) {
        if (!mask.empty() && !mask[p]) continue;
        int moved = 0;
        for (size_t c = 0; c < 3; ++c) {
            const double want = std::clamp(std::round(ref[p * 4 + c]), 0.0, 255.0);
            d.worst = std::max(d.worst, static_cast<int>(std::abs(got[p * 4 + c] - want)));
            moved = std::max(moved, std::abs(int(got[p * 4 + c]) - int(before[p * 4 + c])));
        }
        d.changed += moved > 4;
    }
    return d;
}

}  // namespace

TEST_F(PostGl, TheBlurIsTheCpuGaussianWithinOneLevelThroughEitherFormat) {
    gl::Caps rgba8 = renderer->caps();
    rgba8.half_float_target = false;
    render::Renderer eight(rgba8);
    struct Path {
        const char* name;
        render::Renderer* r;
    };
    std::vector<Path> paths = {{"rgba8", &eight}};
    if (renderer->caps().half_float_target) paths.push_back({"rgba16f", renderer.get()});
    else std::printf("this context has no half-float targets: the RGBA8 path only\n");
    for (const Path& path : paths) {
        const Image plain = render_with(*path.r, "none");
        for (int radius : {2, 5, 12}) {
            SCOPED_TRACE(std::string(path.name) + ", radius " + std::to_string(radius));
            const std::string post = "blur:" + std::to_string(radius);
            const Image blurred = render_with(*path.r, post.c_str());
            const Diff d = compare(blurred, cpu_gaussian(plain, radius), plain);
            std::printf("%s blur:%d: worst %d level(s) from the CPU Gaussian; %d pixels moved by > 4 levels\n",
                        path.name, radius, d.worst, d.changed);
            if (d.worst > 1) save(std::string(path.name) + "_blur" + std::to_string(radius), blurred);
            EXPECT_LE(d.worst, 1);
            EXPECT_GT(d.changed, 100) << "the blur changed the image";
        }
    }
}

TEST_F(PostGl, ShadowBlurIsTheCpuGaussianOfTheHardVisibility) {
    const Image colour = render_with(*renderer, "none");
    const Image hard = render_with(*renderer, "none", render::Aov::Visibility);
    const Image soft = render_with(*renderer, "shadow-blur:6", render::Aov::Visibility);
    // The camera pass draws the blurred visibility only where a surface is: the background stays
    // the visibility AOV's white.
    const glm::vec4 bg = render::kBackground;
    std::vector<bool> surface(static_cast<size_t>(kW * kH));
    int surfaces = 0;
    for (size_t p = 0; p < surface.size(); ++p) {
        const auto lvl = [&](float v) { return static_cast<int>(std::lround(v * 255.0f)); };
        surface[p] = std::abs(colour[p * 4] - lvl(bg.r)) > 1 || std::abs(colour[p * 4 + 1] - lvl(bg.g)) > 1 ||
                     std::abs(colour[p * 4 + 2] - lvl(bg.b)) > 1;
        surfaces += surface[p];
    }
    const Diff d = compare(soft, cpu_gaussian(hard, 6), hard, surface);
    std::printf("shadow-blur:6: %d surface pixels, worst %d level(s) from the CPU Gaussian of the hard visibility; "
                "%d moved by > 4 levels\n", surfaces, d.worst, d.changed);
    if (d.worst > 1) save("shadow_blur6", soft);
    EXPECT_GT(surfaces, kW * kH / 4);
    EXPECT_LE(d.worst, 1);
    EXPECT_GT(d.changed, 50) << "the shadow's edge was softened";
    // The colour image with it differs from the hard one only where the visibility did.
    const Image soft_colour = render_with(*renderer, "shadow-blur:6");
    int outside = 0;
    for (size_t p = 0; p < surface.size(); ++p)
        if (hard[p * 4] == 255 && soft[p * 4] == 255)
            for (size_t c = 0; c < 3; ++c) outside += soft_colour[p * 4 + c] != colour[p * 4 + c];
    EXPECT_EQ(outside, 0) << "pixels lit in both visibilities keep their colour";
}

TEST_F(PostGl, BloomOnlyAddsLightAndNoneAboveOne) {
    const Image plain = render_with(*renderer, "none");
    const Image none = render_with(*renderer, "bloom:1");
    const Image bloom = render_with(*renderer, "bloom:0.5");
    int darker = 0, brighter = 0, changed_at_one = 0;
    for (size_t i = 0; i < plain.size(); ++i) {
        if (i % 4 == 3) continue;
        changed_at_one += std::abs(int(none[i]) - int(plain[i])) > 1;
        darker += bloom[i] + 1 < plain[i];
        brighter += bloom[i] > plain[i] + 8;
    }
    std::printf("bloom:0.5: %d channel values brighter by > 8 levels, %d darker; bloom:1 changed %d\n", brighter,
                darker, changed_at_one);
    EXPECT_EQ(changed_at_one, 0);
    EXPECT_EQ(darker, 0);
    EXPECT_GT(brighter, 1000);
}
