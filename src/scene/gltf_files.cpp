// The files a scene reads, as hostile input: only regular files (a FIFO, a device or a folder
// would hang or exhaust the loader), opened without blocking, within a byte budget, and for the
// files a scene names (buffers' and images' uris) only inside the scene's own folder or a folder
// the user allowed (--allow-outside). tinygltf reads external files through FsCallbacks; ours
// enforce these rules and never expand paths (tinygltf's default runs wordexp on them).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>

#include "scene/gltf_internal.h"
#include "scene/printable.h"

namespace penumbra::scene::gltf_internal {
namespace {

std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// The canonical form of an existing path (symbolic links resolved), "" when it has none.
std::string canonical(const std::string& path) {
    char buf[PATH_MAX];
    if (!::realpath(path.c_str(), buf)) return "";
    return buf;
}

bool under(const std::string& path, const std::string& root) {
    if (root.empty()) return false;
    if (path == root) return true;
    const std::string prefix = root.back() == '/' ? root : root + "/";
    return path.compare(0, prefix.size(), prefix) == 0;
}

bool fs_exists(const std::string& abs_filename, void*) {
    struct stat st;
    // Present for FindFile even if it is not a file we will read: ReadWholeFile says why.
    return ::lstat(abs_filename.c_str(), &st) == 0;
}

std::string fs_expand(const std::string& path, void*) { return path; }

bool fs_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "the loader writes no files";
    return false;
}

bool fs_read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    auto& access = *static_cast<FileAccess*>(user);
    std::string problem;
    if (!access.read_named(path, *out, problem)) {
        if (err) *err = problem;
        return false;
    }
    return true;
}

}  // namespace

bool read_regular_file(const std::string& path, std::size_t max_bytes, std::vector<unsigned char>& out,
                       std::string& problem) {
    out.clear();
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        problem = std::string("cannot open: ") + std::strerror(errno);
        return false;
    }
    struct stat st;
    bool ok = false;
    if (::fstat(fd, &st) != 0) {
        problem = std::string("cannot stat: ") + std::strerror(errno);
    } else if (!S_ISREG(st.st_mode)) {
        problem = "is " + kind_of(st.st_mode) + ", not a regular file";
    } else if (static_cast<unsigned long long>(st.st_size) > max_bytes) {
        problem = "is " + std::to_string(st.st_size) + " bytes, over the limit of " + std::to_string(max_bytes);
    } else {
        out.resize(static_cast<std::size_t>(st.st_size));
        std::size_t done = 0;
        ok = true;
        while (done < out.size()) {
            const ssize_t n = ::read(fd, out.data() + done, out.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) {
                problem = std::string("cannot read: ") + std::strerror(errno);
                ok = false;
                break;
            }
            if (n == 0) break;  // shrank while being read: what is there is what we have
            done += static_cast<std::size_t>(n);
        }
        out.resize(done);
    }
    ::close(fd);
    if (!ok) out.clear();
    return ok;
}

FileAccess::FileAccess(const std::string& scene_dir, const LoadOptions& options) : limits_(options.limits) {
    if (!scene_dir.empty()) {
        folder_ = canonical(scene_dir);
        if (!folder_.empty()) roots_.push_back(folder_);
    }
    for (const auto& allowed : options.allow_outside) {
        const std::string c = canonical(allowed);
        if (!c.empty()) roots_.push_back(c);
    }
}

std::string FileAccess::check_inside(const std::string& path) const {
    const std::string c = canonical(path);
    if (c.empty()) return std::string("cannot open: ") + std::strerror(errno);
    for (const auto& root : roots_)
        if (under(c, root)) return "";
    if (folder_.empty()) return "is outside the scene's folder (a scene from memory reads no files)";
    return "is outside the scene's folder " + printable(folder_) + " (allow it with --allow-outside PATH)";
}

bool FileAccess::read_named(const std::string& path, std::vector<unsigned char>& out, std::string& problem) {
    problem = check_inside(path);
    if (!problem.empty()) return false;
    if (used_ >= limits_.max_total_bytes) {
        problem = "the scene's files exceed the budget of " + std::to_string(limits_.max_total_bytes) + " bytes";
        return false;
    }
    const std::size_t cap = std::min(limits_.max_file_bytes, limits_.max_total_bytes - used_);
    if (!read_regular_file(path, cap, out, problem)) return false;
    used_ += out.size();
    return true;
}

tinygltf::FsCallbacks FileAccess::callbacks() {
    tinygltf::FsCallbacks fs{};
    fs.FileExists = &fs_exists;
    fs.ExpandFilePath = &fs_expand;
    fs.ReadWholeFile = &fs_read;
    fs.WriteWholeFile = &fs_write;
    fs.user_data = this;
    return fs;
}

}  // namespace penumbra::scene::gltf_internal
