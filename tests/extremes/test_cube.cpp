// A point light's cube (--cascades cube) against the ray-traced truth on tests/data/bulb_room.gltf
// (a bulb among boxes and spheres in a closed 8 x 3 x 6 m room; make_large_scenes.py): the error
// with shadows on every wall, the floor and the ceiling beside one perspective map's, shadows that
// cross a face's edge, only the faces that see a visible receiver drawn, still faces kept, every
// encoding and filter, and the deferred path.
#include "gl_fixture.h"
#include "truth_frame.h"

#include <cstdio>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/check.h"
#include "measure/metrics.h"
#include "measure/ray_tracer.h"
#include "plan/techniques/reports.h"
#include "plan/options.h"
#include "scene/gltf_loader.h"
#include "shadow/cube.h"
#include "../cube_passes.h"

using namespace penumbra;

namespace {

constexpr int kSize = 512;
// The error goal against the truth (issue 12): 0.5 % of the valid pixels.
constexpr double kGoalPct = 0.5;

scene::Scene room() {
    const scene::LoadResult r = scene::load_gltf(test::test_data_dir() + "/bulb_room.gltf");
    EXPECT_TRUE(r.ok) << r.error;
    return r.scene;
}

render::Settings settings(const char* cascades, const char* filter = "hard", const char* encoding = "rgba",
                          const char* layout = "atlas") {
    render::Settings s;
    EXPECT_EQ(render::parse_option(s, "cascades", cascades), "");
    EXPECT_EQ(render::parse_option(s, "cube-layout", layout), "");
    EXPECT_EQ(render::parse_option(s, "filter", filter), "");
    EXPECT_EQ(render::parse_option(s, "encoding", encoding), "");
    s.aov = render::Aov::Visibility;
    return s;
}

// The scene's camera, and one from the opposite corner: between them every wall is seen.
glm::mat4 opposite_view() {
    return glm::lookAt(glm::vec3(-3.7f, 2.6f, -2.7f), glm::vec3(1.5f, 1.1f, 1.3f), glm::vec3(0.0f, 1.0f, 0.0f));
}

class Cube : public test::GlTest {
protected:
    scene::Scene scene_ = room();

    std::vector<std::uint8_t> visibility(const render::Settings& s, const glm::mat4* view = nullptr,
                                         render::FramePlan* plan_out = nullptr) {
        return visibility_frame(scene_, s, kSize, view, plan_out);
    }

    measure::TruthImage truth(const glm::mat4& view_proj) { return test::truth_frame(scene_, view_proj, kSize); }

    int object(const char* name) const {
        for (size_t i = 0; i < scene_.objects.size(); ++i)
            if (scene_.objects[i].name == name) return static_cast<int>(i);
        ADD_FAILURE() << "no object " << name;
        return -1;
    }

    // The passes of a plan into the cube's faces, and how many of them ran.
    static int face_passes(const render::FramePlan& p, int* ran = nullptr) { return test::cube_face_passes(p, ran); }
};

// The valid pixels of `t` within `reach` pixels of one whose point lies in another face of the
// light's cube: the seams' neighbourhood.
std::vector<std::uint8_t> seam_mask(const measure::TruthImage& t, const glm::vec3& light, int reach) {
    std::vector<int> face(t.lit.size(), -1);
    for (size_t i = 0; i < face.size(); ++i)
        if (t.valid(i)) face[i] = shadow::cube_face_of(t.position[i] - light);
    std::vector<std::uint8_t> m(face.size(), 0);
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) {
            const int f = face[static_cast<size_t>(y * t.width + x)];
            if (f < 0) continue;
            for (int dy = -reach; dy <= reach && !m[static_cast<size_t>(y * t.width + x)]; ++dy)
                for (int dx = -reach; dx <= reach; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u < 0 || v < 0 || u >= t.width || v >= t.height) continue;
                    const int g = face[static_cast<size_t>(v * t.width + u)];
                    if (g >= 0 && g != f) {
                        m[static_cast<size_t>(y * t.width + x)] = 1;
                        break;
                    }
                }
        }
    return m;
}

