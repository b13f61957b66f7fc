// Shadow volumes without a GL context: the volumes are closed, outward-facing surfaces for closed
// and open meshes and every kind of light; silhouettes come from edge multiplicity; the near-plane
// test, the infinite far plane and the fill count; and the plan of a volumes frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan/techniques/reports.h"
#include "plan/plan.h"
#include "scenes/course_scene.h"
#include "scene/primitives.h"
#include "scene/scene_source.h"
#include "shadow/volumes.h"

using namespace penumbra;

namespace {

using Key = std::tuple<float, float, float, float>;
Key key(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }

// Every directed edge of the triangles has its reverse as often: the surface is closed and
// consistently wound (which, for a volume, also means its faces all face out or all in).
// Returns the number of unmatched directed edges.
int open_edges(const std::vector<glm::vec4>& tris) {
    std::map<std::pair<Key, Key>, int> edges;
    for (size_t k = 0; k + 2 < tris.size(); k += 3)
        for (size_t e = 0; e < 3; ++e) {
            const Key a = key(tris[k + e]), b = key(tris[k + (e + 1) % 3]);
            if (a == b) continue;  // a degenerate side (a directional light's apex)
            if (a < b) ++edges[{a, b}];
            else --edges[{b, a}];
        }
    int open = 0;
    for (const auto& [e, n] : edges) open += std::abs(n);
    return open;
}

std::vector<glm::vec4> all(const shadow::ShadowVolume& v) {
    std::vector<glm::vec4> out = v.sides;
    out.insert(out.end(), v.near_cap.begin(), v.near_cap.end());
    out.insert(out.end(), v.far_cap.begin(), v.far_cap.end());
    return out;
}

// The near cap's triangles face the light (counter-clockwise seen from it): with the surface
// closed and consistently wound, the whole volume then faces out.
bool caps_face_the_light(const shadow::ShadowVolume& v, const glm::vec3& light) {
    for (size_t k = 0; k + 2 < v.near_cap.size(); k += 3) {
        const glm::vec3 a(v.near_cap[k]), b(v.near_cap[k + 1]), c(v.near_cap[k + 2]);
        if (glm::dot(glm::cross(b - a, c - a), light - a) <= 0.0f) return false;
    }
    return true;
}

scene::Mesh open_box() {
    scene::Mesh m = scene::make_box(glm::vec3(0.5f));
    m.indices.resize(m.indices.size() - 6);  // one face gone
    scene::seal(m);
    return m;
}

struct LightCase {
    const char* name;
    glm::vec4 light;
};

const LightCase kLights[] = {{"point", {3.0f, 4.0f, 2.0f, 1.0f}},
                             {"directional", {0.3f, 1.0f, 0.2f, 0.0f}},
                             {"point-inside-the-bowl", {0.1f, -0.3f, 0.05f, 1.0f}}};

TEST(ShadowVolumes, AreClosedForClosedAndOpenMeshesUnderEveryLight) {
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(0.2f, 0.5f, -0.1f)) *
                            glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(1.0f, 0.0f, 0.3f));
    const std::pair<const char*, scene::Mesh> meshes[] = {{"sphere", scene::make_sphere(1.0f, 16, 8)},
                                                          {"box", scene::make_box(glm::vec3(0.5f, 0.3f, 0.7f))},
                                                          {"bowl", scene::make_bowl(1.0f, 16, 8)},
                                                          {"open box", open_box()},
                                                          {"quad", scene::make_quad(2.0f)}};
    for (const auto& [name, mesh] : meshes)
        for (const LightCase& l : kLights) {
            ASSERT_TRUE(mesh.topology) << name;
            const auto v = shadow::extrude_volume(*mesh.topology, world, l.light, mesh.closed, true);
            EXPECT_GT(v.triangles(), 0) << name << ", " << l.name;
            EXPECT_EQ(open_edges(all(v)), 0) << name << ", " << l.name << ": the volume has holes";
            if (l.light.w != 0.0f) {
                EXPECT_TRUE(caps_face_the_light(v, glm::vec3(l.light))) << name << ", " << l.name;
            } else {
                EXPECT_TRUE(v.far_cap.empty()) << "a directional light's volume meets at one point";
            }
        }
}

TEST(ShadowVolumes, TheCheckCanFail) {
    // Dropping the caps (depth-pass geometry) leaves the volume open: open_edges sees it.
    const scene::Mesh sphere = scene::make_sphere(1.0f, 16, 8);
    const auto v = shadow::extrude_volume(*sphere.topology, glm::mat4(1.0f), {3, 4, 2, 1}, true, false);
    EXPECT_TRUE(v.near_cap.empty());
    EXPECT_GT(open_edges(v.sides), 0);
}

