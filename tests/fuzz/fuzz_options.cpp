// libFuzzer target: the option table's parser (render::parse_option on render::Options). The input
// is lines of name=value (a line without '=' is a name with the value ""); each is parsed in turn,
// a refused one leaving the options as they were. Then what the options print must read back:
// every pair of to_pairs() parses without a problem into fresh options, which print the same
// to_args() (the shortest float and 17 significant digits read back exactly).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "plan/options.h"

using namespace penumbra;

namespace {

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz_options: %s\n", what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view in(reinterpret_cast<const char*>(data), size);
    render::Options o;
    while (!in.empty()) {
        const std::size_t nl = in.find('\n');
        const std::string_view line = in.substr(0, nl);
        in = nl == std::string_view::npos ? std::string_view{} : in.substr(nl + 1);
        const std::size_t eq = line.find('=');
        const std::string_view name = line.substr(0, eq);
        const std::string_view value = eq == std::string_view::npos ? std::string_view{} : line.substr(eq + 1);
        const render::Options before = o;
        const std::string err = render::parse_option(o, name, value);
        if (!err.empty() && !(o == before)) fail("a refused option changed the options: " + err);
        // The technique-only parser agrees with the full one on technique options.
        render::Settings s = before.settings;
        const std::string serr = render::parse_option(s, name, value);
        if (serr.empty() && (!err.empty() || !(s == o.settings)))
            fail("parse_option(Settings) and parse_option(Options) disagree on --" + std::string(name));
    }
    const std::string args = render::to_args(o);
    render::Options back;
    for (const auto& [k, v] : render::to_pairs(o))
        if (const std::string err = render::parse_option(back, k, v); !err.empty())
            fail("to_pairs gave --" + k + " '" + v + "', which parse_option refuses: " + err);
    if (render::to_args(back) != args) fail("round trip: '" + args + "' read back as '" + render::to_args(back) + "'");
    return 0;
}
