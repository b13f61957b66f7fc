// Shadow volumes that cost what they draw: a plan keeps the previous plan's volume of a caster
// whose object, light and method did not change (the same triangles, the same pointer, so the
// renderer keeps them uploaded), extrudes again only what moved, and its statistics and printed
// plan are those of a plan made from nothing.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "full_caps.h"
#include "plan/plan.h"
#include "plan/techniques/reports.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

using penumbra::testing::full_caps;
using Triangles = std::shared_ptr<const std::vector<glm::vec4>>;

const render::FrameInputs kInputs = render::offscreen(64, 48);

// Each counting pass's draws' triangle lists, by pass and caster ("volumes-zpass teapot").
std::map<std::string, Triangles> volume_lists(const render::FramePlan& p) {
    std::map<std::string, Triangles> out;
    for (const auto& pass : p.passes)
        if (pass.module == "volumes")
            for (const auto& d : pass.draws)
                if (d.triangles) out[pass.name + " " + d.label] = d.triangles;
    return out;
}

// The printed plan without the line that says what was kept (the only line a kept plan adds).
std::string text_without_kept(const render::FramePlan& p) {
    std::string t = p.to_text();
    const auto at = t.find("shadow volumes kept from the previous frame");
    if (at != std::string::npos) t.erase(at, t.find('\n', at) + 1 - at);
    return t;
}

render::Settings volumes(bool show = false) {
    render::Settings s;
    s.technique = render::Technique::Volumes;
    s.show_volumes = show;
    // The table's volume too (the shadows fit leaves it out: it shadows nothing in view): two
    // casters, one still while the other moves.
    s.light_fit = render::LightFit::Tight;
    return s;
}

// What a plan made from nothing gives: the same passes, draws, triangles and statistics.
void expect_as_from_nothing(const scene::Scene& scene, const render::Settings& s, const render::FramePlan& kept) {
    const render::FramePlan fresh = render::plan(scene, s, full_caps(), kInputs);
    EXPECT_EQ(text_without_kept(kept), fresh.to_text());
    EXPECT_EQ(kept.to_json(), fresh.to_json());
    const auto a = volume_lists(kept), b = volume_lists(fresh);
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [name, list] : a) {
        ASSERT_TRUE(b.count(name)) << name;
        EXPECT_EQ(*list, *b.at(name)) << name;
    }
    const render::VolumeStats &x = *render::volumes_of(kept), &y = *render::volumes_of(fresh);
    EXPECT_EQ(x.fill, y.fill);  // exactly: the same sums in the same order
    EXPECT_EQ(x.fill_per_pixel, y.fill_per_pixel);
    EXPECT_EQ(x.triangles, y.triangles);
    EXPECT_EQ(x.silhouette_edges, y.silhouette_edges);
}

TEST(VolumeCache, AStillFrameKeepsEveryVolumeAndItsFill) {
    for (bool show : {false, true}) {
        scene::CourseScene course = scene::make_course_scene(4);
        scene::animate_course(course, 0.6, 0.6);
        const render::Settings s = volumes(show);
        const render::FramePlan first = render::plan(course.scene, s, full_caps(), kInputs);
        const render::VolumeStats& f = *render::volumes_of(first);
        EXPECT_EQ(f.kept, 0);
        ASSERT_GT(f.extruded, 0);
        EXPECT_EQ(first.to_text().find("kept from the previous frame"), std::string::npos) << "nothing to keep";
        const render::FramePlan second = render::plan(course.scene, s, full_caps(), kInputs, &first);
        const render::VolumeStats& v = *render::volumes_of(second);
        EXPECT_EQ(v.kept, f.extruded);
        EXPECT_EQ(v.extruded, 0);
        EXPECT_EQ(v.fill_kept, f.extruded) << "neither the volumes nor the camera changed";
        const auto a = volume_lists(first), b = volume_lists(second);
        ASSERT_FALSE(a.empty());
        EXPECT_EQ(a.count("volumes-show the volumes' front faces"), show ? 1u : 0u);
        for (const auto& [name, list] : b) EXPECT_EQ(list, a.at(name)) << name << ": the same list, not a copy";
        EXPECT_NE(second.to_text().find("shadow volumes kept from the previous frame: " + std::to_string(v.kept) + " of " +
                                        std::to_string(v.kept)),
                  std::string::npos);
        expect_as_from_nothing(course.scene, s, second);
    }
}

