#pragma once

namespace texsplat::nodes {

/// @brief Registers every node type of the nodes library with sg::NodeRegistry, so that the
/// scene reader can create them by name: the cameras, Transform, Material, DirectionalLight,
/// TransferFunction, VolumeData, Coordinate3, IndexedFaceSet, Mesh, Fibers (and the abstract
/// Camera). Calling it again does nothing; it is safe from several threads.
void registerNodeTypes();

} // namespace texsplat::nodes
