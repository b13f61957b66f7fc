// The ground truth against analytic answers: a sphere over a plane under a directional light
// straight down (a disc of the sphere's radius), the same under a point light overhead (the
// disc grows by the tangent cone), a box resting on the plane under a tilted directional light
// (the shadow is the convex hull of the box's corners projected along the light), an area light's
// umbra and fully-lit region, a grazing light's shadow edges to a seventh of a pixel, and the
// validity mask: background, the silhouette band, the faces
// turned from the light, back faces culled as the renderer culls them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/primitives.h"
#include "measure/ray_tracer.h"

using namespace penumbra;
using measure::PixelClass;

namespace {

constexpr float kRadius = 1.0f;
constexpr float kHeight = 2.0f;
constexpr float kPlane = 10.0f;
constexpr int kSize = 200;

scene::Scene sphere_over_plane() {
    scene::Scene s;
    s.meshes = {scene::make_quad(kPlane), scene::make_sphere(kRadius, 96, 48)};
    s.materials.resize(1);
    scene::Object plane;
    plane.name = "ground";
    plane.mesh = 0;
    scene::Object ball;
    ball.name = "sphere";
    ball.mesh = 1;
    ball.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, kHeight, 0.0f));
    s.objects = {plane, ball};
    s.light.type = scene::LightType::Directional;
    s.light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 7.0f, 7.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(50.0f);
    s.camera.znear = 0.5f;
    s.camera.zfar = 40.0f;
    return s;
}

// The renderer's camera matrix for a square viewport.
glm::mat4 view_proj(const scene::Camera& c) { return glm::perspective(c.yfov, 1.0f, c.znear, c.zfar) * c.view; }

measure::TruthImage trace(const scene::Scene& s, int soft_samples = 0, float light_radius = 0.0f) {
    measure::RayTracer rt(s);
    measure::TruthOptions o;
    o.width = o.height = kSize;
    o.view_proj = view_proj(s.camera);
    o.soft_samples = soft_samples;
    o.light_radius = light_radius;
    return rt.render(o);
}

bool is(const measure::TruthImage& t, size_t i, PixelClass c) { return t.pixel_class[i] == static_cast<std::uint8_t>(c); }

// Every pixel with a 4-neighbour on another object (or the background) is in the silhouette band.
void expect_band_around_objects(const measure::TruthImage& t) {
    const size_t w = static_cast<size_t>(t.width), h = static_cast<size_t>(t.height);
    size_t missing = 0;
    for (size_t y = 0; y < h; ++y)
        for (size_t x = 0; x < w; ++x) {
            const size_t i = y * w + x;
            if (t.object[i] < 0) continue;
            bool edge = false;
            if (x > 0) edge = edge || t.object[i - 1] != t.object[i];
            if (x + 1 < w) edge = edge || t.object[i + 1] != t.object[i];
            if (y > 0) edge = edge || t.object[i - w] != t.object[i];
            if (y + 1 < h) edge = edge || t.object[i + w] != t.object[i];
            if (edge && !is(t, i, PixelClass::Silhouette)) ++missing;
        }
    EXPECT_EQ(missing, 0u) << "pixels beside another object that are not in the silhouette band";
}

// Plane pixels: the shadow must be exactly `inside(p)`, away from a `margin` around its edge.
template <typename Inside, typename Distance>
void expect_plane_shadow(const measure::TruthImage& t, Inside inside, Distance edge_distance, float margin,
                         int min_shadowed) {
    int checked = 0, shadowed = 0, wrong = 0;
    for (size_t i = 0; i < t.lit.size(); ++i) {
        if (t.object[i] != 0 || !t.valid(i)) continue;
        const glm::vec3 p = t.position[i];
        EXPECT_NEAR(p.y, 0.0f, 1e-4f);
        if (edge_distance(p) < margin) continue;
        ++checked;
        const bool in = inside(p);
        shadowed += in;
        wrong += (t.lit[i] != 0) == in;
    }
    EXPECT_EQ(wrong, 0) << "of " << checked << " plane pixels";
    EXPECT_GT(shadowed, min_shadowed);
    EXPECT_GT(checked, kSize * kSize / 4);
}

