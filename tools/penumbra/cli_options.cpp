#include "cli_options.h"

#include <algorithm>

#include "measure.h"

namespace penumbra::tools {

std::string option_help(const render::OptionInfo& o, const std::string& default_value) {
    std::string h(o.help);
    if (o.type != render::OptionType::Text) h += " [" + render::accepted_values(o) + "]";
    if (!default_value.empty()) h += " (default " + default_value + ")";
    return h;
}

TableOptions::TableOptions(CLI::App* cmd, const std::vector<std::string>& names, render::Options defaults)
    : cmd_(cmd), defaults_(std::move(defaults)) {
    for (const auto& o : render::option_table()) {
        const std::string name(o.info.name);
        if (!names.empty() && std::find(names.begin(), names.end(), name) == names.end()) continue;
        cmd->add_option("--" + name, raw_[name], option_help(o.info, o.print(defaults_)));
    }
}

render::Options TableOptions::parse() const {
    render::Options base = defaults_;
    for (const auto& [name, value] : raw_) {
        if (cmd_->get_option("--" + name)->count() == 0) continue;
        if (const std::string err = render::parse_option(base, name, value); !err.empty()) throw CommandError{err, 2};
    }
    return base;
}

}  // namespace penumbra::tools
