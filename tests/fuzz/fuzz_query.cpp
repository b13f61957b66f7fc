// libFuzzer target: the pages' URL query (examples/query.h) applied to a CourseApp through
// set_option, as penumbra_set_query does in the browser, without a GL context (CourseApp makes its
// renderer only in create_gl). The first byte picks the exercise, the rest is the query.
// Checked: every note is one line of UTF-8; what the app then writes as its query (a reload's URL)
// reads back without a note into the same query.
// The apps are made once per exercise (the course scene's marble texture takes milliseconds) and put
// back to their first state after each input, checked; one that does not come back is made again.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "exercise_list.h"
#include "exercises.h"
#include "query.h"
#include "scene/printable.h"

using namespace penumbra;
using examples::CourseApp;

namespace {

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz_query: %s\n", what.c_str());
    std::abort();
}

struct Slot {
    std::unique_ptr<CourseApp> app;
    render::Settings settings;  // the first state
    std::vector<std::pair<std::string, std::string>> pairs;  // to_pairs(settings)
    std::string query;
    std::vector<std::pair<std::string, std::string>> toggles;
};

std::vector<std::string> apply_to(CourseApp& app, std::string_view q) {
    return examples::apply_query(q, [&](std::string_view n, std::string_view v) { return app.set_option(n, v); });
}

std::vector<std::pair<std::string, std::string>> toggle_values(const CourseApp& app) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& t : examples::toggle_table()) out.emplace_back(t.info.name, app.value_of(t.info.name));
    return out;
}

bool in_first_state(const Slot& s) {
    const CourseApp& a = *s.app;
    return a.settings() == s.settings && a.query() == s.query && toggle_values(a) == s.toggles && !a.paused() &&
           !a.eye_in_shadow() && a.light_time() == 0.0 && a.jump_time() == 0.0;
}

void make(Slot& s, std::string_view e) {
    s.app = std::make_unique<CourseApp>(e);
    s.settings = s.app->settings();
    s.pairs = render::to_pairs(s.settings);
    s.query = s.app->query();
    s.toggles = toggle_values(*s.app);
}

void reset(Slot& s, std::string_view e) {
    CourseApp& a = *s.app;
    // Only what differs is set again (set_option on every option each time halves the speed).
    const auto now = render::to_pairs(a.settings());
    for (std::size_t i = 0; i < now.size() && i < s.pairs.size(); ++i)
        if (now[i].second != s.pairs[i].second) a.set_option(s.pairs[i].first, s.pairs[i].second);
    const auto toggles = toggle_values(a);
    for (std::size_t i = 0; i < toggles.size(); ++i)
        if (toggles[i].second != s.toggles[i].second) a.set_option(s.toggles[i].first, s.toggles[i].second);
    a.set_option("eye", "scene");
    a.set_time(0.0);
    a.set_paused(false);
    if (!in_first_state(s)) make(s, e);
}

void check_notes(const std::vector<std::string>& notes) {
    for (const auto& n : notes)
        if (n.empty() || !scene::valid_utf8(n) || n.find('\n') != std::string::npos)
            fail("a note that is not one line of UTF-8: " + scene::printable(n));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // One app per exercise, as many as the list has.
    static std::vector<Slot> slots(examples::exercise_list().size());
    if (size == 0) return 0;
    const std::size_t count = slots.size();
    const auto& info = examples::exercise_list()[data[0] % count];
    Slot& s = slots[data[0] % count];
    if (!s.app) make(s, info.name);
    const std::string_view q(reinterpret_cast<const char*>(data + 1), size - 1);

    check_notes(apply_to(*s.app, q));
    // A reload: the query the app writes now, read into an app in its first state.
    const std::string written = s.app->query();
    const render::Settings settings = s.app->settings();
    reset(s, info.name);
    const std::vector<std::string> notes = apply_to(*s.app, written);
    if (!notes.empty()) fail("the app's own query '" + written + "' read back with a note: " + notes.front());
    if (s.app->query() != written) fail("the app's own query '" + written + "' read back as '" + s.app->query() + "'");
    if (!(s.app->settings() == settings)) fail("the app's own query '" + written + "' read back other settings");
    reset(s, info.name);
    return 0;
}
