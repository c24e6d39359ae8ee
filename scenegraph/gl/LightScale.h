#pragma once

#include <string>

namespace texsplat::gl {

/// @brief The factor by which GL draws light (the frame's colours, not its alpha): 2^-64.
/// GL blends in float without clamping: the light of many splats near FLT_MAX added up to +Inf,
/// and an opaque splat in front multiplied that by 0 (NaN). Drawn scaled, the sum of up to 2^64
/// splats of FLT_MAX each stays finite; the GL backend's read-back and the viewer scale it
/// back (a power of two: exact), and the read-back clamps to FLT_MAX, as the CPU backend and the
/// ray caster do. Light below 2^-62 (about 2e-19) is lost to GL's flushing of denormals.
constexpr float kLightScale = 0x1p-64f;

/// @brief `source`, a shader that opens with its #version line, with the constant
/// `lightScale` (kLightScale) declared after that line, for the shaders that write the frame.
std::string withLightScale(const char* source);

} // namespace texsplat::gl
