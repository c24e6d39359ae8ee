#pragma once

#include "nodes/image/Image.h"
#include "scenegraph/actions/RayCastAction.h"

namespace texsplat::render {

/// @brief The last render of `action` as an image: premultiplied float RGBA, top row first
/// (the same layout as the backends' draw() of a Frame of the same size).
image::Image rayCastImage(const sg::RayCastAction& action);

} // namespace texsplat::render
