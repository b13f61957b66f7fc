// PNG I/O: what is written reads back the same, channels are picked from RGBA, and a failure
// names the file and leaves nothing behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "measure/image_io.h"
#include "../test_paths.h"

using namespace penumbra::measure;
namespace fs = std::filesystem;

namespace {

fs::path out_dir() {
    const fs::path d = fs::path(penumbra::test::test_out_dir()) / "measure";
    fs::create_directories(d);
    return d;
}

TEST(ImageIo, WritesAndReadsBack) {
    for (int channels : {1, 3, 4}) {
        Pixels px{5, 3, channels, {}};
        for (int i = 0; i < 5 * 3 * channels; ++i) px.data.push_back(static_cast<std::uint8_t>(17 * i));
        const std::string path = (out_dir() / ("round_trip_" + std::to_string(channels) + ".png")).string();
        ASSERT_EQ(write_png(path, px), "");
        Pixels back;
        ASSERT_EQ(read_png(path, back), "");
        EXPECT_EQ(back.width, 5);
        EXPECT_EQ(back.height, 3);
        EXPECT_EQ(back.channels, channels);
        EXPECT_EQ(back.data, px.data);
    }
}

TEST(ImageIo, FromRgbaPicksChannels) {
    const std::vector<std::uint8_t> rgba = {1, 2, 3, 4, 5, 6, 7, 8};
    EXPECT_EQ(from_rgba(rgba, 2, 1, 1).data, (std::vector<std::uint8_t>{1, 5}));
    EXPECT_EQ(from_rgba(rgba, 2, 1, 3).data, (std::vector<std::uint8_t>{1, 2, 3, 5, 6, 7}));
}

TEST(ImageIo, FailuresNameTheFileAndLeaveNothing) {
    const fs::path missing = out_dir() / "no_such_folder" / "x.png";
    const std::string err = write_png(missing.string(), Pixels{1, 1, 1, {0}});
    EXPECT_NE(err.find(missing.string()), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(missing.parent_path()));
    Pixels px;
    EXPECT_NE(read_png((out_dir() / "not_there.png").string(), px), "");
}

}  // namespace
