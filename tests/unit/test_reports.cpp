// The plan's reports (plan/plan.h: FramePlan::reports) and the questions the core asks a technique
// module (plan/techniques/technique.h): the plan holds no technique's results as fields, and
// nothing outside the modules branches on which technique it is (tests/layering.sh checks the
// source; these check the behaviour).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "full_caps.h"
#include "plan/frames/area_light.h"
#include "plan/plan.h"
#include "plan/techniques/reports.h"
#include "plan/techniques/technique.h"
#include "scenes/course_scene.h"

using namespace penumbra;

namespace {

using penumbra::testing::full_caps;

// A report of a key the registry does not list (a new module's).
struct ProbeReport {
    static constexpr const char* kKey = "probe";
    int value = 0;
    static std::string text(const ProbeReport& r) { return "probe: " + std::to_string(r.value) + "\n"; }
    static std::string json(const ProbeReport& r) { return "{\"value\":" + std::to_string(r.value) + "}"; }
};

render::FramePlan plan_with(render::Technique t) {
    scene::CourseScene course = scene::make_course_scene(4);
    scene::animate_course(course, 0.6, 0.6);
    render::Settings s;
    s.technique = t;
    return render::plan(course.scene, s, full_caps(), render::offscreen(64, 64));
}

}  // namespace

TEST(Reports, EveryRegisteredKeyIsInTheJsonAndAnUnreportedOneIsItsAbsentValue) {
    const render::FramePlan planar = plan_with(render::technique_named("planar"));
    EXPECT_EQ(render::light_frustum_of(planar), nullptr);
    const nlohmann::json j = nlohmann::json::parse(planar.to_json());
    for (const render::ReportSlot& slot : render::report_slots())
        ASSERT_TRUE(j.contains(std::string(slot.key))) << slot.key;
    EXPECT_TRUE(j["light_frustum"].is_null());
    EXPECT_TRUE(j["volumes"].is_null());
    EXPECT_EQ(j["cascades"], nlohmann::json::parse("{\"why\":\"\",\"list\":[]}"));
    // Control: the shadow map reports its frustum, so the key is no longer null.
    const render::FramePlan map = plan_with(render::technique_named("shadowmap"));
    ASSERT_NE(render::light_frustum_of(map), nullptr);
    EXPECT_TRUE(nlohmann::json::parse(map.to_json())["light_frustum"].is_object());
    EXPECT_NE(map.to_text().find("light: perspective frustum"), std::string::npos);
}

TEST(Reports, AKeyOutsideTheRegistryFollowsItsSlotsAndPutReplacesDropRemoves) {
    render::FramePlan p = plan_with(render::technique_named("none"));
    p.put(ProbeReport{3});
    p.put(ProbeReport{7});  // replaces
    ASSERT_NE(p.find<ProbeReport>(), nullptr);
    EXPECT_EQ(p.find<ProbeReport>()->value, 7);
    EXPECT_EQ(p.reports.size(), 1u);
    const std::string j = p.to_json();
    const size_t area = j.find("\"area\":"), probe = j.find("\"probe\":{\"value\":7}"), bits = j.find("\"stencil_bits\":");
    ASSERT_NE(probe, std::string::npos);
    EXPECT_LT(area, probe);
    EXPECT_LT(probe, bits);
    EXPECT_NE(p.to_text().find("probe: 7\n"), std::string::npos);
    p.drop(ProbeReport::kKey);
    EXPECT_EQ(p.find<ProbeReport>(), nullptr);
    EXPECT_EQ(p.to_json().find("\"probe\""), std::string::npos);
}

TEST(Reports, APreviousPlansReportIsWhatTheNextFrameReads) {
    // The light samples' progress crosses frames through the previous plan's report only.
    const scene::CourseScene course = scene::make_course_scene(4);
    render::Settings s;
    s.area_samples = 8;
    s.area_per_frame = 3;
    s.light_radius = 0.3f;
    const render::FrameInputs in = render::offscreen(32, 32);
    const render::FramePlan a = render::plan(course.scene, s, full_caps(), in);
    const render::FramePlan b = render::plan(course.scene, s, full_caps(), in, &a);
    ASSERT_NE(render::area_of(a), nullptr);
    ASSERT_NE(render::area_of(b), nullptr);
    EXPECT_EQ(render::area_of(a)->done, 3);
    EXPECT_EQ(render::area_of(b)->done, 6);
    // Control: without the previous plan the sum starts again.
    EXPECT_EQ(render::area_of(render::plan(course.scene, s, full_caps(), in))->done, 3);
}

TEST(TechniqueQuestions, TheAnswersTheCoreBranchesOn) {
    using render::Aov;
    const auto& m = [](const char* name) -> const render::Module& {
        return render::technique_module(render::technique_named(name));
    };
    EXPECT_FALSE(m("none").shadows());
    EXPECT_TRUE(m("shadowmap").shadows());
    EXPECT_FALSE(m("gooch").soft_by_itself().empty());
    EXPECT_TRUE(m("planar").soft_by_itself().empty());
    EXPECT_FALSE(m("volumes").later_pass_problem().empty());
    EXPECT_TRUE(m("shadowmap").depth_map());
    EXPECT_FALSE(m("gooch").depth_map());
    EXPECT_EQ(render::aov_problem(render::technique_named("planar"), Aov::LightDepth),
              "--aov light-depth: needs --technique shadowmap");
    EXPECT_EQ(render::aov_problem(render::technique_named("shadowmap"), Aov::StencilCount),
              "--aov stencil-count: needs --technique volumes");
    EXPECT_EQ(render::aov_problem(render::technique_named("volumes"), Aov::StencilCount), "");
    EXPECT_EQ(render::aov_problem(render::technique_named("gooch"), Aov::Visibility), "");
    EXPECT_EQ(render::techniques_that(&render::Module::shades_deferred), "--technique shadowmap or none");
}

TEST(TechniqueQuestions, TechniqueNamedIsTheInverseOfItsName) {
    for (render::Technique t : render::kAllTechniques) EXPECT_EQ(render::technique_named(render::to_string(t)), t);
    EXPECT_THROW(render::technique_named("shadowmaps"), std::invalid_argument);
}
