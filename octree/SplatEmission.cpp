#include "octree/SplatEmission.h"

#include "octree/ClassifiedGrid.h"
#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/SliceOrder.h"
#include "octree/View.h"
#include "octree/detail/BackToFront.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/Random.h"

#include <glm/geometric.hpp>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace texsplat::octree {
double MarkEmission::expectedMarks(std::uint64_t voxels) const {
    return std::min(marksPerVoxel * static_cast<double>(voxels), double(kMaxMarksPerSplat));
}

namespace {

// The hash that draws how many marks the splat named by `key` (a voxel's index or a node's key)
// carries, and seeds the stream that places them.
std::uint64_t markHash(const MarkEmission& emission, std::uint64_t key) {
    constexpr std::uint64_t kMarkStream = 0x6d61726b73ull; // apart from other uses of the key
    return sg::Random::mix(key ^ (static_cast<std::uint64_t>(emission.seed) << 32) ^ kMarkStream);
}

// How many marks a splat carries on average, split for drawing: the whole part always, and one
// more when the splat's hash falls below the fraction's share of 2^64 (one hash a splat: most
// voxels of a deep volume draw no mark, and this is all they cost).
struct MarkShare {
    int whole;
    std::uint64_t threshold;

    explicit MarkShare(double expected)
        : whole(static_cast<int>(std::floor(expected))),
          threshold(static_cast<std::uint64_t>(std::ldexp(expected - std::floor(expected), 64))) {}

    int count(std::uint64_t hash) const { return whole + (hash < threshold ? 1 : 0); }
};

// A mark at a random point of `voxel`'s cell carrying its vector and medium.
SplatMark markInCell(const ClassifiedGrid& grid, glm::u64vec3 voxel, sg::Random& random) {
    glm::dvec3 at(voxel);
    for (int axis = 0; axis < 3; ++axis) {
        at[axis] += random.uniform(-0.5, 0.5);
    }
    const glm::vec4 medium = grid.voxel(voxel);
    SplatMark mark;
    mark.position = glm::vec3(grid.toWorld(at));
    mark.phase = static_cast<float>(random.uniform());
    mark.vector = grid.vector(voxel);
    mark.extinction = medium.w;
    mark.color = glm::vec3(medium);
    return mark;
}

// A coarse node's key: its level above the voxel bits, so it never equals a voxel's index.
std::uint64_t nodeKey(const NodeRef& node) {
    return node.index ^ (static_cast<std::uint64_t>(node.level) << 58);
}

// Whether a vector can orient a mark: finite and not zero.
bool isDirection(glm::vec3 vector) {
    return std::isfinite(vector.x) && std::isfinite(vector.y) && std::isfinite(vector.z) &&
           vector != glm::vec3(0.0f);
}

// A non-empty voxel of `node`, each with the same chance: down the tree, a child with the
// chance of its share of the node's non-empty voxels.
glm::u64vec3 randomVoxel(const Octree& octree, NodeRef node, sg::Random& random) {
    std::array<NodeRef, 8> children;
    while (node.level > 0) {
        const int count = octree.children(node, children);
        TEXSPLAT_ASSERT(count > 0, "randomVoxel(): a node of the tree without children");
        std::uint64_t total = 0;
        std::array<std::uint64_t, 8> weights{};
        for (int c = 0; c < count; ++c) {
            weights[static_cast<std::size_t>(c)] =
                children[static_cast<std::size_t>(c)].level == 0
                    ? 1
                    : octree
                          .nodes()[static_cast<std::size_t>(
                              children[static_cast<std::size_t>(c)].index)]
                          .nonEmptyCount;
            total += weights[static_cast<std::size_t>(c)];
        }
        std::uint64_t pick = random.nextBits() % total;
        int chosen = 0;
        while (pick >= weights[static_cast<std::size_t>(chosen)]) {
            pick -= weights[static_cast<std::size_t>(chosen++)];
        }
        node = children[static_cast<std::size_t>(chosen)];
    }
    return node.coord;
}

} // namespace

