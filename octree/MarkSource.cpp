#include "octree/MarkSource.h"

#include "octree/ClassifiedGrid.h"
#include "octree/DepthSort.h"
#include "octree/View.h"
#include "octree/detail/MarkPlaces.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Random.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace texsplat::octree {
namespace {

constexpr std::uint64_t kCellVoxels =
    MarkSource::kCellSize * MarkSource::kCellSize * MarkSource::kCellSize;

// The random numbers of candidate `index` of the whole grid's `cell` for `seed` (see MarkSource).
sg::Random candidateRandom(glm::u64vec3 cell, std::uint64_t index, std::uint32_t seed) {
    constexpr std::uint64_t kMarkStream = 0x6d61726b73ull; // apart from other uses of the seed
    const std::uint64_t cellKey = cell.x ^ (cell.y << 21U) ^ (cell.z << 42U);
    return sg::Random(sg::Random::mix(
        cellKey ^ sg::Random::mix(index ^ (static_cast<std::uint64_t>(seed) << 32) ^ kMarkStream)));
}

// Appends to `marks` the marks of the whole grid's `cell` that lie in `grid` (at `offset` in the
// whole): `whole` candidates, and one more when its first draw falls below `part`.
void drawCellMarks(const ClassifiedGrid& grid, glm::u64vec3 offset, glm::u64vec3 cell,
                   std::uint32_t seed, std::uint64_t whole, double part,
                   std::vector<SplatMark>& marks) {
    constexpr std::uint64_t kSize = MarkSource::kCellSize;
    for (std::uint64_t index = 0; index <= whole; ++index) {
        sg::Random random = candidateRandom(cell, index, seed);
        // Drawn for every candidate, so that its other numbers do not depend on the count.
        const double presence = random.uniform();
        if (index == whole && presence >= part) {
            break;
        }
        const std::uint64_t slot = random.nextBits() % kCellVoxels;
        const glm::u64vec3 voxel =
            cell * kSize + glm::u64vec3(slot % kSize, (slot / kSize) % kSize, slot / (kSize * kSize));
        glm::dvec3 jitter;
        for (int axis = 0; axis < 3; ++axis) {
            jitter[axis] = random.uniform(-0.5, 0.5);
        }
        const auto phase = static_cast<float>(random.uniform());
        // Another brick's voxel, or past the grid's far faces.
        if (glm::any(glm::lessThan(voxel, offset)) ||
            glm::any(glm::greaterThanEqual(voxel - offset, grid.dims()))) {
            continue;
        }
        const glm::u64vec3 local = voxel - offset;
        const glm::vec4 medium = grid.voxel(local);
        if (medium == glm::vec4(0.0f)) {
            continue;
        }
        SplatMark mark;
        mark.position = glm::vec3(grid.toWorld(glm::dvec3(local) + jitter));
        mark.phase = phase;
        mark.vector = grid.vector(local);
        mark.extinction = medium.w;
        mark.color = glm::vec3(medium);
        marks.push_back(mark);
    }
}

// A mark's or a splat's distance along the view (larger: farther), as sortByDepth() orders.
double depthOf(const View& view, const glm::vec3& position) {
    const glm::dvec3 at(position);
    return view.isPerspective() ? glm::distance(at, view.eye()) : glm::dot(at, view.direction());
}

} // namespace

MarkSource::MarkSource(std::shared_ptr<const ClassifiedGrid> grid, glm::u64vec3 offset)
    : mGrid(std::move(grid)), mOffset(offset) {
    TEXSPLAT_ASSERT(mGrid && mGrid->hasVectors(), "MarkSource: needs a grid with vectors");
    // The whole grid's cells that the grid's blocks holding a non-empty voxel meet: one a block
    // when the grid starts on a cell boundary, up to eight for a brick that does not.
    constexpr std::uint64_t kSize = ClassifiedGrid::kBlockSize;
    mGrid->forEachBlock([&](glm::u64vec3 block, ClassifiedGrid::StorageIndex first) {
        if (mGrid->storedBlockCount(first) == 0) {
            return;
        }
        const glm::u64vec3 low = (block * kSize + mOffset) / kCellSize;
        const glm::u64vec3 last = glm::min(block * kSize + kSize, mGrid->dims()) - std::uint64_t{1};
        const glm::u64vec3 high = (last + mOffset) / kCellSize;
        for (std::uint64_t z = low.z; z <= high.z; ++z) {
            for (std::uint64_t y = low.y; y <= high.y; ++y) {
                for (std::uint64_t x = low.x; x <= high.x; ++x) {
                    mCells.emplace_back(x, y, z);
                }
            }
        }
    });
    const auto before = [](const glm::u64vec3& a, const glm::u64vec3& b) {
        return std::tie(a.z, a.y, a.x) < std::tie(b.z, b.y, b.x);
    };
    std::sort(mCells.begin(), mCells.end(), before);
    mCells.erase(std::unique(mCells.begin(), mCells.end()), mCells.end());
    mVoxels = mGrid->nonEmptyVoxelCount();
}

