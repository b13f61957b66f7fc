// The lab's splice (snippet_block), in a file of its own: a browser page's module links it only
// where its exercise has the lab's panel (Exercise::lab), the renderer's reference being weak there
// (render/shader_library.cpp), so that the other pages leave out the lab's GLSL scan as well.
#include <string>

#include "plan/snippets.h"

namespace penumbra::render {

namespace {

// `text` with every byte outside printable ASCII in its comments written as '?' (GLSL ES 1.00's
// character set is ASCII; the scan refuses such bytes outside comments).
std::string ascii_comments(std::string_view text) {
    std::string out(text);
    enum { Code, Line, Block } state = Code;
    for (size_t i = 0; i < out.size(); ++i) {
        const char c = out[i];
        const char next = i + 1 < out.size() ? out[i + 1] : '\0';
        if (state == Code && c == '/' && next == '/') state = Line, ++i;
        else if (state == Code && c == '/' && next == '*') state = Block, ++i;
        else if (state == Line && c == '\n') state = Code;
        else if (state == Block && c == '*' && next == '/') state = Code, ++i;
        else if (state != Code && (static_cast<unsigned char>(c) > 0x7e || (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r')))
            out[i] = '?';
    }
    return out;
}

}  // namespace

std::string snippet_block(std::string_view text, shadow::Encoding e) {
    const SnippetScan scan = scan_snippets(text);
    std::string out = "// The sheet's answer for the functions the snippets leave out.\n";
    for (SnippetFn f : kAllSnippetFns)
        if (!scan.defines_fn(f)) out += sheet_answer_fn(f, e);
    out += "#line 1 " + std::to_string(kSnippetSourceString) + "\n";
    out += ascii_comments(text);
    if (out.empty() || out.back() != '\n') out += '\n';
    out += "#line 1 0\n";
    return out;
}

}  // namespace penumbra::render
