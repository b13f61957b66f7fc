// penumbra-catalog: prints the exercise list (examples/exercise_list.h) as JSON: every exercise
// with its controls, and every option they name with its type, label, choices, range and default.
// Built for node by the web build, which runs it to generate the exercise pages from one template
// (web/pages.py), so the pages repeat no list of exercises or options of their own.
#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "exercise_list.h"
#include "plan/json.h"

namespace penumbra::examples {
namespace {

using render::Choice;
using render::OptionInfo;

using render::json_quote;

std::string choices_json(const std::vector<Choice>& choices) {
    std::string j = "[";
    for (size_t i = 0; i < choices.size(); ++i)
        j += std::string(i ? "," : "") + "{\"value\":" + json_quote(choices[i].value) +
             ",\"label\":" + json_quote(choices[i].label) + "}";
    return j + "]";
}

std::string option_json(const OptionInfo& o, const std::string& default_value) {
    static const char* types[] = {"choice", "integer", "number", "size", "text", "number-or-word"};
    return "{\"name\":" + json_quote(o.name) + ",\"type\":" + json_quote(types[static_cast<int>(o.type)]) +
           ",\"label\":" + json_quote(o.label) + ",\"help\":" + json_quote(o.help) +
           ",\"choices\":" + choices_json(o.choices) + ",\"presets\":" + choices_json(o.presets) +
           ",\"min\":" + render::json_number(o.min) + ",\"max\":" + render::json_number(o.max) +
           ",\"step\":" + render::json_number(o.step) + ",\"default\":" + json_quote(default_value) + "}";
}

// The technique its frames are drawn with (the default, where a control offers the technique).
std::string technique_of(const Exercise& x) {
    for (const auto& [name, value] : x.frame)
        if (name == "technique") return std::string(value);
    return render::find_option(render::option_table(), "technique")->print(render::Options{});
}

}  // namespace

std::string catalog_json() {
    std::string j = "{\"exercises\":[";
    std::vector<std::string_view> named;
    for (size_t i = 0; i < exercise_list().size(); ++i) {
        const Exercise& x = exercise_list()[i];
        static const char* kinds[] = {"toggle", "radio", "select", "checkbox", "number", "slider"};
        j += std::string(i ? "," : "") + "{\"name\":" + json_quote(x.name) + ",\"title\":" + json_quote(x.title) +
             ",\"text\":" + json_quote(x.text) + ",\"brief\":" + json_quote(x.brief) +
             ",\"lookFor\":" + json_quote(x.look_for) + ",\"canvas\":" + json_quote(x.canvas) +
             ",\"technique\":" + json_quote(technique_of(x)) +
             ",\"fly\":" + std::string(flies(x) ? "true" : "false") +
             ",\"controls\":[";
        for (size_t c = 0; c < x.controls.size(); ++c) {
            const Control& k = x.controls[c];
            std::string values = "[";
            for (size_t v = 0; v < k.values.size(); ++v) values += std::string(v ? "," : "") + json_quote(k.values[v]);
            j += std::string(c ? "," : "") + "{\"option\":" + json_quote(k.option) + ",\"group\":" + json_quote(k.group) +
                 ",\"kind\":" + json_quote(kinds[static_cast<int>(k.kind)]) + ",\"values\":" + values +
                 "],\"label\":" + json_quote(k.label) + ",\"hint\":" + json_quote(k.hint) +
                 ",\"min\":" + render::json_number(k.min) + ",\"max\":" + render::json_number(k.max) + "}";
            if (std::find(named.begin(), named.end(), k.option) == named.end()) named.push_back(k.option);
        }
        j += "]}";
    }
    j += "],\"options\":{";
    const render::Options defaults;
    const Toggles toggles;
    bool first = true;
    for (std::string_view name : named) {
        std::string o;
        if (const auto* t = render::find_option(toggle_table(), name)) o = option_json(t->info, t->print(toggles));
        else if (const auto* r = render::find_option(render::option_table(), name)) o = option_json(r->info, r->print(defaults));
        else throw std::logic_error("catalog: a control names no option: " + std::string(name));
        j += std::string(first ? "" : ",") + json_quote(name) + ":" + o;
        first = false;
    }
    return j + "}}";
}

}  // namespace penumbra::examples

int main() {
    std::printf("%s\n", penumbra::examples::catalog_json().c_str());
    return 0;
}
