// One option table. Every setting is declared once, in option_table.cpp (or, for what only the course exercises
// have, in examples/exercise_list.cpp with the same types): its name, type, choices, default, help
// and whether it belongs to the technique (render::Settings) or to the job (render::Job). The
// command line (`penumbra`, `penumbra-desktop`), their --help, the -v printout, the pages' URL
// parameters and controls (generated from the table at build time), the bench's lists and --set
// all read it. Values are checked in one place (check_value) and every error names the option and
// what it accepts.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "plan/settings.h"
#include "scene/printable.h"

namespace penumbra::render {

// The bounds of the job's numbers (the table's ranges, the measuring commands' too).
inline constexpr int kMaxImageSide = 16384;    // --size: each side (llvmpipe's and most GPUs' maximum)
inline constexpr int kMaxFrames = 10000;       // --frames (render, plan, bench)
inline constexpr double kMaxTime = 1e6;        // --time: seconds, either sign (about 11 days)
inline constexpr double kMaxBudgetMs = 1e4;    // --budget-ms: 10 s a frame
inline constexpr double kMaxErrorPct = 100.0;  // --max-error: % of the image
inline constexpr int kMaxMapSize = 65536;      // --map-size (the context clamps it further, with a note)
inline constexpr int kMaxSoftSamples = 16384;  // --soft-samples of truth and bench (area-light rays per pixel)
inline constexpr double kMaxLightRadius = 1e6; // --light-radius

// The job part: what to render and where the result goes.
struct Job {
    std::string scene = "teapot";  // "teapot" or a .gltf/.glb path
    double time = 0.0;             // seconds; animation is a pure function of it
    int width = 512;
    int height = 512;
    std::string out;  // PNG path; empty: write nothing
    int frames = 1;
    // --budget-ms: the most accurate shadow-map settings whose frames fit this many ms, chosen from
    // the frames' measured times (plan/budget.h); 0: off, the settings as given.
    double budget_ms = 0.0;
    // --max-error: the least work predicted to keep the frame within this % of the hard truth
    // (tools/penumbra/max_error.h); 0: off.
    double max_error = 0.0;
    bool eye_in_shadow = false;  // --eye in-shadow: scene::place_eye_in_shadow
    bool operator==(const Job& o) const;
};

// Everything `penumbra render` takes.
struct Options {
    Settings settings;
    Job job;
    bool operator==(const Options& o) const { return settings == o.settings && job == o.job; }
};

enum class OptionPart { Technique, Job };
enum class OptionType {
    Choice,        // one of `choices` (with `list`: a comma list of them, each once, or the first alone)
    Integer,       // a whole number in [min, max], or one of `choices` where it has any (--map-size auto)
    Number,        // a finite number in [min, max]
    Size,          // WIDTHxHEIGHT, each a whole number in [1, max]
    Text,          // any non-empty text
    NumberOrWord,  // a number in [min, max] or one of `choices` (bias: default, auto)
};

struct Choice {
    std::string_view value;  // as typed: "r8"
    std::string_view label;  // as a page shows it: "8-bit red (r8)"
};

// What every option declares, whatever it is stored in.
struct OptionInfo {
    std::string_view name;  // --name, ?name=, the desktop's --name
    OptionPart part = OptionPart::Technique;
    OptionType type = OptionType::Text;
    std::string_view help;   // one line for --help
    std::string_view label;  // a page control's label
    std::vector<Choice> choices;
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    std::vector<Choice> presets;            // Integer, Text: the values a page's select offers
    double step = 0.0;                      // Number(OrWord): a page's number box step (0: any)
    bool may_be_empty = false;              // Text: "" is a value (--out: write nothing)
    // Choice: a comma list of distinct choices in any order ("outline,mirror"); the first choice
    // ("none") stands alone. --effects.
    bool list = false;
    // Text: the form the value must have, "" or what is wrong with it (nullptr: any text).
    std::string (*form)(std::string_view value) = nullptr;
};

// An OptionInfo with the fields every option has; range, presets and step are set after.
OptionInfo make_option_info(std::string_view name, OptionPart part, OptionType type, std::string_view help,
                            std::string_view label, std::vector<Choice> choices = {});

// An option stored in a `Target` (render::Options here; the exercises' toggles in examples/).
template <typename Target>
struct Option {
    OptionInfo info;
    void (*store)(Target&, std::string_view checked);  // the value has passed check_value
    std::string (*print)(const Target&);              // what check_value reads back
};

// "" when `value` is of the option's type, among its choices and in its range; otherwise one line
// naming the option and what it accepts ("--encoding: unknown value 'r16' (r8, rgba, depthtex)").
std::string check_value(const OptionInfo& option, std::string_view value);

// What an option accepts, in words ("r8, rgba, depthtex"; "a whole number >= 1").
std::string accepted_values(const OptionInfo& option);

template <typename Target>
const Option<Target>* find_option(const std::vector<Option<Target>>& table, std::string_view name) {
    for (const auto& o : table)
        if (o.info.name == name) return &o;
    return nullptr;
}

// Checks and stores one option; "" or the problem, and `target` unchanged on a problem.
template <typename Target>
std::string set_option(const std::vector<Option<Target>>& table, Target& target, std::string_view name,
                       std::string_view value) {
    const Option<Target>* o = find_option(table, name);
    if (!o) return "unknown option --" + scene::printable(name);
    if (std::string err = check_value(o->info, value); !err.empty()) return err;
    o->store(target, value);
    return {};
}

// The renderer's and the job's options, in printing order.
const std::vector<Option<Options>>& option_table();
const OptionInfo& option_info(std::string_view name);  // one of option_table()'s; throws if unknown

// parse_option: set_option over option_table().
std::string parse_option(Options& o, std::string_view name, std::string_view value);
// A technique option alone (a job option is refused with "--size: not a technique setting").
std::string parse_option(Settings& s, std::string_view name, std::string_view value);

// Every option (or every one of `part`) with its value, as parse_option reads it back.
std::vector<std::pair<std::string, std::string>> to_pairs(const Options& o);
std::vector<std::pair<std::string, std::string>> to_pairs(const Settings& s);
// "--scene teapot --time 0 ..." for labels and logs (an empty --out is left out; each value through
// scene::printable, so the line stays one line).
std::string to_args(const Options& o);
std::string to_args(const Settings& s);

// ---- the parsing every command line shares ------------------------------------------------------
// Whole text only: "12" yes, "12x", "1.5", " 3" no.
bool parse_int(std::string_view text, int& out);
// A finite number as people type it (1e-3, .5); no trailing text, no inf or nan.
bool parse_number(std::string_view text, double& out);
// The whole text as a decimal number ([+-] digits [. digits] [e [+-] digits], or .5) or inf,
// infinity, nan (any case): what strtod reads but hexadecimal, leading spaces and trailing text.
// The value is correctly rounded: natively by strtod, in the browser by JavaScript's Number()
// (exact to 20 significant digits, and %.17g prints 17), which keeps the C library's strtod and
// the long-double arithmetic it needs (6.3 KB gzipped) out of every page's module.
bool read_number(std::string_view text, double& out);
// "640x360".
bool parse_size(std::string_view text, int& width, int& height);
// The items of a comma list ("outline,mirror"), empty ones included ("a,,b" has three).
std::vector<std::string_view> list_items(std::string_view value);
// "a,b,c" -> each checked as a value of `option`; "" or the first problem.
std::string parse_list(const OptionInfo& option, std::string_view text, std::vector<std::string>& out);
// The shortest text that reads back as the same float (a URL's 0.003, not 0.0030000000260770321).
std::string shortest_float(float v);
std::string format_number(double v);  // 17 significant digits, as the table prints a double

}  // namespace penumbra::render
