// Soft shadows from a light with a size, on a GL context: Heckbert-Herf (--area-samples) over each
// hard technique, PCSS (--filter pcss), against
//  - the closed form: a flat disc over a plane, lit by a disc light straight above it, seen from
//    above. The visibility of a ground point is the part of the light's disc that the caster's
//    disc, projected from the point onto the light's plane, leaves uncovered (two circles' overlap),
//    and the penumbra runs from (aH - Rh)/(H - h) to (aH + Rh)/(H - h) from the axis;
//  - the ray-traced area-light truth (measure::RayTracer with soft samples) on the course scene,
//    where the teapot stands on the table, so its penumbra narrows to nothing at the contact.
// Also: at light radius 0 every method is its hard counterpart, and the progressive accumulation
// of a still frame ends in the same image as all samples at once.
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "measure/image_io.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "plan/frames/area_light.h"
#include "plan/options.h"
#include "render/shader_library.h"
#include "scenes/course_scene.h"
#include "scene/primitives.h"

using namespace penumbra;

namespace {

constexpr int kSize = 256;
constexpr float kPi = 3.14159265f;

// The disc scene's measures: caster radius a at height h, light radius R at height H.
constexpr float kA = 1.0f, kH = 1.0f, kLightH = 5.0f, kR = 0.5f;
constexpr float kHalfView = 2.0f;  // the camera sees [-2, 2]^2 of the ground
constexpr float kEye = 40.0f;      // from this height

using test::object;

// A flat disc of radius r in the plane y = 0, both faces (an open mesh).
scene::Mesh disc(float r, int segments) {
    scene::Mesh m;
    for (int side = 0; side < 2; ++side) {
        const glm::vec3 n(0.0f, side == 0 ? 1.0f : -1.0f, 0.0f);
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        m.positions.push_back(glm::vec3(0.0f));
        m.normals.push_back(n);
        for (int i = 0; i < segments; ++i) {
            const float t = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
            m.positions.push_back(r * glm::vec3(std::cos(t), 0.0f, std::sin(t)));
            m.normals.push_back(n);
        }
        for (int i = 0; i < segments; ++i) {
            const std::uint32_t a = base + 1 + static_cast<std::uint32_t>(i);
            const std::uint32_t b = base + 1 + static_cast<std::uint32_t>((i + 1) % segments);
            // Counter-clockwise seen from the side the normal points to.
            if (side == 0) m.indices.insert(m.indices.end(), {base, b, a});
            else m.indices.insert(m.indices.end(), {base, a, b});
        }
    }
    scene::seal(m);
    return m;
}

scene::Scene disc_scene() {
    scene::Scene s;
    s.meshes = {scene::make_quad(12.0f), disc(kA, 128)};
    s.materials.resize(1);
    s.objects = {object("ground", 0, glm::mat4(1.0f)),
                 object("disc", 1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, kH, 0.0f)))};
    s.objects[1].receives_shadow = false;
    s.ground_plane = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    s.ground_object = 0;
    s.light.type = scene::LightType::Point;
    s.light.position = glm::vec3(0.0f, kLightH, 0.0f);
    s.light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.light.radius = kR;
    // Straight down from high above (shadow volumes need a perspective camera): the ground is
    // parallel to the image, so its pixels are evenly spaced; the disc looks 1/39 larger.
    s.camera.view = glm::lookAt(glm::vec3(0.0f, kEye, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    s.camera.yfov = 2.0f * std::atan(kHalfView / kEye);
    s.camera.znear = 0.5f * kEye;
    s.camera.zfar = 2.0f * kEye;
    s.camera.aspect = 1.0f;
    return s;
}

render::FrameInputs top_down() { return render::offscreen(kSize, kSize); }

// The area of the intersection of two discs of radii r1, r2 whose centres are d apart.
double overlap(double r1, double r2, double d) {
    if (d >= r1 + r2) return 0.0;
    if (d <= std::fabs(r1 - r2)) return kPi * std::pow(std::min(r1, r2), 2.0);
    const double a1 = r1 * r1 * std::acos((d * d + r1 * r1 - r2 * r2) / (2.0 * d * r1));
    const double a2 = r2 * r2 * std::acos((d * d + r2 * r2 - r1 * r1) / (2.0 * d * r2));
    const double k = 0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
    return a1 + a2 - k;
}

// The exact visibility of the ground at distance rho from the axis.
double exact_visibility(double rho) {
    const double scale = kLightH / kH;  // from the ground point through the caster to the light's plane
    const double centre = rho * (scale - 1.0);
    return 1.0 - overlap(kR, kA * scale, centre) / (kPi * kR * kR);
}

struct Profile {
    double mae = 0.0;       // mean |rendered - exact| over the ring's pixels, 0..1
    double width = 0.0;     // 10 % to 90 % visibility, world units
    double half = 0.0;      // where the visibility crosses 1/2
    double exact_width = 0.0, exact_half = 0.0;
};

// Where the mean visibility per one-pixel ring first rises through `level`, outwards from rho0.
double crossing(const std::vector<double>& ring, double rho0, double step, double level) {
    for (size_t i = 1; i < ring.size(); ++i)
        if (ring[i - 1] < level && ring[i] >= level)
            return rho0 + step * (static_cast<double>(i - 1) + (level - ring[i - 1]) / (ring[i] - ring[i - 1]));
    return -1.0;
}

// The rendered visibility (red channel, top row first) against the closed form, over the ground
// pixels between rho 1.05 and 1.8 (outside the disc seen from above, inside the view).
Profile profile(const std::vector<std::uint8_t>& rgba) {
    const double px = 2.0 * kHalfView / kSize;
    const double rho0 = 1.05, rho1 = 1.8;
    const auto bins = static_cast<size_t>((rho1 - rho0) / px) + 1;
    std::vector<double> sum(bins, 0.0), exact_sum(bins, 0.0), count(bins, 0.0);
    Profile p;
    double n = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double wx = -kHalfView + (x + 0.5) * px, wz = -kHalfView + (y + 0.5) * px;
            const double rho = std::sqrt(wx * wx + wz * wz);
            if (rho < rho0 || rho >= rho1) continue;
            const double v = rgba[4 * static_cast<size_t>(y * kSize + x)] / 255.0;
            const double e = exact_visibility(rho);
            p.mae += std::fabs(v - e);
            n += 1.0;
            const auto b = static_cast<size_t>((rho - rho0) / px);
            sum[b] += v;
            exact_sum[b] += e;
            count[b] += 1.0;
        }
    p.mae /= n;
    for (size_t b = 0; b < bins; ++b) {
        sum[b] /= std::max(count[b], 1.0);
        exact_sum[b] /= std::max(count[b], 1.0);
    }
    p.half = crossing(sum, rho0, px, 0.5);
    p.width = crossing(sum, rho0, px, 0.9) - crossing(sum, rho0, px, 0.1);
    p.exact_half = crossing(exact_sum, rho0, px, 0.5);
    p.exact_width = crossing(exact_sum, rho0, px, 0.9) - crossing(exact_sum, rho0, px, 0.1);
    return p;
}

