// The option table (plan/options.h) on a CLI11 command: each option of the table becomes a
// --name of the command, with the table's help, accepted values and default in --help, and is
// checked and stored by the table's own parser after CLI11 has read the command line.
// And the checks every command makes before any work: its numbers (finite, in range), its
// outputs (a folder that exists and takes a new file), its messages (one line).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "plan/options.h"

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

// Each value given to `cmd`'s --NAME (NAME = info.name), as typed, checked as the option table
// checks its own (a finite number in range, a whole number in range, ...): a problem throws
// CommandError (exit status 2) naming the option, the value and the rule. Nothing when not given.
void check_given(const CLI::App& cmd, const render::OptionInfo& info);

// --allow-outside PATH (repeatable) on a command that takes --scene: where the scene's files may
// also be read (scene::LoadOptions::allow_outside).
void add_allow_outside(CLI::App* cmd, std::vector<std::string>& paths);

// A file the command will write, checked before any work: `extension` (".png"; empty: any), a
// folder that exists, not a folder itself, and a folder in which a new file can be created (tried
// and removed at once). A problem throws CommandError (exit status 2) with the system's reason.
void check_output_file(const std::string& option, const std::string& path, const std::string& extension);

// A folder the command will write into: created when missing, then tried as above.
void prepare_output_dir(const std::string& option, const std::string& dir);

// Writes `bytes` to `path` whole or not at all (scene::write_file: every write and the close
// checked, a temporary file renamed into place); a failure throws CommandError (exit status 2)
// naming the path and the system's reason. Every file the command line writes goes through it or
// through measure::write_png / scene::write_gltf, which use the same writer.
void write_output(const std::string& path, std::string_view bytes);

// The first option of `argv` (the command line `app` parses) that takes a value and is given none:
// it is the last argument, or the next is another option ("--scene --time 0.5": "--scene: needs a
// value (got the option --time instead)"), or it is "--name=" with nothing after the '='. CLI11
// would blame the next word instead ("The following
// argument was not expected: 0.5"). Looked up in the subcommand the words name, for every option
// that takes a value (the table's and each command's own); "" when each has one, or where a word
// asks for help. An option-like next word is "--" and a letter, or "-" and a letter: "-0.5" is a value.
std::string missing_value(const CLI::App& app, int argc, const char* const* argv);

// A message as one line of valid UTF-8: control characters and bytes that are not UTF-8 escaped
// (\n, \xNN), the rest (backslashes too) left as it is: the last guard before stderr, after the
// names in it went through scene::printable.
std::string one_line(std::string_view message);

}  // namespace penumbra::tools
