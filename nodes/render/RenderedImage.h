#pragma once

#include "nodes/image/Image.h"
#include "scenegraph/actions/RenderAction.h"

namespace texsplat::render {

/// @brief Whether renderedImage() also reads the depth buffer.
enum class DepthReadback { Without, With };

/// @brief The last frame of `action` as an image: premultiplied float RGBA (±Inf from blending
/// overflow clamped to ±FLT_MAX; NaN stays NaN), top row first and,
/// with DepthReadback::With, the window-space depth in [0, 1] of the opaque geometry (1 where
/// there is none; splats do not write depth). Counts as RenderPhase::ReadBack.
image::Image renderedImage(sg::RenderAction& action, DepthReadback depth = DepthReadback::Without);

} // namespace texsplat::render
