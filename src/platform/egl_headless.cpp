// Headless GLES2 through EGL's surfaceless platform (EGL_MESA_platform_surfaceless): Mesa picks
// llvmpipe when there is no GPU. No surface is made: everything renders into FBOs.
// Or, when a device is chosen (--egl-device N, PENUMBRA_EGL_DEVICE=N), through EGL's device
// platform (EGL_EXT_device_enumeration + EGL_EXT_platform_device) on the Nth device EGL lists.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "platform/platform.h"

namespace penumbra::platform {

namespace {

bool has_word(const char* list, const char* word) {
    const std::string l = list ? list : "", w = word;
    for (size_t at = l.find(w); at != std::string::npos; at = l.find(w, at + 1)) {
        const size_t end = at + w.size();
        if ((at == 0 || l[at - 1] == ' ') && (end == l.size() || l[end] == ' ')) return true;
    }
    return false;
}

bool client_has(const char* extension) { return has_word(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), extension); }

template <typename F>
F proc(const char* name) {
    return reinterpret_cast<F>(eglGetProcAddress(name));
}

// What names a device: its DRM nodes (EGL_EXT_device_drm, EGL_EXT_device_drm_render_node), its
// vendor and renderer (EGL_EXT_device_query_name), its CUDA index (EGL_NV_device_cuda), Mesa's
// software device (EGL_MESA_device_software).
std::string device_name(EGLDeviceEXT device) {
    const auto query_string = proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    if (!query_string) return "?";
    const char* ext = query_string(device, EGL_EXTENSIONS);
    std::string name;
    const auto add = [&](const std::string& part) {
        if (!part.empty()) name += (name.empty() ? "" : ", ") + part;
    };
    const auto text = [&](EGLint what) {
        const char* s = query_string(device, what);
        return std::string(s ? s : "");
    };
    if (has_word(ext, "EGL_EXT_device_drm")) add(text(EGL_DRM_DEVICE_FILE_EXT));
    if (has_word(ext, "EGL_EXT_device_drm_render_node")) {
        const std::string node = text(EGL_DRM_RENDER_NODE_FILE_EXT);
        if (!node.empty()) add("render node " + node);
    }
    if (has_word(ext, "EGL_EXT_device_query_name")) {
        const std::string renderer = text(EGL_RENDERER_EXT), vendor = text(EGL_VENDOR);
        add(renderer + (vendor.empty() ? "" : " (" + vendor + ")"));
    }
    if (has_word(ext, "EGL_NV_device_cuda")) {
        const auto query_attrib = proc<PFNEGLQUERYDEVICEATTRIBEXTPROC>("eglQueryDeviceAttribEXT");
        EGLAttrib cuda = -1;
        if (query_attrib && query_attrib(device, EGL_CUDA_DEVICE_NV, &cuda)) add("CUDA device " + std::to_string(cuda));
    }
    if (has_word(ext, "EGL_MESA_device_software")) add("software (EGL_MESA_device_software)");
    return name.empty() ? std::string(ext && *ext ? ext : "unnamed") : name;
}

// eglQueryDevicesEXT's list, or empty with `error` saying why.
std::vector<EGLDeviceEXT> query_devices(std::string& error) {
    error.clear();
    if (!client_has("EGL_EXT_device_enumeration") && !client_has("EGL_EXT_device_base")) {
        error = "EGL cannot list its devices here (no EGL_EXT_device_enumeration)";
        return {};
    }
    const auto query = proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    EGLint n = 0;
    if (!query || !query(0, nullptr, &n) || n < 0) {
        error = "eglQueryDevicesEXT failed";
        return {};
    }
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(n));
    if (n > 0 && !query(n, devices.data(), &n)) {
        error = "eglQueryDevicesEXT failed";
        return {};
    }
    devices.resize(static_cast<size_t>(n));
    return devices;
}

// The device create_headless opens: -1 the default (surfaceless Mesa). `decided`: chosen by
// choose_egl_device, or the environment already read.
struct Choice {
    int index = -1;
    bool decided = false;
};
Choice& choice() {
    static Choice c;
    return c;
}

std::string egl_error_name(EGLint e) {
    switch (e) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: break;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%04X", static_cast<unsigned>(e));
    return buf;
}

