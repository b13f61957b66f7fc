// The score columns drive the CSV, the JSON and the Markdown: every name, heading and value in
// them comes from the one table, in its order, and a row written to the CSV reads back.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "measure/metrics.h"
#include "measure/score_columns.h"

using namespace penumbra::measure;

namespace {

std::vector<std::string> split(const std::string& s, const std::string& sep) {
    std::vector<std::string> out;
    size_t start = 0;
    while (true) {
        const size_t at = s.find(sep, start);
        out.push_back(s.substr(start, at == std::string::npos ? std::string::npos : at - start));
        if (at == std::string::npos) return out;
        start = at + sep.size();
    }
}

std::vector<std::string> keys() {
    std::vector<std::string> out;
    for (const ScoreColumn& c : score_columns()) out.emplace_back(c.key);
    return out;
}

std::vector<std::string> table_headings() {
    std::vector<std::string> out;
    for (const ScoreColumn& c : score_columns())
        if (c.table_digits >= 0) out.emplace_back(c.heading);
    return out;
}

// A hard score (no area-light truth) and one with it.
Score example(bool soft) {
    Score s;
    s.valid = 8239;
    s.truth_shadowed = 920;
    s.false_shadow = 5;
    s.false_lit = 11;
    s.false_shadow_pct = 100.0 * 5 / 8239;
    s.false_lit_pct = 100.0 * 11 / 8239;
    s.error_pct = s.false_shadow_pct + s.false_lit_pct;
    s.mae_pct = 0.93921;
    if (soft) {
        s.mae_soft_pct = 0.99372;
        s.penumbra = 412;
        s.mae_penumbra_pct = 7.12345;
    }
    return s;
}

TEST(ScoreColumns, TheTableIsWellFormed) {
    std::set<std::string> seen_keys, seen_headings;
    for (const ScoreColumn& c : score_columns()) {
        EXPECT_TRUE(seen_keys.insert(std::string(c.key)).second) << c.key;
        EXPECT_TRUE(seen_headings.insert(std::string(c.heading)).second) << c.heading;
        EXPECT_FALSE(c.meaning.empty()) << c.key;
        EXPECT_GE(c.digits, 0) << c.key;
        EXPECT_FALSE(c.optional && c.required) << c.key << ": a CSV may lack what a score may lack";
        ASSERT_NE(c.get, nullptr);
        ASSERT_NE(c.set, nullptr);
        // A score has every column but the optional ones.
        EXPECT_EQ(c.get(example(false)).has_value(), !c.optional) << c.key;
        EXPECT_TRUE(c.get(example(true)).has_value()) << c.key;
        EXPECT_EQ(find_score_column(c.key), &c);
    }
    EXPECT_EQ(find_score_column("no_such_column"), nullptr);
}

// True when `part` appears in `whole` in the same order (other items may come between).
bool in_order(const std::vector<std::string>& part, const std::vector<std::string>& whole) {
    size_t at = 0;
    for (const auto& p : part) {
        while (at < whole.size() && whole[at] != p) ++at;
        if (at == whole.size()) return false;
        ++at;
    }
    return true;
}

// results/bench/results.csv and others' CSVs (three.js runs) have these names in this order:
// renaming or reordering one breaks them and `bench --from-csv` on them. A new column may go
// anywhere (after them keeps the old files' column order).
TEST(ScoreColumns, TheCsvNamesAreTheExistingOnes) {
    const std::vector<std::string> existing = {"valid_pixels", "truth_shadowed_pct", "false_shadow_pct", "false_lit_pct",
                                               "error_pct",    "mae_pct",            "mae_area_light_pct"};
    EXPECT_TRUE(in_order(existing, keys())) << score_csv_header();
    // bench --from-csv still reads the committed results: it has every required column.
    std::ifstream f(PENUMBRA_SOURCE_DIR "/results/bench/results.csv");
    std::string header;
    ASSERT_TRUE(std::getline(f, header));
    const auto names = split(header, ",");
    EXPECT_TRUE(missing_required_columns([&](std::string_view k) {
                    return std::find(names.begin(), names.end(), std::string(k)) != names.end();
                }).empty())
        << header;
    EXPECT_TRUE(in_order(existing, names)) << header;
}

TEST(ScoreColumns, CsvHeaderAndCellsComeFromTheTable) {
    EXPECT_EQ(split(score_csv_header(), ","), keys());
    const auto hard = split(score_csv_cells(example(false)), ",");
    const auto soft = split(score_csv_cells(example(true)), ",");
    ASSERT_EQ(hard.size(), score_columns().size());
    ASSERT_EQ(soft.size(), score_columns().size());
    for (size_t i = 0; i < hard.size(); ++i) {
        const ScoreColumn& c = score_columns()[i];
        EXPECT_EQ(soft[i], format_score_value(*c.get(example(true)), c.digits)) << c.key;
        if (c.optional) {
            EXPECT_EQ(hard[i], "") << c.key;
        } else {
            EXPECT_EQ(hard[i], soft[i]) << c.key;
        }
    }
    // The figures as the CSV writes them.
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"valid_pixels", "8239"}, {"truth_shadowed_pct", "11.166"}, {"false_shadow_pct", "0.0607"}, {"false_lit_pct", "0.1335"},
        {"error_pct", "0.1942"},  {"mae_pct", "0.9392"},            {"mae_area_light_pct", "0.9937"}};
    for (const auto& [key, text] : expected) {
        const auto k = keys();
        const auto at = std::find(k.begin(), k.end(), key);
        ASSERT_NE(at, k.end()) << key;
        EXPECT_EQ(soft[static_cast<size_t>(at - k.begin())], text) << key;
    }
}

