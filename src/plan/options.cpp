#include "plan/options.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "plan/post.h"

#ifdef __EMSCRIPTEN__
// JavaScript's Number() over `length` ASCII bytes that read_number has checked are a decimal:
// src/platform/emscripten_number.js, a JavaScript library every module of the web build links.
extern "C" double penumbra_js_number(const char* text, int length);
#endif

namespace penumbra::render {

bool Job::operator==(const Job& o) const {
    return scene == o.scene && time == o.time && width == o.width && height == o.height && out == o.out &&
           frames == o.frames && budget_ms == o.budget_ms && max_error == o.max_error && eye_in_shadow == o.eye_in_shadow;
}

// ---- parsing ----------------------------------------------------------------------------------

bool parse_int(std::string_view v, int& out) {
    if (v.empty() || v.size() > 11) return false;
    const std::string s(v);
    char* end = nullptr;
    const long x = std::strtol(s.c_str(), &end, 10);
    if (end != s.c_str() + s.size() || std::isspace(static_cast<unsigned char>(s.front()))) return false;
    if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max()) return false;
    out = static_cast<int>(x);
    return true;
}

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// `v` from `at` on, case aside, is `word`.
bool rest_is(std::string_view v, size_t at, std::string_view word) {
    if (v.size() - at != word.size()) return false;
    for (size_t i = 0; i < word.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(v[at + i])) != word[i]) return false;
    return true;
}

}  // namespace

bool read_number(std::string_view v, double& out) {
    size_t i = 0;
    const bool minus = !v.empty() && v[0] == '-';
    if (!v.empty() && (v[0] == '-' || v[0] == '+')) ++i;
    if (rest_is(v, i, "inf") || rest_is(v, i, "infinity")) {
        out = minus ? -HUGE_VAL : HUGE_VAL;
        return true;
    }
    if (rest_is(v, i, "nan")) {
        out = std::nan("");
        return true;
    }
    // [+-] digits [. digits] | [+-] . digits, then [eE [+-] digits]: the whole text.
    size_t digits = 0;
    for (; i < v.size() && is_digit(v[i]); ++i) ++digits;
    if (i < v.size() && v[i] == '.')
        for (++i; i < v.size() && is_digit(v[i]); ++i) ++digits;
    if (digits == 0) return false;
    if (i < v.size() && (v[i] == 'e' || v[i] == 'E')) {
        ++i;
        if (i < v.size() && (v[i] == '-' || v[i] == '+')) ++i;
        if (i == v.size() || !is_digit(v[i])) return false;
        while (i < v.size() && is_digit(v[i])) ++i;
    }
    if (i != v.size()) return false;
#ifdef __EMSCRIPTEN__
    out = penumbra_js_number(v.data(), static_cast<int>(v.size()));
#else
    out = std::strtod(std::string(v).c_str(), nullptr);
#endif
    return true;
}

bool parse_number(std::string_view v, double& out) {
    double x = 0.0;
    if (!read_number(v, x) || !std::isfinite(x)) return false;
    out = x;
    return true;
}

bool parse_size(std::string_view v, int& w, int& h) {
    const auto x = v.find('x');
    return x != std::string_view::npos && parse_int(v.substr(0, x), w) && parse_int(v.substr(x + 1), h);
}

// The shortest form that reads back as the same double: "0.6", not %.17g's "0.59999999999999998".
// Read back by read_number, as the option is (in the pages, JavaScript's Number(): strtod would add
// libc's parser to every page).
std::string format_number(double v) {
    char buf[32];
    for (int precision = 1; precision < 17; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, v);
        double back = 0.0;
        if (read_number(buf, back) && back == v) return buf;
    }
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string shortest_float(float f) {
    for (int precision = 1; precision <= 9; ++precision) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.*g", precision, static_cast<double>(f));
        double back = 0.0;
        if (read_number(buf, back) && static_cast<float>(back) == f) return buf;
    }
    return format_number(static_cast<double>(f));
}