render::Settings settings(const char* args) {
    render::Settings s;
    s.aov = render::Aov::Visibility;
    // "name=value name=value"
    std::string rest = args;
    while (!rest.empty()) {
        const size_t sp = rest.find(' ');
        const std::string kv = rest.substr(0, sp);
        rest = sp == std::string::npos ? "" : rest.substr(sp + 1);
        const size_t eq = kv.find('=');
        EXPECT_EQ(render::parse_option(s, kv.substr(0, eq), kv.substr(eq + 1)), "") << kv;
    }
    return s;
}

class Soft : public test::GlTest {
protected:
    std::vector<std::uint8_t> frame(const scene::Scene& sc, const render::Settings& s, const render::FrameInputs& in) {
        return frame_on(*renderer, sc, s, in);
    }
    static std::vector<std::uint8_t> frame_on(render::Renderer& r, const scene::Scene& sc, const render::Settings& s,
                                              const render::FrameInputs& in) {
        EXPECT_EQ(r.check(sc, s, in), "");
        r.render(sc, s, in);
        return r.read_image();
    }

    // The course scene against the area-light truth: mean abs error (%) and inside the penumbra.
    struct Course {
        scene::CourseScene course = scene::make_course_scene(10);
        measure::TruthImage truth;
        float radius = 0.3f;
        explicit Course(float r) : radius(r) {
            scene::animate_course(course, 0.0, 0.0);
            const render::FrameInputs in = render::offscreen(kSize, kSize);
            measure::TruthOptions to;
            to.width = to.height = kSize;
            to.view_proj = render::camera_view(course.scene, in).view_proj;
            to.soft_samples = 256;
            to.light_radius = r;
            truth = measure::RayTracer(course.scene).render(to);
        }
    };
    measure::Score course_score(const Course& c, const char* args, const char* what, render::Renderer& r) {
        render::Settings s = settings(args);
        s.light_radius = c.radius;
        const auto rgba = frame_on(r, c.course.scene, s, render::offscreen(kSize, kSize));
        const measure::Score sc =
            measure::score(measure::from_rgba(rgba, kSize, kSize, 1).data, c.truth.lit, c.truth.valid_mask(), &c.truth.soft);
        std::printf("course scene, light radius %.2f, %-40s mean abs error vs the area light %.3f%%, in the penumbra %.2f%%\n",
                    static_cast<double>(c.radius), what, sc.mae_soft_pct, sc.mae_penumbra_pct);
        return sc;
    }
    double course_error(const Course& c, const char* args, const char* what) {
        return course_score(c, args, what, *renderer).mae_soft_pct;
    }
};

