// budget-ms in the exercises (the desktop's and the pages' app, examples/exercises.h): an option the
// URL keeps, shown by W09P2c's control, refused where the exercise's technique has no map.
#include <gtest/gtest.h>

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
