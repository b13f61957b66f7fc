// Which faces go into the shadow map (--map-faces), checked against the ray-traced truth on a scene
// with a closed mesh (a low box lying on the ground) and an open one (a sheet tilted over the
// ground, its front face turned away from the light, so its shadow comes from its back face alone).
#include "gl_fixture.h"

#include <cstdio>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "plan/options.h"
#include "scene/primitives.h"

using namespace penumbra;

namespace {

constexpr int kSize = 256;

using test::object;

scene::Scene sphere_and_sheet() {
    scene::Scene s;
    s.meshes = {scene::make_quad(10.0f), scene::make_box(glm::vec3(0.8f, 0.25f, 0.8f)), scene::make_quad(1.6f)};
    s.materials.resize(1);
    // The sheet: 1.2 above the ground, tilted 30 degrees and turned upside down (its normal points
    // down and away from the light above), beside the sphere.
    const glm::mat4 sheet = glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 1.2f, 0.0f)) *
                            glm::rotate(glm::mat4(1.0f), glm::radians(150.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    s.objects = {object("ground", 0, glm::mat4(1.0f)),
                 object("box", 1, glm::translate(glm::mat4(1.0f), glm::vec3(-1.2f, 0.25f, 0.0f))),
                 object("sheet", 2, sheet)};
    s.light.type = scene::LightType::Point;
    s.light.position = glm::vec3(4.0f, 3.0f, 2.0f);
    s.camera.view = glm::lookAt(glm::vec3(0.0f, 5.0f, 6.0f), glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    s.camera.yfov = glm::radians(50.0f);
    s.camera.znear = 0.1f;
    s.camera.zfar = 40.0f;
    return s;
}

class MapFaces : public test::GlTest {
protected:
    struct Result {
        measure::Score score;
        std::vector<std::uint8_t> vis;
        std::map<std::string, gl::Cull> cull;  // per object, as the shadow-map pass draws it
    };

    // The course's fit (--light-fit tight, the ground in the map) unless `fit` says otherwise: the
    // acne below needs the texel density it was measured at.
    Result run(const scene::Scene& sc, const char* faces, const char* bias = "auto",
               render::LightFit fit = render::LightFit::Tight) {
        render::Settings s;
        s.light_fit = fit;
        EXPECT_EQ(render::parse_option(s, "map-faces", faces), "");
        EXPECT_EQ(render::parse_option(s, "bias", bias), "");
        s.aov = render::Aov::Visibility;
        s.map_size = 1024;
        const render::FrameInputs in = render::offscreen(kSize, kSize);
        Result r;
        const auto& plan = renderer->render(sc, s, in);
        for (const auto& p : plan.passes)
            if (p.name == "shadow-map")
                for (const auto& d : p.draws) r.cull[d.label] = d.cull.value_or(p.state.cull);
        const auto rgba = renderer->read_image();
        r.vis.resize(rgba.size() / 4);
        for (size_t i = 0; i < r.vis.size(); ++i) r.vis[i] = rgba[i * 4];
        measure::TruthOptions to;
        to.width = kSize;
        to.height = kSize;
        to.view_proj = plan.camera.view_proj;
        const measure::TruthImage t = measure::RayTracer(sc).render(to);
        r.score = measure::score(r.vis, t.lit, t.valid_mask());
        std::printf("--map-faces %-5s --bias %-5s error %.3f%% (false shadow %.3f%%, false lit %.3f%%)\n", faces, bias,
                    r.score.error_pct, r.score.false_shadow_pct, r.score.false_lit_pct);
        RecordProperty(std::string(faces) + "_" + bias + "_error_pct", std::to_string(r.score.error_pct));
        return r;
    }
};

TEST(MeshClosure, ClosedMeshesAreFoundFromTheirIndices) {
    EXPECT_TRUE(scene::make_sphere(1.0f, 16, 8).closed);  // its seam and poles weld
    EXPECT_TRUE(scene::make_box(glm::vec3(1.0f)).closed);  // 24 vertices: the corners weld
    EXPECT_FALSE(scene::make_quad(1.0f).closed);
    scene::Mesh holed = scene::make_box(glm::vec3(1.0f));
    holed.indices.resize(holed.indices.size() - 3);  // one triangle gone
    EXPECT_FALSE(scene::is_closed(holed));
    scene::Mesh flipped = scene::make_box(glm::vec3(1.0f));
    std::swap(flipped.indices[0], flipped.indices[1]);  // one triangle wound the other way
    EXPECT_FALSE(scene::is_closed(flipped));
    scene::Mesh doubled = scene::make_box(glm::vec3(1.0f));
    doubled.indices.insert(doubled.indices.end(), doubled.indices.begin(), doubled.indices.begin() + 3);
    EXPECT_FALSE(scene::is_closed(doubled));  // an edge run twice the same way
    EXPECT_FALSE(scene::is_closed(scene::Mesh{}));
}

TEST_F(MapFaces, AutoTakesTheBackFacesOfAClosedMeshAndBothOfAnOpenOne) {
    const scene::Scene sc = sphere_and_sheet();
    ASSERT_TRUE(sc.meshes[1].closed);
    ASSERT_FALSE(sc.meshes[2].closed);
    const Result a = run(sc, "auto");
    const Result both = run(sc, "both");
    const Result front = run(sc, "front");
    const Result back = run(sc, "back");
    const Result sheet_auto = run(sc, "auto", "sheet");
    const Result sheet_both = run(sc, "both", "sheet");
    EXPECT_EQ(a.cull.at("box"), gl::Cull::Front);  // back faces in
    EXPECT_EQ(a.cull.at("sheet"), gl::Cull::None);
    EXPECT_EQ(a.cull.at("ground"), gl::Cull::None);
    // The ground, a flat quad under both, shadows nothing in view: --light-fit shadows leaves it out.
    const Result shadows = run(sc, "auto", "auto", render::LightFit::Shadows);
    EXPECT_EQ(shadows.cull.count("ground"), 0u);
    EXPECT_EQ(shadows.cull.at("box"), gl::Cull::Front);
    EXPECT_LE(shadows.score.error_pct, a.score.error_pct + 0.02);
    EXPECT_EQ(a.vis, back.vis);
    // Front faces alone lose the sheet's shadow (its front face looks away from the light).
    EXPECT_GT(front.score.false_lit_pct, a.score.false_lit_pct + 1.0);
    // With the slope bias, the back faces do as well as both; with the sheet's constant they keep the
    // box's lit top from shadowing itself (acne) where both faces do not.
    EXPECT_LE(a.score.error_pct, both.score.error_pct + 0.02);
    EXPECT_LT(sheet_auto.score.false_shadow_pct + 0.1, sheet_both.score.false_shadow_pct);
    EXPECT_LT(a.score.error_pct, 0.5);
}

}  // namespace
