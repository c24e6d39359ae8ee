#pragma once

#include "scenegraph/Separator.h"

namespace texsplat::nodes {

/// @brief The scene `texsplat render` draws when given none: the magnitude of Crawfis's tornado
/// (the paper's figure 5 data) as texture splats with a brown transfer function, and three
/// opaque fibers (IndexedFaceSet cylinders) running through the funnel, so the default image
/// shows both passes: polygons inside a volume rendering (the paper's figure 7 idea).
///
/// The graph has no camera; the caller frames one (Camera::viewAll). Written as a scene file
/// (`texsplat info` / WriteAction) it is `examples/tornado.iv` with the fibers inline.
/// @param resolution samples of the tornado per axis (>= 2).
sg::Separator::Ptr makeDefaultScene(int resolution = 64);

} // namespace texsplat::nodes
