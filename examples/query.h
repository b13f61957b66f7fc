// The pages' URL query ("?encoding=r8&bias=auto") read in C++ rather than by the browser's
// URLSearchParams, so the one parser is the one the fuzz target (tests/fuzz/fuzz_query.cpp) runs:
// pairs split at '&' (empty ones skipped) and at the first '=' (none: the value is ""), '+' read as
// a space and %XX escapes decoded. Unlike URLSearchParams nothing is guessed: a malformed escape
// ("%zz", a '%' at the end) or a name or value that is not UTF-8 once decoded skips its pair with
// a note, and a query longer than kMaxQueryBytes (after its '?') is ignored whole, with a note.
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace penumbra::examples {

// Longer than any query the pages write (CourseApp::query() is a few hundred bytes).
inline constexpr std::size_t kMaxQueryBytes = 8192;

struct QueryPair {
    std::string name;
    std::string value;
};

// The decoded pairs, in order; every pair skipped adds one line to `notes` (control characters and
// bytes that are not UTF-8 escaped, so a note is one printable line).
std::vector<QueryPair> parse_query(std::string_view query, std::vector<std::string>& notes);

// A number as the URLs and the desktop's lines write it: 6 significant digits ("0.003", "1e+06").
inline std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// A name or value as a query writes it: '%', '+', '&', '=', '#', spaces, control characters and
// bytes outside ASCII as %XX, so parse_query reads back the same bytes ("1e+06": "1e%2B06").
inline std::string encode_query_component(std::string_view s) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(s.size());
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (c <= 0x20 || c >= 0x7F || c == '%' || c == '+' || c == '&' || c == '=' || c == '#') {
            out += '%';
            out += kHex[c >> 4];
            out += kHex[c & 15];
        } else {
            out += ch;
        }
    }
    return out;
}

// parse_query, then `set_option(name, value)` on each pair in order ("" or a problem, as
// CourseApp::set_option answers). Returns the notes in the query's order: the parser's for a pair
// it skips, set_option's answer for a pair it refuses.
std::vector<std::string> apply_query(
    std::string_view query, const std::function<std::string(std::string_view, std::string_view)>& set_option);

}  // namespace penumbra::examples