TEST_F(Soft, TheClosedFormIsWhatTheTruthTraces) {
    // The reference itself: the ray tracer's area light on the disc scene agrees with the formula
    // (its disc faces each point, ours is horizontal: near the axis they are alike).
    const scene::Scene sc = disc_scene();
    measure::TruthOptions to;
    to.width = to.height = kSize;
    to.view_proj = render::camera_view(sc, top_down()).view_proj;
    to.soft_samples = 256;
    to.light_radius = kR;
    const measure::TruthImage t = measure::RayTracer(sc).render(to);
    std::vector<std::uint8_t> rgba(4 * t.soft.size());
    for (size_t i = 0; i < t.soft.size(); ++i)
        rgba[4 * i] = static_cast<std::uint8_t>(std::lround(255.0f * t.soft[i]));
    const Profile p = profile(rgba);
    std::printf("disc: the truth's profile: mean abs %.4f, half at %.4f (exact %.4f), 10-90 width %.4f (exact %.4f)\n",
                p.mae, p.half, p.exact_half, p.width, p.exact_width);
    EXPECT_LT(p.mae, 0.01);
    EXPECT_NEAR(p.half, p.exact_half, 0.02);
    EXPECT_NEAR(p.width, p.exact_width, 0.1 * p.exact_width);
    // The formula's own penumbra, from the similar triangles: the edges' radii.
    EXPECT_NEAR(exact_visibility((kA * kLightH - kR * kH) / (kLightH - kH) - 1e-4), 0.0, 1e-6);
    EXPECT_NEAR(exact_visibility((kA * kLightH + kR * kH) / (kLightH - kH) + 1e-4), 1.0, 1e-6);
}

