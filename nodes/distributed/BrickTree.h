#pragma once

#include "nodes/volume/IndexBox.h"

#include <glm/vec3.hpp>

#include <vector>

namespace texsplat::distributed {

/// @brief Where the eye is, in a grid's index space (voxel i at coordinate i): what the bricks'
/// visibility order follows.
struct Viewpoint {
    bool isPerspective = false;           ///< the eye is a point (else a direction)
    glm::dvec3 eye{0.0};                  ///< the eye (perspective)
    glm::dvec3 direction{0.0, 0.0, -1.0}; ///< the viewing direction, from the eye into the scene
};

/// @brief The bricks of a grid split over processes, as a k-d tree: each inner node splits its box
/// in two by a plane across one axis, between two voxels; the leaves are the bricks, numbered
/// from 0 (brick r goes to rank r). Any two bricks are separated by the plane of the node where
/// their paths part, which gives their visibility order for any eye (backToFront()).
///
/// A render split by texsplat makes its tree with split(); a simulation that brings its own blocks
/// gets theirs found with of().
class BrickTree {
public:
    /// @brief The most a split prefers the slicing axis: its bricks may be this many times
    /// longer across it than along it (split()).
    static constexpr int kMaxSliceAspect = 16;

    /// @brief The k-d split of `box` into `count` bricks (count >= 1, any count): each node
    /// splits its box in two parts for floor(n/2) and ceil(n/2) of its n bricks, across the
    /// axis `sliceAxis` (0, 1 or 2; -1: none) while its thinner part stays at least 2 voxels
    /// thick and at most kMaxSliceAspect times longer across the other axes than along it, else
    /// across the box's longest axis, at the voxel that shares it in proportion, moved to a
    /// multiple of 8 voxels when both parts keep voxels. Splitting across the axis the splats are
    /// sliced along (octree::SliceOrder) keeps the bricks' order that of the one-process picture
    /// (docs/distributed.md). A box with fewer voxels than bricks leaves some bricks empty.
    static BrickTree split(const volume::IndexBox& box, int count, int sliceAxis = -1);

    /// @brief The tree of given bricks (a simulation's blocks, one per rank, each with no voxel
    /// of another): found by planes that part them, recursively. Empty bricks (ranks without
    /// voxels) go anywhere in the order.
    /// @throws DataError when two bricks share voxels ("the blocks of ranks 1 and 3 overlap:
    /// ..."), or no plane parts a group of them (blocks laid out as a pinwheel; a grid of blocks
    /// or a k-d tree always parts).
    static BrickTree of(const std::vector<volume::IndexBox>& bricks);

    /// @brief The bricks, by number.
    const std::vector<volume::IndexBox>& bricks() const { return mBricks; }

    /// @brief The bricks' numbers from the farthest to the nearest for `view` (index space): a
    /// brick comes before every brick that lies in front of it on a common line of sight, so
    /// compositing their images with "over" in this order gives the picture of the whole.
    std::vector<int> backToFront(const Viewpoint& view) const;

    /// @brief The axis each inner node splits across (for the docs and tests): in node order.
    std::vector<int> splitAxes() const;

private:
    struct Node {
        int axis = -1;          ///< -1: a leaf
        std::int64_t plane = 0; ///< voxels below it on `axis` go `below`
        int below = -1;         ///< child node (inner) ...
        int above = -1;
        int brick = -1; ///< leaf: the brick's number
    };

    int splitNode(const volume::IndexBox& box, int count, int sliceAxis);
    int partNode(std::vector<int> members);
    void appendBackToFront(int node, const Viewpoint& view, std::vector<int>& order) const;

    std::vector<Node> mNodes; // mNodes[0] is the root
    std::vector<volume::IndexBox> mBricks;
};

} // namespace texsplat::distributed
