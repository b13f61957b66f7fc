// The little JSON this project writes by hand (the plan, the pages' state): quoted strings and
// numbers that JSON.parse and nlohmann::json read back exactly. The browser build carries no JSON
// library, so this is all there is.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include <glm/gtc/type_ptr.hpp>

namespace penumbra::render {

inline std::string json_quote(std::string_view s) {
    std::string o = "\"";
    for (char c : s) {
        switch (c) {
            case '"': o += "\\\""; break;
            case '\\': o += "\\\\"; break;
            case '\n': o += "\\n"; break;
            case '\t': o += "\\t"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
                    o += buf;
                } else {
                    o += c;
                }
        }
    }
    return o + "\"";
}

// Nine significant digits (a float read back exactly); non-finite values as null.
inline std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

inline std::string json_bool(bool v) { return v ? "true" : "false"; }

// A glm vector or matrix as a JSON array of its floats (column-major for a matrix).
template <typename T>
std::string json_floats(const T& v) {
    const float* f = glm::value_ptr(v);
    std::string s = "[";
    for (int i = 0; i < static_cast<int>(sizeof(T) / sizeof(float)); ++i)
        s += (i ? "," : "") + json_number(static_cast<double>(f[i]));
    return s + "]";
}

}  // namespace penumbra::render
