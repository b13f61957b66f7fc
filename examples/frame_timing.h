// The time a frame takes: the ms/frame of the last frames (draw + wait, measured on the CPU) and,
// where the context has a GPU timer, each pass's GPU time over the last frames read back. No GL.
#pragma once

#include <cstddef>
#include <deque>
#include <vector>

#include "gl/timer.h"

namespace penumbra::examples {

class FrameTiming {
public:
    static constexpr std::size_t kWindow = 60;     // frames in the ms/frame median
    static constexpr std::size_t kGpuWindow = 30;  // frames of GPU times kept

    // One frame drawn in `ms`.
    void add(double ms);
    // GPU frames read back (a few frames old); the oldest beyond kGpuWindow are dropped.
    void add_gpu(std::vector<gl::GpuFrame> frames);
    // Forgets the times (a new context: the old one's say nothing about it); the frame count stays.
    void clear();
    // Median ms/frame over the last kWindow frames, 0 before the first.
    double median_ms() const;
    long frames() const { return frames_; }
    // Each pass's median over the kept GPU frames, and their totals' (frames 0: none read yet).
    gl::GpuSummary gpu_summary() const;

private:
    std::vector<double> ms_;  // ring of the last frame times
    std::deque<gl::GpuFrame> gpu_;
    long frames_ = 0;
};

}  // namespace penumbra::examples
