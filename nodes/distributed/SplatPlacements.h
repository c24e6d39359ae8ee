#pragma once

#include "nodes/render/CameraView.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace texsplat::sg {
class Node;
} // namespace texsplat::sg

namespace texsplat::nodes {
class ScalarSplat;
class VolumeData;
} // namespace texsplat::nodes

namespace texsplat::distributed {

/// @brief Where a splat node of a scene draws its volume: what a render split over processes
/// splits and places (docs/distributed.md).
struct SplatPlacement {
    nodes::ScalarSplat* splat = nullptr; ///< the splat node
    nodes::VolumeData* volume = nullptr; ///< the VolumeData it draws
    glm::mat4 model{1.0f};               ///< the volume's local space to the scene's root space
    render::CameraView camera;           ///< the camera it is seen through
    /// @brief Further VolumeData the node reads voxel by voxel along its volume's (its fields
    /// `maskData`, `colorData`): split as its volume is.
    std::vector<nodes::VolumeData*> companions;
};

/// @brief The splat nodes of `root` in traversal order, each with what it draws and how it is
/// placed, for an image of `aspect` (width over height). The nodes' fields are checked as a
/// render checks them.
/// @throws DataError naming the node for a splat node without a VolumeData, TransferFunction or
/// camera before it, or a field out of range.
std::vector<SplatPlacement> findSplatPlacements(sg::Node& root, float aspect);

/// @brief Every VolumeData under `root` (children and the nodes fields hold), once each.
std::vector<nodes::VolumeData*> findVolumes(sg::Node& root);

} // namespace texsplat::distributed
