#pragma once

namespace texsplat::render {

/// @brief Adds the nodes library's entries to sg::RayCastAction's method table: the splat nodes
/// (ScalarSplat::rayCast(): the reconstructed medium, render::KernelVolumeMedium) and the
/// polygon geometry (IndexedFaceSet, Mesh, Fibers: render::MeshSurface, lit like the GL
/// backend's opaque pass). Called by nodes::registerNodeTypes(); calling it again, from any
/// thread, does nothing.
void registerRayCastMethods();

} // namespace texsplat::render
