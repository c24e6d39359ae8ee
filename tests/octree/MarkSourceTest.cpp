// Vector marks (Crawfis & Max 1993, "Combined Vector and Scalar Textures"): where MarkSource
// draws them, how a frame extends or shrinks their sequence, and where the emitters put them
// among the splats.
#include "octree/MarkSource.h"

#include "octree/ClassifiedGrid.h"
#include "octree/Cut.h"
#include "octree/DepthSort.h"
#include "octree/Octree.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "octree/View.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

namespace texsplat::octree {
namespace {

// An n³ grid (spacing 1, origin 0) whose voxels `isFilled(i, j, k)` have unit extinction and the
// vector `vectorAt(i, j, k)`.
template <class IsFilled, class VectorAt>
std::shared_ptr<ClassifiedGrid> vectorGrid(std::uint64_t n, IsFilled isFilled, VectorAt vectorAt) {
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(n), glm::dvec3(1.0), glm::dvec3(0.0));
    grid->enableVectors();
    for (std::uint64_t k = 0; k < n; ++k) {
        for (std::uint64_t j = 0; j < n; ++j) {
            for (std::uint64_t i = 0; i < n; ++i) {
                if (isFilled(i, j, k)) {
                    grid->setVoxel({i, j, k}, glm::vec3(0.5f), 1.0f);
                    grid->setVector({i, j, k}, vectorAt(i, j, k));
                }
            }
        }
    }
    return grid;
}

const auto kEverywhere = [](auto, auto, auto) { return true; };
const auto kAlongX = [](auto, auto, auto) { return glm::vec3(1.0f, 0.0f, 0.0f); };

// The voxel whose cell holds `position` (spacing 1, origin 0).
glm::u64vec3 cellOf(glm::vec3 position) {
    return glm::u64vec3(glm::floor(position + 0.5f));
}

std::vector<SplatMark> drawn(const MarkSource& source, std::uint32_t seed, double marksPerVoxel) {
    std::vector<SplatMark> marks;
    source.drawMarks(seed, marksPerVoxel, marks);
    return marks;
}

// Whether `part` is `whole` with some marks left out, the others in the same order.
bool isSubsequence(const std::vector<SplatMark>& part, const std::vector<SplatMark>& whole) {
    std::size_t next = 0;
    for (const SplatMark& mark : whole) {
        next += next < part.size() && part[next] == mark ? 1 : 0;
    }
    return next == part.size();
}

TEST(MarkSource, marksSitInNonEmptyVoxelsWithTheirVectorExtinctionAndColourEachAsOften) {
    // A diagonal line of 16 voxels in a 16³ grid (a 16th of its blocks' voxels are filled), each
    // with its own vector, extinction and colour: every mark lies on the line, follows the voxel
    // it sits in, and the voxels are picked uniformly.
    auto grid = vectorGrid(
        16, [](std::uint64_t i, std::uint64_t j, std::uint64_t k) { return i == j && j == k; },
        [](std::uint64_t i, auto, auto) {
            return glm::vec3(std::cos(0.4f * static_cast<float>(i)),
                             std::sin(0.4f * static_cast<float>(i)), 0.0f);
        });
    for (std::uint64_t i = 0; i < 16; ++i) {
        grid->setVoxel({i, i, i}, glm::vec3(0.05f * static_cast<float>(i)), 1.0f + i);
    }
    const MarkSource source(grid);
    EXPECT_EQ(source.voxels(), 16u);
    std::array<int, 16> hits{};
    for (const SplatMark& mark : drawn(source, 1, 100.0)) {
        const glm::u64vec3 voxel = cellOf(mark.position);
        ASSERT_TRUE(voxel.x == voxel.y && voxel.y == voxel.z)
            << "a mark at (" << mark.position.x << ", " << mark.position.y << ", "
            << mark.position.z << "), outside the data";
        EXPECT_EQ(mark.vector, grid->vector(voxel));
        EXPECT_EQ(mark.extinction, 1.0f + static_cast<float>(voxel.x));
        EXPECT_EQ(mark.color, grid->voxel(voxel).r * glm::vec3(1.0f));
        EXPECT_GE(mark.phase, 0.0f);
        EXPECT_LT(mark.phase, 1.0f);
        ++hits[static_cast<std::size_t>(voxel.x)];
    }
    // 100 marks a voxel on average, within four standard deviations (sqrt(100) = 10).
    for (std::size_t i = 0; i < 16; ++i) {
        EXPECT_NEAR(hits[i], 100, 40) << "voxel " << i;
    }
}

TEST(MarkSource, marksFallAtRandomAcrossTheirCellsWithNoTraceOfTheGrid) {
    // Where in its cell each mark sits: uniform, so that the marks together form no lattice.
    // The offsets' mean is near 0 and their variance near 1/12 on every axis; phases average 1/2.
    const MarkSource source(vectorGrid(24, kEverywhere, kAlongX));
    const std::vector<SplatMark> marks = drawn(source, 3, 1.5);
    // 1.5 marks a voxel of 24³: 20 736 on average, within four standard deviations.
    ASSERT_NEAR(static_cast<double>(marks.size()), 20736.0, 600.0);
    glm::dvec3 sum(0.0);
    glm::dvec3 squares(0.0);
    double phases = 0.0;
    for (const SplatMark& mark : marks) {
        const glm::dvec3 offset(mark.position - glm::vec3(cellOf(mark.position)));
        sum += offset;
        squares += offset * offset;
        phases += mark.phase;
    }
    const double count = static_cast<double>(marks.size());
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(sum[axis] / count, 0.0, 0.01) << axis;
        EXPECT_NEAR(squares[axis] / count, 1.0 / 12.0, 0.004) << axis;
    }
    EXPECT_NEAR(phases / count, 0.5, 0.01);
}

