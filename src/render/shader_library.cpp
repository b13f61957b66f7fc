#include "render/shader_library.h"

#include "gl/check.h"
#include "render/shader_sources.h"

namespace penumbra::render {

std::string variant_source(const std::string& file, const std::vector<std::string>& defines) {
    for (const ShaderSource& s : embedded_shaders()) {
        if (file != s.name) continue;
        std::string text = s.text;
        const std::string version = "#version 100\n";
        if (text.rfind(version, 0) != 0) throw gl::Error(file + ": must start with '#version 100'");
        std::string lines;
        for (const auto& d : defines) lines += "#define " + d + (d.find(' ') == std::string::npos ? " 1\n" : "\n");
        // gl_FragData[i > 0] needs the extension, declared before anything else but #version.
        for (const auto& d : defines)
            if (d == "GBUFFER_MRT") lines = "#extension GL_EXT_draw_buffers : require\n" + lines;
        text.insert(version.size(), lines);
        return text;
    }
    throw gl::Error("shader '" + file + "' is not embedded");
}

const gl::Program& ShaderLibrary::get(const Variant& v) {
    const std::string key = v.key();
    auto it = programs_.find(key);
    if (it != programs_.end()) return it->second;
    gl::Program p(variant_source(v.vertex, v.defines), variant_source(v.fragment, v.defines), key);
    return programs_.emplace(key, std::move(p)).first->second;
}

}  // namespace penumbra::render
