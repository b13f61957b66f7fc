#include "plan/snippets.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "plan/options.h"

namespace penumbra::render {

std::string_view snippet_name(SnippetFn f) {
    switch (f) {
        case SnippetFn::PackDepth: return "packDepth";
        case SnippetFn::UnpackDepth: return "unpackDepth";
        case SnippetFn::ShadowTest: return "shadowTest";
        case SnippetFn::OffsetLookup: return "offset_lookup";
    }
    return "";
}

std::string_view snippet_signature(SnippetFn f) {
    switch (f) {
        case SnippetFn::PackDepth: return "vec4 packDepth(float z)";
        case SnippetFn::UnpackDepth: return "float unpackDepth(const in vec4 rgbaDepth)";
        case SnippetFn::ShadowTest: return "float shadowTest(float zLight, float depth, float bias)";
        case SnippetFn::OffsetLookup: return "vec4 offset_lookup(sampler2D map, vec3 shadowCoord, vec2 offset)";
    }
    return "";
}

bool SnippetScan::defines_fn(SnippetFn f) const { return std::find(defines.begin(), defines.end(), f) != defines.end(); }

namespace {

struct Token {
    enum Kind { Name, Number, Punct } kind;
    std::string text;
    int line;
};

// Tokens of GLSL ES 1.00 text, comments dropped; a '#' or a byte outside printable ASCII (and tab,
// CR, LF) is a problem and the scan stops there.
std::vector<Token> tokenize(std::string_view s, std::vector<SnippetProblem>& problems) {
    std::vector<Token> out;
    int line = 1;
    const auto head = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
    const auto tail = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    static const char* const kTwo[] = {"++", "--", "+=", "-=", "*=", "/=", "<=", ">=", "==", "!=", "&&", "||", "^^"};
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') {
            ++line;
            ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
            continue;
        }
        if (u < 0x20 || u > 0x7e) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "byte 0x%02X is not printable ASCII (GLSL ES 1.00 source is ASCII)", u);
            problems.push_back({line, buf});
            return out;
        }
        // Comments may hold any byte but NUL (a student's own language: snippet_block writes it as '?').
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n' && s[i] != '\0') ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            const int start = line;
            size_t j = i + 2;
            while (j + 1 < s.size() && !(s[j] == '*' && s[j + 1] == '/') && s[j] != '\0') line += s[j++] == '\n';
            if (j < s.size() && s[j] == '\0') {
                i = j;
                continue;  // said at the NUL
            }
            if (j + 1 >= s.size()) {
                problems.push_back({start, "a /* comment is never closed"});
                return out;
            }
            i = j + 2;
            continue;
        }
        if (c == '#') {
            problems.push_back({line, "preprocessor directives (#...) are not allowed: the snippets are compiled inside "
                                      "the renderer's shader, whose #defines they would reach"});
            return out;
        }
        if (head(c)) {
            size_t j = i;
            while (j < s.size() && tail(s[j])) ++j;
            out.push_back({Token::Name, std::string(s.substr(i, j - i)), line});
            i = j;
            continue;
        }
        if (std::isdigit(u) || (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            size_t j = i;
            while (j < s.size() && (tail(s[j]) || s[j] == '.' ||
                                    ((s[j] == '+' || s[j] == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
                ++j;
            out.push_back({Token::Number, std::string(s.substr(i, j - i)), line});
            i = j;
            continue;
        }
        std::string p(1, c);
        if (i + 1 < s.size())
            for (const char* two : kTwo)
                if (s[i] == two[0] && s[i + 1] == two[1]) p = two;
        out.push_back({Token::Punct, p, line});
        i += p.size();
    }
    return out;
}

bool reserved_name(const std::string& n) {
    static const char* const kPrefixes[] = {"u_", "a_", "v_", "g_", "gl_", "penumbra", "PENUMBRA"};
    for (const char* p : kPrefixes)
        if (n.rfind(p, 0) == 0) return true;
    return n == "main";
}

bool type_name(const std::string& n) {
    static const char* const kTypes[] = {"void",  "float", "int",   "bool",  "vec2",  "vec3", "vec4",      "ivec2",
                                         "ivec3", "ivec4", "bvec2", "bvec3", "bvec4", "mat2", "mat3",      "mat4",
                                         "sampler2D", "samplerCube"};
    for (const char* t : kTypes)
        if (n == t) return true;
    return false;
}

// The contract's function of that name, if it is one.
bool contract_fn(const std::string& name, SnippetFn& f) {
    for (SnippetFn g : kAllSnippetFns)
        if (snippet_name(g) == name) {
            f = g;
            return true;
        }
    return false;
}

// The parameter types of a contract function, and its return type.
std::vector<std::string> contract_types(SnippetFn f) {
    switch (f) {
        case SnippetFn::PackDepth: return {"vec4", "float"};
        case SnippetFn::UnpackDepth: return {"float", "vec4"};
        case SnippetFn::ShadowTest: return {"float", "float", "float", "float"};
        case SnippetFn::OffsetLookup: return {"vec4", "sampler2D", "vec3", "vec2"};
    }
    return {};
}

// A number token's value ("1.5", "2", "1e-3", "0x1F"; "017" is 17, as C's strtod reads it).
bool number_value(const std::string& t, double& v) {
    if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) {
        if (!std::all_of(t.begin() + 2, t.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; }))
            return false;
        v = static_cast<double>(std::strtoull(t.c_str() + 2, nullptr, 16));
        return true;
    }
    return read_number(t, v);
}

struct Call {
    std::string callee;
    double times;
};

struct Function {
    std::string name;
    int line = 0;
    size_t body_begin = 0, body_end = 0;  // tokens inside the braces
    std::vector<Call> calls;              // Scanner::loops
    double cost = -1;                     // -1: not yet, -2: being computed (a cycle)
};

class Scanner {
public:
    Scanner(const std::vector<Token>& t, std::vector<SnippetProblem>& p) : t_(t), problems_(p) {}

    void run(SnippetScan& scan) {
        keywords();
        if (!problems_.empty()) return;
        functions(scan);
        if (!problems_.empty()) return;
        // Every loop must lie in a function the scan read, or its count and cost go unchecked.
        for (size_t i = 0; i < t_.size(); ++i)
            if (t_[i].text == "for" && std::none_of(fns_.begin(), fns_.end(), [&](const Function& f) {
                    return i >= f.body_begin && i < f.body_end;
                })) {
                problem(i, "a loop outside a function of a built-in return type");
                return;
            }
        for (Function& f : fns_) f.calls = loops(f);
        if (!problems_.empty()) return;
        for (Function& f : fns_) {
            SnippetFn c;
            if (!contract_fn(f.name, c)) continue;
            const double cost = cost_of(f.name);
            if (cost < 0) return;  // a cycle, said
            if (cost > kMaxSnippetCost)
                problems_.push_back({f.line, f.name + " does about " + std::to_string(static_cast<long long>(cost)) +
                                                 " steps per call (loop iterations and calls); at most " +
                                                 std::to_string(kMaxSnippetCost) + " are allowed, it runs per pixel"});
        }
    }

private:
    const Token& at(size_t i) const {
        static const Token kEnd{Token::Punct, "", 0};
        return i < t_.size() ? t_[i] : kEnd;
    }
    void problem(size_t i, std::string m) { problems_.push_back({at(i).line, std::move(m)}); }

    void keywords() {
        for (size_t i = 0; i < t_.size(); ++i) {
            const Token& k = t_[i];
            if (k.kind != Token::Name) continue;
            if (k.text == "uniform" || k.text == "attribute" || k.text == "varying")
                problem(i, "declares a " + k.text + " of its own: the lab's functions get what they need as parameters "
                                                    "(and texmapscale)");
            else if (k.text == "main")
                problem(i, "defines or names main: the renderer's shader has its own; write only the sheet's functions");
            else if (k.text == "while" || k.text == "do")
                problem(i, "a " + k.text + " loop: GLSL ES 1.00 (appendix A) allows only for loops with constant bounds");
            else if (k.text == "out" || k.text == "inout")
                problem(i, "an " + k.text + " parameter: the lab's functions return their result");
            else if (k.text == "struct")
                // (a function returning one would also escape the loop and cost checks, which look
                // at the functions whose return type is a built-in one)
                problem(i, "a struct: the lab's functions take and return the sheet's types");
            else if (k.text == "discard")
                problem(i, "discard: the lab's functions return a value, they do not drop the pixel");
            else if (k.text == "texmapscale" && i > 0 && type_name(at(i - 1).text))
                problem(i, "declares texmapscale: it is given (1/width, 1/height of the shadow map)");
            else if (reserved_name(k.text))
                problem(i, "the name " + k.text + " belongs to the renderer (u_, a_, v_, g_, gl_ and penumbra names)");
        }
    }

    // Every function definition at the top level, the contract's checked against their signatures.
    void functions(SnippetScan& scan) {
        int depth = 0;
        for (size_t i = 0; i < t_.size(); ++i) {
            const Token& k = t_[i];
            if (k.text == "{") ++depth;
            if (k.text == "}") --depth;
            if (depth < 0) {
                problem(i, "a } closes nothing");
                return;
            }
            if (depth != 0 || k.kind != Token::Name || at(i + 1).text != "(" || i == 0 || !type_name(at(i - 1).text)) continue;
            // name ( params ) { or ;
            size_t j = i + 2;
            std::vector<std::vector<std::string>> params(1);
            while (j < t_.size() && at(j).text != ")") {
                if (at(j).text == ",")
                    params.emplace_back();
                else
                    params.back().push_back(at(j).text);
                ++j;
            }
            if (at(j + 1).text != "{") continue;  // a prototype
            Function f{k.text, k.line, j + 2, j + 2, {}, -1};
            int d = 1;
            size_t e = j + 2;
            for (; e < t_.size() && d > 0; ++e) {
                if (at(e).text == "{") ++d;
                if (at(e).text == "}") --d;
            }
            if (d != 0) {
                problem(i, k.text + "'s { is never closed");
                return;
            }
            f.body_end = e - 1;
            for (const Function& g : fns_)
                if (g.name == f.name) problem(i, f.name + " is defined twice (first at line " + std::to_string(g.line) + ")");
            SnippetFn c;
            if (contract_fn(f.name, c)) {
                // Types: the return type and each parameter's type (its last but one word, or its
                // only one: "const in highp vec4 rgba" -> vec4).
                std::vector<std::string> types{at(i - 1).text};
                for (const auto& p : params) {
                    if (p.empty()) continue;
                    std::string type;
                    for (const auto& w : p)
                        if (type_name(w)) type = w;
                    types.push_back(type);
                }
                if (types != contract_types(c))
                    problem(i, f.name + " must be " + std::string(snippet_signature(c)) + " (the contract's signature)");
                else
                    scan.defines.push_back(c);
            }
            fns_.push_back(f);
        }
        if (depth != 0) problems_.push_back({at(t_.size() - 1).line, "a { is never closed"});
        std::vector<SnippetFn> ordered;  // in kAllSnippetFns' order
        for (SnippetFn f : kAllSnippetFns)
            if (std::find(scan.defines.begin(), scan.defines.end(), f) != scan.defines.end()) ordered.push_back(f);
        scan.defines = ordered;
    }

    // The for loops of a function's body: each header `for (T i = A; i OP B; STEP)` with literal
    // A and B, run here to count its iterations; no assignment to i in the body; loops nested at
    // most kMaxLoopDepth deep. Returns the calls of named functions, each times the iterations of
    // the loops around it.
    std::vector<Call> loops(const Function& f) {
        struct Loop {
            std::string index;
            double iterations;
            int brace;   // the brace depth its braced body closes at; -1: a single statement
            int parens;  // the paren depth of the statement
        };
        std::vector<Loop> stack;
        std::vector<Call> calls;
        double mult = 1;
        int brace = 0, parens = 0;
        const auto pop_singles = [&]() {
            while (!stack.empty() && stack.back().brace < 0 && parens == stack.back().parens) {
                mult /= stack.back().iterations;
                stack.pop_back();
            }
        };
        for (size_t i = f.body_begin; i < f.body_end; ++i) {
            const Token& k = t_[i];
            if (k.text == "for") {
                Loop l{};
                if (!for_header(i, l.index, l.iterations)) return calls;
                if (stack.size() + 1 > static_cast<size_t>(kMaxLoopDepth)) {
                    problem(i, "loops nested more than " + std::to_string(kMaxLoopDepth) + " deep");
                    return calls;
                }
                // skip to the header's closing paren
                int d = 0;
                size_t j = i + 1;
                for (; j < f.body_end; ++j) {
                    if (at(j).text == "(") ++d;
                    if (at(j).text == ")" && --d == 0) break;
                }
                l.parens = parens;
                if (at(j + 1).text == "{") {
                    l.brace = brace + 1;
                } else {
                    l.brace = -1;
                }
                stack.push_back(l);
                mult *= l.iterations;
                calls.push_back({"", mult});  // the iterations themselves: a step each
                i = j;
                continue;
            }
            if (k.text == "{") ++brace;
            if (k.text == "}") {
                --brace;
                while (!stack.empty() && stack.back().brace == brace + 1) {
                    mult /= stack.back().iterations;
                    stack.pop_back();
                    pop_singles();
                }
            }
            if (k.text == "(") ++parens;
            if (k.text == ")") --parens;
            if (k.text == ";") pop_singles();
            if (k.kind == Token::Name) {
                for (const Loop& l : stack)
                    if (k.text == l.index) {
                        const std::string& next = at(i + 1).text;
                        const std::string& prev = at(i - 1).text;
                        const bool assigned = next == "=" || next == "+=" || next == "-=" || next == "*=" ||
                                              next == "/=" || next == "++" || next == "--" || prev == "++" ||
                                              prev == "--";
                        if (assigned)
                            problem(i, "assigns the loop index " + k.text +
                                           " in the loop's body (GLSL ES 1.00 appendix A: the index is constant there)");
                    }
                if (at(i + 1).text == "(") calls.push_back({k.text, mult});
            }
        }
        return calls;
    }

    // `for ( [type] i = A ; i OP B ; STEP )` at token i ("for"): its index and how many times it runs.
    bool for_header(size_t i, std::string& index, double& iterations) {
        size_t j = i + 1;
        const auto expect = [&](const char* s) { return at(j).text == s ? (++j, true) : false; };
        const auto number = [&](double& v) {
            bool neg = false;
            if (at(j).text == "-" || at(j).text == "+") neg = at(j++).text == "-";
            if (at(j).kind != Token::Number || !number_value(at(j).text, v)) return false;
            if (neg) v = -v;
            ++j;
            return true;
        };
        const std::string bad = "a for loop must read `for (int i = A; i < B; ++i)` with literal numbers A and B "
                                "(GLSL ES 1.00 appendix A; the lab runs it per pixel)";
        if (!expect("(")) return problem(i, bad), false;
        if (type_name(at(j).text)) ++j;
        if (at(j).kind != Token::Name) return problem(i, bad), false;
        index = at(j++).text;
        double a = 0, b = 0, step = 0;
        if (!expect("=") || !number(a) || !expect(";")) return problem(i, bad), false;
        if (at(j).text != index) return problem(i, bad), false;
        ++j;
        const std::string op = at(j++).text;
        if (op != "<" && op != "<=" && op != ">" && op != ">=" && op != "!=") return problem(i, bad), false;
        if (!number(b) || !expect(";")) return problem(i, bad), false;
        if ((at(j).text == "++" || at(j).text == "--") && at(j + 1).text == index) {
            step = at(j).text == "++" ? 1 : -1;
            j += 2;
        } else if (at(j).text == index && (at(j + 1).text == "++" || at(j + 1).text == "--")) {
            step = at(j + 1).text == "++" ? 1 : -1;
            j += 2;
        } else if (at(j).text == index && (at(j + 1).text == "+=" || at(j + 1).text == "-=")) {
            const bool minus = at(j + 1).text == "-=";
            j += 2;
            if (!number(step)) return problem(i, bad), false;
            if (minus) step = -step;
        } else {
            return problem(i, bad), false;
        }
        if (!expect(")")) return problem(i, bad), false;
        iterations = 0;
        double x = a;
        const auto holds = [&](double v) {
            if (op == "<") return v < b;
            if (op == "<=") return v <= b;
            if (op == ">") return v > b;
            if (op == ">=") return v >= b;
            return v != b;
        };
        while (holds(x) && iterations <= kMaxLoopIterations) {
            ++iterations;
            x += step;
        }
        if (iterations > kMaxLoopIterations) {
            problem(i, "this loop runs more than " + std::to_string(kMaxLoopIterations) +
                           " times (or never ends); the lab's loops are short, they run per pixel");
            return false;
        }
        iterations = std::max(iterations, 1.0);
        return true;
    }

    // Steps per call of `name`: 1, plus each call's times its callee's cost. -1 on a cycle.
    double cost_of(const std::string& name) {
        auto f = std::find_if(fns_.begin(), fns_.end(), [&](const Function& g) { return g.name == name; });
        if (f == fns_.end()) return 1;  // a built-in (texture2D, dot, ...), or "": one step
        if (f->cost == -2) {
            problems_.push_back({f->line, name + " calls itself (recursion is not allowed in GLSL ES 1.00)"});
            return -1;
        }
        if (f->cost >= 0) return f->cost;
        f->cost = -2;
        double cost = 1;
        const std::vector<Call>& calls = f->calls;  // fns_ is not resized below
        for (const Call& c : calls) {
            const double sub = cost_of(c.callee);
            if (sub < 0) return -1;
            cost += c.times * sub;
        }
        f = std::find_if(fns_.begin(), fns_.end(), [&](const Function& g) { return g.name == name; });
        f->cost = cost;
        return cost;
    }

    const std::vector<Token>& t_;
    std::vector<SnippetProblem>& problems_;
    std::vector<Function> fns_;
};

}  // namespace