TEST(MarkSource, moreMarksPerVoxelKeepTheMarksDrawnBeforeAndAnotherSeedDrawsOthers) {
    const MarkSource source(vectorGrid(8, kEverywhere, [](std::uint64_t i, auto, std::uint64_t k) {
        return glm::vec3(static_cast<float>(i) - 3.5f, 1.0f, static_cast<float>(k));
    }));
    const std::vector<SplatMark> many = drawn(source, 7, 5.8);
    const std::vector<SplatMark> fewer = drawn(source, 7, 2.3);
    const std::vector<SplatMark> few = drawn(source, 7, 0.9);
    ASSERT_LT(few.size(), fewer.size());
    ASSERT_LT(fewer.size(), many.size());
    // A closer view draws the marks of a farther one and more; a farther one keeps a part.
    EXPECT_TRUE(isSubsequence(fewer, many));
    EXPECT_TRUE(isSubsequence(few, fewer));
    const std::vector<SplatMark> reseeded = drawn(source, 8, 5.8);
    std::size_t same = 0;
    for (std::size_t i = 0; i < std::min(many.size(), reseeded.size()); ++i) {
        same += std::memcmp(&many[i], &reseeded[i], sizeof(SplatMark)) == 0 ? 1 : 0;
    }
    EXPECT_EQ(same, 0u);
}

