#include "scenegraph/gl/EglContext.h"

#include "scenegraph/Error.h"
#include "scenegraph/Log.h"

#include <epoxy/egl.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::gl {
namespace {

constexpr const char* kPlatformVariable = "TEXSPLAT_EGL_PLATFORM";

// Why one platform (or one device) gave no context; collected into the final GlError.
class PlatformFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

std::string eglErrorName(EGLint code) {
    switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: break;
    }
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(code));
    return std::string("EGL error ") + hex;
}

PlatformFailure callFailed(const char* call) {
    return PlatformFailure(std::string(call) + " failed (" + eglErrorName(eglGetError()) + ")");
}

struct Created {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

EGLContext createCoreContext(EGLDisplay display, EGLConfig config, EGLint major, EGLint minor,
                             bool debug) {
    std::vector<EGLint> attributes = {EGL_CONTEXT_MAJOR_VERSION_KHR,
                                      major,
                                      EGL_CONTEXT_MINOR_VERSION_KHR,
                                      minor,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR};
    if (debug) {
        attributes.insert(attributes.end(),
                          {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR});
    }
    attributes.push_back(EGL_NONE);
    return eglCreateContext(display, config, EGL_NO_CONTEXT, attributes.data());
}

// Initializes `display` and makes a current desktop GL core context on it, without a surface.
// The display is not terminated on failure: EGL displays are process-wide, and terminating one
// would also break every other context on it.
Created createOn(EGLDisplay display, const char* getDisplayCall, bool debug) {
    if (display == EGL_NO_DISPLAY) {
        throw callFailed(getDisplayCall);
    }
    EGLint eglMajor = 0;
    EGLint eglMinor = 0;
    if (!eglInitialize(display, &eglMajor, &eglMinor)) {
        throw callFailed("eglInitialize");
    }
    if (!epoxy_has_egl_extension(display, "EGL_KHR_create_context")) {
        throw PlatformFailure("EGL_KHR_create_context not supported");
    }
    if (!epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context")) {
        throw PlatformFailure("EGL_KHR_surfaceless_context not supported");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        throw callFailed("eglBindAPI(EGL_OPENGL_API)");
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!epoxy_has_egl_extension(display, "EGL_KHR_no_config_context")) {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, wanted, &config, 1, &count) || count < 1) {
            throw PlatformFailure("no EGLConfig renders desktop OpenGL");
        }
    }
    // 4.5 first for its features; 3.3 core is what texsplat needs at least.
    EGLContext context = createCoreContext(display, config, 4, 5, debug);
    if (context == EGL_NO_CONTEXT) {
        context = createCoreContext(display, config, 3, 3, debug);
    }
    if (context == EGL_NO_CONTEXT) {
        throw callFailed("eglCreateContext (OpenGL 4.5 and 3.3 core)");
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        PlatformFailure failure = callFailed("eglMakeCurrent");
        eglDestroyContext(display, context);
        throw failure;
    }
    return {display, context};
}

bool isSoftwareDevice(EGLDeviceEXT device) {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_query")) {
        return false;
    }
    const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
    return extensions &&
           std::string_view(extensions).find("EGL_MESA_device_software") != std::string_view::npos;
}

// The devices EGL lists (EGL_EXT_device_enumeration). Listing them initializes no display, so
// it loads no driver.
std::vector<EGLDeviceEXT> listDevices() {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration")) {
        throw PlatformFailure("EGL_EXT_device_enumeration not supported");
    }
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count)) {
        throw callFailed("eglQueryDevicesEXT");
    }
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (count > 0 && !eglQueryDevicesEXT(count, devices.data(), &count)) {
        throw callFailed("eglQueryDevicesEXT");
    }
    devices.resize(static_cast<std::size_t>(count));
    return devices;
}

