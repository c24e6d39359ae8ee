#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace texsplat::gl {
class EglContext;
} // namespace texsplat::gl

namespace texsplat::render {

/// @brief What draws a frame (docs/design.md, "Backends: one frame, several ways to draw it").
enum class Backend {
    Cpu, ///< render::cpu::CpuRenderer: no GL
    Gl,  ///< render::GlRenderer: instanced quads through OpenGL
};

/// @brief The backend a user asks for: `--backend cpu|gl|auto`.
enum class BackendRequest { Auto, Cpu, Gl };

/// @brief "auto", "cpu" or "gl"; throws DataError("--backend: expected cpu, gl or auto, got
/// '<text>'") otherwise.
BackendRequest parseBackendRequest(std::string_view text);

/// @brief Whether a GL renderer string names a software rasterizer (Mesa's llvmpipe, softpipe,
/// swrast), on which the CPU backend is the faster way to draw splats.
bool isSoftwareRenderer(std::string_view renderer);

/// @brief The backend a request resolves to, with the GL context when it is GL.
struct BackendChoice {
    Backend backend = Backend::Cpu;
    /// @brief Current on this thread when backend is Gl (include scenegraph/gl/EglContext.h to
    /// use it); never set in a build without GL.
    std::shared_ptr<gl::EglContext> context;
    double contextSeconds = 0.0;             ///< time spent making (or trying) a context
    std::string reason; ///< for reports: why `auto` chose it, or "asked for"

    /// @brief Resolves `request`: Cpu makes no context; Gl makes one (throws GlError when it
    /// cannot, Error in a build without GL); Auto takes the CPU where EGL lists no GPU device,
    /// else makes a context and keeps it unless it fails or its renderer is a software
    /// rasterizer, then takes the CPU (always, without GL).
    static BackendChoice resolve(BackendRequest request);
};

} // namespace texsplat::render
