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
#include <utility>

namespace texsplat::octree {
namespace {

// Mark `index` of `seed`'s sequence of `grid`'s marks (see MarkSource).
SplatMark drawMark(const ClassifiedGrid& grid, const std::vector<glm::u64vec3>& blocks,
                   const std::vector<std::uint64_t>& firsts, std::uint32_t seed,
                   std::uint64_t index) {
    constexpr std::uint64_t kMarkStream = 0x6d61726b73ull; // apart from other uses of the seed
    sg::Random random(
        sg::Random::mix(index ^ (static_cast<std::uint64_t>(seed) << 32) ^ kMarkStream));
    constexpr std::uint64_t kSize = ClassifiedGrid::kBlockSize;
    const glm::u64vec3 dims = grid.dims();
    for (int attempt = 0; attempt < MarkSource::kMaxTries; ++attempt) {
        const auto block = static_cast<std::size_t>(random.nextBits() % blocks.size());
        const std::uint64_t offset = random.nextBits() % ClassifiedGrid::kBlockVoxels;
        const glm::u64vec3 voxel =
            blocks[block] * kSize +
            glm::u64vec3(offset % kSize, (offset / kSize) % kSize, offset / (kSize * kSize));
        if (glm::any(glm::greaterThanEqual(voxel, dims))) {
            continue; // a block clipped by the grid's far faces
        }
        const glm::vec4 medium = grid.storedVoxel(firsts[block] + offset);
        if (medium == glm::vec4(0.0f)) {
            continue;
        }
        glm::dvec3 at(voxel);
        for (int axis = 0; axis < 3; ++axis) {
            at[axis] += random.uniform(-0.5, 0.5);
        }
        SplatMark mark;
        mark.position = glm::vec3(grid.toWorld(at));
        mark.phase = static_cast<float>(random.uniform());
        mark.vector = grid.storedVector(firsts[block] + offset);
        mark.extinction = medium.w;
        mark.color = glm::vec3(medium);
        return mark;
    }
    return SplatMark{}; // nothing found: no direction, draws nothing
}

// A mark's or a splat's distance along the view (larger: farther), as sortByDepth() orders.
double depthOf(const View& view, const glm::vec3& position) {
    const glm::dvec3 at(position);
    return view.isPerspective() ? glm::distance(at, view.eye()) : glm::dot(at, view.direction());
}

} // namespace

MarkSource::MarkSource(std::shared_ptr<const ClassifiedGrid> grid) : mGrid(std::move(grid)) {
    TEXSPLAT_ASSERT(mGrid && mGrid->hasVectors(), "MarkSource: needs a grid with vectors");
    mGrid->forEachBlock([&](glm::u64vec3 block, ClassifiedGrid::StorageIndex first) {
        mBlocks.push_back(block);
        mFirsts.push_back(first);
    });
    mVoxels = mGrid->nonEmptyVoxelCount();
}

void MarkSource::drawMarks(std::uint32_t seed, std::size_t count,
                           std::vector<SplatMark>& marks) const {
    const std::size_t drawn = std::min(marks.size(), count);
    marks.resize(mVoxels > 0 ? count : 0);
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(drawn, marks.size(), 1024), [&](const Range& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            marks[i] = drawMark(*mGrid, mBlocks, mFirsts, seed, i);
        }
    });
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
