// examples/file_watch.h: the desktop app's --snippets reload sees a saved file once, and not
// between saves or sooner than its period.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "../../examples/file_watch.h"

using penumbra::examples::FileWatch;

TEST(FileWatch, SeesEachSaveOnceAndNothingBetween) {
    const auto path = std::filesystem::temp_directory_path() / "penumbra_file_watch_test.glsl";
    std::filesystem::remove(path);
    { std::ofstream(path) << "float a;\n"; }
    FileWatch w(path.string(), 0.25);
    EXPECT_FALSE(w.changed(0.0));  // unchanged since made
    { std::ofstream(path) << "float a; float b;\n"; }  // another size: seen even within the same tick
    EXPECT_FALSE(w.changed(0.1));  // sooner than the period: not looked at
    EXPECT_TRUE(w.changed(0.3));
    EXPECT_FALSE(w.changed(0.6));  // once
    std::filesystem::remove(path);
    EXPECT_TRUE(w.changed(0.9));   // gone
    { std::ofstream(path) << "x"; }
    EXPECT_TRUE(w.changed(1.2));   // back
    EXPECT_FALSE(w.changed(1.5));
    std::filesystem::remove(path);
}
