// budget-ms and max-error in the exercises (the desktop's and the pages' app, examples/exercises.h):
// options the URL keeps, shown by W09P2c's controls, one at a time, refused where the exercise's
// technique has no map; and max-error's choice among the rungs (render/error_target.h).
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "exercises.h"

using penumbra::examples::CourseApp;

TEST(ExerciseOptions, TheBudgetIsAnOptionTheQueryKeeps) {
    // W09P2c shows a control for it: the query always says it (off: 0).
    CourseApp a("w09p2c");
    EXPECT_NE(a.query().find("budget-ms=0&"), std::string::npos) << a.query();
    ASSERT_EQ(a.set_option("budget-ms", "8"), "");
    EXPECT_NE(a.query().find("budget-ms=8&"), std::string::npos) << a.query();
    EXPECT_EQ(a.budget(), nullptr);  // made at the first frame on a context (its caps)
    EXPECT_EQ(a.set_option("budget-ms", "-1").rfind("budget-ms: ", 0), 0u) << a.set_option("budget-ms", "-1");
    EXPECT_NE(a.query().find("budget-ms=8&"), std::string::npos) << "a bad value changes nothing: " << a.query();
    ASSERT_EQ(a.set_option("budget-ms", "0"), "");
    EXPECT_NE(a.query().find("budget-ms=0&"), std::string::npos) << a.query();
    // Elsewhere (no control) it is kept in the query while on, as another setting changed.
    CourseApp c("cascades");
    EXPECT_EQ(c.query().find("budget-ms"), std::string::npos) << c.query();
    ASSERT_EQ(c.set_option("budget-ms", "16"), "");
    EXPECT_NE(c.query().find("budget-ms=16"), std::string::npos) << c.query();
    // Shadow volumes have no map for it to choose.
    CourseApp v("volumes");
    EXPECT_NE(v.set_option("budget-ms", "8").find("--technique volumes has none"), std::string::npos) << v.set_option("budget-ms", "8");
    EXPECT_EQ(v.query().find("budget-ms"), std::string::npos) << v.query();
}

TEST(ExerciseOptions, TheErrorTargetIsAnOptionTheQueryKeepsOneOfItAndTheBudget) {
    CourseApp a("w09p2c");
    EXPECT_NE(a.query().find("max-error=0&"), std::string::npos) << a.query();  // W09P2c's control
    ASSERT_EQ(a.set_option("max-error", "0.1"), "");
    EXPECT_NE(a.query().find("max-error=0.1&"), std::string::npos) << a.query();
    EXPECT_EQ(a.error_choice(), nullptr);  // made after the first frame on a context
    EXPECT_EQ(a.set_option("max-error", "101").rfind("max-error: ", 0), 0u) << a.set_option("max-error", "101");
    EXPECT_NE(a.query().find("max-error=0.1&"), std::string::npos) << "a bad value changes nothing: " << a.query();
    // One control at a time: the budget turns the target off and says so, and the other way.
    ASSERT_EQ(a.set_option("budget-ms", "8"), "");
    EXPECT_NE(a.note().find("max-error off"), std::string::npos) << a.note();
    EXPECT_NE(a.query().find("max-error=0&"), std::string::npos) << a.query();
    EXPECT_NE(a.query().find("budget-ms=8&"), std::string::npos) << a.query();
    ASSERT_EQ(a.set_option("max-error", "0.05"), "");
    EXPECT_NE(a.note().find("budget-ms off"), std::string::npos) << a.note();
    EXPECT_NE(a.query().find("budget-ms=0&"), std::string::npos) << a.query();
    EXPECT_NE(a.query().find("max-error=0.05&"), std::string::npos) << a.query();
    // Off, nothing else changes; the control: off with the budget off says nothing.
    ASSERT_EQ(a.set_option("max-error", "0"), "");
    EXPECT_EQ(a.note(), "");
    // Elsewhere (no control) it is kept in the query while on (the cascades' frame then says why
    // it cannot be predicted: their maps keep their size).
    CourseApp c("cascades");
    EXPECT_EQ(c.query().find("max-error"), std::string::npos) << c.query();
    ASSERT_EQ(c.set_option("max-error", "0.2"), "");
    EXPECT_NE(c.query().find("max-error=0.2"), std::string::npos) << c.query();
    // Shadow volumes have no map for it to choose.
    CourseApp v("volumes");
    EXPECT_NE(v.set_option("max-error", "0.1").find("--technique volumes has none"), std::string::npos)
        << v.set_option("max-error", "0.1");
    EXPECT_EQ(v.query().find("max-error"), std::string::npos) << v.query();
}