TEST(MarkSource, theBricksOfAGridDrawTogetherExactlyItsMarks) {
    // A 21³ grid cut at x = 5 and y = 13 (off the cells of 8³) into four bricks: each brick's
    // marks are the whole grid's in its box, and together they are all of them.
    const auto vectorAt = [](std::uint64_t i, std::uint64_t j, std::uint64_t k) {
        return glm::vec3(static_cast<float>(i), static_cast<float>(j) + 1.0f,
                         static_cast<float>(k));
    };
    const auto isFilled = [](std::uint64_t i, std::uint64_t j, std::uint64_t k) {
        return (i + 2 * j + 3 * k) % 5 != 0;
    };
    const std::uint64_t n = 21;
    const MarkSource whole(vectorGrid(n, isFilled, vectorAt));
    const std::vector<SplatMark> wholeMarks = drawn(whole, 9, 0.7);
    std::size_t inBricks = 0;
    for (const glm::u64vec3 low : {glm::u64vec3(0, 0, 0), glm::u64vec3(5, 0, 0),
                                   glm::u64vec3(0, 13, 0), glm::u64vec3(5, 13, 0)}) {
        const glm::u64vec3 high(low.x == 0 ? 5 : n, low.y == 0 ? 13 : n, n);
        const glm::u64vec3 dims = high - low;
        auto grid = std::make_shared<ClassifiedGrid>(dims, glm::dvec3(1.0), glm::dvec3(low));
        grid->enableVectors();
        for (std::uint64_t k = 0; k < dims.z; ++k) {
            for (std::uint64_t j = 0; j < dims.y; ++j) {
                for (std::uint64_t i = 0; i < dims.x; ++i) {
                    const glm::u64vec3 at = low + glm::u64vec3(i, j, k);
                    if (isFilled(at.x, at.y, at.z)) {
                        grid->setVoxel({i, j, k}, glm::vec3(0.5f), 1.0f);
                        grid->setVector({i, j, k}, vectorAt(at.x, at.y, at.z));
                    }
                }
            }
        }
        const std::vector<SplatMark> brickMarks = drawn(MarkSource(grid, low), 9, 0.7);
        std::vector<SplatMark> expected;
        for (const SplatMark& mark : wholeMarks) {
            const glm::u64vec3 voxel = cellOf(mark.position);
            if (glm::all(glm::greaterThanEqual(voxel, low)) && glm::all(glm::lessThan(voxel, high))) {
                expected.push_back(mark);
            }
        }
        ASSERT_EQ(brickMarks.size(), expected.size()) << "brick at x " << low.x << ", y " << low.y;
        // The whole's order is its cells', so each brick's marks keep it.
        EXPECT_EQ(brickMarks, expected) << "brick at x " << low.x << ", y " << low.y;
        inBricks += brickMarks.size();
    }
    EXPECT_EQ(inBricks, wholeMarks.size());
}

TEST(MarkSource, theMarksAreTheSameForAnyNumberOfThreads) {
    const MarkSource source(vectorGrid(20, kEverywhere, kAlongX));
    std::vector<SplatMark> serial;
    tbb::task_arena(1).execute([&] { source.drawMarks(4, 6.0, serial); });
    EXPECT_EQ(drawn(source, 4, 6.0), serial);
}

TEST(MarkSource, anEmptyGridHasNoMarksAndAZeroVectorsMarksHaveNone) {
    const MarkSource empty(vectorGrid(
        8, [](auto, auto, auto) { return false; }, kAlongX));
    EXPECT_EQ(empty.voxels(), 0u);
    EXPECT_TRUE(drawn(empty, 1, 10.0).empty());
    // Combined splats keep voxels whose vector is zero (or masked out): their marks draw nothing.
    const MarkSource still(vectorGrid(4, kEverywhere, [](std::uint64_t i, auto, auto) {
        return i < 2 ? glm::vec3(0.0f) : glm::vec3(0.0f, 0.0f, 2.0f);
    }));
    for (const SplatMark& mark : drawn(still, 1, 6.0)) {
        EXPECT_EQ(mark.vector,
                  cellOf(mark.position).x < 2 ? glm::vec3(0.0f) : glm::vec3(0.0f, 0.0f, 2.0f));
    }
}

// The slice (z, for a view along −z) of the splat or mark at `position`.
std::uint64_t sliceOf(glm::vec3 position) {
    return cellOf(position).z;
}

