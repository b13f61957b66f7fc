// Compiles shader variants (render/variants.h) on first use and keeps them: the embedded source of
// each file with the variant's #define lines after `#version 100`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "render/variants.h"

namespace penumbra::render {

// The embedded source of `file` with `#define NAME 1` (or `#define NAME TEXT`) lines inserted after
// `#version 100`. Throws gl::Error when the file is not embedded.
std::string variant_source(const std::string& file, const std::vector<std::string>& defines);

class ShaderLibrary {
public:
    const gl::Program& get(const Variant& v);
    std::size_t compiled() const { return programs_.size(); }
    void clear() { programs_.clear(); }

private:
    std::map<std::string, gl::Program> programs_;
};

}  // namespace penumbra::render
