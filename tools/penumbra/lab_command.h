// The shader lab on the command line (docs/snippets.md):
//   render --snippets FILE   the frame drawn with a snippets file (render's other options apply)
//   grade DIR --out FILE.csv every snippets file of a folder scored on the course's frames against
//                            the sheet's answer and the ray-traced truth, with an HTML report
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "plan/options.h"
#include "plan/snippets.h"

namespace penumbra::tools {

// The text of a snippets file (at most kMaxSnippetBytes are read: a longer file is refused by the
// scan with its size). A file that cannot be read is a CommandError (exit status 2).
std::string read_snippets(const std::string& option, const std::string& path);

// "FILE:3: message; FILE:7: message" (line 0: "FILE: message").
std::string snippet_problems_text(const std::string& path, const std::vector<render::SnippetProblem>& problems);

struct GradeOptions {
    std::string dir;
    std::string out;                // FILE.csv; the report is FILE.html beside it, its thumbnails FILE_files/
    std::string encoding = "rgba";  // the exercise: r8 (the depth in red) or rgba (bit-shift packing)
    std::string filter = "pcf4x4";  // hard, pcf2x2 or pcf4x4 (the sheet's 4x4 lookup)
    std::string size = "192x144";   // each frame's size
};
// grade needs the ray-traced truth (PENUMBRA_HAVE_TRUTH).
CLI::App* add_grade_command(CLI::App& app, GradeOptions& o);
int run_grade(const GradeOptions& o);

}  // namespace penumbra::tools
