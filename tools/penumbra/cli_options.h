// The option table (render/options.h) on a CLI11 command: each option of the table becomes a
// --name of the command, with the table's help, accepted values and default in --help, and is
// checked and stored by the table's own parser after CLI11 has read the command line.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/options.h"

namespace penumbra::tools {

class TableOptions {
public:
    // Adds `names` (or, when empty, every option of the table) to `cmd`, with `defaults` (the
    // table's own unless a command has others) shown in --help.
    TableOptions(CLI::App* cmd, const std::vector<std::string>& names = {}, render::Options defaults = {});
    // The defaults with the options given on the command line; a bad value throws CommandError
    // (exit status 2) naming the option and what it accepts.
    render::Options parse() const;

private:
    CLI::App* cmd_;
    render::Options defaults_;
    std::map<std::string, std::string> raw_;
};

// "--help" text of one option: its help, what it accepts and its default.
std::string option_help(const render::OptionInfo& o, const std::string& default_value);

}  // namespace penumbra::tools
