// The GLSL ES 1.00 sources of shaders_gles2/, includes spliced, embedded at build time.
#pragma once

#include <string>
#include <vector>

namespace penumbra::render {

struct ShaderSource {
    const char* name;  // file name, e.g. "lit.frag"
    const char* text;  // starts with "#version 100"
};

const std::vector<ShaderSource>& embedded_shaders();

}  // namespace penumbra::render