std::vector<std::string_view> list_items(std::string_view value) {
    std::vector<std::string_view> items;
    for (size_t start = 0; start <= value.size();) {
        size_t end = value.find(',', start);
        if (end == std::string_view::npos) end = value.size();
        items.push_back(value.substr(start, end - start));
        start = end + 1;
    }
    return items;
}

namespace {

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);  // 1000000, not 1e+06
    return buf;
}

std::string word_list(const std::vector<Choice>& choices, const char* quote = "") {
    std::string s;
    for (const Choice& c : choices) s += (s.empty() ? "" : ", ") + std::string(quote) + std::string(c.value) + quote;
    return s;
}

// "" when v lies in the option's range, else the rule it breaks.
std::string range_problem(const OptionInfo& o, double v) {
    const bool low = std::isfinite(o.min), high = std::isfinite(o.max);
    if ((!low || v >= o.min) && (!high || v <= o.max)) return {};
    if (low && high) return "must lie in [" + number_text(o.min) + ", " + number_text(o.max) + "]";
    if (low) return "must be at least " + number_text(o.min);
    return "must be at most " + number_text(o.max);
}

std::string range_words(const OptionInfo& o) {
    const bool low = std::isfinite(o.min), high = std::isfinite(o.max);
    if (low && high) return " in [" + number_text(o.min) + ", " + number_text(o.max) + "]";
    if (low) return " >= " + number_text(o.min);
    if (high) return " <= " + number_text(o.max);
    return {};
}

}  // namespace

std::string accepted_values(const OptionInfo& o) {
    switch (o.type) {
        case OptionType::Choice:
            if (o.list && !o.choices.empty())
                return "a comma list of " + word_list({o.choices.begin() + 1, o.choices.end()}) + ", or " +
                       std::string(o.choices.front().value);
            return word_list(o.choices);
        case OptionType::Integer:
            return "a whole number" + range_words(o) + (o.choices.empty() ? std::string() : ", or " + word_list(o.choices));
        case OptionType::Number: return "a number" + range_words(o);
        case OptionType::Size: return "WIDTHxHEIGHT" + (std::isfinite(o.max) ? ", each <= " + number_text(o.max) : std::string());
        case OptionType::Text: return std::string(o.help);
        case OptionType::NumberOrWord: return "a number" + range_words(o) + ", or " + word_list(o.choices);
    }
    return {};
}

std::string check_value(const OptionInfo& o, std::string_view value) {
    const std::string opt = "--" + std::string(o.name) + ": ";
    const std::string quoted = "'" + scene::printable(value) + "'";  // one line, valid UTF-8
    const auto among = [&] {
        for (const Choice& c : o.choices)
            if (c.value == value) return true;
        return false;
    };
    // No value at all (`--time ''`, a page's `?time=`): the option named, and what it takes.
    if (value.empty() && !o.may_be_empty) return opt + "needs a value: " + accepted_values(o);
    switch (o.type) {
        case OptionType::Choice:
            if (o.list && !o.choices.empty() && value != o.choices.front().value) {
                // A comma list: each item one of the choices after the first, and each once.
                std::vector<std::string_view> seen;
                for (std::string_view item : list_items(value)) {
                    bool known = false;
                    for (size_t i = 1; i < o.choices.size(); ++i) known = known || o.choices[i].value == item;
                    if (!known)
                        return opt + "unknown value '" + scene::printable(item) + "' in " + quoted + " (" +
                               accepted_values(o) + ")";
                    if (std::find(seen.begin(), seen.end(), item) != seen.end())
                        return opt + "'" + scene::printable(item) + "' twice in " + quoted;
                    seen.push_back(item);
                }
                return {};
            }
            if (!among()) return opt + "unknown value " + quoted + " (" + word_list(o.choices) + ")";
            return {};
        case OptionType::Integer: {
            if (among()) return {};  // a word it also takes (--map-size auto)
            int v = 0;
            if (!parse_int(value, v))
                return opt + "not a whole number: " + quoted +
                       (o.choices.empty() ? std::string() : " (or " + word_list(o.choices, "'") + ")");
            if (std::string r = range_problem(o, v); !r.empty()) return opt + r + ", got " + quoted;
            return {};
        }
        case OptionType::Number:
        case OptionType::NumberOrWord: {
            if (o.type == OptionType::NumberOrWord && among()) return {};
            double v = 0.0;
            if (!parse_number(value, v)) {
                double x = 0.0;
                if (read_number(value, x) && !std::isfinite(x))
                    return opt + "must be a finite number" + range_words(o) + ", got " + quoted;
                return opt + "not a number: " + quoted +
                       (o.type == OptionType::NumberOrWord ? " (or " + word_list(o.choices, "'") + ")" : "");
            }
            if (std::string r = range_problem(o, v); !r.empty()) return opt + r + ", got " + quoted;
            return {};
        }
        case OptionType::Size: {
            int w = 0, h = 0;
            if (!parse_size(value, w, h)) return opt + "expected WIDTHxHEIGHT, got " + quoted;
            if (w < 1 || h < 1) return opt + "width and height must be at least 1, got " + quoted;
            if (std::isfinite(o.max) && (w > o.max || h > o.max))
                return opt + "width and height must be at most " + number_text(o.max) + " (the maximum), got " + quoted;
            return {};
        }
        case OptionType::Text:
            if (o.form)
                if (std::string why = o.form(value); !why.empty()) return opt + why + ", got " + quoted;
            return {};
    }
    return {};
}

