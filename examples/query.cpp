#include "query.h"

#include "scene/printable.h"

namespace penumbra::examples {

namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// '+' as a space, %XX as its byte; false (out unspecified) on a malformed escape.
bool decode(std::string_view in, std::string& out) {
    out.clear();
    out.reserve(in.size());
    for (std::size_t i = 0; i < in.size(); ++i) {
        const char c = in[i];
        if (c == '+') {
            out += ' ';
        } else if (c == '%') {
            if (i + 2 >= in.size()) return false;
            const int hi = hex_digit(in[i + 1]);
            const int lo = hex_digit(in[i + 2]);
            if (hi < 0 || lo < 0) return false;
            out += static_cast<char>(hi * 16 + lo);
            i += 2;
        } else {
            out += c;
        }
    }
    return true;
}

// A pair as it stood in the URL, shortened for a note.
std::string quoted(std::string_view raw) {
    constexpr std::size_t kShown = 60;
    std::string s = scene::printable(raw.substr(0, kShown));
    if (raw.size() > kShown) s += "...";
    return "'" + s + "'";
}

// An answer as one printable line; one already printable stays as it is (not escaped twice).
std::string one_line(std::string s) {
    bool plain = scene::valid_utf8(s);
    for (const char c : s) plain = plain && static_cast<unsigned char>(c) >= 0x20 && c != 0x7F;
    return plain ? s : scene::printable(s);
}

// Each pair of `query` in order: `on_pair(pair)` or `on_note(note)` for one that is refused.
template <typename OnPair, typename OnNote>
void for_each_pair(std::string_view query, OnPair on_pair, OnNote on_note) {
    if (!query.empty() && query.front() == '?') query.remove_prefix(1);
    if (query.size() > kMaxQueryBytes) {
        on_note("the query is longer than " + std::to_string(kMaxQueryBytes) + " bytes: ignored");
        return;
    }
    while (!query.empty()) {
        const std::size_t amp = query.find('&');
        const std::string_view raw = query.substr(0, amp);
        query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
        if (raw.empty()) continue;
        const std::size_t eq = raw.find('=');
        QueryPair p;
        if (!decode(raw.substr(0, eq), p.name) ||
            (eq != std::string_view::npos && !decode(raw.substr(eq + 1), p.value)))
            on_note(quoted(raw) + ": a malformed escape (a '%' not followed by two hex digits)");
        else if (!scene::valid_utf8(p.name) || !scene::valid_utf8(p.value))
            on_note(quoted(raw) + ": not UTF-8 once decoded");
        else
            on_pair(std::move(p));
    }
}

}  // namespace

std::vector<QueryPair> parse_query(std::string_view query, std::vector<std::string>& notes) {
    std::vector<QueryPair> pairs;
    for_each_pair(
        query, [&](QueryPair p) { pairs.push_back(std::move(p)); },
        [&](std::string note) { notes.push_back(std::move(note)); });
    return pairs;
}

std::vector<std::string> apply_query(
    std::string_view query, const std::function<std::string(std::string_view, std::string_view)>& set_option) {
    std::vector<std::string> notes;
    for_each_pair(
        query,
        [&](const QueryPair& p) {
            if (std::string err = set_option(p.name, p.value); !err.empty()) notes.push_back(one_line(std::move(err)));
        },
        [&](std::string note) { notes.push_back(std::move(note)); });
    return notes;
}

}  // namespace penumbra::examples
