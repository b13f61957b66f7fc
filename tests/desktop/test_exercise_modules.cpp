// What a browser page's module links (examples/exercise_registry.cpp, plan/techniques/techniques.cpp,
// plan/frames/forward.cpp): each exercise names the technique and effect modules and the frame
// shapes its frames can use, checked here against what its frame, controls and defaults reach;
// natively every one is linked. And the fixed list of the options held only where offered.
#include <gtest/gtest.h>

#include <algorithm>

#include "exercises.h"
#include "plan/frames/frame.h"
#include "plan/techniques/technique.h"

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

}  // namespace

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
