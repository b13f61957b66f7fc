#include "cli_options.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <unistd.h>

#include "measure.h"
#include "scene/file_write.h"
#include "scene/printable.h"

namespace fs = std::filesystem;

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

void check_given(const CLI::App& cmd, const render::OptionInfo& info) {
    const CLI::Option* opt = cmd.get_option_no_throw("--" + std::string(info.name));
    if (!opt) return;
    for (const std::string& value : opt->results())
        if (const std::string err = render::check_value(info, value); !err.empty()) throw CommandError{err, 2};
}

void add_allow_outside(CLI::App* cmd, std::vector<std::string>& paths) {
    cmd->add_option("--allow-outside", paths,
                    "the scene's files (buffers, images) may also be read under this folder; repeatable "
                    "(default: only under the scene file's own folder)")
        ->type_name("PATH");
}

namespace {

bool option_word(std::string_view a) {
    const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
    if (a.size() < 2 || a[0] != '-') return false;
    if (a[1] == '-') return a.size() > 2 && letter(a[2]);  // "--" alone ends the options
    return letter(a[1]);
}

// The option `word` names on `cmd` or a command above it (nullptr: none).
const CLI::Option* find_option(const CLI::App* cmd, const std::string& word) {
    for (; cmd; cmd = cmd->get_parent())
        if (const CLI::Option* o = cmd->get_option_no_throw(word)) return o;
    return nullptr;
}

}  // namespace

std::string missing_value(const CLI::App& app, int argc, const char* const* argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "-h" || a == "--help" || a == "--help-all") return {};  // CLI11 prints the help
    }
    const CLI::App* cmd = &app;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--") break;
        if (!option_word(a)) {
            // A subcommand's name: its options from here on. Any other word is a value.
            for (const CLI::App* sub : cmd->get_subcommands([](const CLI::App*) { return true; }))
                if (sub->check_name(a)) {
                    cmd = sub;
                    break;
                }
            continue;
        }
        if (const size_t eq = a.find('='); eq != std::string::npos) {  // --name=value
            const CLI::Option* o = find_option(cmd, a.substr(0, eq));
            if (o && o->get_items_expected_min() > 0 && eq + 1 == a.size())
                return a.substr(0, eq) + ": needs a value (nothing after its '=')";
            continue;
        }
        const CLI::Option* o = find_option(cmd, a);
        if (!o || o->get_items_expected_min() == 0) continue;  // unknown (CLI11 says so), or a flag
        if (i + 1 >= argc) return a + ": needs a value (it is the last argument)";
        if (option_word(argv[i + 1]))
            return a + ": needs a value (got the option " + scene::printable(argv[i + 1]) + " instead)";
        ++i;  // its value
    }
    return {};
}

namespace {

std::string shown(const std::string& path) { return scene::printable(path); }

std::string reason(int err) { return std::strerror(err); }

// Creates and removes a new file in `folder` (the way the writers put theirs: a temporary file
// beside the target); "" or the system's reason.
std::string try_create_in(const fs::path& folder, const std::string& stem) {
    const fs::path probe = folder / (stem + ".probe" + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) return reason(errno);
    ::close(fd);
    ::unlink(probe.c_str());
    return {};
}

}  // namespace

void check_output_file(const std::string& option, const std::string& path, const std::string& extension) {
    const std::string what = option + " " + shown(path) + ": ";
    const fs::path out(path);
    if (path.empty() || !out.has_filename()) throw CommandError{what + "expected a file name", 2};
    if (!extension.empty() && out.extension() != extension)
        throw CommandError{what + "the file name must end in " + extension, 2};
    const fs::path folder = out.has_parent_path() ? out.parent_path() : fs::path(".");
    std::error_code ec;
    const fs::file_status fst = fs::status(folder, ec);
    if (!fs::exists(fst)) throw CommandError{what + "folder " + shown(folder.string()) + " does not exist", 2};
    if (!fs::is_directory(fst))
        throw CommandError{what + shown(folder.string()) + " is not a folder (" + reason(ENOTDIR) + ")", 2};
    if (fs::is_directory(fs::status(out, ec))) throw CommandError{what + "cannot write (" + reason(EISDIR) + ")", 2};
    if (const std::string why = try_create_in(folder, out.filename().string()); !why.empty())
        throw CommandError{what + "cannot write in folder " + shown(folder.string()) + " (" + why + ")", 2};
}

void prepare_output_dir(const std::string& option, const std::string& dir) {
    const std::string what = option + " " + shown(dir) + ": ";
    if (dir.empty()) throw CommandError{option + ": expected a folder", 2};
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw CommandError{what + "cannot create (" + ec.message() + ")", 2};
    if (!fs::is_directory(dir, ec)) throw CommandError{what + "not a folder (" + reason(ENOTDIR) + ")", 2};
    if (const std::string why = try_create_in(dir, "penumbra"); !why.empty())
        throw CommandError{what + "cannot write in it (" + why + ")", 2};
}

void write_output(const std::string& path, std::string_view bytes) {
    if (const std::string err = scene::write_file(path, bytes); !err.empty()) throw CommandError{err, 2};
}

std::string one_line(std::string_view m) {
    std::string out;
    out.reserve(m.size());
    for (size_t i = 0; i < m.size();) {
        const auto c = static_cast<unsigned char>(m[i]);
        if (c >= 0x20 && c != 0x7F && c < 0x80) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        // A UTF-8 sequence as it is when valid (printable's rules), a control character escaped.
        size_t n = 0;
        if (c >= 0x80)
            for (size_t len = 2; len <= 4 && i + len <= m.size(); ++len)
                if (scene::valid_utf8(m.substr(i, len))) {
                    n = len;
                    break;
                }
        if (n) {
            out.append(m.substr(i, n));
            i += n;
        } else {
            out += scene::printable(m.substr(i, 1));
            ++i;
        }
    }
    return out;
}

}  // namespace penumbra::tools