void MarkSource::drawMarks(std::uint32_t seed, double marksPerVoxel,
                           std::vector<SplatMark>& marks) const {
    marks.clear();
    const double candidates = marksPerVoxel * static_cast<double>(kCellVoxels);
    if (mVoxels == 0 || !(candidates > 0.0) || !std::isfinite(candidates)) {
        return;
    }
    const auto whole = static_cast<std::uint64_t>(std::floor(candidates));
    const double part = candidates - std::floor(candidates);
    // Runs of cells drawn in parallel into lists of their own, joined in the cells' order.
    constexpr std::size_t kCellsPerRun = 64;
    std::vector<std::vector<SplatMark>> runs((mCells.size() + kCellsPerRun - 1) / kCellsPerRun);
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, runs.size()), [&](const Range& range) {
        for (std::size_t run = range.begin(); run < range.end(); ++run) {
            const std::size_t end = std::min(mCells.size(), (run + 1) * kCellsPerRun);
            for (std::size_t c = run * kCellsPerRun; c < end; ++c) {
                drawCellMarks(*mGrid, mOffset, mCells[c], seed, whole, part, runs[run]);
            }
        }
    });
    std::size_t count = 0;
    for (const std::vector<SplatMark>& run : runs) {
        count += run.size();
    }
    marks.reserve(count);
    for (const std::vector<SplatMark>& run : runs) {
        marks.insert(marks.end(), run.begin(), run.end());
    }
}

void emitMarkSplats(const std::vector<SplatMark>& marks, const View& view, SplatList& splats) {
    TEXSPLAT_ASSERT(marks.size() <= SplatList::kMaxMarks, "emitMarkSplats(): too many marks");
    std::vector<std::size_t> seen;
    seen.reserve(marks.size());
    for (std::size_t m = 0; m < marks.size(); ++m) {
        if (!view.isPerspective() || view.depth(glm::dvec3(marks[m].position)) > 0.0) {
            seen.push_back(m);
        }
    }
    splats.resize(seen.size(), true, seen.size());
    Splat* const out = splats.writableSplats();
    SplatMark* const outMarks = splats.writableMarks();
    std::uint32_t* const begins = splats.writableMarkBegins();
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, seen.size(), 4096), [&](const Range& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            const SplatMark& mark = marks[seen[i]];
            Splat& splat = out[i];
            splat.position = mark.position;
            splat.size = 1.0f;
            splat.color = mark.color;
            splat.extinction = mark.extinction;
            outMarks[i] = mark;
            begins[i] = static_cast<std::uint32_t>(i);
        }
    });
    begins[seen.size()] = static_cast<std::uint32_t>(seen.size());
    sortByDepth(splats, view);
}

void attachMarksByDepth(const std::vector<SplatMark>& marks, const View& view, SplatList& splats) {
    TEXSPLAT_ASSERT(!splats.hasMarks(), "attachMarksByDepth(): the list holds marks already");
    TEXSPLAT_ASSERT(marks.size() <= SplatList::kMaxMarks, "attachMarksByDepth(): too many marks");
    const std::size_t count = splats.size();
    if (count == 0) {
        splats.resize(0, true, 0);
        return;
    }
    // The splats' depths, decreasing along the list (back to front), and each mark's place: after
    // the last splat no nearer than the mark (the first splat for a mark behind them all).
    std::vector<double> depths(count);
    const Splat* const splat = splats.splats().data();
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, count, 4096), [&](const Range& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            depths[i] = depthOf(view, splat[i].position);
        }
    });
    std::vector<detail::MarkPlace> places(marks.size());
    tbb::parallel_for(Range(0, marks.size(), 1024), [&](const Range& range) {
        for (std::size_t m = range.begin(); m < range.end(); ++m) {
            const double depth = depthOf(view, marks[m].position);
            const auto nearer =
                std::partition_point(depths.begin(), depths.end(),
                                     [&](double splatDepth) { return splatDepth >= depth; });
            places[m].after =
                static_cast<std::size_t>(std::max<std::ptrdiff_t>(nearer - depths.begin() - 1, 0));
            places[m].depth = depth;
        }
    });
    detail::placeMarks(marks, places, splats);
}

} // namespace texsplat::octree
