// The unit tests' look at a plan's passes by name.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "plan/plan.h"

namespace penumbra::testing {

inline std::vector<std::string> pass_names(const render::FramePlan& p) {
    std::vector<std::string> names;
    for (const auto& pass : p.passes) names.push_back(pass.name);
    return names;
}

inline const render::Pass& pass_named(const render::FramePlan& p, const std::string& name) {
    for (const auto& pass : p.passes)
        if (pass.name == name) return pass;
    throw std::runtime_error("no pass " + name);
}

}  // namespace penumbra::testing
