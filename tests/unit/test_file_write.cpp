// scene::write_file, the writer under every file the command line writes: whole or not at all, every
// failure one line with the path and the system's reason, no temporary file left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "scene/file_write.h"

using penumbra::scene::write_file;
namespace fs = std::filesystem;

namespace {

class FileWrite : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("penumbra_file_write_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    static std::string read(const std::string& p) {
        std::ifstream f(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    }
    // Everything in the folder, for "nothing else was written".
    size_t entries() const { return static_cast<size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }

    fs::path dir_;
};

TEST_F(FileWrite, WritesAndReplacesWhole) {
    const std::string p = path("a.txt");
    ASSERT_EQ(write_file(p, "first"), "");
    EXPECT_EQ(read(p), "first");
    ASSERT_EQ(write_file(p, "second, longer"), "");
    EXPECT_EQ(read(p), "second, longer");
    ASSERT_EQ(write_file(p, ""), "");
    EXPECT_EQ(read(p), "");
    EXPECT_EQ(entries(), 1u);  // no temporary left
}

TEST_F(FileWrite, KeepsTheReplacedFilesPermissions) {
    const std::string p = path("script.sh");
    ASSERT_EQ(write_file(p, "#!/bin/sh\n"), "");
    fs::permissions(p, fs::perms::owner_all | fs::perms::group_read, fs::perm_options::replace);
    ASSERT_EQ(write_file(p, "#!/bin/sh\ntrue\n"), "");
    EXPECT_EQ(fs::status(p).permissions(), fs::perms::owner_all | fs::perms::group_read);
}

TEST_F(FileWrite, ALinkStaysALinkToTheFileItNames) {
    const std::string target = path("target.txt"), link = path("link.txt");
    ASSERT_EQ(write_file(target, "old"), "");
    fs::create_symlink("target.txt", link);
    ASSERT_EQ(write_file(link, "new"), "");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(read(target), "new");
    EXPECT_EQ(entries(), 2u);
}

TEST_F(FileWrite, AFullDiskIsAnErrorAndLeavesTheLink) {
    const std::string link = path("full.png");
    fs::create_symlink("/dev/full", link);
    const std::string err = write_file(link, std::string(100000, 'x'));
    EXPECT_EQ(err, link + ": cannot write (No space left on device)");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(fs::read_symlink(link), "/dev/full");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(FileWrite, AFolderIsNotAFile) {
    const std::string p = path("out.png");
    fs::create_directory(p);
    EXPECT_EQ(write_file(p, "x"), p + ": cannot write (Is a directory)");
    EXPECT_TRUE(fs::is_directory(p));
    EXPECT_TRUE(fs::is_empty(p));
    EXPECT_EQ(entries(), 1u);
}

TEST_F(FileWrite, MissingFolderOrAFileAsTheFolder) {
    EXPECT_EQ(write_file(path("no/x.png"), "x"), path("no/x.png") + ": cannot write (No such file or directory)");
    ASSERT_EQ(write_file(path("file"), "x"), "");
    EXPECT_EQ(write_file(path("file/x.png"), "x"), path("file/x.png") + ": cannot write (Not a directory)");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(FileWrite, NamesAreShownEscaped) {
    const std::string p = path("no\nfolder/x.png");
    const std::string err = write_file(p, "x");
    EXPECT_EQ(err.find('\n'), std::string::npos) << err;
    EXPECT_NE(err.find("no\\nfolder/x.png"), std::string::npos) << err;
}

}  // namespace