TEST(ScoreColumns, CsvCellsReadBack) {
    for (bool with_soft : {false, true}) {
        const std::vector<std::string> header = keys();
        const std::vector<std::string> cells = split(score_csv_cells(example(with_soft)), ",");
        const Score back = score_from_cells([&](std::string_view key) -> std::optional<std::string> {
            for (size_t i = 0; i < header.size(); ++i)
                if (header[i] == key) return cells[i];
            return std::nullopt;
        });
        // Written again, it is the same row.
        EXPECT_EQ(score_csv_cells(back), score_csv_cells(example(with_soft)));
        EXPECT_EQ(back.valid, 8239u);
        EXPECT_EQ(back.truth_shadowed, 920u);
        EXPECT_EQ(back.mae_soft_pct >= 0.0, with_soft);
    }
    // A CSV without the optional and the unrequired columns (e.g. an older three.js run).
    const Score partial = score_from_cells([](std::string_view key) -> std::optional<std::string> {
        if (key == "valid_pixels") return "100";
        if (key == "error_pct") return "2.5";
        return std::nullopt;
    });
    EXPECT_EQ(partial.valid, 100u);
    EXPECT_DOUBLE_EQ(partial.error_pct, 2.5);
    EXPECT_DOUBLE_EQ(partial.mae_soft_pct, -1.0);
    EXPECT_THROW(score_from_cells([](std::string_view key) -> std::optional<std::string> {
                     return key == "mae_pct" ? std::optional<std::string>("1.2x") : std::nullopt;
                 }),
                 std::invalid_argument);
}

TEST(ScoreColumns, RequiredColumns) {
    std::vector<std::string> required;
    for (const ScoreColumn& c : score_columns())
        if (c.required) required.emplace_back(c.key);
    EXPECT_EQ(missing_required_columns([](std::string_view) { return false; }), required);
    EXPECT_TRUE(missing_required_columns([](std::string_view) { return true; }).empty());
    EXPECT_EQ(missing_required_columns([](std::string_view k) { return k != "error_pct"; }),
              std::vector<std::string>{"error_pct"});
}

