// `penumbra options [--markdown]`: the option table (plan/options.h, src/plan/option_table.cpp)
// printed, one option a line (name, part, default, what it accepts: tab-separated), or as the Markdown reference committed as
// docs/options.md (tests/docs_options.sh fails when that file is stale). Nothing here opens a
// context; the output depends on the table alone, so it is the same on every machine.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace penumbra::tools {

CLI::App* add_options_command(CLI::App& app, bool& markdown);
// The reference page (Markdown) or the plain listing.
std::string options_text(bool markdown);

}  // namespace penumbra::tools