TEST_F(Cube, ABulbInARoomIsWithinHalfAPercentOfTheTruthOnEveryWall) {
    const glm::mat4 views[2] = {scene_.camera.view, opposite_view()};
    // Per wall, floor and ceiling: the truth's shadowed pixels seen over both views.
    const char* panels[] = {"floor", "ceiling", "wall -x", "wall +x", "wall -z", "wall +z"};
    std::map<int, size_t> shadowed;
    for (const glm::mat4& view : views) {
        render::FramePlan cube_plan, one_plan, map_plan;
        const auto cube = visibility(settings("cube"), &view, &cube_plan);
        const auto one = visibility(settings("1"), &view, &one_plan);
        const auto map = visibility(settings("cube", "hard", "rgba", "cubemap"), &view, &map_plan);
        ASSERT_TRUE((render::cube_of(cube_plan) != nullptr));
        ASSERT_FALSE((render::cube_of(one_plan) != nullptr));
        ASSERT_TRUE((render::cube_of(map_plan) != nullptr) && render::cube_of(map_plan)->cube_map);
        const measure::TruthImage t = truth(cube_plan.camera.view_proj);
        const auto valid = t.valid_mask();
        const measure::Score c = measure::score(cube, t.lit, valid);
        const measure::Score o = measure::score(one, t.lit, valid);
        const measure::Score m = measure::score(map, t.lit, valid);
        std::printf("cube (%d faces): error %.3f %% (as a GL cube map %.3f %%); one perspective map: %.3f %%\n",
                    render::cube_of(cube_plan)->drawn(), c.error_pct, m.error_pct, o.error_pct);
        EXPECT_LE(m.error_pct, kGoalPct);
        RecordProperty(std::string(&view == &views[0] ? "scene" : "opposite") + "_cube_error_pct", std::to_string(c.error_pct));
        RecordProperty(std::string(&view == &views[0] ? "scene" : "opposite") + "_one_map_error_pct", std::to_string(o.error_pct));
        EXPECT_LE(c.error_pct, kGoalPct);
        EXPECT_GT(o.error_pct, 4.0 * c.error_pct) << "one map should miss what lies outside its frustum";
        for (const char* name : panels) {
            const int k = object(name);
            for (size_t i = 0; i < t.lit.size(); ++i)
                if (valid[i] && t.object[i] == k && !t.lit[i]) ++shadowed[k];
        }
    }
    for (const char* name : panels) EXPECT_GT(shadowed[object(name)], 300u) << name << " has no shadow to score";
}

TEST_F(Cube, AShadowCrossingAFaceEdgeStaysContinuous) {
    // Within 2 pixels of a seam, hard and PCF 4x4 (whose taps reach into the guard band), the
    // error is as small as anywhere, and the truth has shadow there to get wrong.
    // A GL cube map has no guard band: its taps past an edge read the next face.
    for (const char* layout : {"atlas", "cubemap"})
        for (const char* filter : {"hard", "pcf4x4"}) {
            render::FramePlan plan;
            const auto v = visibility(settings("cube", filter, "rgba", layout), nullptr, &plan);
            const measure::TruthImage t = truth(plan.camera.view_proj);
            const auto seams = seam_mask(t, scene_.light.position, 2);
            const measure::Score s = measure::score(v, t.lit, seams);
            std::printf("--cube-layout %s --filter %s: %zu pixels by a seam, %zu of them shadowed in the truth, error "
                        "there %.3f %%\n", layout, filter, s.valid, s.truth_shadowed, s.error_pct);
            EXPECT_GT(s.valid, 2000u);
            EXPECT_GT(s.truth_shadowed, 200u) << "no shadow crosses a seam in this view";
            EXPECT_LE(s.error_pct, 1.0) << layout << " " << filter;
        }
}

TEST_F(Cube, OnlyTheFacesThatSeeAVisibleReceiverAreDrawn) {
    // Looking down at the floor from under the ceiling: the ceiling and the walls behind the
    // camera are out of view, and so are the faces that see only them.
    const glm::mat4 view =
        glm::lookAt(glm::vec3(-2.5f, 2.8f, 1.5f), glm::vec3(-2.5f, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    render::FramePlan plan;
    const auto v = visibility(settings("cube"), &view, &plan);
    ASSERT_TRUE((render::cube_of(plan) != nullptr));
    const int drawn = render::cube_of(plan)->drawn();
    EXPECT_EQ(face_passes(plan), drawn);
    EXPECT_LT(drawn, 6);
    EXPECT_TRUE(render::cube_of(plan)->faces[3].drawn) << "the floor is below the light";
    EXPECT_FALSE(render::cube_of(plan)->faces[2].drawn) << "the ceiling is out of view";
    const measure::TruthImage t = truth(plan.camera.view_proj);
    const measure::Score s = measure::score(v, t.lit, t.valid_mask());
    std::printf("%d faces drawn, error %.3f %%\n", drawn, s.error_pct);
    EXPECT_LE(s.error_pct, kGoalPct);
    EXPECT_GT(s.truth_shadowed, 1000u);
}

TEST_F(Cube, StillFacesAreKeptAndAMovedCasterRedrawsOnlyItsFaces) {
    const render::Settings s = settings("cube");
    render::FramePlan first, second, third;
    const auto a = visibility(s, nullptr, &first);
    int ran = 0;
    const int faces = face_passes(first, &ran);
    EXPECT_EQ(ran, faces);
    visibility(s, nullptr, &second);
    face_passes(second, &ran);
    EXPECT_EQ(ran, 0) << "nothing moved: every face is kept";
    // The crate sits on the floor below the bulb, away from it in +x: only the faces that hold
    // it are drawn again.
    const int crate = object("crate");
    scene_.objects[static_cast<size_t>(crate)].world =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.1f)) * scene_.objects[static_cast<size_t>(crate)].world;
    const auto c = visibility(s, nullptr, &third);
    face_passes(third, &ran);
    int holding = 0;  // the face passes that draw the crate
    for (const render::Pass& p : third.passes)
        if (p.name.rfind("shadow-map face ", 0) == 0)
            for (const render::Draw& d : p.draws) holding += d.object == crate;
    EXPECT_GE(ran, 1);
    EXPECT_EQ(ran, holding) << "exactly the faces that draw the crate run";
    EXPECT_LT(ran, faces);
    // And the frame is that of a cube drawn afresh.
    const measure::TruthImage t = truth(third.camera.view_proj);
    EXPECT_LE(measure::score(c, t.lit, t.valid_mask()).error_pct, kGoalPct);
    EXPECT_NE(a, c) << "the crate's shadow moved";
}

