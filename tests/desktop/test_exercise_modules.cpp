// What a browser page's module links (examples/exercise_registry.cpp, plan/techniques/techniques.cpp,
// plan/frames/forward.cpp): each exercise names the technique and effect modules and the frame
// shapes its frames can use, checked here against what its frame, controls and defaults reach;
// natively every one is linked. And the fixed list of the options held only where offered.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>

#include "exercises.h"
#include "plan/frames/frame.h"
#include "plan/techniques/technique.h"
#include "scene/eye.h"
#include "scenes/course_scene.h"
#include "scenes/portal_scene.h"
#include "../unit/full_caps.h"

using penumbra::examples::CourseApp;
using penumbra::examples::Exercise;
using penumbra::examples::exercise_list;

namespace {

// The values of a technique option an exercise's frames can be drawn with: its frame's, else every
// value its control offers (all of the option's where the control lists none), else its default.
std::vector<std::string> values_reached(const Exercise& x, std::string_view option) {
    using namespace penumbra;
    for (const auto& [name, value] : x.frame)
        if (name == option) return {std::string(value)};
    for (const auto& c : x.controls) {
        if (c.option != option) continue;
        std::vector<std::string> out(c.values.begin(), c.values.end());
        const render::OptionInfo& info = render::option_info(option);
        if (out.empty())
            for (const auto& ch : info.choices.empty() ? info.presets : info.choices) out.emplace_back(ch.value);
        return out;
    }
    for (const auto& [name, value] : x.defaults)
        if (name == option) return {std::string(value)};
    return {CourseApp(x.name).value_of(option)};
}

// What the exercise's modules and frame shapes (Exercise::modules, frames) leave out of what its
// frames can use: "" or a list.
std::string modules_missing(const Exercise& x) {
    using namespace penumbra;
    const auto has = [&](const render::Module& m) {
        return std::any_of(x.modules.begin(), x.modules.end(), [&](auto get) { return &get() == &m; });
    };
    const auto has_shape = [&](const render::FrameShape& f) {
        return std::any_of(x.frames.begin(), x.frames.end(), [&](auto get) { return &get() == &f; });
    };
    std::string missing;
    for (const std::string& v : values_reached(x, "shading"))
        if (v == "deferred" && !has_shape(render::deferred_shape())) missing += " shading=" + v;
    for (const std::string& v : values_reached(x, "post")) {
        if (v.find("shadow-blur") != std::string::npos && !has_shape(render::shadow_blur_shape())) missing += " post=" + v;
        if ((v.find("blur:") == 0 || v.find(",blur") != std::string::npos || v.find("bloom") != std::string::npos) &&
            !has_shape(render::image_post_shape()))
            missing += " post=" + v;
    }
    for (const std::string& v : values_reached(x, "area-samples"))
        if (std::stoi(v) > 1 && !has_shape(render::area_light_shape())) missing += " area-samples=" + v;
    if (examples::offers(x, "reference") && !has_shape(render::area_light_shape())) missing += " reference=on";
    for (const std::string& v : values_reached(x, "technique")) {
        render::Settings s;
        if (!render::parse_option(s, "technique", v).empty()) {
            missing += " (not a technique: " + v + ")";
            continue;
        }
        const render::Module& m = render::technique_module(s.technique);
        if (&m != &render::unshadowed_module() && !has(m)) missing += " technique=" + v;
    }
    for (const std::string& v : values_reached(x, "effects")) {
        render::Settings s;
        if (!render::parse_option(s, "effects", v).empty()) continue;  // "none"
        for (render::Effect e : s.effects)
            if (!has(render::effect_module(e))) missing += " effects=" + std::string(render::to_string(e));
    }
    return missing;
}

// The layouts beside one map ("cascades", "cube") that the course scene's frames take with
// --cascades auto and `effects` over 20 s of its animation (the light's circle, the teapot's
// jumps; a course exercise's camera does not fly), a layout's passes being named "... cascade K"
// and "... face F". `light_at`: the light put there in every frame instead.
std::set<std::string> course_layouts(std::string_view effects, std::optional<glm::vec3> light_at = std::nullopt) {
    using namespace penumbra;
    scene::CourseScene course = scene::make_course_scene(4, true, false);
    render::Settings s;
    EXPECT_EQ(render::parse_option(s, "technique", "shadowmap"), "");
    EXPECT_EQ(render::parse_option(s, "effects", effects), "");
    std::set<std::string> out;
    for (int k = 0; k <= 80; ++k) {
        scene::animate_course(course, 0.25 * k, 0.25 * k);
        if (light_at) course.scene.light.position = *light_at;
        const render::FramePlan p = render::plan(course.scene, s, penumbra::testing::full_caps(), render::offscreen(512, 512));
        for (const render::Pass& pass : p.passes) {
            if (pass.name.find(" cascade ") != std::string::npos) out.insert("cascades");
            if (pass.name.find(" face ") != std::string::npos) out.insert("cube");
        }
    }
    return out;
}

// What the exercise's layouts (Exercise::layouts) leave out of what its frames can take: "" or a
// list. With the shadow map among its techniques: a cube where its cascades control offers
// "cube", cascades where it offers 2 to 4; with auto, the layout of its own scene's light
// (directional: cascades, else a cube: its camera flies anywhere) or what the course scene's
// frames take with each of its effects.
std::string layouts_missing(const Exercise& x) {
    using namespace penumbra;
    const std::vector<std::string> techniques = values_reached(x, "technique");
    if (std::find(techniques.begin(), techniques.end(), "shadowmap") == techniques.end()) return {};
    std::set<std::string> want;
    for (const std::string& v : values_reached(x, "cascades")) {
        if (v == "cube") want.insert("cube");
        if (v == "2" || v == "3" || v == "4") want.insert("cascades");
        if (v != "auto") continue;
        if (flies(x)) {
            want.insert(x.make_scene().light.type == scene::LightType::Directional ? "cascades" : "cube");
            continue;
        }
        for (const std::string& e : values_reached(x, "effects"))
            for (const std::string& l : course_layouts(e)) want.insert(l);
    }
    const auto has = [&](const render::MapLayout& l) {
        return std::any_of(x.layouts.begin(), x.layouts.end(), [&](auto get) { return &get() == &l; });
    };
    std::string missing;
    if (want.count("cascades") && !has(render::cascades_layout())) missing += " cascades";
    if (want.count("cube") && !has(render::cube_layout())) missing += " cube";
    return missing;
}

}  // namespace

