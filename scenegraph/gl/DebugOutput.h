#pragma once

namespace texsplat::gl {

/// @brief Routes the driver's KHR_debug messages of the current context to `texsplat::log`
/// (high severity as errors, medium as warnings, low as info, notifications as debug).
///
/// Drivers say most in a debug context (`EglContextOptions::debug`). Needs OpenGL 4.3 or
/// GL_KHR_debug.
/// @return false, changing nothing, when the context supports neither.
/// @throws GlError when no context is current.
bool enableDebugOutput();

} // namespace texsplat::gl