// Every encoding with the hard, PCF 4x4 and PCSS lookups, either precision, and the deferred path:
// the shadows are there with zero GL errors.
TEST_F(Cube, EveryEncodingFilterAndPathLooksUpTheFaces) {
    render::FramePlan plan;
    visibility(settings("cube"), nullptr, &plan);
    const measure::TruthImage t = truth(plan.camera.view_proj);
    // depthtex with a cube map: the atlas instead (no cube depth texture in WebGL 1), said in a note.
    for (const char* layout : {"atlas", "cubemap"})
        for (const char* e : {"r8", "rgba", "depthtex"})
            for (const char* f : {"hard", "pcf4x4", "pcss"})
                for (const char* precision : {"highp", "mediump"}) {
                    render::Settings s = settings("cube", f, e, layout);
                    EXPECT_EQ(render::parse_option(s, "precision", precision), "");
                    render::FramePlan p;
                    const auto v = visibility(s, nullptr, &p);
                    const bool cube_map = std::string(layout) == "cubemap" && std::string(e) != "depthtex";
                    EXPECT_EQ(render::cube_of(p)->cube_map, cube_map) << layout << " " << e;
                    const measure::Score sc = measure::score(v, t.lit, t.valid_mask());
                    std::printf("--cube-layout %-7s --encoding %-8s --filter %-6s --precision %-7s error %.3f %%\n",
                                layout, e, f, precision, sc.error_pct);
                    EXPECT_LT(sc.error_pct, 2.0) << layout << " " << e << " " << f << " " << precision;
                    EXPECT_GT(sc.truth_shadowed, 1000u);
                }
    render::Settings deferred = settings("cube", "pcf4x4");
    EXPECT_EQ(render::parse_option(deferred, "shading", "deferred"), "");
    const measure::Score d = measure::score(visibility(deferred), t.lit, t.valid_mask());
    EXPECT_EQ(render::parse_option(deferred, "cube-layout", "cubemap"), "");
    const measure::Score dm = measure::score(visibility(deferred), t.lit, t.valid_mask());
    std::printf("deferred, pcf4x4: error %.3f %% (a cube map %.3f %%)\n", d.error_pct, dm.error_pct);
    EXPECT_LE(d.error_pct, kGoalPct);
    EXPECT_LE(dm.error_pct, kGoalPct);
}