TEST(MarkSource, aVoxelListsMarksAfterTheLastSplatOfTheirSliceFartherFirst) {
    const auto grid = vectorGrid(6, kEverywhere, kAlongX);
    const std::vector<SplatMark> marks = drawn(MarkSource(grid), 2, 2.3);
    ASSERT_GT(marks.size(), 300u);
    const View view = View::orthographic({0.2, 0.1, -1.0});
    SplatList splats;
    emitVoxelSplats(*grid, view, splats, &marks);
    ASSERT_EQ(splats.size(), 216u);
    ASSERT_EQ(splats.marks().size(), marks.size());
    for (std::size_t n = 0; n < splats.size(); ++n) {
        const std::uint64_t slice = sliceOf(splats.splats()[n].position);
        const bool lastOfSlice =
            n + 1 == splats.size() || sliceOf(splats.splats()[n + 1].position) != slice;
        const std::size_t begin = splats.markBegin(n);
        const std::size_t end = splats.markBegin(n + 1);
        if (!lastOfSlice) {
            EXPECT_EQ(begin, end) << "marks in the middle of slice " << slice;
        }
        for (std::size_t m = begin; m < end; ++m) {
            EXPECT_EQ(sliceOf(splats.marks()[m].position), slice);
            if (m > begin) {
                EXPECT_GE(view.depth(glm::dvec3(splats.marks()[m - 1].position)),
                          view.depth(glm::dvec3(splats.marks()[m].position)));
            }
        }
    }
}

TEST(MarkSource, aCutListsEachMarkAfterTheLastSplatNoNearerThanIt) {
    // Colours that vary along x, so that the exact cut holds nodes of several sizes.
    auto grid = vectorGrid(16, kEverywhere, kAlongX);
    for (std::uint64_t k = 0; k < 16; ++k) {
        for (std::uint64_t j = 0; j < 16; ++j) {
            for (std::uint64_t i = 0; i < 16; ++i) {
                grid->setVoxel({i, j, k}, glm::vec3(i < 8 ? 0.5f : 0.05f * i), 1.0f);
            }
        }
    }
    const Octree octree(grid);
    const View view = View::perspective({30.0, 20.0, 40.0}, {-0.5, -0.4, -0.8});
    const std::vector<SplatMark> marks = drawn(MarkSource(grid), 5, 0.07);
    ASSERT_GT(marks.size(), 200u);
    SplatList cut;
    emitSplats(Cut::byError(octree, 0.0), view, cut);
    ASSERT_GT(cut.size(), 1u);
    sortByDepth(cut, view);
    attachMarksByDepth(marks, view, cut);
    ASSERT_EQ(cut.marks().size(), marks.size());
    const auto depthOf = [&](glm::vec3 position) {
        return glm::distance(glm::dvec3(position), view.eye());
    };
    for (std::size_t n = 0; n < cut.size(); ++n) {
        for (std::size_t m = cut.markBegin(n); m < cut.markBegin(n + 1); ++m) {
            const double depth = depthOf(cut.marks()[m].position);
            if (n > 0) {
                EXPECT_GE(depthOf(cut.splats()[n].position), depth);
            }
            if (n + 1 < cut.size()) {
                EXPECT_LT(depthOf(cut.splats()[n + 1].position), depth);
            }
        }
    }
}

TEST(MarkSource, marksAloneAreListedBackToFrontAndThoseBehindTheEyeLeftOut) {
    const auto grid = vectorGrid(8, kEverywhere, kAlongX);
    const std::vector<SplatMark> marks = drawn(MarkSource(grid), 6, 2.0);
    const View view = View::perspective({4.0, 3.5, 3.5}, {1.0, 0.0, 0.0});
    SplatList splats;
    emitMarkSplats(marks, view, splats);
    std::size_t ahead = 0;
    for (const SplatMark& mark : marks) {
        ahead += mark.position.x > 4.0f ? 1 : 0;
    }
    ASSERT_EQ(splats.size(), ahead);
    ASSERT_EQ(splats.marks().size(), ahead);
    for (std::size_t n = 0; n < splats.size(); ++n) {
        ASSERT_EQ(splats.markBegin(n), n);
        EXPECT_EQ(splats.marks()[n].position, splats.splats()[n].position);
        EXPECT_GT(splats.splats()[n].position.x, 4.0f);
        if (n > 0) {
            EXPECT_GE(glm::distance(glm::dvec3(splats.splats()[n - 1].position), view.eye()),
                      glm::distance(glm::dvec3(splats.splats()[n].position), view.eye()));
        }
    }
}

} // namespace
} // namespace texsplat::octree
