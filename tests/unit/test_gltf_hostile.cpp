// The loader's validation layer through its API (the corpus in tests/data/bad runs through the
// command line in tests/bad_inputs.sh): loading from memory, the limits, the scene's folder and
// --allow-outside, files that are not regular, and the printable names in messages.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "scene/gltf_loader.h"
#include "scene/printable.h"
#include "../test_paths.h"

namespace fs = std::filesystem;
using namespace penumbra::scene;

namespace {

std::string data(const std::string& name) { return penumbra::test::test_data_dir() + "/" + name; }

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

LoadResult from_memory(const std::string& text, const std::string& name = "mem.gltf", const std::string& dir = "",
                       const LoadOptions& options = {}) {
    return load_gltf_memory(name, reinterpret_cast<const unsigned char*>(text.data()), text.size(), dir, options);
}

// A fresh folder per test under the system's temporary folder.
struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("penumbra-hostile-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

// The base triangle of the corpus with its buffer's uri replaced.
std::string with_buffer_uri(const std::string& uri) {
    std::string text = read(data("bad/buffer_is_folder.gltf"));
    const std::string from = "\"uri\": \".\"";
    text.replace(text.find(from), from.size(), "\"uri\": \"" + uri + "\"");
    return text;
}

// The triangle's 44 bytes (3 positions, 3 indices, 2 padding) as a file beside the scene.
std::string triangle_bytes() {
    std::string b(44, '\0');
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
    const unsigned short idx[3] = {0, 1, 2};
    std::memcpy(&b[0], pos, 36);
    std::memcpy(&b[36], idx, 6);
    return b;
}

}  // namespace

TEST(GltfHostile, MemoryLoadMatchesTheFile) {
    const std::string text = read(data("sphere_over_plane.gltf"));
    const LoadResult mem = from_memory(text, "sphere_over_plane.gltf");
    const LoadResult file = load_gltf(data("sphere_over_plane.gltf"));
    ASSERT_TRUE(mem.ok) << mem.error;
    ASSERT_TRUE(file.ok) << file.error;
    EXPECT_EQ(mem.scene.objects.size(), file.scene.objects.size());
    EXPECT_EQ(mem.scene.meshes.size(), file.scene.meshes.size());
}

TEST(GltfHostile, EveryCorpusFileFailsFromMemoryToo) {
    // The corpus without its exit-0 case, loaded from memory with no folder: an error, never a crash.
    std::ifstream list(data("bad/expected.tsv"));
    std::string line;
    int n = 0;
    while (std::getline(list, line)) {
        if (line.empty() || line[0] == '#') continue;
        const std::string file = line.substr(0, line.find('\t'));
        const std::string status = line.substr(file.size() + 1, 1);
        const LoadResult r = from_memory(read(data("bad/" + file)), file);
        if (status == "0") {
            EXPECT_TRUE(r.ok) << file << ": " << r.error;
        } else {
            EXPECT_FALSE(r.ok) << file;
            EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
            EXPECT_EQ(r.error.rfind(file + ": ", 0), 0u) << r.error;
        }
        ++n;
    }
    EXPECT_GT(n, 30);
}

TEST(GltfHostile, TheLimitsAreTheOptions) {
    LoadOptions tight;
    tight.limits.max_json_depth = 3;
    const LoadResult deep = from_memory(read(data("sphere_over_plane.gltf")), "s.gltf", "", tight);
    EXPECT_FALSE(deep.ok);
    EXPECT_NE(deep.error.find("nested deeper than 3 levels"), std::string::npos) << deep.error;

    LoadOptions few;
    few.limits.max_elements = 1;
    const LoadResult many = from_memory(read(data("sphere_over_plane.gltf")), "s.gltf", "", few);
    EXPECT_FALSE(many.ok);
    EXPECT_NE(many.error.find("entries, over the limit of 1"), std::string::npos) << many.error;

    LoadOptions small;
    small.limits.max_file_bytes = 100;
    const LoadResult big = load_gltf(data("sphere_over_plane.gltf"), small);
    EXPECT_FALSE(big.ok);
    EXPECT_NE(big.error.find("over the limit of 100"), std::string::npos) << big.error;
}

TEST(GltfHostile, BuffersInsideTheFolderLoad) {
    TempDir dir;
    write(dir.path / "tri.bin", triangle_bytes());
    write(dir.path / "tri.gltf", with_buffer_uri("tri.bin"));
    const LoadResult r = load_gltf((dir.path / "tri.gltf").string());
    EXPECT_TRUE(r.ok) << r.error;
    // From memory with that folder as the base: the same.
    const LoadResult m = from_memory(with_buffer_uri("tri.bin"), "tri.gltf", dir.path.string());
    EXPECT_TRUE(m.ok) << m.error;
    // From memory without a folder: nothing may be read.
    const LoadResult none = from_memory(with_buffer_uri("tri.bin"), "tri.gltf");
    EXPECT_FALSE(none.ok);
}

TEST(GltfHostile, OutsideTheFolderOnlyWhenAllowed) {
    TempDir dir;
    fs::create_directories(dir.path / "scene");
    fs::create_directories(dir.path / "shared");
    write(dir.path / "shared" / "tri.bin", triangle_bytes());
    write(dir.path / "scene" / "tri.gltf", with_buffer_uri("../shared/tri.bin"));
    const std::string scene = (dir.path / "scene" / "tri.gltf").string();

    const LoadResult refused = load_gltf(scene);
    EXPECT_FALSE(refused.ok);
    EXPECT_NE(refused.error.find("buffers[0].uri '../shared/tri.bin' is outside the scene's folder"), std::string::npos)
        << refused.error;

    LoadOptions allow;
    allow.allow_outside = {(dir.path / "shared").string()};
    const LoadResult allowed = load_gltf(scene, allow);
    EXPECT_TRUE(allowed.ok) << allowed.error;

    // A symbolic link inside the folder that leads out of it is outside.
    fs::create_symlink(dir.path / "shared" / "tri.bin", dir.path / "scene" / "link.bin");
    write(dir.path / "scene" / "link.gltf", with_buffer_uri("link.bin"));
    const LoadResult link = load_gltf((dir.path / "scene" / "link.gltf").string());
    EXPECT_FALSE(link.ok);
    EXPECT_NE(link.error.find("is outside the scene's folder"), std::string::npos) << link.error;
}

TEST(GltfHostile, NotRegularFilesAreRefusedWithoutBlocking) {
    TempDir dir;
    const fs::path fifo = dir.path / "fifo.gltf";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const LoadResult r = load_gltf(fifo.string());  // would block forever on a blocking open or read
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("is a FIFO, not a regular file"), std::string::npos) << r.error;