// --cube-layout cubemap: each face of the GL cube map holds what the atlas's tile of that face
// holds, turned 180 degrees (textureCube reads a face with s and t against the atlas's x and y:
// GLES 2 spec, table 3.21). With one tap there is no guard band, so the two hold the same view.
TEST_F(Cube, ACubeMapFaceHoldsTheAtlasTileTurnedHalfAround) {
    render::Settings s = settings("cube");
    s.map_size = 128;
    // Every caster in each face, the room's walls included (the shadows fit leaves out those that
    // shadow nothing in view, and a face can then hold too little surface to compare).
    s.light_fit = render::LightFit::Tight;
    visibility(s);
    gl::Device& dev = renderer->device();
    const auto read = [&](const gl::Target& t, int x, int y, int n) {
        dev.bind_target(t);
        return dev.read_rgba(x, y, n, n);
    };
    const render::ResourceDesc atlas = renderer->last_plan()->resource("shadow-map")->desc;
    ASSERT_FALSE(atlas.cube);
    std::vector<std::vector<std::uint8_t>> tiles;
    for (int f = 0; f < 6; ++f)
        tiles.push_back(read(renderer->pool().whole("shadow-map"), (f % 3) * 128, (f / 3) * 128, 128));
    EXPECT_EQ(render::parse_option(s, "cube-layout", "cubemap"), "");
    visibility(s);
    ASSERT_TRUE(renderer->last_plan()->resource("shadow-map")->desc.cube);
    for (int f = 0; f < 6; ++f) {
        if (!render::cube_of(*renderer->last_plan())->faces[static_cast<size_t>(f)].drawn) continue;
        const auto face = read(renderer->pool().whole("shadow-map", f), 0, 0, 128);
        int differ = 0, deep = 0;
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) {
                const size_t a = static_cast<size_t>((y * 128 + x) * 4);
                const size_t b = static_cast<size_t>(((127 - y) * 128 + (127 - x)) * 4);
                // The packed depth's top byte: the same surface within 1/256 of the range.
                differ += std::abs(int(tiles[static_cast<size_t>(f)][a]) - int(face[b])) > 1;
                deep += tiles[static_cast<size_t>(f)][a] < 250;
            }
        std::printf("face %s: %d of 16384 texels differ (%d hold a surface)\n", shadow::cube_face_name(f), differ, deep);
        EXPECT_GT(deep, 1000) << shadow::cube_face_name(f);
        EXPECT_LT(differ, 16384 / 50) << shadow::cube_face_name(f);  // rasterisation of edges only
    }
    gl::check_errors("cube map faces read");
}

}  // namespace

// Issue 56: a spot light with an 80-degree outer cone low over a 40-long cable
// (tests/data/wide_cone.gltf). From 12 to 18 along the cable on either side its shadow is 75-80
// degrees off the spot's axis: inside the cone, outside any one frustum the fit allows. At the
// defaults auto gives the spot the cube's faces its cone reaches; every technique that reads a map
// then stays within the 0.15 % of the truth, where one map (--cascades 1, the control)
// misses several percent.
class WideCone : public test::GlTest {
protected:
    scene::Scene scene_ = [] {
        const scene::LoadResult r = scene::load_gltf(test::test_data_dir() + "/wide_cone.gltf");
        EXPECT_TRUE(r.ok) << r.error;
        return r.scene;
    }();
    measure::Score score(render::Settings s, render::FramePlan* plan = nullptr) {
        s.aov = render::Aov::Visibility;
        render::FramePlan p;
        const auto vis = visibility_frame(scene_, s, kSize, nullptr, &p);
        const measure::TruthImage t = test::truth_frame(scene_, p.camera.view_proj, kSize);
        if (plan) *plan = p;
        return measure::score(vis, t.lit, t.valid_mask());
    }
};

TEST_F(WideCone, EveryMapTechniqueHoldsTheShadowBeyondSeventyFiveDegrees) {
    render::Settings one;
    ASSERT_EQ(render::parse_option(one, "cascades", "1"), "");
    const measure::Score control = score(one);
    std::printf("one map: %.3f %%\n", control.error_pct);
    EXPECT_GT(control.error_pct, 1.0) << "one map should lose the shadow beyond its window";
    const std::vector<std::pair<const char*, const char*>> cases = {
        {"filter", "hard"}, {"filter", "pcf4x4"}, {"encoding", "depthtex"}, {"encoding", "r8"}, {"filter", "pcss"}};
    for (const auto& [name, value] : cases) {
        render::Settings s;
        ASSERT_EQ(render::parse_option(s, name, value), "");
        render::FramePlan p;
        const measure::Score sc = score(s, &p);
        std::printf("--%s %s: %.3f %% (%d faces)\n", name, value, sc.error_pct,
                    render::cube_of(p) ? render::cube_of(p)->drawn() : 0);
        ASSERT_NE(render::cube_of(p), nullptr) << name << " " << value;
        EXPECT_LE(sc.error_pct, 0.15) << name << " " << value;
    }
}

// A point light in the spot's place: the ground it lights runs beside and behind it, which one
// map (fitted around the whole scene) counts as lit; auto's cube holds it.
TEST_F(WideCone, APointLightThereGetsTheCubeToo) {
    scene_.light.type = scene::LightType::Point;
    render::Settings one;
    ASSERT_EQ(render::parse_option(one, "cascades", "1"), "");
    const measure::Score control = score(one);
    render::FramePlan p;
    const measure::Score cube = score(render::Settings{}, &p);
    std::printf("point light: one map %.3f %%, auto %.3f %%\n", control.error_pct, cube.error_pct);
    EXPECT_GT(control.error_pct, 1.0);
    ASSERT_NE(render::cube_of(p), nullptr);
    EXPECT_LE(cube.error_pct, 0.15);
}
