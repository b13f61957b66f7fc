// Procedural marble (value noise turbulence through a sine of x), made on the CPU so no image
// file is needed. Deterministic for a given size and seed.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace penumbra::scene {

Image make_marble(int size, std::uint32_t seed = 1);

}  // namespace penumbra::scene
