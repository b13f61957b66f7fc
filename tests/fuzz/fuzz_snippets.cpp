// libFuzzer target: the shader lab's snippets scan (plan/snippets.h), the gate between a student's
// (or a hostile) text and the renderer's shaders, with the block built from what it lets through
// and the compiler-log parser. Checked: a refused text defines nothing and every problem has a line
// of the text (0: the whole file) and a one-line message; a taken text's block holds it after
// `#line 1 7` with every byte outside its comments as it was, and no byte outside printable ASCII
// (and tab, CR, LF); the log parser's lines are never negative.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "plan/snippets.h"

using namespace penumbra;

namespace {
[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz_snippets: %s\n", what.c_str());
    std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const render::SnippetScan scan = render::scan_snippets(text);
    long lines = 1;
    for (char c : text) lines += c == '\n';
    for (const auto& p : scan.problems) {
        if (p.line < 0 || p.line > lines) fail("a problem at line " + std::to_string(p.line) + " of " + std::to_string(lines));
        if (p.message.empty() || p.message.find('\n') != std::string::npos) fail("a problem's message is not one line");
    }
    if (!scan.problems.empty() && !scan.defines.empty()) fail("a refused text defines functions");
    if (scan.problems.empty()) {
        for (auto e : {shadow::Encoding::R8, shadow::Encoding::RGBA}) {
            const std::string block = render::snippet_block(text, e);
            const size_t at = block.find("#line 1 7\n");
            if (at == std::string::npos) fail("no #line before the text");
            if (block.size() < at + 10 + text.size()) fail("the block is shorter than the text");
            for (unsigned char c : block)
                if ((c < 0x20 && c != '\n' && c != '\t' && c != '\r') || c > 0x7e) fail("a byte outside ASCII in the block");
        }
    }
    for (const auto& p : render::snippet_log_problems(text))
        if (p.line < 0) fail("a negative line from the log parser");
    return 0;
}