TEST(Truth, SphereOverPlaneDirectionalDisc) {
    const scene::Scene s = sphere_over_plane();
    const measure::TruthImage t = trace(s);
    ASSERT_EQ(t.lit.size(), static_cast<size_t>(kSize * kSize));
    // The tessellated sphere's outline lies between r cos(pi/96) and r: a 2% margin holds it.
    expect_plane_shadow(
        t, [](const glm::vec3& p) { return std::hypot(p.x, p.z) < kRadius; },
        [](const glm::vec3& p) { return std::fabs(std::hypot(p.x, p.z) - kRadius); }, 0.02f, 500);
    // The sphere: lit wherever it faces the light; its lower half faces away and is not valid.
    int sphere_valid = 0;
    for (size_t i = 0; i < t.lit.size(); ++i) {
        if (t.object[i] != 1) continue;
        const glm::vec3 n = t.position[i] - glm::vec3(0.0f, kHeight, 0.0f);
        if (t.valid(i)) {
            ++sphere_valid;
            EXPECT_EQ(t.lit[i], 1) << "a convex sphere does not shadow its lit side";
            EXPECT_GT(n.y, -0.05f);
        }
        if (n.y < -0.05f) {
            EXPECT_FALSE(t.valid(i)) << "the lower half faces away from the light";
        }
    }
    EXPECT_GT(sphere_valid, 300);
    EXPECT_GT(t.count(PixelClass::FacingAway), 100u);
    EXPECT_GT(t.count(PixelClass::Background), 100u);  // above the plane's far edge
    EXPECT_EQ(t.pixel_class[0], static_cast<std::uint8_t>(PixelClass::Background));
    expect_band_around_objects(t);
}

TEST(Truth, SphereOverPlanePointLightOverhead) {
    scene::Scene s = sphere_over_plane();
    s.light.type = scene::LightType::Point;
    constexpr float kLightY = 6.0f;
    s.light.position = glm::vec3(0.0f, kLightY, 0.0f);
    const measure::TruthImage t = trace(s);
    // The tangent cone from the light: sin(theta) = r / (H - h); on the plane R = H tan(theta).
    const float theta = std::asin(kRadius / (kLightY - kHeight));
    const float shadow_radius = kLightY * std::tan(theta);
    expect_plane_shadow(
        t, [&](const glm::vec3& p) { return std::hypot(p.x, p.z) < shadow_radius; },
        [&](const glm::vec3& p) { return std::fabs(std::hypot(p.x, p.z) - shadow_radius); }, 0.03f, 800);
}

TEST(Truth, SpotLightConeBoundsTheValidPixels) {
    scene::Scene s = sphere_over_plane();
    s.light.type = scene::LightType::Spot;
    s.light.position = glm::vec3(0.0f, 6.0f, 0.0f);
    s.light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.light.spot_outer_cone = 0.5f;
    const measure::TruthImage t = trace(s);
    int inside = 0, outside = 0;
    for (size_t i = 0; i < t.lit.size(); ++i) {
        if (t.object[i] != 0 || is(t, i, PixelClass::Silhouette)) continue;
        const glm::vec3 p = t.position[i];
        const float angle = std::atan2(std::hypot(p.x, p.z), 6.0f);
        if (std::fabs(angle - 0.5f) < 0.01f) continue;
        if (angle > 0.5f) {
            ++outside;
            EXPECT_TRUE(is(t, i, PixelClass::OutsideCone)) << "at " << angle << " rad from the axis";
        } else {
            ++inside;
            EXPECT_TRUE(t.valid(i));
            // Inside the cone the shadow is the point light's: the tangent cone of the sphere.
            const float shadow_radius = 6.0f * std::tan(std::asin(kRadius / (6.0f - kHeight)));
            if (std::fabs(std::hypot(p.x, p.z) - shadow_radius) > 0.03f) {
                EXPECT_EQ(t.lit[i] != 0, std::hypot(p.x, p.z) > shadow_radius);
            }
        }
    }
    EXPECT_GT(inside, 2000);
    EXPECT_GT(outside, 2000);
}