TEST_F(Soft, ThePenumbraOfADiscMatchesTheClosedForm) {
    const scene::Scene sc = disc_scene();
    struct Case {
        const char* args;
        double max_mae;     // mean |v - exact| over the ring
        double max_width;   // relative error of the 10-90 width
    };
    // Bounds: about twice the values measured on llvmpipe (printed; in the comments).
    const Case cases[] = {
        {"technique=shadowmap area-samples=16", 0.025, 0.12},   // measured 0.0120, width -4.8 %
        {"technique=shadowmap area-samples=64", 0.01, 0.06},    // 0.0047, +1.3 %
        {"technique=shadowmap area-samples=256", 0.004, 0.04},  // 0.0016, +0.3 %
        {"technique=planar area-samples=64", 0.01, 0.06},       // 0.0047
        {"technique=volumes area-samples=64", 0.01, 0.06},      // 0.0046
        {"technique=shadowmap filter=pcss pcss-search=16 pcss-taps=16", 0.02, 0.06},  // 0.0086, -0.1 %
        {"technique=shadowmap filter=pcss pcss-search=32 pcss-taps=32", 0.012, 0.06},  // 0.0050
    };
    const render::FrameInputs in = top_down();
    for (const Case& c : cases) {
        const Profile p = profile(frame(sc, settings(c.args), in));
        std::printf("disc: %-58s mean abs %.4f, half at %.4f (exact %.4f), 10-90 width %.4f (exact %.4f)\n", c.args, p.mae,
                    p.half, p.exact_half, p.width, p.exact_width);
        EXPECT_LT(p.mae, c.max_mae) << c.args;
        EXPECT_NEAR(p.half, p.exact_half, 0.03) << c.args;
        EXPECT_NEAR(p.width, p.exact_width, c.max_width * p.exact_width) << c.args;
    }
    // The score can fail: a hard shadow and a constant PCF blur have no penumbra of this width.
    for (const char* hard : {"technique=shadowmap", "technique=shadowmap filter=pcf4x4"}) {
        const Profile p = profile(frame(sc, settings(hard), in));
        std::printf("disc: %-58s mean abs %.4f, 10-90 width %.4f (exact %.4f)\n", hard, p.mae, p.width, p.exact_width);
        EXPECT_GT(p.mae, 0.04) << hard;
        EXPECT_LT(p.width, 0.5 * p.exact_width) << hard;
    }
}

TEST_F(Soft, AtRadiusZeroEveryMethodIsItsHardCounterpart) {
    const scene::Scene sc = disc_scene();
    const render::FrameInputs in = top_down();
    for (const char* technique : {"shadowmap", "planar", "volumes"}) {
        render::Settings hard = settings((std::string("technique=") + technique).c_str());
        hard.light_radius = 0.0f;
        const auto want = frame(sc, hard, in);
        render::Settings area = hard;
        area.area_samples = 64;
        const auto got = frame(sc, area, in);
        EXPECT_EQ(got, want) << technique << " with 64 samples of a point light";
        EXPECT_FALSE(render::area_of(renderer->render(sc, area, in))) << "a point light needs one sample";
    }
    render::Settings hard = settings("technique=shadowmap");
    hard.light_radius = 0.0f;
    render::Settings pcss = hard;
    pcss.filter = shadow::Filter::PCSS;
    EXPECT_EQ(frame(sc, pcss, in), frame(sc, hard, in)) << "PCSS of a point light";
    // And the course scene, with its textures and curved receivers.
    scene::CourseScene course = scene::make_course_scene(10);
    scene::animate_course(course, 0.7, 0.7);
    EXPECT_EQ(frame(course.scene, pcss, render::offscreen(kSize, kSize)),
              frame(course.scene, hard, render::offscreen(kSize, kSize)));
}

TEST_F(Soft, AStillFrameConvergesToAllSamplesAtOnce) {
    const scene::Scene sc = disc_scene();
    const render::FrameInputs in = top_down();
    render::Settings all = settings("technique=shadowmap area-samples=32");
    render::Settings progressive = all;
    progressive.area_per_frame = 8;
    std::vector<std::uint8_t> first, got;
    for (int k = 1; k <= 5; ++k) {
        const render::FramePlan& p = renderer->render(sc, progressive, in);
        ASSERT_TRUE(render::area_of(p));
        EXPECT_EQ(render::area_of(p)->done, std::min(32, 8 * k)) << "frame " << k;
        EXPECT_EQ(render::area_of(p)->added, k <= 4 ? 8 : 0) << "frame " << k;
        got = renderer->read_image();
        if (k == 1) first = got;
    }
    render::Renderer fresh(renderer->caps());
    fresh.render(sc, all, in);
    const auto want = fresh.read_image();
    EXPECT_NE(first, want) << "8 of 32 samples";
    EXPECT_EQ(got, want);
    // The finished sum is kept by a still frame, whatever the frames add.
    EXPECT_EQ(render::area_of(fresh.render(sc, progressive, in))->added, 0);
    // Anything moving starts the sum again.
    scene::Scene moved = sc;
    moved.light.position.x += 0.1f;
    const render::FramePlan& p = renderer->render(moved, progressive, in);
    EXPECT_EQ(render::area_of(p)->done, 8);
}

