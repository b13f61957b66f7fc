// `penumbra mipmaps`: a texture's mip chain rendered on the GPU level by level from the level above
// (render/mipmaps.h: the box filter or the normal map's renormalising one; into the texture's own
// levels where the context can, else into textures of their own copied into the levels, with the
// reason printed), against glGenerateMipmap and the same filter on the CPU: per level the largest
// and mean difference, the normals' mean length, and the time of each way to build the chain.
// Writes every level of the three chains as PNGs, an index.html that shows them side by side, and
// a CSV of the table.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace penumbra::tools {

struct MipmapsOptions {
    std::string source = "normals";  // marble, normals (built in) or FILE.png (square, power of two)
    int size = 256;                  // the built-in sources' size
    std::string filter = "auto";     // box, normal, auto (normal for the normal map, else box)
    std::string path = "auto";       // levels, textures, auto
    std::string out_dir = "out/mipmaps";
    int repeat = 9;                  // timed builds of each kind (the median is printed)
};

CLI::App* add_mipmaps_command(CLI::App& app, MipmapsOptions& options);
// Returns the exit status (2: bad input, 1: a failure), one line on stderr for a problem.
int run_mipmaps(const MipmapsOptions& options);

}  // namespace penumbra::tools
