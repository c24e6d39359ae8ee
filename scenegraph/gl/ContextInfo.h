#pragma once

#include <string>

namespace texsplat::gl {

/// @brief What the driver says about an OpenGL context: the strings of `glGetString` and the
/// version numbers of `glGetIntegerv(GL_MAJOR_VERSION/GL_MINOR_VERSION)`.
struct ContextInfo {
    std::string vendor;      ///< GL_VENDOR, e.g. "Mesa".
    std::string renderer;    ///< GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string version;     ///< GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6".
    std::string glslVersion; ///< GL_SHADING_LANGUAGE_VERSION, e.g. "4.50".
    int majorVersion = 0;    ///< 4 for an OpenGL 4.5 context.
    int minorVersion = 0;    ///< 5 for an OpenGL 4.5 context.
    std::string platform;    ///< How the context was made, e.g. "EGL surfaceless".

    /// @brief One line for logs and reports: "<version> | <renderer>".
    std::string summary() const { return version + " | " + renderer; }
};

} // namespace texsplat::gl