// The device platform: GPU devices first; software devices only when `allowSoftware`.
Created createOnDevice(bool allowSoftware, bool debug, std::string& platform) {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device") ||
        !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration")) {
        throw PlatformFailure(
            "EGL_EXT_platform_device or EGL_EXT_device_enumeration not supported");
    }
    std::vector<EGLDeviceEXT> devices = listDevices();
    std::stable_partition(devices.begin(), devices.end(),
                          [](EGLDeviceEXT device) { return !isSoftwareDevice(device); });
    const auto softwareCount = std::count_if(devices.begin(), devices.end(), isSoftwareDevice);
    if (!allowSoftware) {
        devices.resize(devices.size() - static_cast<std::size_t>(softwareCount));
    }
    if (devices.empty()) {
        if (softwareCount == 0) {
            throw PlatformFailure("no devices");
        }
        throw PlatformFailure("no GPU devices (" + std::to_string(softwareCount) +
                              " software only)");
    }
    std::string reasons;
    for (std::size_t i = 0; i < devices.size(); ++i) {
        try {
            Created created = createOn(
                eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr),
                "eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT)", debug);
            platform = isSoftwareDevice(devices[i]) ? "EGL device (software)" : "EGL device";
            return created;
        } catch (const PlatformFailure& failure) {
            reasons += (reasons.empty() ? "" : ", ") + std::string("device ") +
                       std::to_string(i) + ": " + failure.what();
        }
    }
    throw PlatformFailure(reasons);
}

Created createOnSurfaceless(bool debug, std::string& platform) {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        throw PlatformFailure("EGL_MESA_platform_surfaceless not supported");
    }
    Created created = createOn(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA,
                                                        EGL_DEFAULT_DISPLAY, nullptr),
                               "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)", debug);
    platform = "EGL surfaceless";
    return created;
}

EglPlatform resolve(EglPlatform platform) {
    if (platform != EglPlatform::FromEnvironment) {
        return platform;
    }
    const char* value = std::getenv(kPlatformVariable);
    return EglContext::parsePlatform(value ? value : "");
}

} // namespace

EglContext::EglContext() : EglContext(EglContextOptions{}) {}

EglContext::EglContext(const EglContextOptions& options) {
    const EglPlatform platform = resolve(options.platform);
    std::string reasons;
    std::string description;
    Created created;
    if (platform == EglPlatform::Auto || platform == EglPlatform::Device) {
        try {
            created = createOnDevice(platform == EglPlatform::Device, options.debug, description);
        } catch (const PlatformFailure& failure) {
            reasons += std::string("device platform: ") + failure.what();
        }
    }
    if (created.context == EGL_NO_CONTEXT &&
        (platform == EglPlatform::Auto || platform == EglPlatform::Surfaceless)) {
        try {
            created = createOnSurfaceless(options.debug, description);
        } catch (const PlatformFailure& failure) {
            reasons += (reasons.empty() ? "" : "; ") + std::string("surfaceless platform: ") +
                       failure.what();
        }
    }
    if (created.context == EGL_NO_CONTEXT) {
        throw GlError("no EGL context: " + reasons);
    }
    if (!reasons.empty()) {
        // Expected on machines without a GPU (Auto falls back to surfaceless): not a warning.
        log(LogLevel::Debug, "EglContext: using " + description + " after " + reasons);
    }
    mDisplay = created.display;
    mContext = created.context;
    makeCurrent();
    queryInfo(description);
}

EglContext::~EglContext() {
    // The display stays initialized (see createOn): other contexts of the process may use it.
    if (eglGetCurrentContext() == mContext) {
        eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(mDisplay, mContext);
    clearCurrent();
}

std::optional<std::size_t> EglContext::gpuDeviceCount() {
    try {
        const std::vector<EGLDeviceEXT> devices = listDevices();
        return static_cast<std::size_t>(std::count_if(
            devices.begin(), devices.end(),
            [](EGLDeviceEXT device) { return !isSoftwareDevice(device); }));
    } catch (const PlatformFailure&) {
        return std::nullopt;
    }
}

EglPlatform EglContext::parsePlatform(std::string_view value) {
    if (value.empty() || value == "auto") {
        return EglPlatform::Auto;
    }
    if (value == "device") {
        return EglPlatform::Device;
    }
    if (value == "surfaceless") {
        return EglPlatform::Surfaceless;
    }
    throw GlError(std::string(kPlatformVariable) + ": unknown EGL platform '" +
                  std::string(value) + "' (expected 'device', 'surfaceless' or 'auto')");
}

void EglContext::makePlatformCurrent() {
    // The bound API is per thread, and eglMakeCurrent binds to it: another thread may still
    // have EGL's default (OpenGL ES).
    if (!eglBindAPI(EGL_OPENGL_API) ||
        !eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, mContext)) {
        throw GlError("EglContext: eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")");
    }
}

} // namespace texsplat::gl
