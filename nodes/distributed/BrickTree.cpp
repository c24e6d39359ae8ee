#include "nodes/distributed/BrickTree.h"

#include "scenegraph/Error.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace texsplat::distributed {
namespace {

constexpr std::int64_t kBlock = 8; // octree::ClassifiedGrid's blocks: bricks start on them
// The thinnest brick a split across the slicing axis makes.
constexpr std::int64_t kMinSliceThickness = 2;

// Where a box of `extent` voxels from `lo` is split for `below` of its `count` bricks: in
// proportion, then on a multiple of a block when both parts keep voxels.
std::int64_t splitPlane(std::int64_t lo, std::int64_t extent, int below, int count) {
    const std::int64_t plane = lo + (extent * below + count / 2) / count;
    const std::int64_t onBlock = (plane + kBlock / 2) / kBlock * kBlock;
    return onBlock > lo && onBlock < lo + extent ? onBlock : plane;
}

// The axis a box of `dims` is split across for `below` of its `count` bricks (see split()).
int splitAxis(const glm::i64vec3& dims, int below, int count, int sliceAxis) {
    if (sliceAxis >= 0) {
        const std::int64_t thinner = dims[sliceAxis] * below / count;
        std::int64_t across = 0;
        for (int axis = 0; axis < 3; ++axis) {
            if (axis != sliceAxis) {
                across = std::max(across, dims[axis]);
            }
        }
        if (thinner >= kMinSliceThickness && thinner * BrickTree::kMaxSliceAspect >= across) {
            return sliceAxis;
        }
    }
    int longest = sliceAxis >= 0 ? sliceAxis : 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (dims[axis] > dims[longest]) {
            longest = axis;
        }
    }
    return longest;
}

} // namespace

BrickTree BrickTree::split(const volume::IndexBox& box, int count, int sliceAxis) {
    if (count < 1) {
        throw DataError("bricks: expected a count of 1 or more, got " + std::to_string(count));
    }
    BrickTree tree;
    tree.splitNode(box, count, sliceAxis);
    return tree;
}

int BrickTree::splitNode(const volume::IndexBox& box, int count, int sliceAxis) {
    const int index = static_cast<int>(mNodes.size());
    mNodes.emplace_back();
    if (count == 1) {
        mNodes[static_cast<std::size_t>(index)].brick = static_cast<int>(mBricks.size());
        mBricks.push_back(box);
        return index;
    }
    const int below = count / 2;
    const glm::i64vec3 dims = box.dims();
    const int axis = splitAxis(dims, below, count, sliceAxis);
    // A box of one voxel along every axis (or none) keeps it in its first part; the rest of its
    // bricks are empty.
    const std::int64_t plane =
        dims[axis] >= 2 ? splitPlane(box.lo[axis], dims[axis], below, count) : box.hi[axis];
    volume::IndexBox lower = box;
    volume::IndexBox upper = box;
    lower.hi[axis] = plane;
    upper.lo[axis] = plane;
    const int lowerNode = splitNode(lower, below, sliceAxis);
    mNodes[static_cast<std::size_t>(index)] = {axis, plane, lowerNode,
                                               splitNode(upper, count - below, sliceAxis), -1};
    return index;
}

BrickTree BrickTree::of(const std::vector<volume::IndexBox>& bricks) {
    if (bricks.empty()) {
        throw DataError("bricks: expected at least one");
    }
    for (std::size_t a = 0; a < bricks.size(); ++a) {
        for (std::size_t b = a + 1; b < bricks.size(); ++b) {
            const volume::IndexBox shared = bricks[a].intersection(bricks[b]);
            if (!shared.isEmpty()) {
                throw DataError("the blocks of ranks " + std::to_string(a) + " and " +
                                std::to_string(b) + " overlap: " + bricks[a].text() + " and " +
                                bricks[b].text() + " share the voxels " + shared.text() +
                                "; each voxel must belong to one rank (leave ghost cells out of "
                                "the blocks' boxes)");
            }
        }
    }
    BrickTree tree;
    tree.mBricks = bricks;
    std::vector<int> members(bricks.size());
    std::iota(members.begin(), members.end(), 0);
    tree.partNode(std::move(members));
    return tree;
}

