// Which uniforms a GLSL ES 1.00 source declares, with its #ifdef / #if defined() / #else blocks
// resolved against the #define lines it holds (a variant's defines are such lines). A name the
// program does not declare is a bug in the caller (a misspelling, or a uniform of a feature the
// variant lacks): debug builds turn setting one into an error (Program::set). No GL here.
#pragma once

#include <set>
#include <string>
#include <string_view>

namespace penumbra::gl {

// Names of the uniforms declared in the active parts of `source`. A condition it cannot decide
// (an #if expression other than defined(NAME), or a GL_ built-in macro) keeps every branch, so a
// declaration is never missed.
std::set<std::string> declared_uniforms(std::string_view source);

}  // namespace penumbra::gl
