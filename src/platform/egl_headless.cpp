// Headless GLES2 through EGL's surfaceless platform (EGL_MESA_platform_surfaceless): Mesa picks
// llvmpipe when there is no GPU. No surface is made: everything renders into FBOs.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>

#include "platform/platform.h"

namespace penumbra::platform {

namespace {

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

    bool init(std::string& error) {
        const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        const std::string ext = client_ext ? client_ext : "";
        if (ext.find("EGL_MESA_platform_surfaceless") == std::string::npos)
            return fail(error, "EGL_MESA_platform_surfaceless is not available (install libegl-mesa0)");
        auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!get_display) return fail(error, "eglGetPlatformDisplayEXT is missing");
        display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
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
        description_ = "EGL " + std::to_string(major) + "." + std::to_string(minor) + " surfaceless (" +
                       (vendor ? vendor : "?") + ")";
        return true;
    }

    std::string description() const override { return description_; }
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

std::unique_ptr<Platform> create_headless(std::string& error) {
    auto p = std::make_unique<EglHeadless>();
    if (!p->init(error)) return nullptr;
    return p;
}

}  // namespace penumbra::platform
