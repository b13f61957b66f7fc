// Compiles shader variants (plan/variants.h) on first use and keeps them: the embedded source of
// each file with the variant's #define lines after `#version 100`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "plan/variants.h"

namespace penumbra::render {

// The embedded source of `file` with `#define NAME 1` (or `#define NAME TEXT`) lines inserted after
// `#version 100`. Throws gl::Error when the file is not embedded.
// A LAB variant (Settings::lab) gets the lab's snippets at pack.glsl's marker:
// render::snippet_block(snippets, the variant's encoding); "" = the sheet's answer.
std::string variant_source(const std::string& file, const std::vector<std::string>& defines,
                           const std::string& snippets = "");

// The #defines of `defines` that can change `file`'s code: those whose name is a word of the file
// (after its includes are spliced) or of a kept define's text, and GBUFFER_MRT (it also adds an
// #extension line). The others are #defined and never read: leaving them out compiles the same
// shader, so the every-variant test compiles each stage's distinct code once.
std::vector<std::string> defines_read_by(const std::string& file, const std::vector<std::string>& defines);

// Every variant of `variants` compiled and linked on the current context with the sources and
// attribute bindings ShaderLibrary::get uses (less the #defines the file never reads), through
// gl::check_programs (each distinct source compiled once, in batches, with the driver free to
// compile in parallel), and nothing kept. Returns one line per variant that failed: its key, the
// stage and the log, as get() would throw it.
std::vector<std::string> check_variants(const std::vector<Variant>& variants, const std::string& snippets = "");

class ShaderLibrary {
public:
    const gl::Program& get(const Variant& v);
    std::size_t compiled() const { return programs_.size(); }
    void clear() { programs_.clear(); }
    // The shader lab's snippets for the LAB variants (plan/snippets.h; "" = the sheet's answer):
    // their programs compiled before are dropped when the text changes.
    void set_snippets(std::string text);
    const std::string& snippets() const { return snippets_; }

private:
    std::map<std::string, gl::Program> programs_;
    std::string snippets_;
};

}  // namespace penumbra::render
