// Comparing a rendered image with an approved one (a golden) so that what any conformant GLES 2 /
// WebGL 1 implementation may do differently passes, and a regression fails. The rules that allow
// a difference, each with the tolerance that follows from it:
//
// - A small step on every pixel (`step`, in 8-bit levels): the precision of colour arithmetic,
//   varying interpolation and texture filtering is the implementation's (GLES 2.0 2.1.1, 3.7.7:
//   the filter weights' precision is not fixed; GLSL ES 1.00 4.5.2: mediump may be fp16), and
//   dithering, on by default, may pick either neighbouring level (GLES 2.0 4.1.7).
// - An edge one pixel over: the rasteriser's sub-pixel precision and its rule for pixel centres
//   exactly on an edge are the implementation's (GLES 2.0 3.5.1), and so are the texture
//   coordinate's precision and so which of two texels NEAREST picks at their boundary
//   (3.7.7, 3.7.8). A pixel whose colour is found within one pixel in the golden is "explained".
// - What no rule explains may still happen on a few isolated pixels (an edge seen through a
//   shadow map's texel that flipped, two rounding rules meeting): a small share of the image, in
//   clusters of a few pixels. A shadow that moved is a long line or an area of unexplained
//   pixels, and fails on the cluster size even where the share is small.
#pragma once

#include <string>

#include "measure/image_io.h"

namespace penumbra::measure {

struct CompareRules {
    int step = 8;                      // per-channel levels any pixel may be off
    int reach = 1;                     // how far (pixels) an edge may have moved
    double max_off_share = 0.05;       // share of pixels off by more than step, explained or not
    double max_unexplained_share = 2e-4;  // share of pixels off that no 1-pixel shift explains
    int max_cluster = 6;               // largest 8-connected group of unexplained pixels
};

struct ImageComparison {
    int max = 0;              // largest per-channel difference
    double mean = 0.0;        // mean per-channel difference
    int off = 0;              // pixels off by more than step
    int unexplained = 0;      // of those, not explained by an edge one pixel over
    int largest_cluster = 0;  // the largest 8-connected group of unexplained pixels
    int pixels = 0;
    bool passed = false;
    std::string summary() const;  // one line with every figure
};

// a and b of the same size and channel count (else throws std::invalid_argument).
ImageComparison compare_images(const Pixels& actual, const Pixels& golden, const CompareRules& rules = {});

// Per pixel: 0 same within step, 128 off but explained, 255 unexplained: what to look at.
Pixels comparison_map(const Pixels& actual, const Pixels& golden, const CompareRules& rules = {});

}  // namespace penumbra::measure