std::string parse_list(const OptionInfo& o, std::string_view text, std::vector<std::string>& out) {
    std::vector<std::string> items;
    for (std::string_view item : list_items(text)) {
        if (std::string err = check_value(o, item); !err.empty()) return err;
        items.emplace_back(item);
    }
    out.insert(out.end(), items.begin(), items.end());
    return {};
}

// An option's entry in the table (option_table.cpp).
OptionInfo make_option_info(std::string_view name, OptionPart part, OptionType type, std::string_view help,
                            std::string_view label, std::vector<Choice> choices) {
    OptionInfo o;
    o.name = name;
    o.part = part;
    o.type = type;
    o.help = help;
    o.label = label;
    o.choices = std::move(choices);
    return o;
}

std::string parse_option(Options& o, std::string_view name, std::string_view value) {
    return set_option(option_table(), o, name, value);
}

std::string parse_option(Settings& s, std::string_view name, std::string_view value) {
    const auto* o = find_option(option_table(), name);
    if (o && o->info.part != OptionPart::Technique) return "--" + scene::printable(name) + ": not a technique setting";
    Options all;
    all.settings = s;
    std::string err = parse_option(all, name, value);
    if (err.empty()) s = all.settings;
    return err;
}

std::vector<std::pair<std::string, std::string>> to_pairs(const Options& o) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& opt : option_table()) out.emplace_back(std::string(opt.info.name), opt.print(o));
    return out;
}

std::vector<std::pair<std::string, std::string>> to_pairs(const Settings& s) {
    Options o;
    o.settings = s;
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& opt : option_table())
        if (opt.info.part == OptionPart::Technique) out.emplace_back(std::string(opt.info.name), opt.print(o));
    return out;
}

namespace {
std::string args_of(const std::vector<std::pair<std::string, std::string>>& pairs) {
    std::string out;
    for (const auto& [k, v] : pairs) {
        // No file, no budget and no error target, the defaults, say nothing (a logged command line stays as it was).
        if ((k == "out" && v.empty()) || ((k == "budget-ms" || k == "max-error") && v == "0")) continue;
        out += (out.empty() ? "--" : " --") + k + " " + scene::printable(v);  // a log's one line
    }
    return out;
}
}  // namespace

std::string to_args(const Options& o) { return args_of(to_pairs(o)); }
std::string to_args(const Settings& s) { return args_of(to_pairs(s)); }

}  // namespace penumbra::render