// A browser page links the shadow map's cascades and cube only where its exercise names them: the
// layouts its frames can take (the course scene's point light stays above the table and outside
// it, the portal's lawn spans less than one cascade's depth ratio, so those frames take one map).
// The controls: the bulb without its cube, the cascades exercise without its cascades, and the
// course scene's light put inside it (a cube), which the sweep must see.
TEST(ExerciseList, EachExerciseNamesTheMapLayoutsItsFramesTake) {
    using namespace penumbra;
    for (const auto& x : exercise_list()) EXPECT_EQ(layouts_missing(x), "") << x.name;
    Exercise bulb = *examples::find_exercise("bulb");
    bulb.layouts.clear();
    EXPECT_EQ(layouts_missing(bulb), " cube");
    Exercise cascades = *examples::find_exercise("cascades");
    cascades.layouts.clear();
    EXPECT_EQ(layouts_missing(cascades), " cascades");
    EXPECT_EQ(course_layouts("none", glm::vec3(0.0f, 0.3f, 0.0f)), std::set<std::string>{"cube"});
    EXPECT_TRUE(render::map_layout_linked("cascades") && render::map_layout_linked("cube"));  // natively, all
    // The shader lab's splice: named by the exercise whose page has the lab's panel.
    for (const auto& x : exercise_list()) EXPECT_EQ(x.lab != nullptr, x.name == "w09p2c") << x.name;
}

// budget-ms and max-error's code: named by the exercises that offer either control, and by no
// other (a page links it only where named). W09P2c offers them, so the rule is not empty.
TEST(ExerciseList, TheExercisesThatOfferTheBudgetOrTheErrorTargetNameTheirCode) {
    using namespace penumbra::examples;
    const auto offers_trade = [](const Exercise& x) { return offers(x, "budget-ms") || offers(x, "max-error"); };
    for (const auto& x : exercise_list()) EXPECT_EQ(x.trade != nullptr, offers_trade(x)) << x.name;
    const Exercise& w09p2c = *find_exercise("w09p2c");
    EXPECT_TRUE(offers(w09p2c, "budget-ms") && offers(w09p2c, "max-error"));
    EXPECT_TRUE(w09p2c.trade == &course_trade);
}