TEST(ScoreColumns, JsonKeysComeFromTheTable) {
    for (bool with_soft : {false, true}) {
        const Score s = example(with_soft);
        const nlohmann::json j = nlohmann::json::parse(score_json(s).dump());
        ASSERT_TRUE(j.is_object());
        EXPECT_EQ(j.size(), score_columns().size());
        // In the table's order in the text, too (ordered_json keeps it).
        const nlohmann::ordered_json ordered = score_json(s);
        std::vector<std::string> order;
        for (const auto& item : ordered.items()) order.push_back(item.key());
        EXPECT_EQ(order, keys());
        for (const ScoreColumn& c : score_columns()) {
            ASSERT_TRUE(j.contains(std::string(c.key))) << c.key;
            const auto& v = j.at(std::string(c.key));
            const auto expected = c.get(s);
            if (!expected) {
                EXPECT_TRUE(v.is_null()) << c.key;  // absent: null, not left out
                continue;
            }
            if (c.digits == 0) {
                EXPECT_TRUE(v.is_number_integer()) << c.key;
            }
            // The same figure as the CSV cell.
            EXPECT_DOUBLE_EQ(v.get<double>(), std::stod(format_score_value(*expected, c.digits))) << c.key;
        }
    }
    const nlohmann::json j = nlohmann::json::parse(score_json(example(false)).dump());
    EXPECT_EQ(j.at("valid_pixels"), 8239);
    EXPECT_DOUBLE_EQ(j.at("false_shadow_pct").get<double>(), 0.0607);
    EXPECT_TRUE(j.at("mae_area_light_pct").is_null());
}

TEST(ScoreColumns, ColumnsJsonIsTheTable) {
    const nlohmann::json j = nlohmann::json::parse(score_columns_json().dump());
    ASSERT_TRUE(j.is_array());
    ASSERT_EQ(j.size(), score_columns().size());
    for (size_t i = 0; i < j.size(); ++i) {
        const ScoreColumn& c = score_columns()[i];
        EXPECT_EQ(j[i].at("key"), std::string(c.key));
        EXPECT_EQ(j[i].at("heading"), std::string(c.heading));
        EXPECT_EQ(j[i].at("digits"), c.digits);
        EXPECT_EQ(j[i].at("table_digits"), c.table_digits);
        EXPECT_EQ(j[i].at("optional"), c.optional);
        EXPECT_EQ(j[i].at("required"), c.required);
        EXPECT_EQ(j[i].at("meaning"), std::string(c.meaning));
    }
}

TEST(ScoreColumns, MarkdownHeadingsAndCellsComeFromTheTable) {
    EXPECT_EQ(split(score_table_headings(), " | "), table_headings());
    // results.md's tables have had these headings in this order.
    EXPECT_TRUE(in_order({"false shadow %", "false lit %", "error %", "mean abs error %", "vs area light %"}, table_headings()));
    EXPECT_EQ(score_table_rule().size(), 5u * table_headings().size());
    const auto hard = split(score_table_cells(example(false)), " | ");
    const auto soft = split(score_table_cells(example(true)), " | ");
    const auto headings = table_headings();
    ASSERT_EQ(hard.size(), headings.size());
    ASSERT_EQ(soft.size(), headings.size());
    for (size_t i = 0; i < headings.size(); ++i) {
        const ScoreColumn* c = nullptr;
        for (const ScoreColumn& col : score_columns())
            if (col.heading == headings[i]) c = &col;
        ASSERT_NE(c, nullptr);
        EXPECT_EQ(soft[i], format_score_value(*c->get(example(true)), c->table_digits)) << c->key;
        // Without an area-light truth, the optional columns read "-".
        EXPECT_EQ(hard[i], c->optional ? "-" : soft[i]) << c->key;
    }
    EXPECT_EQ(soft[0], "0.06");  // false shadow %, two decimals
}

TEST(ScoreColumns, MeanOverTheScoresThatHaveAColumn) {
    Score a = example(true), b = example(false);
    b.error_pct = a.error_pct + 2.0;
    b.valid = 8241;
    const Score m = mean_score({&a, &b});
    EXPECT_DOUBLE_EQ(m.error_pct, a.error_pct + 1.0);
    EXPECT_EQ(m.valid, 8240u);
    EXPECT_DOUBLE_EQ(m.mae_soft_pct, a.mae_soft_pct);  // only a has it
    EXPECT_LT(mean_score({&b, &b}).mae_soft_pct, 0.0);  // none has it: still absent
    EXPECT_EQ(score_csv_cells(mean_score({})), score_csv_cells(Score{}));
}

}  // namespace