int BrickTree::partNode(std::vector<int> members) {
    const int index = static_cast<int>(mNodes.size());
    mNodes.emplace_back();
    // Empty bricks draw nothing: they go last, each its own leaf.
    const auto firstEmpty = std::stable_partition(members.begin(), members.end(), [&](int brick) {
        return !mBricks[static_cast<std::size_t>(brick)].isEmpty();
    });
    const auto nonEmpty = static_cast<std::size_t>(firstEmpty - members.begin());
    if (members.size() == 1) {
        mNodes[static_cast<std::size_t>(index)].brick = members.front();
        return index;
    }
    std::vector<int> below;
    std::vector<int> above;
    int axis = -1;
    std::int64_t plane = 0;
    if (nonEmpty <= 1) {
        // One brick with voxels at most: the first, then the others.
        below.assign(members.begin(), members.begin() + 1);
        above.assign(members.begin() + 1, members.end());
        axis = 0;
        plane = nonEmpty == 1 ? mBricks[static_cast<std::size_t>(members.front())].hi.x : 0;
    } else {
        // A plane between two bricks' faces that no brick with voxels straddles, parting them
        // most evenly.
        std::size_t bestBalance = 0;
        for (int candidateAxis = 0; candidateAxis < 3; ++candidateAxis) {
            for (std::size_t m = 0; m < nonEmpty; ++m) {
                const std::int64_t candidate =
                    mBricks[static_cast<std::size_t>(members[m])].lo[candidateAxis];
                std::size_t lower = 0;
                bool parts = true;
                for (std::size_t other = 0; other < nonEmpty && parts; ++other) {
                    const volume::IndexBox& brick =
                        mBricks[static_cast<std::size_t>(members[other])];
                    if (brick.hi[candidateAxis] <= candidate) {
                        ++lower;
                    } else if (brick.lo[candidateAxis] < candidate) {
                        parts = false;
                    }
                }
                const std::size_t balance = std::min(lower, nonEmpty - lower);
                if (parts && balance > bestBalance) {
                    bestBalance = balance;
                    axis = candidateAxis;
                    plane = candidate;
                }
            }
        }
        if (axis < 0) {
            std::string ranks;
            for (std::size_t m = 0; m < nonEmpty; ++m) {
                ranks += (m == 0 ? "" : ", ") + std::to_string(members[m]);
            }
            throw DataError("no plane parts the blocks of ranks " + ranks +
                            " into two groups (a pinwheel of blocks has no visibility order); "
                            "lay the blocks out as a grid or a k-d tree");
        }
        for (std::size_t m = 0; m < members.size(); ++m) {
            const volume::IndexBox& brick = mBricks[static_cast<std::size_t>(members[m])];
            const bool isBelow = m < nonEmpty && brick.hi[axis] <= plane;
            (isBelow ? below : above).push_back(members[m]);
        }
    }
    const int belowNode = partNode(std::move(below));
    mNodes[static_cast<std::size_t>(index)] = {axis, plane, belowNode, partNode(std::move(above)),
                                               -1};
    return index;
}

std::vector<int> BrickTree::backToFront(const Viewpoint& view) const {
    std::vector<int> order;
    order.reserve(mBricks.size());
    appendBackToFront(0, view, order);
    return order;
}

void BrickTree::appendBackToFront(int index, const Viewpoint& view, std::vector<int>& order) const {
    const Node& node = mNodes[static_cast<std::size_t>(index)];
    if (node.axis < 0) {
        order.push_back(node.brick);
        return;
    }
    // The plane lies between voxels plane - 1 and plane. The side away from the eye comes first.
    const double plane = static_cast<double>(node.plane) - 0.5;
    const bool aboveIsFar =
        view.isPerspective ? view.eye[node.axis] < plane : view.direction[node.axis] > 0.0;
    appendBackToFront(aboveIsFar ? node.above : node.below, view, order);
    appendBackToFront(aboveIsFar ? node.below : node.above, view, order);
}

std::vector<int> BrickTree::splitAxes() const {
    std::vector<int> axes;
    for (const Node& node : mNodes) {
        if (node.axis >= 0) {
            axes.push_back(node.axis);
        }
    }
    return axes;
}

} // namespace texsplat::distributed