class EglHeadless final : public Platform {
public:
    ~EglHeadless() override {
        if (display_ != EGL_NO_DISPLAY) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
            eglTerminate(display_);
        }
    }

    bool init(int device_index, std::string& error) {
        const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        const std::string ext = client_ext ? client_ext : "";
        std::string platform = "surfaceless";
        if (device_index < 0) {
            if (ext.find("EGL_MESA_platform_surfaceless") == std::string::npos)
                return fail(error, "EGL_MESA_platform_surfaceless is not available (install libegl-mesa0)");
        } else if (!client_has("EGL_EXT_platform_device")) {
            return fail(error, "EGL_EXT_platform_device is not available (an EGL device was chosen)");
        }
        auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!get_display) return fail(error, "eglGetPlatformDisplayEXT is missing");
        if (device_index < 0) {
            display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        } else {
            std::string why;
            const std::vector<EGLDeviceEXT> devices = query_devices(why);
            if (static_cast<size_t>(device_index) >= devices.size()) {
                error = "headless EGL: no EGL device " + std::to_string(device_index) + " (" +
                        (why.empty() ? std::to_string(devices.size()) + " found" : why) + ")";
                return false;
            }
            display_ = get_display(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(device_index)], nullptr);
            platform = "device " + std::to_string(device_index) + " [" +
                       device_name(devices[static_cast<size_t>(device_index)]) + "]";
        }
        if (display_ == EGL_NO_DISPLAY) return fail(error, "eglGetPlatformDisplayEXT");
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor)) return fail(error, "eglInitialize");
        if (!eglBindAPI(EGL_OPENGL_ES_API)) return fail(error, "eglBindAPI(EGL_OPENGL_ES_API)");
        const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                         EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!eglChooseConfig(display_, config_attribs, &config, 1, &count) || count < 1)
            return fail(error, "eglChooseConfig (no GLES2 config)");
        const EGLint context_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
        if (context_ == EGL_NO_CONTEXT) return fail(error, "eglCreateContext (GLES 2)");
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            return fail(error, "eglMakeCurrent without a surface (EGL_KHR_surfaceless_context)");
        const char* vendor = eglQueryString(display_, EGL_VENDOR);
        description_ = "EGL " + std::to_string(major) + "." + std::to_string(minor) + " " + platform + " (" +
                       (vendor ? vendor : "?") + ")";
        return true;
    }

    std::string description() const override { return description_; }
    std::string details() const override {
        const auto str = [&](EGLint name) {
            const char* s = eglQueryString(display_, name);
            std::string text = s ? s : "?";
            while (!text.empty() && text.back() == ' ') text.pop_back();
            return text;
        };
        std::string d = "EGL vendor: " + str(EGL_VENDOR) + "\nEGL version: " + str(EGL_VERSION) +
                        "\nEGL client APIs: " + str(EGL_CLIENT_APIS) + "\nEGL display's device: ";
        // EGL_EXT_device_query: the device behind the display (whichever platform made it).
        const auto query_display = proc<PFNEGLQUERYDISPLAYATTRIBEXTPROC>("eglQueryDisplayAttribEXT");
        EGLAttrib device = 0;
        if (!(client_has("EGL_EXT_device_query") || client_has("EGL_EXT_device_base")) || !query_display)
            return d + "unknown (no EGL_EXT_device_query)";
        if (!query_display(display_, EGL_DEVICE_EXT, &device) || !device)
            return d + "unknown (eglQueryDisplayAttribEXT(EGL_DEVICE_EXT) failed)";
        d += device_name(reinterpret_cast<EGLDeviceEXT>(device));
        std::string why;
        const std::vector<EGLDeviceEXT> devices = query_devices(why);
        for (size_t i = 0; i < devices.size(); ++i)
            if (devices[i] == reinterpret_cast<EGLDeviceEXT>(device)) d += " (device " + std::to_string(i) + ")";
        return d;
    }
    Api api() const override { return Api::GLES2; }
    Proc proc_address(const char* name) const override { return eglGetProcAddress(name); }
    bool has_default_framebuffer() const override { return false; }
    void run(const FrameCallback& frame) override {
        for (long i = 0;; ++i)
            if (!frame(FrameInfo{static_cast<double>(i) / 60.0, 0, 0, i})) break;
    }

private:
    bool fail(std::string& error, const char* what) {
        error = std::string("headless EGL: ") + what + " failed (" + egl_error_name(eglGetError()) + ")";
        return false;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    std::string description_;
};

}  // namespace

std::vector<EglDevice> egl_devices(std::string& error) {
    std::vector<EglDevice> out;
    const std::vector<EGLDeviceEXT> devices = query_devices(error);
    for (size_t i = 0; i < devices.size(); ++i) out.push_back({static_cast<int>(i), device_name(devices[i])});
    return out;
}

std::string choose_egl_device(const std::string& value, const std::string& source) {
    Choice& c = choice();
    c.decided = true;
    c.index = -1;
    const std::string what = source + " '" + value + "': ";
    if (value.empty() || value.size() > 4 || value.find_first_not_of("0123456789") != std::string::npos)
        return what + "expected an EGL device index, a whole number from 0 (penumbra caps lists the devices)";
    const int index = std::atoi(value.c_str());
    std::string why;
    const std::vector<EglDevice> devices = egl_devices(why);
    if (!why.empty()) return what + why;
    if (static_cast<size_t>(index) >= devices.size())
        return what + "no such EGL device (" +
               (devices.empty()       ? std::string("none found")
                : devices.size() == 1 ? std::string("1 found: index 0")
                                      : std::to_string(devices.size()) + " found: indices 0 to " +
                                            std::to_string(devices.size() - 1)) +
               ")";
    c.index = index;
    return "";
}

int chosen_egl_device() { return choice().decided ? choice().index : -1; }

std::unique_ptr<Platform> create_headless(std::string& error) {
    if (!choice().decided) {
        const char* env = std::getenv("PENUMBRA_EGL_DEVICE");
        if (env && *env) {
            if (std::string problem = choose_egl_device(env, "PENUMBRA_EGL_DEVICE"); !problem.empty()) {
                error = "headless EGL: " + problem;
                return nullptr;
            }
        }
        choice().decided = true;
    }
    auto p = std::make_unique<EglHeadless>();
    if (!p->init(choice().index, error)) return nullptr;
    return p;
}

}  // namespace penumbra::platform
