#pragma once

#include "nodes/image/ImageRegion.h"
#include "nodes/render/Frame.h"

namespace texsplat::distributed {

/// @brief The pixels a frame's splats can draw on: the image region covered by the projection of
/// each batch's splat centres, widened by the farthest a splat draws from its centre (its size
/// times SplatFootprint::reach()) and, for marks, by their least length in pixels; the whole
/// image when a batch reaches behind a perspective eye. An empty region for a frame without
/// splats. A brick's screen footprint: what its rank draws and composites (docs/distributed.md).
image::ImageRegion splatFootprint(const render::Frame& frame);

/// @brief Turns `frame` (width x height) into the frame of its pixels in `region` (inside the
/// image, not empty): the same splats and meshes, drawn on region.width x region.height pixels
/// that are exactly the image's pixels there (every clip-space matrix moved and scaled to the
/// window, in double precision).
void cropFrame(render::Frame& frame, const image::ImageRegion& region);

} // namespace texsplat::distributed
