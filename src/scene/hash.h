// A fixed integer hash (Wellons' "lowbias32"): the same bits on every platform and standard
// library, unlike std::rand or the std:: distributions. Used where results must be reproducible:
// the procedural marble and the ground truth's area-light samples.
#pragma once

#include <cstdint>

namespace penumbra::scene {

inline std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

}  // namespace penumbra::scene
