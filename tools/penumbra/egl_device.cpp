#include "egl_device.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace penumbra::tools {

EglDeviceOption::EglDeviceOption(CLI::App& app, const std::vector<std::string>& skip) {
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        if (std::find(skip.begin(), skip.end(), sub->get_name()) != skip.end()) continue;
        sub->add_option("--egl-device", values_[sub],
                        "render on this EGL device, an index (penumbra caps lists them), through "
                        "EGL_EXT_platform_device (default: PENUMBRA_EGL_DEVICE, else the surfaceless Mesa platform)")
            ->type_name("N");
    }
}

std::string EglDeviceOption::apply() const {
    for (const auto& [sub, value] : values_) {
        if (!sub->parsed()) continue;
        if (sub->get_option("--egl-device")->count() > 0) return platform::choose_egl_device(value, "--egl-device");
        if (const char* env = std::getenv("PENUMBRA_EGL_DEVICE"); env && *env)
            return platform::choose_egl_device(env, "PENUMBRA_EGL_DEVICE");
    }
    return "";
}

void print_implementation(const platform::Platform& context, const gl::Caps& caps) {
    std::printf("GL_VENDOR: %s\nGL_RENDERER: %s\nGL_VERSION: %s\n", caps.vendor.c_str(), caps.renderer.c_str(),
                caps.version.c_str());
    if (const std::string d = context.details(); !d.empty()) std::printf("%s\n", d.c_str());
    const auto format = [](const char* name, const gl::PrecisionFormat& f) {
        std::printf("fragment %s float (glGetShaderPrecisionFormat): range 2^-%d to 2^%d, precision %d bits\n", name,
                    f.range_min, f.range_max, f.precision);
    };
    format("highp", caps.fragment_highp_float);
    format("mediump", caps.fragment_mediump_float);
    std::string why;
    const std::vector<platform::EglDevice> devices = platform::egl_devices(why);
    if (!why.empty()) {
        std::printf("EGL devices: none listed (%s)\n", why.c_str());
    } else {
        std::printf("EGL devices: %zu (choose one with --egl-device N or PENUMBRA_EGL_DEVICE=N)\n", devices.size());
        for (const auto& d : devices) std::printf("  %d: %s\n", d.index, d.name.c_str());
    }
    const int chosen = platform::chosen_egl_device();
    std::printf("in use: %s\n", chosen < 0 ? "the default, EGL_MESA_platform_surfaceless"
                                           : ("EGL device " + std::to_string(chosen)).c_str());
}

}  // namespace penumbra::tools
