#pragma once

namespace texsplat::render {

/// @brief Adds the nodes library's entries to sg::RenderAction's method table: the splat nodes
/// (ScalarSplat::render(), which TextureSplat and GaussianSplat inherit) and the polygon
/// geometry (IndexedFaceSet, Mesh, Fibers: uploaded and queued for the opaque pass, colored by
/// their TriangleMesh, lit by the state's lights, Material's emissive color added). Called by
/// nodes::registerNodeTypes(); calling it again, from any thread, does nothing.
void registerRenderMethods();

} // namespace texsplat::render