    fs::create_directories(dir.path / "folder.gltf");
    const LoadResult f = load_gltf((dir.path / "folder.gltf").string());
    EXPECT_FALSE(f.ok);
    EXPECT_NE(f.error.find("is a folder, not a regular file"), std::string::npos) << f.error;

    // A FIFO named by a buffer, with the folder allowed: still not a regular file.
    ASSERT_EQ(::mkfifo((dir.path / "data.bin").c_str(), 0600), 0);
    write(dir.path / "tri.gltf", with_buffer_uri("data.bin"));
    const LoadResult b = load_gltf((dir.path / "tri.gltf").string());
    EXPECT_FALSE(b.ok);
    EXPECT_NE(b.error.find("is not a regular file"), std::string::npos) << b.error;
}

TEST(GltfHostile, MessagesNameTheFileOnOneLine) {
    const std::string text = read(data("bad/version_3.gltf"));
    const LoadResult r = from_memory(text, "two\nlines\xff.gltf");
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.error.rfind("two\\nlines\\xFF.gltf: asset.version is '3.0'", 0), 0u) << r.error;
    EXPECT_TRUE(valid_utf8(r.error));
}

TEST(Printable, EscapesControlsAndBrokenUtf8) {
    EXPECT_EQ(printable("plain/ä.gltf"), "plain/ä.gltf");
    EXPECT_EQ(printable("a\nb\tc\\d"), "a\\nb\\tc\\\\d");
    EXPECT_EQ(printable(std::string("x\x01\x7f", 3)), "x\\x01\\x7F");
    EXPECT_EQ(printable("\xC3"), "\\xC3");              // cut sequence
    EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");     // overlong '/'
    EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");  // a surrogate
    EXPECT_TRUE(valid_utf8("€ and 😀"));
    EXPECT_FALSE(valid_utf8("\xF5\x80\x80\x80"));
}
