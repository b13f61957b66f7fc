// The unit tests' GL context, for plans made without one: what headless Mesa reports, so every
// technique's resources are possible (depth textures, packed depth-stencil, 24-bit depth,
// 32-bit indices, 4096 a side).
#pragma once

#include "gl/caps.h"

namespace penumbra::testing {

inline gl::Caps full_caps() {
    gl::Caps c;
    c.depth_texture = c.packed_depth_stencil = c.depth24 = c.element_index_uint = true;
    c.max_texture_size = c.max_renderbuffer_size = c.max_viewport_width = c.max_viewport_height = 4096;
    return c;
}

}  // namespace penumbra::testing
