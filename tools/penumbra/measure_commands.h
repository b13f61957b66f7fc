// The measuring subcommands of `penumbra`, registered by main.cpp with two calls:
//   export  the scene at time t as one self-contained glTF 2.0 file (for three.js, any other renderer)
//   truth   the ray-traced ground truth of one frame as PNGs, and optionally the score of a visibility PNG
//   bench   the sweep: accuracy against the ground truth, time and memory of every technique
// truth and bench need the Embree ground truth (CMake option PENUMBRA_TRUTH, on for native builds).
#pragma once

#include <memory>

#include <CLI/CLI.hpp>

namespace penumbra::tools {

struct MeasureCommands;

// Adds the subcommands and their options to `app`; the returned object holds the parsed values.
std::shared_ptr<MeasureCommands> add_measure_commands(CLI::App& app);

// After app.parse(): runs the one that was given and returns its exit status (one line on stderr
// for a problem: 2 for bad input, 1 for a failure), or -1 when none of them was given.
int run_measure_commands(MeasureCommands& commands);

}  // namespace penumbra::tools
