// Cascaded shadow maps on a context (also run under ASan, where every uniform the executor sets is
// checked against the variant's source): every encoding and filter, forward and deferred, draws
// shadows with no GL error; --aov cascades shows each of the four cascades in its colour, nearest
// first. Their accuracy against the truth: tests/extremes/test_cascades.cpp.
#include "gl_fixture.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/check.h"
#include "plan/techniques/reports.h"
#include "plan/options.h"
#include "scene/primitives.h"

using namespace penumbra;

namespace {

constexpr int kW = 192, kH = 108;

// A kilometre of ground, boxes from 8 m to 800 m ahead, a sun 32 degrees up from the side; the
// camera 2 m above the ground looking along it.
scene::Scene field() {
    scene::Scene s;
    s.meshes = {scene::make_quad(1000.0f), scene::make_box(glm::vec3(1.0f))};
    s.materials.resize(1);
    s.objects.push_back(test::object("ground", 0, glm::mat4(1.0f)));
    for (int i = 0; i < 6; ++i) {
        const float z = -8.0f * std::pow(2.5f, static_cast<float>(i));
        const float size = 2.0f * std::pow(1.8f, static_cast<float>(i));
        s.objects.push_back(test::object(
            "box", 1,
            glm::translate(glm::mat4(1.0f), glm::vec3(0.5f * size, size, z)) * glm::scale(glm::mat4(1.0f), glm::vec3(size, 2.0f * size, size))));
    }
    s.light.type = scene::LightType::Directional;
    s.light.direction = glm::normalize(glm::vec3(-0.8f, -0.53f, 0.25f));
    s.camera.view = glm::lookAt(glm::vec3(-3.0f, 2.0f, 0.0f), glm::vec3(-3.0f, 1.0f, -40.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(58.0f);
    s.camera.znear = 0.5f;
    s.camera.zfar = 1500.0f;
    return s;
}

class CascadesGl : public test::GlTest {
protected:
    scene::Scene scene_ = field();

    std::vector<std::uint8_t> render(const char* encoding, const char* filter, const char* shading, const char* aov) {
        render::Settings s;
        EXPECT_EQ(render::parse_option(s, "cascades", "4"), "");
        EXPECT_EQ(render::parse_option(s, "encoding", encoding), "");
        EXPECT_EQ(render::parse_option(s, "filter", filter), "");
        EXPECT_EQ(render::parse_option(s, "shading", shading), "");
        EXPECT_EQ(render::parse_option(s, "aov", aov), "");
        s.map_size = 256;
        const render::FramePlan& plan = renderer->render(scene_, s, render::offscreen(kW, kH));
        EXPECT_EQ(render::cascades_of(plan).size(), 4u);
        gl::check_errors("a cascaded frame");
        return renderer->read_image();
    }
};

TEST_F(CascadesGl, EveryEncodingFilterAndShadingDrawsShadows) {
    for (const char* e : {"r8", "rgba", "depthtex"})
        for (const char* f : {"hard", "pcf4x4", "pcss"})
            for (const char* shading : {"forward", "deferred"}) {
                const auto rgba = render(e, f, shading, "visibility");
                int dark = 0, lit = 0;
                for (size_t i = 0; i < rgba.size(); i += 4) {
                    dark += rgba[i] < 64;
                    lit += rgba[i] > 192;
                }
                EXPECT_GT(dark, 100) << e << " " << f << " " << shading << ": no shadow";
                EXPECT_GT(lit, kW * kH / 4) << e << " " << f << " " << shading;
            }
}

// The tints: red, green, blue, yellow (cascades 0 to 3) mixed half and half with the image.
TEST_F(CascadesGl, TheCascadesAovShowsEachCascadeInItsColour) {
    const auto rgba = render("rgba", "hard", "forward", "cascades");
    int seen[4] = {0, 0, 0, 0};
    int bottom = -1;  // the cascade of the ground just in front of the camera (the image's bottom row)
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const std::uint8_t* p = &rgba[(static_cast<size_t>(y) * kW + static_cast<size_t>(x)) * 4];
            const int r = p[0], g = p[1], b = p[2];
            int k = -1;
            if (r > g + 40 && r > b + 40 && g > b - 20 && r - g > 60) k = 0;
            else if (g > r + 30 && g > b + 30) k = 1;
            else if (b > r + 30 && b > g + 20) k = 2;
            else if (r > b + 60 && g > b + 60 && std::abs(r - g) < 50) k = 3;
            if (k < 0) continue;
            ++seen[k];
            if (y == kH - 1 && x == kW / 2) bottom = k;
        }
    for (int k = 0; k < 4; ++k) EXPECT_GT(seen[k], 20) << "cascade " << k << " not seen";
    EXPECT_EQ(bottom, 0) << "the nearest ground is the first cascade's";
}

}  // namespace