namespace {

// voxelMarks() with the voxel's share of marks worked out.
int marksOfVoxel(const MarkEmission& emission, const MarkShare& share, const ClassifiedGrid& grid,
                 glm::u64vec3 voxel, SplatMark* out) {
    // The count first: most voxels of a deep volume draw none, and need not read their vector.
    const std::uint64_t hash = markHash(emission, grid.index(voxel));
    const int count = share.count(hash);
    if (count == 0 || !isDirection(grid.vector(voxel))) {
        return 0;
    }
    sg::Random random(hash);
    for (int i = 0; i < count; ++i) {
        out[i] = markInCell(grid, voxel, random);
    }
    return count;
}

} // namespace

int voxelMarks(const MarkEmission& emission, const ClassifiedGrid& grid, glm::u64vec3 voxel,
               SplatMark* out) {
    return marksOfVoxel(emission, MarkShare(emission.expectedMarks(1)), grid, voxel, out);
}

int nodeMarks(const MarkEmission& emission, const Octree& octree, const NodeRef& node,
              SplatMark* out) {
    const ClassifiedGrid& grid = octree.grid();
    if (node.level == 0) {
        return voxelMarks(emission, grid, node.coord, out);
    }
    const std::uint64_t hash = markHash(emission, nodeKey(node));
    const std::uint64_t voxels = octree.nodes()[static_cast<std::size_t>(node.index)].nonEmptyCount;
    const int count = MarkShare(emission.expectedMarks(voxels)).count(hash);
    sg::Random random(hash);
    for (int i = 0; i < count; ++i) {
        out[i] = markInCell(grid, randomVoxel(octree, node, random), random);
    }
    return count;
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

namespace {

// A piece of the list being written: where its splats and marks start.
struct ListOffsets {
    std::size_t splats = 0;
    std::size_t marks = 0;
};

// Lays counted pieces end to end (`offsets[i + 1]` holds piece i's counts, `offsets[0]` zeros)
// and sizes `splats` for them.
void layOut(std::vector<ListOffsets>& offsets, SplatList& splats, bool withMarks) {
    for (std::size_t i = 1; i < offsets.size(); ++i) {
        offsets[i].splats += offsets[i - 1].splats;
        offsets[i].marks += offsets[i - 1].marks;
    }
    if (withMarks && offsets.back().marks > SplatList::kMaxMarks) {
        throw DataError("vector splats: " + std::to_string(offsets.back().marks) +
                        " marks are more than a splat list holds (" +
                        std::to_string(SplatList::kMaxMarks) + "); lower markDensity");
    }
    splats.resize(offsets.back().splats, withMarks, offsets.back().marks);
}

// Ends the mark offsets of a list written by pieces: the last one, one past the last splat.
void closeMarks(std::uint32_t* begins, const ListOffsets& end) {
    if (begins != nullptr) {
        begins[end.splats] = static_cast<std::uint32_t>(end.marks);
    }
}

// Writes one splat and its marks at `at` (its own mark offset: closeMarks() writes the last),
// moving `at` on.
void write(Splat* out, SplatMark* outMarks, std::uint32_t* begins, ListOffsets& at,
           const Splat& splat, const SplatMark* marks, int markCount) {
    out[at.splats] = splat;
    if (begins != nullptr) {
        begins[at.splats] = static_cast<std::uint32_t>(at.marks);
        std::copy(marks, marks + markCount, outMarks + at.marks);
        at.marks += static_cast<std::size_t>(markCount);
    }
    ++at.splats;
}

} // namespace

void emitSplats(const Cut& cut, const View& view, SplatList& splats, const MarkEmission* marks) {
    const Octree& octree = cut.octree();
    TEXSPLAT_ASSERT(!marks || octree.grid().hasVectors(),
                    "emitSplats(): vector splats need vectors");
    splats.clear();
    if (octree.isEmpty()) {
        return;
    }
    const detail::BackToFrontDescent descent(cut, view);
    // Calls add(splat, marks, markCount) for the splats of the traversal piece from `start`.
    const auto emit = [&](const NodeRef& start, auto&& add) {
        std::array<SplatMark, MarkEmission::kMaxMarksPerSplat> placed;
        detail::forEachBackToFrontFrom(descent, start, [&](const NodeRef& node) {
            const Splat splat = splatOf(octree, node);
            const int count = marks != nullptr ? nodeMarks(*marks, octree, node, placed.data()) : 0;
            add(splat, placed.data(), count);
        });
    };
    const auto threads = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
    if (threads == 1) {
        splats.reserve(static_cast<std::size_t>(cut.splatCount()), marks != nullptr);
        emit(octree.root(), [&](const Splat& splat, const SplatMark* placed, int markCount) {
            if (marks != nullptr) {
                splats.add(splat, placed, static_cast<std::size_t>(markCount));
            } else {
                splats.add(splat);
            }
        });
        return;
    }
    // Pieces of the traversal on all threads: each counts its splats and marks, the pieces are
    // laid end to end, and each writes at its offset. The serial traversal's list for any
    // number of threads, in the list's own memory (arrays per piece, copied in, held a cut's list
    // twice and faulted it in anew every frame). Many more pieces than threads, as subtrees
    // differ in size.
    const std::vector<NodeRef> starts = traversalPieces(descent, 32 * threads);
    std::vector<ListOffsets> offsets(starts.size() + 1);
    tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t i) {
        ListOffsets& count = offsets[i + 1];
        emit(starts[i], [&](const Splat&, const SplatMark*, int markCount) {
            ++count.splats;
            count.marks += static_cast<std::size_t>(markCount);
        });
    });
    layOut(offsets, splats, marks != nullptr);
    Splat* const out = splats.writableSplats();
    SplatMark* const outMarks = splats.writableMarks();
    std::uint32_t* const begins = splats.writableMarkBegins();
    tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t i) {
        ListOffsets at = offsets[i];
        emit(starts[i], [&](const Splat& splat, const SplatMark* placed, int markCount) {
            write(out, outMarks, begins, at, splat, placed, markCount);
        });
    });
    closeMarks(begins, offsets.back());
}

