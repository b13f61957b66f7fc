// Heckbert-Herf's bands and interleaved sampling (--area-interleave), on a GL context. N light
// samples lay N sharp displaced copies of a thin caster's shadow: on bench_hard's grille (bars 4 cm
// wide, 12 cm apart, 0.8 above the ground, the light grazing along them) the copies of the bars'
// shadows stack into bands where the ray-traced area light is a smooth gradient. The measure:
// the high-frequency energy of the visibility across the bars' shadows (the mean squared second
// difference, down the image's columns, of the visibility averaged over a few columns, i.e. along
// the bands), against the ray-traced truth's. Also: a still frame's interleaved rounds end in the
// image without interleaving, byte for byte.
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "measure/ray_tracer.h"
#include "plan/frames/area_light.h"
#include "plan/options.h"
#include "scene/gltf_loader.h"

using namespace penumbra;

namespace {

constexpr int kSize = 512;
constexpr float kRadius = 0.34024847f;  // 0.02 of bench_hard's extent, the bench's smallest radius

render::Settings hh(int samples, int interleave) {
    render::Settings s;
    for (const auto& [k, v] : std::vector<std::pair<std::string, std::string>>{
             {"technique", "shadowmap"}, {"map-size", "1024"}, {"encoding", "rgba"}, {"bias", "auto"}})
        EXPECT_EQ(render::parse_option(s, k, v), "") << k;
    s.aov = render::Aov::Visibility;
    s.light_radius = kRadius;
    s.area_samples = samples;
    s.area_interleave = interleave;
    return s;
}

// The window of the ground under the grille's shadow (pixels, top row first), found from the
// truth: the ground pixels whose visibility is neither lit nor dark, in the columns and rows that
// hold most of them.
struct Window {
    int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

// Mean squared second difference down the columns of the visibility averaged over `band` columns
// at a time (the bands run along the image's rows): the energy at the highest spatial frequencies
// across the bars' shadows.
// Only where all the pixels averaged are the ground's (`ground`: 1 per pixel), so the grille's own
// silhouettes are left out.
double band_energy(const std::vector<float>& vis, const std::vector<std::uint8_t>& ground, const Window& w, int band) {
    double sum = 0.0;
    int n = 0;
    for (int x = w.x0; x + band <= w.x1; x += band) {
        std::vector<double> profile;
        std::vector<bool> on;
        for (int y = w.y0; y < w.y1; ++y) {
            double v = 0.0;
            bool all = true;
            for (int c = x; c < x + band; ++c) {
                v += vis[static_cast<size_t>(y * kSize + c)];
                all = all && ground[static_cast<size_t>(y * kSize + c)];
            }
            profile.push_back(v / band);
            on.push_back(all);
        }
        for (size_t i = 1; i + 1 < profile.size(); ++i) {
            if (!(on[i - 1] && on[i] && on[i + 1])) continue;
            const double d2 = profile[i - 1] - 2.0 * profile[i] + profile[i + 1];
            sum += d2 * d2;
            ++n;
        }
    }
    return n ? sum / n : 0.0;
}

std::vector<float> to_float(const std::vector<std::uint8_t>& red) {
    std::vector<float> v(red.size());
    for (size_t i = 0; i < red.size(); ++i) v[i] = red[i] / 255.0f;
    return v;
}

class SoftBands : public test::GlTest {
protected:
    scene::Scene load() {
        const scene::LoadResult l = scene::load_gltf(test::test_data_dir() + "/bench_hard.gltf");
        EXPECT_TRUE(l.ok) << l.error;
        return l.scene;
    }
    std::vector<float> vis(const scene::Scene& sc, const render::Settings& s) {
        return to_float(visibility_frame(sc, s, kSize));
    }
};

// The grille's shadow on the ground, from the truth: the box around the ground's penumbra pixels
// within the grille's shadow (left half of the image, where bench_hard's grille stands).
Window grille_window(const measure::TruthImage& t, int ground) {
    Window w{kSize, 0, kSize, 0};
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize / 2; ++x) {
            const size_t i = static_cast<size_t>(y * kSize + x);
            if (t.object[i] != ground || !(t.soft[i] > 0.05f && t.soft[i] < 0.95f)) continue;
            w.x0 = std::min(w.x0, x);
            w.x1 = std::max(w.x1, x + 1);
            w.y0 = std::min(w.y0, y);
            w.y1 = std::max(w.y1, y + 1);
        }
    return w;
}

TEST_F(SoftBands, InterleavedSamplesSmoothTheGrillesBands) {
    const scene::Scene sc = load();
    int ground = -1;
    for (size_t i = 0; i < sc.objects.size(); ++i)
        if (sc.objects[i].name == "ground") ground = static_cast<int>(i);
    ASSERT_GE(ground, 0);
    measure::TruthOptions to;
    to.width = to.height = kSize;
    to.view_proj = render::camera_view(sc, render::offscreen(kSize, kSize)).view_proj;
    to.soft_samples = 512;
    to.light_radius = kRadius;
    const measure::TruthImage truth = measure::RayTracer(sc).render(to);
    const Window w = grille_window(truth, ground);
    std::vector<std::uint8_t> on_ground = truth.valid_mask();
    for (size_t i = 0; i < on_ground.size(); ++i) on_ground[i] = on_ground[i] && truth.object[i] == ground;
    ASSERT_GT(w.x1 - w.x0, 16);
    ASSERT_GT(w.y1 - w.y0, 16);
    constexpr int kBand = 8;
    const double want = band_energy(truth.soft, on_ground, w, kBand);
    std::printf("grille window x %d..%d y %d..%d; the truth's band energy %.3e\n", w.x0, w.x1, w.y0, w.y1, want);
    struct Case {
        int samples, interleave;
        double energy;
    };
    std::vector<Case> cases;
    for (int n : {16, 64})
        for (int k : {1, 2, 4}) {
            const double e = band_energy(vis(sc, hh(n, k)), on_ground, w, kBand);
            std::printf("hh %2d, interleave %d: band energy %.3e (%.2f x the truth's)\n", n, k, e, e / want);
            cases.push_back({n, k, e});
        }
    // What converged sampling gives: 256 samples, no interleave (the models' other differences).
    const double e256 = band_energy(vis(sc, hh(256, 1)), on_ground, w, kBand);
    std::printf("hh 256, interleave 1: band energy %.3e (%.2f x the truth's)\n", e256, e256 / want);
    const auto energy = [&](int n, int k) {
        for (const Case& c : cases)
            if (c.samples == n && c.interleave == k) return c.energy;
        return -1.0;
    };
    // Measured on llvmpipe (512x512, truth 512 samples): the truth 7.2e-5; HH 64 without
    // interleaving 36 x that, with 2 x 2 8.2 x, with 4 x 4 4.1 x; HH 256 without 3.7 x, which is
    // the floor of what the renderer's samples reach here (each sample's hard map edge, 1024 texels
    // for a grazing light over 4 cm bars, is itself jagged along the bars; and the renderer's disc
    // lies across the light's axis where the truth's faces each point). So "close to the truth"
    // is held against that floor: interleaved HH 64 within 2.5 x HH 256's energy (2.2 and 1.1 x
    // measured) and under 12 x the truth's; the control, plain HH 64, must stay above 20 x the
    // truth's and 3 x HH 256's (36 and 9.6 x measured): the bands this option removes. (The Halton
    // samples before the lattice gave 7.5 and 6.3 x the truth's over a floor of 5.3 x: the lattice
    // lowers the floor and 4 x 4's energy, and raises 2 x 2's a little.)
    EXPECT_GT(energy(64, 1), 20.0 * want) << "the control: HH 64's bands";
    EXPECT_GT(energy(64, 1), 3.0 * e256) << "the control: HH 64's bands";
    for (int k : {2, 4}) {
        EXPECT_LT(energy(64, k), 2.5 * e256) << "interleave " << k;
        EXPECT_LT(energy(64, k), 12.0 * want) << "interleave " << k;
        EXPECT_LT(energy(64, k), 0.3 * energy(64, 1)) << "interleave " << k;
        EXPECT_LT(energy(16, k), 0.5 * energy(16, 1)) << "interleave " << k << ", 16 samples";
    }
}

TEST_F(SoftBands, AStillFramesRoundsEndInTheImageWithoutInterleaving) {
    const scene::Scene sc = load();
    const render::FrameInputs in = render::offscreen(128, 128);
    for (int k : {2, 4}) {
        render::Settings plain = hh(16, 1);
        renderer->render(sc, plain, in);
        const auto want = renderer->read_image();
        render::Settings s = hh(16, k);
        s.area_per_frame = 20;  // rounds split across frames
        render::Renderer r(renderer->caps());
        std::vector<std::uint8_t> got, first;
        const int frames = (16 * k * k + 19) / 20;
        for (int f = 0; f < frames + 1; ++f) {
            const render::FramePlan& p = r.render(sc, s, in);
            ASSERT_TRUE(render::area_of(p));
            EXPECT_EQ(render::area_of(p)->done, std::min(16 * k * k, 20 * (f + 1))) << f;
            got = r.read_image();
            if (f == 0) first = got;
        }
        EXPECT_NE(first, want) << "the first frame is filtered";
        EXPECT_EQ(got, want) << "interleave " << k;
        // Radius 0: the hard shadow, whatever the interleave.
        render::Settings hard = hh(1, 1);
        hard.light_radius = 0.0f;
        renderer->render(sc, hard, in);
        const auto sharp = renderer->read_image();
        render::Settings point = hh(64, k);
        point.light_radius = 0.0f;
        renderer->render(sc, point, in);
        EXPECT_EQ(renderer->read_image(), sharp);
    }
}

}  // namespace
