// User-given names (file paths, option values) echoed in one-line messages: control characters and
// bytes that are not UTF-8 are escaped (\n, \t, \xNN), so a name can neither break a message into
// two lines nor make it invalid UTF-8 (a JSON type error where the message ends up in JSON).
#pragma once

#include <string>
#include <string_view>

namespace penumbra::scene {

std::string printable(std::string_view name);

// Whether `s` is valid UTF-8 (no overlong forms, no surrogates, nothing above U+10FFFF).
bool valid_utf8(std::string_view s);

}  // namespace penumbra::scene