// A thin pole standing on the ground, lit from the side by a sphere light: its shadow runs along +x
// from the pole's foot, and its penumbra widens from nothing at the contact towards the tip's end.
scene::Scene pole_scene() {
    scene::Scene s = disc_scene();
    s.meshes[1] = scene::make_box(glm::vec3(0.1f, 1.0f, 0.1f));
    s.objects[1] = object("pole", 1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
    s.light.position = glm::vec3(-4.0f, 5.0f, 0.0f);
    s.light.direction = glm::normalize(glm::vec3(4.0f, -5.0f, 0.0f));
    s.light.radius = 0.4f;
    return s;
}

// The 10-90 % width (world units) of the visibility across the shadow (along z, z > 0) at ground
// x, from an image (visibility in [0, 1] per pixel, top row first) of the top-down view.
double width_across(const std::vector<float>& vis, double x) {
    const double px = 2.0 * kHalfView / kSize;
    const int col = static_cast<int>((x + kHalfView) / px);
    std::vector<double> ring;
    const int row0 = kSize / 2;
    for (int row = row0; row < kSize; ++row) {
        double sum = 0.0;
        for (int c = col - 2; c <= col + 2; ++c) sum += vis[static_cast<size_t>(row * kSize + c)];
        ring.push_back(sum / 5.0);
    }
    return crossing(ring, 0.0, px, 0.9) - crossing(ring, 0.0, px, 0.1);
}

std::vector<float> red(const std::vector<std::uint8_t>& rgba) {
    std::vector<float> v(rgba.size() / 4);
    for (size_t i = 0; i < v.size(); ++i) v[i] = rgba[4 * i] / 255.0f;
    return v;
}

TEST_F(Soft, ThePenumbraNarrowsToNothingAtTheContact) {
    const scene::Scene sc = pole_scene();
    const render::FrameInputs in = top_down();
    measure::TruthOptions to;
    to.width = to.height = kSize;
    to.view_proj = render::camera_view(sc, in).view_proj;
    to.soft_samples = 256;
    to.light_radius = sc.light.radius;
    const measure::TruthImage t = measure::RayTracer(sc).render(to);
    const double near_x = 0.35, far_x = 1.8;
    const double truth_near = width_across(t.soft, near_x), truth_far = width_across(t.soft, far_x);
    std::printf("pole: the truth's penumbra is %.3f wide at x = %.2f, %.3f at x = %.2f\n", truth_near, near_x, truth_far, far_x);
    EXPECT_LT(truth_near, 0.3 * truth_far);
    // PCSS with the mean depth of every blocker its search finds (--pcss-blockers mean, Fernando's)
    // is about 40 % too narrow far from the foot: the search spans the cone from the receiver to
    // the light at the light's near plane, which maps over the lower pole too, and those blockers,
    // nearer the receiver, pull the mean depth down. The layered estimate (the default) counts the
    // blockers inside the cone at their own depth: within 15 % there (the goal; measured
    // -8 % on llvmpipe). Near the foot it stays too narrow (0.043 against 0.055 measured on
    // llvmpipe, 0.046 on softpipe), inside the 0.05 bound below.
    struct Case {
        const char* args;
        double far_tolerance;  // of the truth's width far from the foot
    };
    for (const Case& cs : {Case{"technique=shadowmap area-samples=64", 0.1}, Case{"technique=volumes area-samples=64", 0.1},
                           Case{"technique=shadowmap filter=pcss", 0.15}}) {
        const char* args = cs.args;
        const std::vector<float> v = red(frame(sc, settings(args), in));
        const double wn = width_across(v, near_x), wf = width_across(v, far_x);
        const measure::Score score = measure::score(measure::from_rgba(frame(sc, settings(args), in), kSize, kSize, 1).data,
                                                    t.lit, t.valid_mask(), &t.soft);
        std::printf("pole: %-40s penumbra %.3f wide near the foot, %.3f far; mean abs error vs the area light %.3f%%\n",
                    args, wn, wf, score.mae_soft_pct);
        EXPECT_LT(wn, 0.4 * wf) << args;
        EXPECT_NEAR(wf, truth_far, cs.far_tolerance * truth_far) << args;
        EXPECT_NEAR(wn, truth_near, 0.05) << args;
        EXPECT_LT(score.mae_soft_pct, 1.0) << args;
    }
    // The control: the mean estimate misses the 15 % far from the foot (measured -39 %), where the
    // ground is in the map as a blocker (--light-fit tight). The shadows fit leaves the ground out
    // (it shadows nothing), which takes the mean's estimate to -9 % (llvmpipe).
    const double mean_far =
        width_across(red(frame(sc, settings("technique=shadowmap filter=pcss pcss-blockers=mean light-fit=tight"), in)), far_x);
    std::printf("pole: --pcss-blockers mean: penumbra %.3f wide far from the foot\n", mean_far);
    EXPECT_LT(mean_far, 0.85 * truth_far);
}

// Stacked casters: the disc scene's disc (radius 1 at height 1) and, beside its penumbra on +x, a
// small low disc (radius 0.15 at height 0.08, centred at x = 1.6) whose texels lie inside the
// blocker search of the receivers in the big disc's outer penumbra, but outside their cones to
// the light: it hides none of the light from them. The exact visibility of a ground point is the
// part of the light's disc (radius 0.7 at height 5) that neither disc hides, integrated here over
// a fine polar grid of the light (the projections are discs, so this is exact to the grid).
constexpr float kLowX = 1.6f, kLowR = 0.15f, kLowH = 0.08f, kStackR = 0.7f;

scene::Scene stacked_scene() {
    scene::Scene s = disc_scene();
    s.meshes.push_back(disc(kLowR, 64));
    s.objects.push_back(object("low disc", 2, glm::translate(glm::mat4(1.0f), glm::vec3(kLowX, kLowH, 0.0f))));
    s.objects.back().receives_shadow = false;
    // A small disc high up, 1 below the light and off to -z: the light's near plane moves up to
    // it, so the receivers' blocker search (the cone at the near plane) reaches the low disc
    // while their filter (the cone at the big disc) does not. Its shadow falls at z = -1.5 + -0.25,
    // away from the line measured (z = 0), and it hides no light from that line.
    s.meshes.push_back(disc(0.05f, 32));
    s.objects.push_back(object("high disc", 3, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, kLightH - 1.0f, -0.3f))));
    s.objects.back().receives_shadow = false;
    s.light.radius = kStackR;
    return s;
}

