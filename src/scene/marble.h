// Procedural marble (value noise turbulence through a sine of x), made on the CPU so no image
// file is needed. Deterministic for a given size and seed.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace penumbra::scene {

Image make_marble(int size, std::uint32_t seed = 1);
// One texel of the marble's white: what a table shows before its marble is made (1 x 1; the
// marble's noise is most of the course scene's making, which the pages' first frame waits for).
Image marble_placeholder();

// A tangent-space normal map (xyz = n * 0.5 + 0.5, alpha 255) of a grid of 8 x 8 rounded tiles
// with sharp creases between them: where the normals on either side of a crease differ most, a
// box-filtered mip level shortens them (penumbra mipmaps). Tiles for any size.
Image make_tile_normal_map(int size);

}  // namespace penumbra::scene
