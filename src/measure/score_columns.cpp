#include "measure/score_columns.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace penumbra::measure {

namespace {

double pct_of_valid(std::size_t count, const Score& s) {
    return s.valid ? 100.0 * static_cast<double>(count) / static_cast<double>(s.valid) : 0.0;
}

}  // namespace

const std::vector<ScoreColumn>& score_columns() {
    // key, heading, digits, table_digits, optional, required, meaning, get, set
    static const std::vector<ScoreColumn> columns = {
        {"valid_pixels", "valid pixels", 0, -1, false, true,
         "pixels compared: those the truth marks valid (not background, a silhouette band, a non-receiver, "
         "facing away from the light or outside a spot light's cone)",
         [](const Score& s) -> std::optional<double> { return static_cast<double>(s.valid); },
         [](Score& s, double v) { s.valid = static_cast<std::size_t>(std::max(0.0, std::round(v))); }},
        {"truth_shadowed_pct", "truth shadowed %", 3, -1, false, false,
         "% of the valid pixels in shadow in the hard-shadow truth",
         [](const Score& s) -> std::optional<double> { return pct_of_valid(s.truth_shadowed, s); },
         [](Score& s, double v) {
             s.truth_shadowed = static_cast<std::size_t>(std::max(0.0, v / 100.0 * static_cast<double>(s.valid) + 0.5));
         }},
        {"false_shadow_pct", "false shadow %", 4, 2, false, true,
         "% of the valid pixels dark (visibility below one half) where the truth is lit: acne, over-darkening, blur "
         "spilling out of a shadow",
         [](const Score& s) -> std::optional<double> { return s.false_shadow_pct; },
         [](Score& s, double v) { s.false_shadow_pct = v; }},
        {"false_lit_pct", "false lit %", 4, 2, false, true,
         "% of the valid pixels not dark where the truth is shadowed: peter-panning, light leaks, lost thin casters",
         [](const Score& s) -> std::optional<double> { return s.false_lit_pct; },
         [](Score& s, double v) { s.false_lit_pct = v; }},
        {"error_pct", "error %", 4, 2, false, true, "false shadow % + false lit %",
         [](const Score& s) -> std::optional<double> { return s.error_pct; },
         [](Score& s, double v) { s.error_pct = v; }},
        {"mae_pct", "mean abs error %", 4, 2, false, true,
         "mean |rendered visibility - hard truth| over the valid pixels, %: the error, plus every grey of a filter",
         [](const Score& s) -> std::optional<double> { return s.mae_pct; },
         [](Score& s, double v) { s.mae_pct = v; }},
        {"mae_area_light_pct", "vs area light %", 4, 2, true, false,
         "mean |rendered visibility - area-light truth| over the valid pixels, %; absent without an area-light truth "
         "(--soft-samples 0)",
         [](const Score& s) -> std::optional<double> {
             return s.mae_soft_pct >= 0.0 ? std::optional<double>(s.mae_soft_pct) : std::nullopt;
         },
         [](Score& s, double v) { s.mae_soft_pct = v; }},
        {"penumbra_pixels", "penumbra pixels", 0, -1, true, false,
         "valid pixels inside the penumbra: area-light truth strictly between 0 and 1 (partly lit); absent without an "
         "area-light truth",
         [](const Score& s) -> std::optional<double> {
             return s.mae_penumbra_pct >= 0.0 ? std::optional<double>(static_cast<double>(s.penumbra)) : std::nullopt;
         },
         [](Score& s, double v) { s.penumbra = static_cast<std::size_t>(std::max(0.0, std::round(v))); }},
        {"mae_penumbra_pct", "in penumbra %", 4, -1, true, false,
         "mean |rendered visibility - area-light truth| over the valid pixels whose area-light truth is strictly "
         "between 0 and 1 (the penumbra only), %; 0 when there are none; absent without an area-light truth",
         [](const Score& s) -> std::optional<double> {
             return s.mae_penumbra_pct >= 0.0 ? std::optional<double>(s.mae_penumbra_pct) : std::nullopt;
         },
         [](Score& s, double v) { s.mae_penumbra_pct = v; }},
    };
    return columns;
}

const ScoreColumn* find_score_column(std::string_view key) {
    for (const ScoreColumn& c : score_columns())
        if (c.key == key) return &c;
    return nullptr;
}

std::string format_score_value(double v, int digits) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

std::string score_csv_header() {
    std::string out;
    for (const ScoreColumn& c : score_columns()) out += (out.empty() ? "" : ",") + std::string(c.key);
    return out;
}

std::string score_csv_cells(const Score& s) {
    std::string out;
    bool first = true;
    for (const ScoreColumn& c : score_columns()) {
        if (!first) out += ",";
        first = false;
        if (const auto v = c.get(s)) out += format_score_value(*v, c.digits);
    }
    return out;
}

Score score_from_cells(const std::function<std::optional<std::string>(std::string_view key)>& cell) {
    Score s;
    for (const ScoreColumn& c : score_columns()) {
        const std::optional<std::string> text = cell(c.key);
        if (!text || text->empty()) continue;
        char* end = nullptr;
        const double v = std::strtod(text->c_str(), &end);
        if (end != text->c_str() + text->size() || !std::isfinite(v))
            throw std::invalid_argument(std::string(c.key) + " '" + *text + "' is not a number");
        c.set(s, v);
    }
    return s;
}

std::vector<std::string> missing_required_columns(const std::function<bool(std::string_view key)>& has) {
    std::vector<std::string> out;
    for (const ScoreColumn& c : score_columns())
        if (c.required && !has(c.key)) out.emplace_back(c.key);
    return out;
}

std::string score_table_headings() {
    std::string out;
    for (const ScoreColumn& c : score_columns())
        if (c.table_digits >= 0) out += (out.empty() ? "" : " | ") + std::string(c.heading);
    return out;
}

std::string score_table_rule() {
    std::string out;
    for (const ScoreColumn& c : score_columns())
        if (c.table_digits >= 0) out += "---:|";
    return out;
}

std::string score_table_cells(const Score& s) {
    std::string out;
    bool first = true;
    for (const ScoreColumn& c : score_columns()) {
        if (c.table_digits < 0) continue;
        if (!first) out += " | ";
        first = false;
        const auto v = c.get(s);
        out += v ? format_score_value(*v, c.table_digits) : "-";
    }
    return out;
}

Score mean_score(const std::vector<const Score*>& scores) {
    Score out;
    for (const ScoreColumn& c : score_columns()) {
        double sum = 0.0;
        int n = 0;
        for (const Score* s : scores)
            if (const auto v = c.get(*s)) {
                sum += *v;
                ++n;
            }
        if (n > 0) c.set(out, sum / n);
    }
    return out;
}

nlohmann::ordered_json score_json(const Score& s) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const ScoreColumn& c : score_columns()) {
        const auto v = c.get(s);
        if (!v) out[std::string(c.key)] = nullptr;
        else if (c.digits == 0) out[std::string(c.key)] = static_cast<std::int64_t>(std::llround(*v));
        else out[std::string(c.key)] = std::round(*v * std::pow(10.0, c.digits)) / std::pow(10.0, c.digits);
    }
    return out;
}

nlohmann::ordered_json score_columns_json() {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const ScoreColumn& c : score_columns())
        out.push_back({{"key", c.key},
                       {"heading", c.heading},
                       {"digits", c.digits},
                       {"table_digits", c.table_digits},
                       {"optional", c.optional},
                       {"required", c.required},
                       {"meaning", c.meaning}});
    return out;
}

}  // namespace penumbra::measure