// The portal's scene and the eye moved into a shadow: named by the exercises whose frames take the
// portal effect (the portal module) and that offer `eye`, and by no other. The stencil exercise
// and volumes have them, so neither rule is empty.
TEST(ExerciseList, ThePortalAndTheEyeInShadowAreNamedWhereOffered) {
    using namespace penumbra;
    using namespace penumbra::examples;
    for (const auto& x : exercise_list()) {
        const bool portal = std::find(x.modules.begin(), x.modules.end(), &render::portal_module) != x.modules.end();
        EXPECT_EQ(x.portal != nullptr, portal) << x.name;
        EXPECT_EQ(x.eye_in_shadow != nullptr, offers(x, "eye")) << x.name;
    }
    EXPECT_TRUE(find_exercise("stencil")->portal == &scene::make_course_portal);
    EXPECT_TRUE(find_exercise("volumes")->eye_in_shadow == &scene::place_eye_in_shadow);
}

// A browser page links only the technique and effect modules and the frame shapes its exercise
// names: they cover every technique, effect and shape its frame, its controls and its defaults
// reach (the controls: the stencil exercise without its mirror, soft without Gooch or the light
// samples' average, multipass without the deferred frame).
TEST(ExerciseList, EachExerciseNamesTheModulesItsFramesUse) {
    using namespace penumbra;
    for (const auto& x : exercise_list()) EXPECT_EQ(modules_missing(x), "") << x.name;
    Exercise control = *examples::find_exercise("stencil");
    control.modules.erase(std::remove_if(control.modules.begin(), control.modules.end(),
                                         [](auto get) { return &get() == &render::mirror_module(); }),
                          control.modules.end());
    EXPECT_EQ(modules_missing(control), " effects=mirror effects=mirror effects=mirror");
    Exercise soft = *examples::find_exercise("soft");
    soft.modules.pop_back();
    EXPECT_NE(modules_missing(soft), "");
    soft = *examples::find_exercise("soft");
    soft.frames.clear();
    EXPECT_EQ(modules_missing(soft), " area-samples=4 area-samples=16 area-samples=64 area-samples=256 reference=on");
    Exercise multipass = *examples::find_exercise("multipass");
    multipass.frames.erase(multipass.frames.begin());
    EXPECT_EQ(modules_missing(multipass), " shading=deferred");
    multipass.frames.pop_back();
    EXPECT_EQ(modules_missing(multipass), " shading=deferred post=blur:4 post=bloom:0.6 post=shadow-blur:6,bloom:0.6");
    // Every native program has every module and every shape.
    for (const char* shape : {"deferred", "area light", "shadow blur", "image post"})
        EXPECT_TRUE(render::frame_shape_linked(shape));
    for (render::Technique t : render::kAllTechniques) EXPECT_TRUE(render::technique_linked(t));
    for (render::Effect e : render::kAllEffects) EXPECT_TRUE(render::effect_linked(e));
    render::Settings s;
    s.technique = render::Technique::Volumes;
    s.effects = {render::Effect::Portal};
    EXPECT_EQ(render::unlinked_problem(s, "technique"), "");
    EXPECT_EQ(render::unlinked_problem(s, "effects"), "");
    s.area_samples = 16;
    EXPECT_EQ(render::unlinked_problem(s, "area-samples"), "");
}

// Whether an option is held only where offered is a fixed list (a page has one exercise): it is
// the options some exercise's control holds here_only().
TEST(ExerciseList, TheHereOnlyListIsTheExercisesHereOnlyControls) {
    using namespace penumbra;
    std::vector<std::string_view> held;
    for (const auto& x : exercise_list())
        for (const auto& c : x.controls)
            if (c.here_only && std::find(held.begin(), held.end(), c.option) == held.end()) held.push_back(c.option);
    std::vector<std::string_view> listed = examples::here_only_options();
    std::sort(held.begin(), held.end());
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(held, listed);
    EXPECT_FALSE(examples::held_here_only("map-size"));
    EXPECT_TRUE(examples::held_here_only("post"));
}