double stacked_visibility(double x) {
    constexpr int kRings = 96, kSpokes = 192;
    int lit = 0;
    for (int i = 0; i < kRings; ++i)
        for (int j = 0; j < kSpokes; ++j) {
            const double r = kStackR * std::sqrt((i + 0.5) / kRings), a = 2.0 * kPi * (j + 0.5) / kSpokes;
            const double qx = r * std::cos(a), qz = r * std::sin(a);
            // The segment from (x, 0, 0) to the light's point at height kLightH, at height h.
            const auto at = [&](double h, double& px, double& pz) {
                px = x + (qx - x) * h / kLightH;
                pz = qz * h / kLightH;
            };
            double px, pz;
            at(kH, px, pz);
            if (px * px + pz * pz <= kA * kA) continue;
            at(kLowH, px, pz);
            if ((px - kLowX) * (px - kLowX) + pz * pz <= kLowR * kLowR) continue;
            ++lit;
        }
    return static_cast<double>(lit) / (kRings * kSpokes);
}

// Mean |rendered - exact| along the ground line z = 0 (5 rows) for x from x0 to x1 (x1 < x0: the
// -x side, its mirror image), and where the rendered and exact profiles cross 1/2 (from x0).
struct Line {
    double mae = 0.0, half = 0.0, exact_half = 0.0;
};
Line along(const std::vector<std::uint8_t>& rgba, double x0, double x1) {
    const double px = 2.0 * kHalfView / kSize;
    std::vector<double> v, e;
    Line l;
    const int c0 = static_cast<int>((x0 + kHalfView) / px), c1 = static_cast<int>((x1 + kHalfView) / px);
    const int step = c1 > c0 ? 1 : -1;
    for (int col = c0; col != c1; col += step) {
        double sum = 0.0;
        for (int row = kSize / 2 - 2; row <= kSize / 2 + 2; ++row) sum += rgba[4 * static_cast<size_t>(row * kSize + col)] / 255.0;
        v.push_back(sum / 5.0);
        e.push_back(stacked_visibility(-kHalfView + (col + 0.5) * px));
        l.mae += std::fabs(v.back() - e.back());
    }
    l.mae /= static_cast<double>(v.size());
    l.half = crossing(v, 0.0, px, 0.5);
    l.exact_half = crossing(e, 0.0, px, 0.5);
    return l;
}

