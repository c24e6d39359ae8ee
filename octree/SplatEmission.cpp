#include "octree/SplatEmission.h"

#include "octree/ClassifiedGrid.h"
#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/SliceOrder.h"
#include "octree/View.h"
#include "octree/detail/BackToFront.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Random.h"

#include <glm/geometric.hpp>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

namespace texsplat::octree {
namespace {

// A coarse node's key: its level above the voxel bits, so it never equals a voxel's index.
std::uint64_t nodeKey(const NodeRef& node) {
    return node.index ^ (static_cast<std::uint64_t>(node.level) << 58);
}

} // namespace

int tableColumn(float towardEye, int columns) {
    TEXSPLAT_ASSERT(columns >= 1, "tableColumn(): no columns");
    if (!(std::abs(towardEye) >= 0.0f)) {
        return 0;
    }
    const float z = std::min(std::abs(towardEye), 1.0f);
    return static_cast<int>(std::lround(z * static_cast<float>(columns - 1)));
}

SplatVector vectorSplat(const VectorEmission& emission, glm::vec3 position, glm::vec3 vector,
                        std::uint64_t key) {
    SplatVector result;
    result.vector = vector;
    result.row = static_cast<std::uint16_t>(
        sg::Random::mix(key ^ (static_cast<std::uint64_t>(emission.seed) << 32)) %
        static_cast<std::uint64_t>(emission.rows));
    // In double: a huge vector's squared length overflows float.
    const glm::dvec3 camera = glm::dmat3(glm::mat3(emission.localToCamera)) * glm::dvec3(vector);
    const double length = glm::length(camera);
    if (!(length > 0.0) || !std::isfinite(length)) {
        return result;
    }
    glm::dvec3 toEye(0.0, 0.0, 1.0);
    if (emission.isPerspective) {
        const glm::dvec3 centre(emission.localToCamera * glm::vec4(position, 1.0f));
        const double distance = glm::length(centre);
        if (distance > 0.0) {
            toEye = -centre / distance;
        }
    }
    result.column = static_cast<std::uint16_t>(tableColumn(
        static_cast<float>(glm::dot(camera, toEye) / length), emission.columns));
    return result;
}

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

} // namespace

void emitSplats(const Cut& cut, const View& view, SplatList& splats,
                const VectorEmission* vectors) {
    const Octree& octree = cut.octree();
    TEXSPLAT_ASSERT(!vectors || octree.grid().hasVectors(),
                    "emitSplats(): vector splats need vectors");
    splats.clear();
    if (octree.isEmpty()) {
        return;
    }
    const detail::BackToFrontDescent descent(cut, view);
    const auto emit = [&](const NodeRef& start, auto&& add) {
        detail::forEachBackToFrontFrom(descent, start, [&](const NodeRef& node) {
            const Splat splat = splatOf(octree, node);
            if (vectors) {
                add(splat, vectorSplat(*vectors, splat.position, octree.meanVector(node),
                                       nodeKey(node)));
            } else {
                add(splat, SplatVector{});
            }
        });
    };
    const auto threads = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
    if (threads == 1) {
        splats.reserve(static_cast<std::size_t>(cut.splatCount()), vectors != nullptr);
        emit(octree.root(), [&](const Splat& splat, const SplatVector& vector) {
            if (vectors) {
                splats.add(splat, vector);
            } else {
                splats.add(splat);
            }
        });
        return;
    }
    // Pieces of the traversal on all threads: each counts its splats, the pieces are laid end to
    // end, and each writes its splats at its offset. The serial traversal's list for any number of
    // threads, in the list's own memory (arrays per piece, copied in, held a cut's list twice and
    // faulted it in anew every frame). Many more pieces than threads, as subtrees differ in size.
    const std::vector<NodeRef> starts = traversalPieces(descent, 32 * threads);
    std::vector<std::size_t> offsets(starts.size() + 1, 0);
    tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t i) {
        std::size_t count = 0;
        detail::forEachBackToFrontFrom(descent, starts[i], [&](const NodeRef&) { ++count; });
        offsets[i + 1] = count;
    });
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    splats.resize(offsets.back(), vectors != nullptr);
    Splat* const out = splats.writableSplats();
    SplatVector* const outVectors = splats.writableVectors();
    tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t i) {
        std::size_t next = offsets[i];
        emit(starts[i], [&](const Splat& splat, const SplatVector& vector) {
            out[next] = splat;
            if (vectors) {
                outVectors[next] = vector;
            }
            ++next;
        });
    });
}

void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats,
                     const VectorEmission* vectors) {
    TEXSPLAT_ASSERT(!vectors || grid.hasVectors(), "emitVoxelSplats(): vector splats need vectors");
    const SliceOrder order(grid, view);
    // The voxel centres' box in front of the eye: no voxel can be behind it.
    const bool cullsBehindEye =
        !view.isBoxInFrontOfEye(grid.toWorld(glm::dvec3(0.0)),
                                grid.toWorld(glm::dvec3(grid.dims()) - 1.0));
    // Whether a voxel makes a splat: not empty, not behind the eye.
    const auto isDrawn = [&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored) {
        return grid.storedVoxel(stored) != glm::vec4(0.0f) &&
               !(cullsBehindEye && view.depth(grid.toWorld(glm::dvec3(voxel))) <= 0.0);
    };
    // Slices in parallel: count each one's splats, lay the slices end to end, then write each
    // slice's splats at its offset. The list is exactly as long as its splats (no growth by
    // doubling, which would hold the old and the new array at once), and the same for any number
    // of threads.
    const std::size_t slices = order.sliceCount();
    std::vector<std::size_t> offsets(slices + 1, 0);
    tbb::parallel_for(std::size_t{0}, slices, [&](std::size_t slice) {
        std::size_t count = 0;
        order.forEachInSlice(slice, [&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored) {
            count += isDrawn(voxel, stored) ? 1 : 0;
        });
        offsets[slice + 1] = count;
    });
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    splats.resize(offsets.back(), vectors != nullptr);
    Splat* const out = splats.writableSplats();
    SplatVector* const outVectors = splats.writableVectors();
    tbb::parallel_for(std::size_t{0}, slices, [&](std::size_t slice) {
        std::size_t next = offsets[slice];
        order.forEachInSlice(slice, [&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored) {
            if (!isDrawn(voxel, stored)) {
                return;
            }
            const glm::vec4 value = grid.storedVoxel(stored);
            // Every member: the list may be refilled over an octree cut's coarse splats.
            Splat& splat = out[next];
            splat.position = glm::vec3(grid.toWorld(glm::dvec3(voxel)));
            splat.size = 1.0f;
            splat.color = glm::vec3(value);
            splat.extinction = value.w;
            if (vectors) {
                outVectors[next] = vectorSplat(*vectors, splat.position, grid.storedVector(stored),
                                               grid.index(voxel));
            }
            ++next;
        });
    });
}

} // namespace texsplat::octree
