#pragma once

#include "scenegraph/gl/Context.h"

#include <cstddef>
#include <optional>
#include <string_view>

namespace texsplat::gl {

/// @brief Which EGL platform an `EglContext` is made on.
enum class EglPlatform {
    /// Read `TEXSPLAT_EGL_PLATFORM` (`device`, `surfaceless` or `auto`); unset or empty is Auto.
    FromEnvironment,
    /// A GPU device (`EGL_EXT_platform_device`) when one is enumerated, else Mesa surfaceless.
    Auto,
    /// Only the device platform; software devices (Mesa's llvmpipe) count too.
    Device,
    /// Only Mesa's surfaceless platform (`EGL_MESA_platform_surfaceless`).
    Surfaceless,
};

/// @brief How to make an `EglContext`.
struct EglContextOptions {
    EglPlatform platform = EglPlatform::FromEnvironment; ///< Where to look for a context.
    bool debug = false; ///< Ask for a debug context (KHR_debug messages, see `DebugOutput.h`).
};

/// @brief A headless OpenGL context through EGL: no window, no display server, no surface.
///
/// It renders only into `Framebuffer`s. Platforms are tried in this order (see
/// docs/headless.md): the EGL device platform when a GPU device is enumerated
/// (`eglQueryDevicesEXT`), then Mesa's surfaceless platform (llvmpipe on machines without a
/// GPU). On each, a desktop OpenGL core context is requested, 4.5 first and 3.3 if 4.5 is
/// refused, without an EGLConfig where `EGL_KHR_no_config_context` allows it. The context is
/// current on the calling thread once constructed.
class EglContext final : public Context {
public:
    /// @brief Creates the context with default options (platform from the environment).
    /// @throws GlError naming each platform tried and why it failed, or a bad
    /// `TEXSPLAT_EGL_PLATFORM`.
    EglContext();

    /// @brief Creates the context as `options` ask.
    /// @throws GlError naming each platform tried and why it failed, or a bad
    /// `TEXSPLAT_EGL_PLATFORM`.
    explicit EglContext(const EglContextOptions& options);

    /// @brief Destroys the EGL context (releasing it first if it is current).
    ~EglContext() override;

    /// @brief How many of the devices EGL lists (`eglQueryDevicesEXT`) are not software
    /// rasterizers, found without initializing a display: no driver is loaded (a context on
    /// llvmpipe costs about 55 MiB resident and a tenth of a second or more). nullopt where EGL
    /// cannot list devices.
    static std::optional<std::size_t> gpuDeviceCount();

    /// @brief Parses a `TEXSPLAT_EGL_PLATFORM` value: "device", "surfaceless", "auto" or "".
    /// @throws GlError "TEXSPLAT_EGL_PLATFORM: unknown EGL platform '<value>' ..." otherwise.
    static EglPlatform parsePlatform(std::string_view value);

protected:
    void makePlatformCurrent() override;

private:
    // EGLDisplay and EGLContext are opaque pointers; EGL's headers stay out of this header.
    void* mDisplay = nullptr;
    void* mContext = nullptr;
};

} // namespace texsplat::gl