TEST_F(Soft, StackedCastersTheLayeredEstimateKeepsEachPenumbra) {
    const scene::Scene sc = stacked_scene();
    const render::FrameInputs in = top_down();
    // The exact answer: the low disc changes nothing up to x = 1.44 (where it starts, seen from
    // above, is 1.45); the big disc's penumbra runs from (aH - Rh) / (H - h) = 1.075 to 1.425.
    EXPECT_NEAR(stacked_visibility(1.2), stacked_visibility(-1.2), 1e-9);
    EXPECT_NEAR(stacked_visibility(1.0), 0.0, 1e-9);
    EXPECT_NEAR(stacked_visibility(1.44), 1.0, 2e-3);
    // Measured over x in [1.05, 1.3] (the filter of those receivers does not reach the low disc;
    // their search does): llvmpipe: layered 0.0111 beside the low disc, 0.0133 alone, mean 0.0139
    // beside it; softpipe: layered 0.0166 and 0.0126, mean 0.0257; Heckbert-Herf 64 0.0119 and
    // 0.0166 on both. The bounds: the layered estimate beside the low disc is within 0.006 of
    // itself alone (PCSS's taps are turned per pixel by a hash of gl_FragCoord and compare depths
    // at the penumbra's edge, both of which round differently from one implementation to the
    // next: 0.004 apart on softpipe), and the mean one is worse beside it than the layered one
    // (the control).
    double layered_plus = 0.0, mean_plus = 0.0;
    for (const char* args : {"technique=shadowmap filter=pcss", "technique=shadowmap filter=pcss pcss-blockers=mean",
                             "technique=shadowmap area-samples=64"}) {
        const auto rgba = frame(sc, settings(args), in);
        const Line plus = along(rgba, 1.05, 1.3), minus = along(rgba, -1.05, -1.3);
        std::printf("stacked: %-52s +x (low disc beside): mean abs %.4f, half at %.4f (exact %.4f); "
                    "-x (alone): mean abs %.4f, half at %.4f\n",
                    args, plus.mae, 1.05 + plus.half, 1.05 + plus.exact_half, minus.mae, 1.05 + minus.half);
        const bool mean = std::string(args).find("mean") != std::string::npos;
        if (mean) mean_plus = plus.mae;
        else if (std::string(args).find("pcss") != std::string::npos) layered_plus = plus.mae;
        if (mean) continue;
        EXPECT_LT(plus.mae, 0.02) << args;
        EXPECT_NEAR(plus.half, plus.exact_half, 0.01) << args;
        EXPECT_LT(plus.mae, minus.mae + 0.006) << args;
    }
    EXPECT_GT(mean_plus, layered_plus);
}

