// A file watched for changes by polling (the desktop app's --snippets: a student edits the file in
// any editor and the window takes it when saved): its modification time and size, read at most
// every `period` seconds of the caller's clock.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>
#include <utility>

namespace penumbra::examples {

class FileWatch {
public:
    explicit FileWatch(std::string path, double period = 0.25) : path_(std::move(path)), period_(period) { stamp(); }

    // True once after the file's time or size changed (or it appeared or vanished) since the last
    // look; `now` in seconds, looks closer together than the period are skipped.
    bool changed(double now) {
        if (now - last_ < period_ && last_ >= 0.0) return false;
        last_ = now;
        const auto before = time_;
        const auto size = size_;
        const bool existed = exists_;
        stamp();
        return exists_ != existed || time_ != before || size_ != size;
    }
    const std::string& path() const { return path_; }

private:
    void stamp() {
        std::error_code ec;
        const auto t = std::filesystem::last_write_time(path_, ec);
        exists_ = !ec;
        time_ = ec ? std::filesystem::file_time_type{} : t;
        const auto s = std::filesystem::file_size(path_, ec);
        size_ = ec ? 0 : s;
    }
    std::string path_;
    double period_;
    double last_ = -1.0;
    bool exists_ = false;
    std::filesystem::file_time_type time_{};
    std::uintmax_t size_ = 0;
};

}  // namespace penumbra::examples
