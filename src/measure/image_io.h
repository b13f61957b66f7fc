// PNG files for the command line, the desktop app and the tests: written whole or not at all (stb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::measure {

struct Pixels {
    int width = 0;
    int height = 0;
    int channels = 0;  // 1 grey, 3 RGB, 4 RGBA
    std::vector<std::uint8_t> data;  // top row first
};

// Encodes in memory and writes it with scene::write_file (a temporary file beside `path`, every
// write and the close checked, renamed into place), so a failure never leaves a partial file.
// Returns "" or one line naming the problem: the path through scene::printable and the system's
// reason ("out.png: cannot write (No space left on device)").
std::string write_png(const std::string& path, const Pixels& px);

// Reads a PNG as `channels` channels (0: as stored). Returns "" or the problem.
std::string read_png(const std::string& path, Pixels& out, int channels = 0);

// Picks channels from RGBA8 pixels: 1 takes red (grey AOVs), 3 drops alpha.
Pixels from_rgba(const std::vector<std::uint8_t>& rgba, int width, int height, int channels);

}  // namespace penumbra::measure