TEST_F(Soft, HeckbertHerfConvergesToTheAreaLightOnTheCourseScene) {
    const Course c(0.3f);
    const double n4 = course_error(c, "area-samples=4", "Heckbert-Herf 4");
    const double n16 = course_error(c, "area-samples=16", "Heckbert-Herf 16");
    const double n64 = course_error(c, "area-samples=64", "Heckbert-Herf 64");
    EXPECT_LT(n16, n4);
    EXPECT_LT(n64, n16);
    EXPECT_LE(n64, 1.0);  // the goal
    for (const char* t : {"technique=planar area-samples=64", "technique=volumes area-samples=64"})
        EXPECT_LE(course_error(c, t, t), 1.0) << t;
}

TEST_F(Soft, TheHorizonIsTheTrianglesOwnAsTheTruthTakesIt) {
    // The truth counts a light sample below the receiver's geometric plane as dark; the renderer
    // takes that plane from dFdx/dFdy of the world position where the context has
    // OES_standard_derivatives (GEOMETRIC_HORIZON), else from the interpolated normal, which on
    // the teapot's smooth terminator leans past the triangle's and lets light in below it. At a
    // small light (0.02 of the scene's size) that terminator is much of the penumbra.
    if (!renderer->caps().standard_derivatives) GTEST_SKIP() << "no OES_standard_derivatives: the interpolated normal's horizon";
    render::Settings hh4 = settings("area-samples=4");
    hh4.light_radius = 0.12f;
    const render::FramePlan plan = renderer->plan(scene::make_course_scene(4).scene, hh4, render::offscreen(kSize, kSize));
    const render::Variant* v = nullptr;
    for (const auto& pass : plan.passes)
        for (const auto& d : pass.draws)
            if (!v && std::find(d.variant.defines.begin(), d.variant.defines.end(), "GEOMETRIC_HORIZON") != d.variant.defines.end())
                v = &d.variant;
    ASSERT_NE(v, nullptr) << "a light sample's pass has the geometric horizon";
    const std::string source = render::variant_source(v->fragment, v->defines);
    EXPECT_EQ(source.find("#extension GL_OES_standard_derivatives : require\n"), std::string("#version 100\n").size())
        << "before anything but #version (GLSL ES 1.00 3.4)";
    gl::Caps without = renderer->caps();
    without.standard_derivatives = false;
    render::Renderer interpolated(without);  // the control: the horizon as before
    const Course c(0.12f);
    for (const char* args : {"area-samples=64", "filter=pcss"}) {
        const measure::Score geometric = course_score(c, args, args, *renderer);
        const measure::Score lean = course_score(c, args, "(the interpolated normal's horizon)", interpolated);
        // Measured (llvmpipe and softpipe, 256x256, truth 256 samples), in the penumbra: HH 64
        // 4.84 % with the interpolated normal's horizon, 2.62 % with the triangle's; PCSS 16/16
        // 7.10-7.17 and 4.79-4.85 %.
        EXPECT_LT(geometric.mae_penumbra_pct, 0.8 * lean.mae_penumbra_pct) << args;
        EXPECT_LT(geometric.mae_soft_pct, lean.mae_soft_pct) << args;
    }
}

TEST_F(Soft, PcssBeatsPcfOnTheCourseScene) {
    for (float r : {0.1f, 0.3f}) {
        const Course c(r);
        const double hard = course_error(c, "filter=hard", "hard");
        const double pcf = course_error(c, "filter=pcf4x4", "pcf4x4");
        const double pcss = course_error(c, "filter=pcss", "pcss 16/16");
        EXPECT_LT(pcss, pcf) << "radius " << r;
        EXPECT_LT(pcss, hard) << "radius " << r;
        EXPECT_LE(pcss, 2.5) << "radius " << r;  // the goal
        for (const char* enc : {"filter=pcss encoding=r8", "filter=pcss encoding=depthtex"}) {
            if (std::string(enc).find("depthtex") != std::string::npos && !renderer->caps().depth_texture) continue;
            EXPECT_LE(course_error(c, enc, enc), 2.5) << enc;
        }
    }
}

}  // namespace
