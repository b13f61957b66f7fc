#include "scene/file_write.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "scene/printable.h"

namespace penumbra::scene {

namespace {

std::string failed(const std::string& path, int err) {
    return printable(path) + ": cannot write (" + std::strerror(err) + ")";
}

// Writes all of `bytes` to `fd`: 0 or the system's error.
int write_all(int fd, std::string_view bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (n == 0) return EIO;  // no progress and no reason: do not spin
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

// close(2) reports what the file system kept back until then (NFS, quotas): checked too. On Linux
// the descriptor is gone whatever it returns, so it is never closed twice.
int close_checked(int fd) { return ::close(fd) == 0 ? 0 : errno; }

// A device or a FIFO that exists: written where it is (there is nothing to rename onto). Opened
// without blocking (a FIFO with no reader fails at once with ENXIO, never hangs), then blocking.
std::string write_in_place(const std::string& path, std::string_view bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return failed(path, errno);
    const int flags = ::fcntl(fd, F_GETFL);
    int err = flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) < 0 ? errno : 0;
    if (!err) err = write_all(fd, bytes);
    const int closed = close_checked(fd);
    if (!err) err = closed;
    return err ? failed(path, err) : std::string();
}

}  // namespace

std::string write_file(const std::string& path, std::string_view bytes) {
    if (path.empty()) return failed(path, ENOENT);
    std::string target = path;  // the file the rename replaces
    bool keep_mode = false;
    mode_t mode = 0666;  // less the umask, as any new file
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return failed(path, EISDIR);
        if (!S_ISREG(st.st_mode)) return write_in_place(path, bytes);
        // An existing file, perhaps through links: the file they name is replaced, in its own folder.
        char* real = ::realpath(path.c_str(), nullptr);
        if (!real) return failed(path, errno);
        target = real;
        std::free(real);
        keep_mode = true;
        mode = st.st_mode & 07777;
    } else if (errno != ENOENT) {
        return failed(path, errno);  // ENOTDIR, EACCES, ELOOP, ENAMETOOLONG...
    }

    static std::atomic<unsigned> serial{0};
    std::string tmp;
    int fd = -1;
    for (int attempt = 0; fd < 0 && attempt < 100; ++attempt) {
        tmp = target + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(serial++);
        fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY, mode);
        if (fd < 0 && errno != EEXIST) return failed(path, errno);
    }
    if (fd < 0) return failed(path, EEXIST);
    // The replaced file's permissions, whatever the umask; where the file system cannot set them
    // (vfat), the new file keeps the default ones: not a reason to refuse the write.
    if (keep_mode) (void)::fchmod(fd, mode);
    int err = write_all(fd, bytes);
    const int closed = close_checked(fd);
    if (!err) err = closed;
    if (!err && ::rename(tmp.c_str(), target.c_str()) != 0) err = errno;
    if (err) {
        ::unlink(tmp.c_str());
        return failed(path, err);
    }
    return {};
}

}  // namespace penumbra::scene
