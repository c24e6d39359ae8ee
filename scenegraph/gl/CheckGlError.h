#pragma once

#include <epoxy/gl.h>

#include <string>
#include <string_view>

namespace texsplat::gl {

/// @brief Drains `glGetError()` and throws if it held any error.
///
/// Meant for the boundaries of an action or a setup step, not for every call on a hot path:
/// glGetError may synchronize with the driver.
/// @param where names the step, e.g. "GlRenderer::render()".
/// @throws GlError "<where>: GL_INVALID_ENUM, GL_INVALID_OPERATION" (each error once, in order).
void checkGlError(std::string_view where);

/// @brief The enum's name for a glGetError code ("GL_INVALID_VALUE"), or its hex value.
std::string glErrorName(GLenum code);

} // namespace texsplat::gl