void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats,
                     const MarkEmission* marks) {
    TEXSPLAT_ASSERT(!marks || grid.hasVectors(), "emitVoxelSplats(): vector splats need vectors");
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
    const MarkShare share(marks != nullptr ? marks->expectedMarks(1) : 0.0);
    // Calls add(voxel, stored, marks, markCount) for the drawn voxels of `slice`.
    const auto emit = [&](std::size_t slice, auto&& add) {
        std::array<SplatMark, MarkEmission::kMaxMarksPerSplat> placed;
        order.forEachInSlice(slice, [&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored) {
            if (isDrawn(voxel, stored)) {
                add(voxel, stored, placed.data(),
                    marks != nullptr ? marksOfVoxel(*marks, share, grid, voxel, placed.data()) : 0);
            }
        });
    };
    // Slices in parallel: count each one's splats and marks, lay the slices end to end, then
    // write each slice's at its offset. The list is exactly as long as its splats (no growth by
    // doubling, which would hold the old and the new array at once), and the same for any number
    // of threads.
    const std::size_t slices = order.sliceCount();
    std::vector<ListOffsets> offsets(slices + 1);
    tbb::parallel_for(std::size_t{0}, slices, [&](std::size_t slice) {
        ListOffsets& count = offsets[slice + 1];
        emit(slice,
             [&](glm::u64vec3, ClassifiedGrid::StorageIndex, const SplatMark*, int markCount) {
                 ++count.splats;
                 count.marks += static_cast<std::size_t>(markCount);
             });
    });
    layOut(offsets, splats, marks != nullptr);
    Splat* const out = splats.writableSplats();
    SplatMark* const outMarks = splats.writableMarks();
    std::uint32_t* const begins = splats.writableMarkBegins();
    tbb::parallel_for(std::size_t{0}, slices, [&](std::size_t slice) {
        ListOffsets at = offsets[slice];
        emit(slice, [&](glm::u64vec3 voxel, ClassifiedGrid::StorageIndex stored,
                        const SplatMark* placed, int markCount) {
            const glm::vec4 value = grid.storedVoxel(stored);
            // Every member: the list may be refilled over an octree cut's coarse splats.
            Splat splat;
            splat.position = glm::vec3(grid.toWorld(glm::dvec3(voxel)));
            splat.size = 1.0f;
            splat.color = glm::vec3(value);
            splat.extinction = value.w;
            write(out, outMarks, begins, at, splat, placed, markCount);
        });
    });
    closeMarks(begins, offsets.back());
}

} // namespace texsplat::octree