namespace {

// A ladder's rungs as render::choose_for_error leaves them, cheapest first: maps of 128 .. 2048,
// each predicted less than the one before.
penumbra::render::ErrorChoice ladder(std::initializer_list<double> predicted) {
    penumbra::render::ErrorChoice c;
    int map = 128, k = 0;
    for (double p : predicted) {
        penumbra::render::ErrorRung g;
        g.settings.encoding = penumbra::shadow::Encoding::DepthTex;
        g.rung = k++;
        g.map = map;
        g.predicted_pct = p;
        g.cost = static_cast<double>(map);
        c.rungs.push_back(g);
        map *= 2;
    }
    return c;
}

}  // namespace

TEST(ErrorTarget, TheCheapestRungPredictedWithinIsChosenElseTheMostAccurate) {
    auto c = ladder({0.30, 0.15, 0.09, 0.05, 0.03});
    penumbra::render::pick_rung(c, 0.1);
    EXPECT_EQ(c.rung().map, 512);
    EXPECT_NE(c.why.find("max-error 0.100 %: depthtex hard 512, predicted 0.090 %"), std::string::npos) << c.why;
    EXPECT_NE(c.why.find("the next cheaper, depthtex hard 256, is predicted 0.150 %"), std::string::npos) << c.why;
    penumbra::render::pick_rung(c, 0.01);
    EXPECT_EQ(c.rung().map, 2048);
    EXPECT_NE(c.why.find("nothing is predicted within it"), std::string::npos) << c.why;
    penumbra::render::pick_rung(c, 1.0);
    EXPECT_EQ(c.rung().map, 128);
    EXPECT_NE(c.why.find("the cheapest setting"), std::string::npos) << c.why;
}

TEST(ErrorTarget, ARungInUseIsLeftForACheaperOneOnlyWellWithinTheTarget) {
    // 1024 in use, still within 0.1 %; 512 is within too (0.09) but not within 0.8 x: kept.
    auto c = ladder({0.30, 0.15, 0.09, 0.05, 0.03});
    penumbra::render::pick_rung(c, 0.1);
    ASSERT_TRUE(penumbra::render::keep_rung(c, 3, 0.1, 0.8));
    EXPECT_EQ(c.rung().map, 1024);
    EXPECT_NE(c.why.find("kept depthtex hard 1024, predicted 0.050 %; the cheaper depthtex hard 512, predicted 0.090 %"),
              std::string::npos) << c.why;
    // The control: 512 well within (0.07 <= 0.08) is taken.
    auto d = ladder({0.30, 0.15, 0.07, 0.05, 0.03});
    penumbra::render::pick_rung(d, 0.1);
    EXPECT_FALSE(penumbra::render::keep_rung(d, 3, 0.1, 0.8));
    EXPECT_EQ(d.rung().map, 512);
    // The rung in use over the target is left upwards at once.
    auto e = ladder({0.30, 0.15, 0.09, 0.05, 0.03});
    penumbra::render::pick_rung(e, 0.1);
    EXPECT_FALSE(penumbra::render::keep_rung(e, 1, 0.1, 0.8));
    EXPECT_EQ(e.rung().map, 512);
    // Nor a rung the ladder lacks (a ladder made again on another context).
    EXPECT_FALSE(penumbra::render::keep_rung(e, 9, 0.1, 0.8));
}
