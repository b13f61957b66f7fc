#include "render/shader_library.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "gl/check.h"
#include "render/shader_sources.h"
#include "plan/snippets.h"
#include "plan/weak_in_pages.h"

namespace penumbra::render {

// The lab's splice (plan/snippet_block.cpp) is in a page's module only where its exercise names it
// (Exercise::lab, the page with the lab's panel): no other page makes a LAB variant (Settings::lab
// is the panel's).
PENUMBRA_WEAK_IN_PAGES std::string snippet_block(std::string_view text, shadow::Encoding e);

namespace {

using Splice = std::string (*)(std::string_view, shadow::Encoding);
Splice lab_splice() { return &snippet_block; }

}  // namespace

std::string variant_source(const std::string& file, const std::vector<std::string>& defines, const std::string& snippets) {
    for (const ShaderSource& s : embedded_shaders()) {
        if (file != s.name) continue;
        std::string text = s.text;
        const std::string version = "#version 100\n";
        if (text.rfind(version, 0) != 0) throw gl::Error(file + ": must start with '#version 100'");
        std::string lines;
        for (const auto& d : defines) lines += "#define " + d + (d.find(' ') == std::string::npos ? " 1\n" : "\n");
        // gl_FragData[i > 0] needs the extension, declared before anything else but #version.
        // dFdx and dFdy likewise (OES_standard_derivatives; core in GLSL ES 3.00, not in 1.00).
        bool derivatives = false;
        for (const auto& d : defines) {
            if (d == "GBUFFER_MRT") lines = "#extension GL_EXT_draw_buffers : require\n" + lines;
            derivatives = derivatives || d == "GEOMETRIC_HORIZON" || d == "PCSS_QUAD";
        }
        if (derivatives) lines = "#extension GL_OES_standard_derivatives : require\n" + lines;
        text.insert(version.size(), lines);
        const bool lab = std::find(defines.begin(), defines.end(), "LAB") != defines.end();
        const std::string marker = "// @snippets\n";
        if (lab) {
            // pack.glsl is spliced in once per file that includes it, its guard keeping one: the
            // marker of each copy (the one compiled may be any of them).
            const bool r8 = std::find(defines.begin(), defines.end(), "ENC_R8") != defines.end();
            const Splice splice = lab_splice();
            if (!splice) throw gl::Error(file + ": the shader lab is not in this page's code (a page with the lab's panel has it)");
            const std::string block = splice(snippets, r8 ? shadow::Encoding::R8 : shadow::Encoding::RGBA);
            for (size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at + block.size()))
                text.replace(at, marker.size(), block);
        }
        return text;
    }
    throw gl::Error("shader '" + file + "' is not embedded");
}

namespace {

// The identifiers in `text` (comments and all: a name is never dropped for being only there).
std::set<std::string> words(const std::string& text) {
    std::set<std::string> out;
    const auto head = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
    const auto tail = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (size_t i = 0; i < text.size();) {
        if (!head(text[i])) {
            // Skip a number's letters too (1e5, 0x1F): they are not names.
            if (tail(text[i]))
                while (i < text.size() && tail(text[i])) ++i;
            else
                ++i;
            continue;
        }
        size_t end = i;
        while (end < text.size() && tail(text[end])) ++end;
        out.insert(text.substr(i, end - i));
        i = end;
    }
    return out;
}

// "NAME", "NAME TEXT", "NAME(ARGS) TEXT": the name.
std::string define_name(const std::string& d) { return d.substr(0, d.find_first_of(" (")); }

}  // namespace

std::vector<std::string> defines_read_by(const std::string& file, const std::vector<std::string>& defines) {
    static std::map<std::string, std::set<std::string>> file_words;
    auto it = file_words.find(file);
    if (it == file_words.end()) it = file_words.emplace(file, words(variant_source(file, {}))).first;
    std::set<std::string> read = it->second;
    std::vector<bool> keep(defines.size(), false);
    // A kept define's text may name another: repeat until nothing more is kept.
    for (bool more = true; more;) {
        more = false;
        for (size_t i = 0; i < defines.size(); ++i) {
            const std::string name = define_name(defines[i]);
            if (keep[i] || (name != "GBUFFER_MRT" && !read.count(name))) continue;
            keep[i] = more = true;
            if (defines[i].size() > name.size()) read.merge(words(defines[i].substr(name.size())));
        }
    }
    std::vector<std::string> out;
    for (size_t i = 0; i < defines.size(); ++i)
        if (keep[i]) out.push_back(defines[i]);
    return out;
}

std::vector<std::string> check_variants(const std::vector<Variant>& variants, const std::string& snippets) {
    std::vector<gl::ProgramSources> programs;
    programs.reserve(variants.size());
    for (const Variant& v : variants)
        programs.push_back({variant_source(v.vertex, defines_read_by(v.vertex, v.defines), snippets),
                            variant_source(v.fragment, defines_read_by(v.fragment, v.defines), snippets), v.key()});
    std::vector<std::string> failed;
    for (std::string& e : gl::check_programs(programs))
        if (!e.empty()) failed.push_back(std::move(e));
    return failed;
}

const gl::Program& ShaderLibrary::get(const Variant& v) {
    const std::string key = v.key();
    auto it = programs_.find(key);
    if (it != programs_.end()) return it->second;
    gl::Program p(variant_source(v.vertex, v.defines, snippets_), variant_source(v.fragment, v.defines, snippets_), key);
    return programs_.emplace(key, std::move(p)).first->second;
}

void ShaderLibrary::set_snippets(std::string text) {
    if (text == snippets_) return;
    snippets_ = std::move(text);
    for (auto it = programs_.begin(); it != programs_.end();) {
        const std::string& key = it->first;
        if (key.find("[LAB") != std::string::npos || key.find(",LAB,") != std::string::npos ||
            key.find(",LAB]") != std::string::npos)
            it = programs_.erase(it);
        else
            ++it;
    }
}

}  // namespace penumbra::render
