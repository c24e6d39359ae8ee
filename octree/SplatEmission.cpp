#include "octree/SplatEmission.h"

#include "octree/ClassifiedGrid.h"
#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/SliceOrder.h"
#include "octree/View.h"
#include "octree/detail/BackToFront.h"
#include "octree/detail/MarkPlaces.h"
#include "scenegraph/Assert.h"

#include <glm/geometric.hpp>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace texsplat::octree {
namespace {

// The splat of `node`, a node of the cut.
Splat splatOf(const Octree& octree, const NodeRef& node) {
    Splat splat;
    if (node.level == 0) {
        // Voxels are most of a fine cut: read them straight from the grid.
        const ClassifiedGrid& grid = octree.grid();
        const glm::vec4 value = grid.voxel(node.coord);
        splat.position = glm::vec3(grid.toWorld(glm::dvec3(node.coord)));
        splat.color = glm::vec3(value);
        splat.extinction = value.w;
    } else {
        const OctreeNode& summary = octree.nodes()[static_cast<std::size_t>(node.index)];
        const glm::u64vec3 extent = octree.voxelEnd(node) - octree.voxelBegin(node);
        splat.position = glm::vec3(octree.center(node));
        splat.size = static_cast<float>(std::max({extent.x, extent.y, extent.z}));
        splat.color = summary.meanColor;
        splat.extinction = summary.meanExtinction;
    }
    return splat;
}

// Splits the back-to-front traversal of the cut into consecutive pieces: the nodes from which
// `forEachBackToFrontFrom()` walks one piece each, so that the pieces' splats, end to end, are
// the traversal's. Split nodes are replaced by their children in the traversal's order, a level
// at a time, until there are `target` pieces or none left to split above the voxels' parents.
std::vector<NodeRef> traversalPieces(const detail::BackToFrontDescent& descent,
                                     std::size_t target) {
    const Cut& cut = descent.cut();
    std::vector<NodeRef> pieces{cut.octree().root()};
    std::vector<NodeRef> next;
    std::array<NodeRef, 8> children;
    const auto isDivided = [&](const NodeRef& node) { return node.level > 1 && cut.isSplit(node); };
    while (pieces.size() < target && std::any_of(pieces.begin(), pieces.end(), isDivided)) {
        next.clear();
        for (const NodeRef& node : pieces) {
            if (!isDivided(node)) {
                next.push_back(node);
            } else if (descent.isEntered(node)) {
                const int count = descent.children(node, children);
                next.insert(next.end(), children.begin(), children.begin() + count);
            }
        }
        pieces.swap(next);
    }
    return pieces;
}

// Sizes `splats` for pieces counted in `offsets` (`offsets[i + 1]` holds piece i's count,
// `offsets[0]` zero) and lays them end to end: `offsets[i]` becomes where piece i starts.
void layOut(std::vector<std::size_t>& offsets, SplatList& splats) {
    for (std::size_t i = 1; i < offsets.size(); ++i) {
        offsets[i] += offsets[i - 1];
    }
    splats.resize(offsets.back(), false, 0);
}

// Where each of `marks` goes in a full-resolution list of `grid` whose slices of `order` end at
// `sliceEnds` (one past each slice's last splat): after the last splat of its voxel's slice.
std::vector<detail::MarkPlace> slicePlaces(const ClassifiedGrid& grid, const SliceOrder& order,
                                           const View& view, const std::vector<std::size_t>& ends,
                                           const std::vector<SplatMark>& marks) {
    const int axis = order.sliceAxis();
    const std::vector<std::uint64_t>& walk = order.axisOrder(axis);
    std::vector<std::size_t> rank(walk.size());
    for (std::size_t i = 0; i < walk.size(); ++i) {
        rank[static_cast<std::size_t>(walk[i])] = i;
    }
    const double last = static_cast<double>(grid.dims()[axis] - 1);
    std::vector<detail::MarkPlace> places(marks.size());
    tbb::parallel_for(std::size_t{0}, marks.size(), [&](std::size_t m) {
        const glm::vec3 position = marks[m].position;
        const double depth = view.depth(glm::dvec3(position));
        if (view.isPerspective() && depth <= 0.0) {
            return; // behind the eye
        }
        // The mark lies in its voxel's cell: the nearest voxel centre along the slicing axis.
        const double at = (double(position[axis]) - grid.origin()[axis]) / grid.spacing()[axis];
        const auto slice = rank[static_cast<std::size_t>(std::clamp(std::round(at), 0.0, last))];
        if (ends[slice + 1] > 0) {
            places[m].after = ends[slice + 1] - 1;
            places[m].depth = depth;
        }
    });
    return places;
}

} // namespace

