#pragma once

namespace texsplat::render {

/// @brief Adds the nodes library's entries to FrameAction's method table: the splat nodes
/// (ScalarSplat::collectFrame()) and the polygon geometry (IndexedFaceSet, Mesh, Fibers: their
/// TriangleMesh with the state's lighting, which the backends' opaque pass draws). Called by
/// nodes::registerNodeTypes(); calling it again, from any thread, does nothing.
void registerFrameMethods();

} // namespace texsplat::render