TEST(ShadowVolumes, TheEdgeTableNamesEachEdgeOnceAndEveryCornersEdge) {
    // weld's table: a closed sphere's E = 3T / 2 edges, each once with its lower vertex first, and
    // each corner's entry the edge from it to the next corner.
    const scene::Mesh sphere = scene::make_sphere(1.0f, 12, 6);
    const scene::Topology& t = *sphere.topology;
    ASSERT_EQ(t.corner_edges.size(), t.triangles.size());
    EXPECT_EQ(2 * t.edge_count(), t.triangles.size());
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (size_t e = 0; e < t.edge_count(); ++e) {
        EXPECT_LT(t.edges[2 * e], t.edges[2 * e + 1]);
        EXPECT_TRUE(seen.insert({t.edges[2 * e], t.edges[2 * e + 1]}).second) << "edge " << e << " twice";
    }
    for (size_t k = 0; k < t.triangles.size(); ++k) {
        const std::uint32_t a = t.triangles[k], b = t.triangles[k - k % 3 + (k + 1) % 3];
        const std::uint32_t e = t.corner_edges[k];
        EXPECT_EQ(std::minmax(a, b), std::minmax(t.edges[2 * e], t.edges[2 * e + 1])) << "corner " << k;
    }
    // A topology made by hand (no table) extrudes to the same volume, mirrored or not; a table that
    // names the wrong edges would not (the control).
    scene::Topology bare;
    bare.positions = t.positions;
    bare.triangles = t.triangles;
    const auto sorted = [](std::vector<glm::vec4> v) {
        std::vector<Key> k;
        for (const auto& p : v) k.push_back(key(p));
        std::sort(k.begin(), k.end());
        return k;
    };
    for (const glm::mat4& world : {glm::mat4(1.0f), glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f))}) {
        const auto with = shadow::extrude_volume(t, world, {3, 4, 2, 1}, true, true);
        const auto without = shadow::extrude_volume(bare, world, {3, 4, 2, 1}, true, true);
        EXPECT_EQ(with.silhouette_edges, without.silhouette_edges);
        EXPECT_EQ(sorted(all(with)), sorted(all(without)));
    }
    scene::Topology wrong = t;
    std::rotate(wrong.corner_edges.begin(), wrong.corner_edges.begin() + 1, wrong.corner_edges.end());
    EXPECT_NE(open_edges(all(shadow::extrude_volume(wrong, glm::mat4(1.0f), {3, 4, 2, 1}, true, true))), 0);
}

TEST(ShadowVolumes, SilhouettesComeFromEdgeMultiplicity) {
    // A closed cube lit straight down: its dark cap is the bottom face (the sides are edge-on), so
    // the silhouette is the bottom's rim, 4 edges. Along the long diagonal: 3 faces, 6 edges.
    const scene::Mesh cube = scene::make_box(glm::vec3(0.5f));
    EXPECT_EQ(shadow::extrude_volume(*cube.topology, glm::mat4(1.0f), {0, 1, 0, 0}, true, false).silhouette_edges, 4);
    EXPECT_EQ(shadow::extrude_volume(*cube.topology, glm::mat4(1.0f), {1, 1, 1, 0}, true, false).silhouette_edges, 6);
    // An open quad: its 4 border edges; the diagonal inside cancels, from either side.
    const scene::Mesh quad = scene::make_quad(2.0f);  // in y = 0, facing +y
    EXPECT_EQ(shadow::extrude_volume(*quad.topology, glm::mat4(1.0f), {0, 3, 0, 1}, false, false).silhouette_edges, 4);
    EXPECT_EQ(shadow::extrude_volume(*quad.topology, glm::mat4(1.0f), {0, -3, 0, 1}, false, false).silhouette_edges, 4);
    // The same quad with one triangle wound the other way (the triangles face opposite ways): turned
    // to face the light, the diagonal still cancels.
    scene::Mesh mixed = scene::make_quad(2.0f);
    std::swap(mixed.indices[0], mixed.indices[1]);
    scene::seal(mixed);
    EXPECT_EQ(shadow::extrude_volume(*mixed.topology, glm::mat4(1.0f), {0, 3, 0, 1}, false, false).silhouette_edges, 4);
    // An open book lit from the side: one page faces the light, the other away; turned towards it,
    // both run the spine the same way, so it is a silhouette edge twice (the two pages' volumes).
    scene::Mesh book;
    book.positions = {{0, 0, 0}, {0, 0, 1}, {1, 1, 0}, {-1, 1, 0}};
    book.normals.assign(4, glm::vec3(0, 1, 0));
    book.indices = {0, 1, 2, 1, 0, 3};  // consistent winding across the spine 0-1
    scene::seal(book);
    const auto side = shadow::extrude_volume(*book.topology, glm::mat4(1.0f), {5, 1, 0.5f, 1}, false, false);
    EXPECT_EQ(side.silhouette_edges, 4 + 2);  // the 4 outer edges and the spine twice
    // Lit from inside the book both pages face the light and the spine cancels.
    const auto inside = shadow::extrude_volume(*book.topology, glm::mat4(1.0f), {0, 5, 0.5f, 1}, false, false);
    EXPECT_EQ(inside.silhouette_edges, 4);
}

