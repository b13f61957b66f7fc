#include "gl/uniforms.h"

#include <cctype>
#include <sstream>
#include <vector>

namespace penumbra::gl {

namespace {

struct Block {
    bool parent_active = true;
    bool active = true;
    bool taken = false;    // a branch of this #if chain was active
    bool unknown = false;  // the chain's conditions could not be decided: every branch counts
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The identifier at the start of `s` (after blanks).
std::string_view first_word(std::string_view s) {
    s = trim(s);
    size_t n = 0;
    while (n < s.size() && identifier_char(s[n])) ++n;
    return s.substr(0, n);
}

// "defined(NAME)" or "defined NAME" (optionally negated with !) as a whole condition; otherwise
// no name and the condition is undecided.
bool defined_condition(std::string_view cond, std::string& name, bool& negated) {
    cond = trim(cond);
    negated = !cond.empty() && cond.front() == '!';
    if (negated) cond = trim(cond.substr(1));
    if (cond.substr(0, 7) != "defined") return false;
    cond = trim(cond.substr(7));
    const bool paren = !cond.empty() && cond.front() == '(';
    if (paren) cond = trim(cond.substr(1));
    const std::string_view word = first_word(cond);
    if (word.empty()) return false;
    cond = trim(cond.substr(word.size()));
    if (paren) {
        if (cond.empty() || cond.front() != ')') return false;
        cond = trim(cond.substr(1));
    }
    if (!cond.empty()) return false;
    name = std::string(word);
    return true;
}

// Decides `name`'s state; GL_ macros are the compiler's, not the source's: undecided.
bool known(const std::string& name) { return name.rfind("GL_", 0) != 0; }

void add_uniforms(std::string_view line, std::set<std::string>& out) {
    // uniform [precision] type name[N] {, name[N]} ;
    for (size_t at = line.find("uniform"); at != std::string_view::npos; at = line.find("uniform", at + 7)) {
        if (at > 0 && identifier_char(line[at - 1])) continue;
        const std::string_view rest = line.substr(at + 7);
        if (rest.empty() || identifier_char(rest.front())) continue;
        std::istringstream words{std::string(rest.substr(0, rest.find(';')))};
        std::string type;
        words >> type;
        if (type == "lowp" || type == "mediump" || type == "highp") words >> type;
        for (std::string item; std::getline(words, item, ',');) {
            const std::string_view name = first_word(item);
            if (!name.empty()) out.insert(std::string(name));
        }
    }
}

}  // namespace

std::set<std::string> declared_uniforms(std::string_view source) {
    std::set<std::string> out, defined;
    std::vector<Block> stack;
    const auto active = [&] { return stack.empty() || (stack.back().parent_active && stack.back().active); };
    size_t start = 0;
    while (start <= source.size()) {
        size_t end = source.find('\n', start);
        if (end == std::string_view::npos) end = source.size();
        std::string_view line = source.substr(start, end - start);
        start = end + 1;
        // Comments: drop // to the end of the line (block comments hold no directives here).
        if (const size_t c = line.find("//"); c != std::string_view::npos) line = line.substr(0, c);
        const std::string_view t = trim(line);
        if (!t.empty() && t.front() == '#') {
            const std::string_view body = trim(t.substr(1));
            const std::string_view directive = first_word(body);
            const std::string_view arg = trim(body.substr(directive.size()));
            if (directive == "define" || directive == "undef") {
                if (active()) {
                    const std::string name(first_word(arg));
                    if (directive == "define") defined.insert(name);
                    else defined.erase(name);
                }
            } else if (directive == "ifdef" || directive == "ifndef" || directive == "if") {
                Block b;
                b.parent_active = active();
                std::string name;
                bool negated = directive == "ifndef";
                bool decided = false;
                if (directive == "if") {
                    decided = defined_condition(arg, name, negated);
                } else {
                    name = std::string(first_word(arg));
                    decided = true;
                }
                decided = decided && known(name);
                b.unknown = !decided;
                b.active = !decided || ((defined.count(name) > 0) != negated);
                b.taken = b.active;
                stack.push_back(b);
            } else if (directive == "elif" && !stack.empty()) {
                Block& b = stack.back();
                std::string name;
                bool negated = false;
                const bool decided = defined_condition(arg, name, negated) && known(name);
                if (!decided) b.unknown = true;
                b.active = b.unknown || (!b.taken && ((defined.count(name) > 0) != negated));
                b.taken = b.taken || b.active;
            } else if (directive == "else" && !stack.empty()) {
                Block& b = stack.back();
                b.active = b.unknown || !b.taken;
                b.taken = true;
            } else if (directive == "endif" && !stack.empty()) {
                stack.pop_back();
            }
            continue;
        }
        if (active()) add_uniforms(line, out);
    }
    return out;
}

}  // namespace penumbra::gl
