// Which EGL device the headless context opens (--egl-device N on every command that opens one,
// PENUMBRA_EGL_DEVICE=N otherwise; platform::choose_egl_device), and what `penumbra caps` prints
// to name the implementation beyond the capability summary.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "gl/caps.h"
#include "platform/platform.h"

namespace penumbra::tools {

class EglDeviceOption {
public:
    // Adds --egl-device N to each subcommand of `app` but those named in `skip` (no context there).
    EglDeviceOption(CLI::App& app, const std::vector<std::string>& skip);
    // After parsing: chooses the device given to the command that ran (or PENUMBRA_EGL_DEVICE's,
    // when set and not empty), before any work. "" or one line naming the problem (bad input).
    std::string apply() const;

private:
    std::map<CLI::App*, std::string> values_;
};

// The lines `penumbra caps` prints after the summary: GL_VENDOR, GL_RENDERER, GL_VERSION, the
// platform's details (EGL vendor, version, the display's device), the fragment shader's highp and
// mediump float formats (glGetShaderPrecisionFormat), the EGL devices there are and the one in use.
void print_implementation(const platform::Platform& context, const gl::Caps& caps);

}  // namespace penumbra::tools