// 2D convex hull (Andrew's monotone chain) of points in the xz plane, counter-clockwise.
std::vector<glm::vec2> hull(std::vector<glm::vec2> p) {
    std::sort(p.begin(), p.end(), [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    const auto cross = [](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::vec2> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);
    return h;
}

// Signed distance to a counter-clockwise convex polygon's boundary: negative inside.
float polygon_distance(const std::vector<glm::vec2>& poly, const glm::vec2& q) {
    float inside = -1e30f;
    float best = 1e30f;
    for (size_t i = 0; i < poly.size(); ++i) {
        const glm::vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        const glm::vec2 e = b - a;
        const glm::vec2 outward = glm::normalize(glm::vec2(e.y, -e.x));
        inside = std::max(inside, glm::dot(q - a, outward));
        const float t = std::clamp(glm::dot(q - a, e) / glm::dot(e, e), 0.0f, 1.0f);
        best = std::min(best, glm::length(q - (a + t * e)));
    }
    return inside < 0.0f ? -best : best;
}

namespace {

// A box of half-extent `half` placed by `world` over the plane, under a directional light along
// `direction`, seen from `eye` looking at `target`.
scene::Scene box_over_plane(const glm::vec3& half, const glm::mat4& world, const glm::vec3& direction, const glm::vec3& eye,
                            const glm::vec3& target) {
    scene::Scene s;
    s.meshes = {scene::make_quad(kPlane), scene::make_box(half)};
    s.materials.resize(1);
    scene::Object plane;
    plane.name = "ground";
    plane.mesh = 0;
    scene::Object box;
    box.name = "box";
    box.mesh = 1;
    box.world = world;
    s.objects = {plane, box};
    s.light.type = scene::LightType::Directional;
    s.light.direction = direction;
    s.camera.view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(50.0f);
    s.camera.znear = 0.5f;
    s.camera.zfar = 40.0f;
    return s;
}

}  // namespace

TEST(Truth, BoxUnderTiltedDirectionalLight) {
    // Resting on the plane, turned 30 degrees about y.
    const glm::mat4 world = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.6f, -0.2f)), glm::radians(30.0f),
                                        glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::vec3 d = glm::normalize(glm::vec3(0.7f, -1.0f, 0.4f));
    const scene::Scene s =
        box_over_plane(glm::vec3(0.5f, 0.6f, 0.4f), world, d, glm::vec3(2.5f, 4.5f, 6.5f), glm::vec3(0.5f, 0.0f, 0.0f));
    const measure::TruthImage t = trace(s);

    // The shadow polygon: every corner of the box slid along the light onto y = 0.
    std::vector<glm::vec2> projected;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 local((i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.6f : -0.6f, (i & 4) ? 0.4f : -0.4f);
        const glm::vec3 w(world * glm::vec4(local, 1.0f));
        const glm::vec3 p = w - d * (w.y / d.y);
        projected.emplace_back(p.x, p.z);
    }
    const std::vector<glm::vec2> poly = hull(projected);
    ASSERT_GE(poly.size(), 4u);
    expect_plane_shadow(
        t, [&](const glm::vec3& p) { return polygon_distance(poly, {p.x, p.z}) < 0.0f; },
        [&](const glm::vec3& p) { return std::fabs(polygon_distance(poly, {p.x, p.z})); }, 0.02f, 300);

    // The box: the faces towards the light are lit, those turned away are not valid.
    int lit_faces = 0, away = 0;
    for (size_t i = 0; i < t.lit.size(); ++i) {
        if (t.object[i] != 1) continue;
        if (t.valid(i)) {
            ++lit_faces;
            EXPECT_EQ(t.lit[i], 1);
        }
        away += is(t, i, PixelClass::FacingAway);
    }
    EXPECT_GT(lit_faces, 200);
    EXPECT_GT(away, 200) << "the camera sees the +x and +z faces, which face away from this light";
    expect_band_around_objects(t);
}

// A bar's shadow under light 8 degrees over the horizon, checked to 2 mm of its edges where a
// pixel spans about 14: the shadow ray must leave the surface on its own line. Started off the
// surface along the normal instead (by epsilon, 1.4 mm here), it runs beside the true ray and
// every edge moves by epsilon x cot(8 degrees), 10 mm: 229 of these pixels came out wrong.
TEST(Truth, AGrazingLightsShadowEdgesStayWhereTheGeometryPutsThem) {
    const float elevation = glm::radians(8.0f);
    const scene::Scene s = box_over_plane(glm::vec3(0.05f, 0.05f, 2.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f)),
                                          glm::vec3(std::cos(elevation), -std::sin(elevation), 0.0f),
                                          glm::vec3(3.5f, 3.0f, 1.0f), glm::vec3(3.5f, 0.0f, 0.0f));
    const measure::TruthImage t = trace(s);

    // A point of the plane is in the shadow when the line back towards the light crosses the bar's
    // cross-section [-0.05, 0.05] x [0.45, 0.55]: x in [-0.05 + 0.45 c, 0.05 + 0.55 c], c = cot.
    const double c = static_cast<double>(s.light.direction.x) / -static_cast<double>(s.light.direction.y);
    const double a = -0.05 + 0.45 * c, b = 0.05 + 0.55 * c;
    expect_plane_shadow(
        t, [&](const glm::vec3& p) { return p.x > a && p.x < b && std::fabs(p.z) < 2.0f; },
        [&](const glm::vec3& p) {
            return static_cast<float>(std::min({std::fabs(p.x - a), std::fabs(p.x - b), std::fabs(std::fabs(p.z) - 2.0)}));
        },
        0.002f, 2000);
}