TEST(ShadowVolumes, AMirroringTransformKeepsTheVolumeOutward) {
    const scene::Mesh sphere = scene::make_sphere(1.0f, 12, 6);
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
    const auto v = shadow::extrude_volume(*sphere.topology, mirror, {3, 4, 2, 1}, true, true);
    EXPECT_EQ(open_edges(all(v)), 0);
    EXPECT_TRUE(caps_face_the_light(v, {3, 4, 2}));
}

TEST(ShadowVolumes, TheNearPlaneTestSeesCastersBetweenTheEyeAndTheLight) {
    const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 1, 5), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));
    const auto near = shadow::near_rectangle(proj * view);
    const glm::vec4 light(0, 10, 5, 1);  // above the eye
    // A box on the segment from the eye to the light: the eye is in its shadow.
    EXPECT_TRUE(shadow::may_shadow_near_plane(near, light, scene::Bounds::around({-0.5f, 5, 4.5f}, {0.5f, 6, 5.5f})));
    // A box in front of the eye, off that segment: it shadows what the eye sees, not the eye.
    EXPECT_FALSE(shadow::may_shadow_near_plane(near, light, scene::Bounds::around({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f})));
    // A directional light from straight above: a box over the eye shadows it, one to the side does not.
    EXPECT_TRUE(shadow::may_shadow_near_plane(near, {0, 1, 0, 0}, scene::Bounds::around({-1, 20, 4}, {1, 21, 6})));
    EXPECT_FALSE(shadow::may_shadow_near_plane(near, {0, 1, 0, 0}, scene::Bounds::around({4, 20, 4}, {5, 21, 6})));
}

TEST(ShadowVolumes, TheFarPlaneMovesToInfinity) {
    glm::mat4 p = glm::perspective(glm::radians(60.0f), 1.5f, 0.5f, 20.0f);
    ASSERT_TRUE(shadow::infinite_far(p));
    const glm::vec4 near = p * glm::vec4(0, 0, -0.5f, 1);
    EXPECT_NEAR(near.z / near.w, -1.0f, 1e-5f);
    const glm::vec4 inf = p * glm::vec4(0.3f, 0.2f, -1.0f, 0.0f);  // a point at infinity ahead
    EXPECT_LT(inf.z / inf.w, 1.0f);
    EXPECT_GT(inf.z / inf.w, 0.9999f);
    glm::mat4 ortho = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);
    EXPECT_FALSE(shadow::infinite_far(ortho));
}

TEST(ShadowVolumes, CoveredPixelsCountsEveryLayerInsideTheView) {
    const glm::mat4 id(1.0f);
    // Two triangles covering the viewport in clip space, twice over: 2 x the pixels.
    const std::vector<glm::vec4> quad = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}};
    std::vector<glm::vec4> twice = quad;
    twice.insert(twice.end(), quad.begin(), quad.end());
    EXPECT_NEAR(shadow::covered_pixels(twice, id, 100, 50), 2.0 * 100 * 50, 1e-6);
    // A triangle four times the view's size is clipped to the view.
    const std::vector<glm::vec4> big = {{-3, -3, 0, 1}, {3, -3, 0, 1}, {0, 3, 0, 1}};
    EXPECT_NEAR(shadow::covered_pixels(big, id, 64, 64), 64.0 * 64.0, 1e-3);
    // Behind the eye: nothing.
    const std::vector<glm::vec4> behind = {{0, 0, 0, -1}, {1, 0, 0, -1}, {0, 1, 0, -1}};
    EXPECT_EQ(shadow::covered_pixels(behind, id, 64, 64), 0.0);
}

// ---- the plan ----------------------------------------------------------------------------------

using penumbra::testing::full_caps;

std::vector<std::string> pass_names(const render::FramePlan& p) {
    std::vector<std::string> n;
    for (const auto& pass : p.passes) n.push_back(pass.name);
    return n;
}

