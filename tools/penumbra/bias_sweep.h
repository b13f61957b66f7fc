// `penumbra bias-sweep`: false-shadow (acne) and false-lit (peter-panning) rates against the bias,
// for each encoding, with and without emulated mediump, for light elevations from 2 to 90 degrees,
// on a box standing on a plane and on the course scene, against the ray-traced truth. Writes a CSV,
// a Markdown summary (fixed defaults against --bias auto) and one SVG chart per scene and
// encoding, with the sheet's thresholds (0.005, 0.0015) marked.
#pragma once

#include <string>

namespace penumbra::tools {

struct BiasSweepOptions {
    std::string out_dir = "results/precision";
    bool quick = false;  // fewer elevations, biases and pixels: for CI
    int size = 256;      // image width = height
    int map_size = 1024;
};

// Returns the process exit code; progress goes to stderr.
int run_bias_sweep(const BiasSweepOptions& options);

}  // namespace penumbra::tools
