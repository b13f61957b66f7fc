// The score columns: one table (score_columns.cpp) of what a measure::Score reports, and how each
// figure is named, written and read back. It drives the score part of
//   - `penumbra bench`'s results.csv (header and rows) and reading them back (`--from-csv`);
//   - the Markdown tables of results.md (the columns with table_digits >= 0, as means);
//   - `penumbra truth --score FILE --json` (one key per column) and `--score-columns` (the table);
//   - so what tools/threejs_compare.mjs reads, writes in its CSV and shows in docs/threejs.md.
// Adding a metric: a field in Score, computed by score(), and one row in the table (docs/measure.md).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "measure/metrics.h"

namespace penumbra::measure {

struct ScoreColumn {
    std::string_view key;      // the CSV column and the JSON key: "false_shadow_pct"
    std::string_view heading;  // the Markdown heading: "false shadow %"
    int digits;                // decimals in the CSV and the JSON (0: a whole number)
    int table_digits;          // decimals of its mean in the Markdown tables; -1: not in those tables
    bool optional;             // may be absent from a Score (no area-light truth): null in JSON,
                               // an empty CSV cell, "-" in a table
    bool required;             // `bench --from-csv` refuses a CSV without this column
    std::string_view meaning;  // one line
    // Its value in a Score; nullopt where the Score has none (only an optional column).
    std::optional<double> (*get)(const Score&);
    // Sets it from a value read back. Called in table order, so a column may use the ones before
    // it (truth_shadowed_pct needs valid_pixels).
    void (*set)(Score&, double);
};

// Every column, in CSV and JSON order.
const std::vector<ScoreColumn>& score_columns();
// The column with this key, or null.
const ScoreColumn* find_score_column(std::string_view key);

// A value as the CSV and the JSON write it: `digits` decimals ("0.0611", "8239").
std::string format_score_value(double v, int digits);

// CSV: the keys joined by commas (the header's score part), and one score's cells in the same
// order (each with its column's digits, "" where absent).
std::string score_csv_header();
std::string score_csv_cells(const Score& s);

// Reads a score back from named cells: cell(key) is the text under that column, or nullopt when
// there is no such column. An empty or missing cell leaves the Score's default (0; -1 for the
// area-light error, i.e. absent). Throws std::invalid_argument("KEY 'TEXT' is not a number").
// The caller checks the required columns first (missing_required_columns).
Score score_from_cells(const std::function<std::optional<std::string>(std::string_view key)>& cell);
// The required keys for which has(key) is false, in table order.
std::vector<std::string> missing_required_columns(const std::function<bool(std::string_view key)>& has);

// Markdown tables (the columns with table_digits >= 0): the headings joined by " | ", the
// alignment rule ("---:|" each), and one score's cells joined by " | " ("-" where absent).
std::string score_table_headings();
std::string score_table_rule();
std::string score_table_cells(const Score& s);

// Each column's mean over several scores (a technique over scene frames), over the scores that
// have it; an optional column none of them has stays absent. Empty input: a default Score.
Score mean_score(const std::vector<const Score*>& scores);

// JSON: one member per column in table order, each rounded to its digits, null where absent.
nlohmann::ordered_json score_json(const Score& s);
// The table itself: [{key, heading, digits, table_digits, optional, required, meaning}, ...].
nlohmann::ordered_json score_columns_json();

}  // namespace penumbra::measure