TEST(VolumeCache, AMovedCasterIsExtrudedAgainAndTheStillOneKept) {
    scene::CourseScene course = scene::make_course_scene(4);
    scene::animate_course(course, 0.6, 0.6);
    const render::Settings s = volumes();
    const render::FramePlan first = render::plan(course.scene, s, full_caps(), kInputs);
    // The teapot jumps; the light and the table stay.
    scene::animate_course(course, 0.6, 0.65);
    const render::FramePlan second = render::plan(course.scene, s, full_caps(), kInputs, &first);
    const std::string teapot = course.scene.objects[static_cast<size_t>(course.teapot)].name;
    const auto a = volume_lists(first), b = volume_lists(second);
    int moved = 0, still = 0;
    for (const auto& [name, list] : b) {
        ASSERT_TRUE(a.count(name)) << name;
        const bool is_teapot = name.size() > teapot.size() && name.compare(name.size() - teapot.size(), teapot.size(), teapot) == 0;
        if (is_teapot) {
            EXPECT_NE(list, a.at(name)) << name << ": the teapot moved";
            EXPECT_NE(*list, *a.at(name)) << name;
            ++moved;
        } else {
            EXPECT_EQ(list, a.at(name)) << name << ": it did not move";
            ++still;
        }
    }
    EXPECT_GT(moved, 0);
    EXPECT_GT(still, 0) << "the table's volume";
    const render::VolumeStats& v = *render::volumes_of(second);
    EXPECT_EQ(v.extruded, 1);
    EXPECT_EQ(v.kept, render::volumes_of(first)->extruded - 1);
    expect_as_from_nothing(course.scene, s, second);
}

TEST(VolumeCache, AMovedLightExtrudesEveryVolume) {
    scene::CourseScene course = scene::make_course_scene(4);
    scene::animate_course(course, 0.6, 0.6);
    const render::Settings s = volumes();
    const render::FramePlan first = render::plan(course.scene, s, full_caps(), kInputs);
    scene::animate_course(course, 0.62, 0.6);
    const render::FramePlan second = render::plan(course.scene, s, full_caps(), kInputs, &first);
    const render::VolumeStats& v = *render::volumes_of(second);
    EXPECT_EQ(v.kept, 0);
    EXPECT_EQ(v.fill_kept, 0);
    for (const auto& [name, list] : volume_lists(second)) EXPECT_NE(list, volume_lists(first).at(name)) << name;
    expect_as_from_nothing(course.scene, s, second);
}

TEST(VolumeCache, AMovedCameraKeepsTheVolumesButCountsTheirFillAgain) {
    scene::CourseScene course = scene::make_course_scene(4);
    scene::animate_course(course, 0.6, 0.6);
    const render::Settings s = volumes();
    const render::FramePlan first = render::plan(course.scene, s, full_caps(), kInputs);
    // A step sideways: the eye stays out of every shadow, so each caster keeps depth-pass.
    course.scene.camera.view = glm::translate(course.scene.camera.view, glm::vec3(0.05f, 0.0f, 0.0f));
    const render::FramePlan second = render::plan(course.scene, s, full_caps(), kInputs, &first);
    const render::VolumeStats& v = *render::volumes_of(second);
    EXPECT_EQ(v.kept, render::volumes_of(first)->extruded);
    EXPECT_EQ(v.fill_kept, 0);
    EXPECT_NE(v.fill, render::volumes_of(first)->fill);
    expect_as_from_nothing(course.scene, s, second);
}

TEST(VolumeCache, ADifferentMethodIsADifferentVolume) {
    scene::CourseScene course = scene::make_course_scene(4);
    scene::animate_course(course, 0.6, 0.6);
    render::Settings s = volumes();
    const render::FramePlan first = render::plan(course.scene, s, full_caps(), kInputs);
    s.volume_method = render::VolumeMethod::ZFail;  // caps and far caps: other triangles
    const render::FramePlan second = render::plan(course.scene, s, full_caps(), kInputs, &first);
    EXPECT_EQ(render::volumes_of(second)->kept, 0);
    expect_as_from_nothing(course.scene, s, second);
    // And back: depth-pass's volumes are no longer in the previous plan (the z-fail one).
    s.volume_method = render::VolumeMethod::Auto;
    const render::FramePlan third = render::plan(course.scene, s, full_caps(), kInputs, &second);
    EXPECT_EQ(render::volumes_of(third)->kept, 0);
    expect_as_from_nothing(course.scene, s, third);
}

TEST(VolumeCache, LightSamplesPlanAsFromNothing) {
    // Heckbert-Herf over volumes: a volume per caster and light sample in one plan (the samples
    // take no previous plan; a still frame adds no samples at all), after a moved frame.
    scene::CourseScene course = scene::make_course_scene(4);
    scene::animate_course(course, 0.6, 0.6);
    render::Settings s = volumes();
    s.light_radius = 0.3f;
    s.area_samples = 4;
    const render::FramePlan first = render::plan(course.scene, s, full_caps(), kInputs);
    size_t lists = 0;
    for (const auto& pass : first.passes)
        for (const auto& d : pass.draws) lists += d.triangles ? 1u : 0u;
    EXPECT_GT(lists, 8u) << "every sample's volumes";
    scene::animate_course(course, 0.62, 0.62);
    const render::FramePlan second = render::plan(course.scene, s, full_caps(), kInputs, &first);
    ASSERT_TRUE(render::volumes_of(second));
    EXPECT_EQ(render::volumes_of(second)->kept, 0);
    expect_as_from_nothing(course.scene, s, second);
}

}  // namespace
