#include "frame_timing.h"

#include <algorithm>

namespace penumbra::examples {

void FrameTiming::add(double ms) {
    if (ms_.size() < kWindow) ms_.push_back(ms);
    else ms_[static_cast<std::size_t>(frames_) % kWindow] = ms;
    ++frames_;
}

void FrameTiming::add_gpu(std::vector<gl::GpuFrame> frames) {
    for (gl::GpuFrame& f : frames) gpu_.push_back(std::move(f));
    while (gpu_.size() > kGpuWindow) gpu_.pop_front();
}

void FrameTiming::clear() {
    ms_.clear();
    gpu_.clear();
}

double FrameTiming::median_ms() const {
    if (ms_.empty()) return 0.0;
    std::vector<double> v = ms_;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

gl::GpuSummary FrameTiming::gpu_summary() const {
    return gl::summarize(std::vector<gl::GpuFrame>(gpu_.begin(), gpu_.end()));
}

}  // namespace penumbra::examples