TEST(VolumesPlan, AmbientThenCountsThenLitWhereTheCountIsZero) {
    scene::CourseScene course = scene::make_course_scene(4);
    render::Settings s;
    s.technique = render::Technique::Volumes;
    const render::FramePlan p = render::plan(course.scene, s, full_caps(), render::offscreen(64, 64));
    // The teapot is open: its near caps are counted too (the camera pass culls its inside).
    EXPECT_EQ(pass_names(p), (std::vector<std::string>{"camera", "volumes-zpass", "volumes-zpass-caps", "volumes-lit"}));
    ASSERT_EQ(p.passes.size(), 4u);
    ASSERT_TRUE(render::volumes_of(p));
    EXPECT_EQ(render::volumes_of(p)->zfail_casters, 0);  // the scene's camera is outside every volume
    EXPECT_GT(render::volumes_of(p)->silhouette_edges, 0);
    EXPECT_GT(render::volumes_of(p)->fill_per_pixel, 0.0);
    const auto& cam = p.passes[0];
    ASSERT_TRUE(cam.clear && cam.clear->stencil);
    for (const auto& d : cam.draws) EXPECT_NE(d.variant.key().find("IN_SHADOW"), std::string::npos);
    EXPECT_FLOAT_EQ(p.camera.proj[2][2], 1.0f / 1048576.0f - 1.0f) << "the far plane is at infinity";
    const auto& zpass = p.passes[1];
    EXPECT_TRUE(zpass.state.stencil.two_sided);
    EXPECT_EQ(zpass.state.stencil.pass, gl::StencilOp::IncrWrap);
    EXPECT_EQ(zpass.state.stencil.back_pass, gl::StencilOp::DecrWrap);
    EXPECT_FALSE(zpass.state.color_write);
    EXPECT_FALSE(zpass.state.depth_write);
    EXPECT_EQ(zpass.state.cull, gl::Cull::None);
    for (const auto& d : zpass.draws) ASSERT_TRUE(d.triangles);
    EXPECT_GT(p.passes[2].state.offset_factor, 0.0f) << "caps are pushed back from the eye";
    const auto& lit = p.passes[3];
    EXPECT_EQ(lit.state.stencil.func, gl::Compare::Equal);
    EXPECT_EQ(lit.state.stencil.ref, 0);
    EXPECT_EQ(lit.state.depth_func, gl::Compare::LEqual);
    for (const auto& d : lit.draws) EXPECT_EQ(d.variant.key().find("IN_SHADOW"), std::string::npos);
    // The printed plan names the volumes' cost.
    EXPECT_NE(p.to_text().find("shadow volumes: "), std::string::npos);
    EXPECT_NE(p.to_json().find("\"volumes\":{\"zpass_casters\""), std::string::npos);
}

TEST(VolumesPlan, AutoTurnsToDepthFailWithTheEyeInAShadow) {
    scene::CourseScene course = scene::make_course_scene(4);
    ASSERT_TRUE(scene::place_eye_in_shadow(course.scene));
    render::Settings s;
    s.technique = render::Technique::Volumes;
    const render::FramePlan p = render::plan(course.scene, s, full_caps(), render::offscreen(64, 64));
    ASSERT_TRUE(render::volumes_of(p));
    EXPECT_GE(render::volumes_of(p)->zfail_casters, 1);
    EXPECT_TRUE(p.has_pass("volumes-zfail"));
    EXPECT_TRUE(p.has_pass("volumes-zfail-caps"));
    s.volume_method = render::VolumeMethod::ZPass;
    const render::FramePlan forced = render::plan(course.scene, s, full_caps(), render::offscreen(64, 64));
    EXPECT_EQ(render::volumes_of(forced)->zfail_casters, 0);
    EXPECT_FALSE(forced.has_pass("volumes-zfail"));
}

TEST(VolumesPlan, TheCountViewAndTheShownVolumes) {
    scene::CourseScene course = scene::make_course_scene(4);
    render::Settings s;
    s.technique = render::Technique::Volumes;
    s.aov = render::Aov::StencilCount;
    s.show_volumes = true;
    const render::FramePlan p = render::plan(course.scene, s, full_caps(), render::offscreen(64, 64));
    EXPECT_FALSE(p.has_pass("volumes-lit"));
    EXPECT_TRUE(p.has_pass("volumes-count-1"));
    EXPECT_TRUE(p.has_pass("volumes-count-negative"));
    ASSERT_TRUE(p.has_pass("volumes-show"));
    for (const auto& pass : p.passes)
        if (pass.name == "volumes-show") {
            EXPECT_EQ(pass.state.blend, gl::Blend::Alpha);
            ASSERT_EQ(pass.draws.size(), 2u);
            EXPECT_EQ(pass.draws[0].cull, gl::Cull::Front);
            EXPECT_EQ(pass.draws[1].cull, gl::Cull::Back);
        }
    render::Settings wrong;
    wrong.aov = render::Aov::StencilCount;
    EXPECT_EQ(render::check(course.scene, wrong, full_caps(), render::offscreen(64, 64)),
              "--aov stencil-count: needs --technique volumes");
    gl::Caps no_stencil = full_caps();
    no_stencil.packed_depth_stencil = false;
    EXPECT_NE(render::check(course.scene, s, no_stencil, render::offscreen(64, 64)), "");
}

}  // namespace
