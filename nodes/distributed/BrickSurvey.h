#pragma once

#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_uint3_sized.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::sg {
class Node;
} // namespace texsplat::sg

namespace texsplat::nodes {
class ScalarSplat;
} // namespace texsplat::nodes

namespace texsplat::octree {
class Refiner;
} // namespace texsplat::octree

namespace texsplat::distributed {

/// @brief What a brick's splat node tells a render split over processes before its frame, for
/// the figures of the whole that its splats depend on (docs/distributed.md, "Octree cuts and
/// marks").
struct SplatSurvey {
    nodes::ScalarSplat* splat = nullptr; ///< the node

    /// @brief Whether it draws marks (vector and combined splats), whose number per voxel
    /// follows the depth of the whole data (octree::VoxelShadows).
    bool drawsMarks = false;
    /// @brief Marks: one bit per column of the whole grid along x, y and z (the (y, z), (x, z)
    /// and (x, y) planes, the first coordinate fastest) holding a non-empty voxel of the brick.
    std::array<std::vector<std::uint64_t>, 3> columns;
    std::uint64_t voxels = 0;    ///< marks: the brick's non-empty voxels
    glm::u64vec3 offset{0};      ///< marks: the brick's voxel (0, 0, 0) in the whole grid
    glm::dvec3 spacing{1.0};     ///< marks: the classified grid's spacing
    glm::dvec3 wholeCentre{0.0}; ///< marks: the whole grid's centre (local space)
    glm::dvec3 wholeLow{0.0};  ///< marks: the whole grid's box's corner at voxel (-0.5, -0.5, -0.5)
    glm::dvec3 wholeHigh{0.0}; ///< marks: the opposite corner (either may be the smaller)

    /// @brief Whether it draws an octree cut (`errorThreshold` or `maxSplats` set).
    bool cuts = false;
    double valueScale = 0.0; ///< cuts: the brick's largest colour or extinction
    /// @brief Cuts: the refiner of the brick's octree for the frame's view (none for a brick
    /// without voxels), whose priorities cutSize() splits by.
    std::shared_ptr<const octree::Refiner> refiner;
    double largestPriority = 0.0; ///< cuts: the root's priority (the most any node has)
};

/// @brief The splats of the cut of `survey`'s brick that splits, from the root, every node whose
/// priority (octree::Refiner::priority(): error times size on screen) exceeds `threshold`: the
/// cut a budget refines to when its last split has that priority (counting stops past `limit`).
/// 0 for a brick without voxels. What a budget is shared over the bricks by: the threshold at
/// which their cuts add up to it (docs/distributed.md).
std::uint64_t cutSize(const SplatSurvey& survey, double threshold, std::uint64_t limit);

/// @brief Classifies, on this rank, the brick of every splat node of `root` that draws marks or
/// cuts its octree (cached for the frame that follows), and tells what it found, in traversal
/// order: the same nodes on every rank. `aspect`: the image's width over height.
/// @throws what classifying throws.
std::vector<SplatSurvey> surveyBricks(sg::Node& root, float aspect);

} // namespace texsplat::distributed