TEST(Truth, AreaLightUmbraAndLitRegion) {
    const scene::Scene s = sphere_over_plane();
    constexpr float kAngle = 0.12f;  // the light's angular radius, radians
    const measure::TruthImage t = trace(s, 64, kAngle);
    ASSERT_EQ(t.soft.size(), t.lit.size());
    int umbra = 0, lit = 0, penumbra = 0;
    for (size_t i = 0; i < t.soft.size(); ++i) {
        if (t.object[i] != 0 || !t.valid(i)) continue;
        const glm::vec3 p = t.position[i];
        const float rho = std::hypot(p.x, p.z);
        const float gamma = std::atan2(rho, kHeight);  // from straight up to the sphere's centre
        const float beta = std::asin(kRadius / std::hypot(rho, kHeight));  // the sphere's angular radius
        if (gamma + kAngle < beta - 0.02f) {
            ++umbra;
            EXPECT_EQ(t.soft[i], 0.0f) << "umbra at rho " << rho;
        } else if (gamma - kAngle > beta + 0.02f) {
            ++lit;
            EXPECT_EQ(t.soft[i], 1.0f) << "fully lit at rho " << rho;
        } else if (t.soft[i] > 0.0f && t.soft[i] < 1.0f) {
            ++penumbra;
        }
        EXPECT_GE(t.soft[i], 0.0f);
        EXPECT_LE(t.soft[i], 1.0f);
    }
    EXPECT_GT(umbra, 200);
    EXPECT_GT(lit, 1000);
    EXPECT_GT(penumbra, 200);
}

TEST(Truth, NonCastersDoNotShadowAndNonReceiversAreNotValid) {
    scene::Scene s = sphere_over_plane();
    s.objects[1].casts_shadow = false;
    measure::TruthImage t = trace(s);
    for (size_t i = 0; i < t.lit.size(); ++i) {
        if (t.object[i] == 0 && t.valid(i)) {
            EXPECT_EQ(t.lit[i], 1);
        }
    }
    s = sphere_over_plane();
    s.objects[0].receives_shadow = false;
    t = trace(s);
    EXPECT_GT(t.count(PixelClass::NotReceiver), 1000u);
    for (size_t i = 0; i < t.lit.size(); ++i) {
        if (t.object[i] == 0) {
            EXPECT_FALSE(t.valid(i));
        }
    }
}

TEST(Truth, BackFacesAreCulledLikeTheRenderer) {
    scene::Scene s = sphere_over_plane();
    s.objects.resize(1);  // the plane alone, seen from below
    s.camera.view = glm::lookAt(glm::vec3(0.0f, -5.0f, 0.1f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const measure::TruthImage t = trace(s);
    EXPECT_EQ(t.count(PixelClass::Background), t.lit.size());
}

TEST(Truth, ValidMaskAndEpsilon) {
    const scene::Scene s = sphere_over_plane();
    measure::RayTracer rt(s);
    // 1e-4 of the scene's diagonal (10 x 3 x 10 box).
    EXPECT_NEAR(rt.epsilon(), 1e-4f * std::sqrt(10.0f * 10.0f + 3.0f * 3.0f + 10.0f * 10.0f), 1e-7f);
    measure::TruthOptions o;
    o.width = 40;
    o.height = 30;
    o.view_proj = glm::perspective(s.camera.yfov, 4.0f / 3.0f, s.camera.znear, s.camera.zfar) * s.camera.view;
    const measure::TruthImage t = rt.render(o);
    const auto mask = t.valid_mask();
    ASSERT_EQ(mask.size(), 1200u);
    size_t total = 0;
    for (int c = 0; c < measure::kPixelClassCount; ++c) total += t.count(static_cast<PixelClass>(c));
    EXPECT_EQ(total, mask.size());
    for (size_t i = 0; i < mask.size(); ++i) EXPECT_EQ(mask[i] != 0, t.valid(i));
    EXPECT_TRUE(t.soft.empty());
    EXPECT_THROW(rt.render(measure::TruthOptions{0, 10}), std::invalid_argument);
}

}  // namespace