SnippetScan scan_snippets(std::string_view text) {
    SnippetScan scan;
    if (text.size() > kMaxSnippetBytes) {
        scan.problems.push_back({0, "the file holds " + std::to_string(text.size()) + " bytes; a snippets file may hold " +
                                        std::to_string(kMaxSnippetBytes)});
        return scan;
    }
    const std::vector<Token> tokens = tokenize(text, scan.problems);
    if (!scan.problems.empty()) return scan;
    Scanner(tokens, scan.problems).run(scan);
    if (!scan.problems.empty()) scan.defines.clear();
    return scan;
}

std::vector<SnippetProblem> snippet_log_problems(std::string_view log) {
    std::vector<SnippetProblem> out;
    const std::string src = std::to_string(kSnippetSourceString);
    size_t start = 0;
    while (start < log.size()) {
        size_t end = log.find('\n', start);
        if (end == std::string_view::npos) end = log.size();
        std::string line(log.substr(start, end - start));
        start = end + 1;
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        // Find "7:N" or "7(N)" where 7 starts a number (not the tail of one).
        int at = 0;
        size_t msg = std::string::npos;
        for (size_t i = 0; i + src.size() < line.size(); ++i) {
            if (line.compare(i, src.size(), src) != 0) continue;
            if (i > 0 && std::isdigit(static_cast<unsigned char>(line[i - 1]))) continue;
            const size_t j = i + src.size();
            const char sep = line[j];
            if (sep != ':' && sep != '(') continue;
            size_t k = j + 1;
            int n = 0;
            // A line number of at most 7 digits (a snippets file has fewer lines than bytes).
            while (k < line.size() && std::isdigit(static_cast<unsigned char>(line[k])) && n < 10000000)
                n = n * 10 + (line[k++] - '0');
            if (k == j + 1 || n <= 0 || (k < line.size() && std::isdigit(static_cast<unsigned char>(line[k])))) continue;
            if (sep == '(' && (k >= line.size() || line[k] != ')')) continue;
            at = n;
            msg = k;
            break;
        }
        std::string text = line;
        if (msg != std::string::npos) {
            // Drop the location's tail ("(12)", ")", ":" and spaces) before the message.
            size_t m = msg;
            if (m < line.size() && line[m] == '(')
                while (m < line.size() && line[m] != ')') ++m;
            while (m < line.size() && (line[m] == ')' || line[m] == ':' || line[m] == ' ')) ++m;
            text = line.substr(m);
        }
        while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\0')) text.pop_back();
        if (!text.empty()) out.push_back({at, text});
    }
    return out;
}

}  // namespace penumbra::render
