// The pages' URL query (examples/query.h): split, decoded, refused with a note where it is
// malformed or not UTF-8, bounded, and written back so that it reads the same (the fuzz target
// fuzz_query found CourseApp::query() writing time=1e+06, which read back as "1e 06").
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "plan/options.h"
#include "query.h"
#include "scene/printable.h"

using namespace penumbra::examples;

namespace {

std::vector<std::pair<std::string, std::string>> pairs_of(std::string_view q, std::vector<std::string>& notes) {
    std::vector<std::pair<std::string, std::string>> out;
    for (auto& p : parse_query(q, notes)) out.emplace_back(p.name, p.value);
    return out;
}

using Pairs = std::vector<std::pair<std::string, std::string>>;

}  // namespace

TEST(Query, SplitsAndDecodes) {
    std::vector<std::string> notes;
    EXPECT_EQ(pairs_of("?bias=auto&encoding=r8", notes), (Pairs{{"bias", "auto"}, {"encoding", "r8"}}));
    EXPECT_EQ(pairs_of("bias=auto", notes), (Pairs{{"bias", "auto"}}));
    EXPECT_EQ(pairs_of("a=1+2&b=%41%2b%3D&c", notes), (Pairs{{"a", "1 2"}, {"b", "A+="}, {"c", ""}}));
    EXPECT_EQ(pairs_of("&&a=b=c&&", notes), (Pairs{{"a", "b=c"}}));
    EXPECT_EQ(pairs_of("x=%C3%A9", notes), (Pairs{{"x", "\xC3\xA9"}}));
    EXPECT_EQ(pairs_of("", notes), Pairs{});
    EXPECT_EQ(pairs_of("?", notes), Pairs{});
    EXPECT_TRUE(notes.empty());
}

TEST(Query, RefusesMalformedEscapesAndNonUtf8WithANote) {
    std::vector<std::string> notes;
    EXPECT_EQ(pairs_of("bias=%zz&encoding=r8&a=%&b=%4&c%=1&time=%FF&d=%C3&e=%ED%A0%80", notes),
              (Pairs{{"encoding", "r8"}}));
    ASSERT_EQ(notes.size(), 7u);
    EXPECT_NE(notes[0].find("'bias=%zz'"), std::string::npos) << notes[0];
    EXPECT_NE(notes[0].find("malformed escape"), std::string::npos) << notes[0];
    EXPECT_NE(notes[4].find("not UTF-8"), std::string::npos) << notes[4];
    for (const auto& n : notes) {
        EXPECT_TRUE(penumbra::scene::valid_utf8(n)) << n;
        EXPECT_EQ(n.find('\n'), std::string::npos) << n;
    }
}

TEST(Query, NotesAreOneLineAndShort) {
    std::vector<std::string> notes;
    const std::string raw = "x=%zz\n\xFF" + std::string(500, 'a');
    pairs_of(raw, notes);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].find('\n'), std::string::npos);
    EXPECT_TRUE(penumbra::scene::valid_utf8(notes[0]));
    EXPECT_LT(notes[0].size(), 200u);
}

TEST(Query, TooLongIsIgnoredWhole) {
    std::vector<std::string> notes;
    std::string q = "bias=auto&x=" + std::string(kMaxQueryBytes, 'a');
    EXPECT_TRUE(parse_query(q, notes).empty());
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("8192"), std::string::npos) << notes[0];
    notes.clear();
    q.resize(kMaxQueryBytes);
    EXPECT_EQ(parse_query(q, notes).size(), 2u);
    EXPECT_TRUE(notes.empty());
    EXPECT_EQ(parse_query("?" + q, notes).size(), 2u);  // the '?' is not counted
    EXPECT_TRUE(notes.empty());
}

TEST(Query, AppliesEachPairAndCollectsTheAnswers) {
    std::map<std::string, std::string> set;
    const auto notes = apply_query("?bias=auto&encoding=r16&bias=%zz&eye=in-shadow",
                                   [&](std::string_view n, std::string_view v) -> std::string {
                                       if (v == "r16") return "encoding: unknown value 'r16' (r8, rgba, depthtex)";
                                       set[std::string(n)] = std::string(v);
                                       return {};
                                   });
    EXPECT_EQ(set, (std::map<std::string, std::string>{{"bias", "auto"}, {"eye", "in-shadow"}}));
    ASSERT_EQ(notes.size(), 2u);  // in the query's order
    EXPECT_EQ(notes[0], "encoding: unknown value 'r16' (r8, rgba, depthtex)");
    EXPECT_NE(notes[1].find("'bias=%zz'"), std::string::npos) << notes[1];
}

TEST(Query, AnAnswerWithAControlCharacterBecomesOneLine) {
    const auto notes = apply_query("a=b", [](std::string_view, std::string_view) -> std::string { return "x\ny"; });
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0], "x\\ny");
}

// The regression fuzz_query found: a value with '+' (time=1e+06) written as it is read back as a space.
TEST(Query, EncodedComponentsReadBackTheSame) {
    EXPECT_EQ(encode_query_component("1e+06"), "1e%2B06");
    EXPECT_EQ(encode_query_component("r8"), "r8");
    EXPECT_EQ(encode_query_component("640x360"), "640x360");
    for (const std::string& v : std::vector<std::string>{"1e+06", "a b", "%41", "x&y=z#w", "\xC3\xA9", std::string("\0\x7F\x1F", 3)}) {
        std::vector<std::string> notes;
        const auto p = parse_query("n=" + encode_query_component(v), notes);
        ASSERT_EQ(p.size(), 1u) << v;
        EXPECT_EQ(p[0].value, v);
    }
}

// A key without its value (`?scene=&time=0.5`, `?scene`) is named, with what it takes, by the
// option table (render::check_value); the pairs after it are still read as their own.
TEST(Query, AKeyWithoutItsValueIsNamed) {
    penumbra::render::Options o;
    const auto set = [&](std::string_view n, std::string_view v) { return penumbra::render::parse_option(o, n, v); };
    auto notes = apply_query("?scene=&time=0.5", set);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].rfind("--scene: needs a value: teapot (the course scene)", 0), 0u) << notes[0];
    EXPECT_EQ(o.job.time, 0.5);
    for (const char* q : {"?time&encoding=", "time=&encoding"}) {
        notes = apply_query(q, set);
        ASSERT_EQ(notes.size(), 2u) << q;
        EXPECT_EQ(notes[0], "--time: needs a value: a number in [-1000000, 1000000]") << q;
        EXPECT_EQ(notes[1], "--encoding: needs a value: r8, rgba, depthtex") << q;
    }
    // Every option of the table that takes a value says so by name; "out" alone may be empty.
    for (const auto& opt : penumbra::render::option_table()) {
        const std::string name(opt.info.name);
        notes = apply_query(name + "=", set);
        if (opt.info.may_be_empty) {
            EXPECT_TRUE(notes.empty()) << name;
            continue;
        }
        ASSERT_EQ(notes.size(), 1u) << name;
        EXPECT_EQ(notes[0].rfind("--" + name + ": needs a value: ", 0), 0u) << notes[0];
    }
    // The control: with values, no note; a bad value is not called a missing one.
    EXPECT_TRUE(apply_query("?scene=teapot&time=0.25", set).empty());
    EXPECT_EQ(o.job.time, 0.25);
    notes = apply_query("?time=soon", set);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].find("needs a value"), std::string::npos) << notes[0];
}