void emitSplats(const Cut& cut, const View& view, SplatList& splats) {
    const Octree& octree = cut.octree();
    splats.clear();
    if (octree.isEmpty()) {
        return;
    }
    const detail::BackToFrontDescent descent(cut, view);
    const auto threads = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
    if (threads == 1) {
        splats.reserve(static_cast<std::size_t>(cut.splatCount()), false);
        detail::forEachBackToFrontFrom(descent, octree.root(), [&](const NodeRef& node) {
            splats.add(splatOf(octree, node));
        });
        return;
    }
    // Pieces of the traversal on all threads: each counts its splats, the pieces are laid end
    // to end, and each writes at its offset. The serial traversal's list for any number of
    // threads, in the list's own memory (arrays per piece, copied in, held a cut's list twice
    // and faulted it in anew every frame). Many more pieces than threads, as subtrees differ in
    // size.
    const std::vector<NodeRef> starts = traversalPieces(descent, 32 * threads);
    std::vector<std::size_t> offsets(starts.size() + 1, 0);
    tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t i) {
        detail::forEachBackToFrontFrom(descent, starts[i],
                                       [&](const NodeRef&) { ++offsets[i + 1]; });
    });
    layOut(offsets, splats);
    Splat* const out = splats.writableSplats();
    tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t i) {
        std::size_t at = offsets[i];
        detail::forEachBackToFrontFrom(
            descent, starts[i], [&](const NodeRef& node) { out[at++] = splatOf(octree, node); });
    });
}

Splat voxelSplat(const ClassifiedGrid& grid, glm::u64vec3 voxel,
                 ClassifiedGrid::StorageIndex stored) {
    const glm::vec4 value = grid.storedVoxel(stored);
    // Every member: a list may be refilled over an octree cut's coarse splats.
    Splat splat;
    splat.position = glm::vec3(grid.toWorld(glm::dvec3(voxel)));
    splat.size = 1.0f;
    splat.color = glm::vec3(value);
    splat.extinction = value.w;
    return splat;
}

DrawnVoxels::DrawnVoxels(const ClassifiedGrid& grid, const View& view)
    : mGrid(&grid), mView(view),
      // The voxel centres' box in front of the eye: no voxel can be behind it.
      mCullsBehindEye(!view.isBoxInFrontOfEye(grid.toWorld(glm::dvec3(0.0)),
                                              grid.toWorld(glm::dvec3(grid.dims()) - 1.0))) {}

bool DrawnVoxels::isBehindEye(glm::u64vec3 voxel) const {
    return mView.depth(mGrid->toWorld(glm::dvec3(voxel))) <= 0.0;
}

namespace {

// emitVoxelSplats() of slices [sliceBegin, sliceEnd): returns where each slice's splats end in
// `splats` (entry i + 1 one past slice sliceBegin + i's last splat, entry 0 zero).
std::vector<std::size_t> emitSlices(const SliceOrder& order, const DrawnVoxels& drawn,
                                    std::size_t sliceBegin, std::size_t sliceEnd,
                                    SplatList& splats) {
    const ClassifiedGrid& grid = drawn.grid();
    // Calls add(voxel, stored) for the drawn voxels of `slice`.
    const auto forEachDrawn = [&](std::size_t slice, auto&& add) {
        order.forEachInSlice(slice, [&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored) {
            if (drawn.isDrawn(voxel, stored)) {
                add(voxel, stored);
            }
        });
    };
    // Slices in parallel: count each one's splats, lay the slices end to end, then write each
    // slice's at its offset. The list is exactly as long as its splats (no growth by doubling,
    // which would hold the old and the new array at once), and the same for any number of
    // threads.
    const std::size_t slices = sliceEnd - sliceBegin;
    std::vector<std::size_t> offsets(slices + 1, 0);
    tbb::parallel_for(std::size_t{0}, slices, [&](std::size_t slice) {
        forEachDrawn(sliceBegin + slice,
                     [&](glm::u64vec3, ClassifiedGrid::StorageIndex) { ++offsets[slice + 1]; });
    });
    layOut(offsets, splats);
    Splat* const out = splats.writableSplats();
    tbb::parallel_for(std::size_t{0}, slices, [&](std::size_t slice) {
        std::size_t at = offsets[slice];
        forEachDrawn(sliceBegin + slice,
                     [&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored) {
                         out[at++] = voxelSplat(grid, voxel, stored);
                     });
    });
    // offsets[i + 1] is now one past slice i's last splat.
    return offsets;
}

} // namespace

void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats,
                     const std::vector<SplatMark>* marks) {
    const SliceOrder order(grid, view);
    const std::vector<std::size_t> ends =
        emitSlices(order, DrawnVoxels(grid, view), 0, order.sliceCount(), splats);
    if (marks != nullptr) {
        detail::placeMarks(*marks, slicePlaces(grid, order, view, ends, *marks), splats);
    }
}

void emitVoxelSplats(const SliceOrder& order, const DrawnVoxels& drawn, std::size_t sliceBegin,
                     std::size_t sliceEnd, SplatList& splats) {
    emitSlices(order, drawn, sliceBegin, sliceEnd, splats);
}

} // namespace texsplat::octree
