// Vector marks at emission (Crawfis & Max 1993, "Combined Vector and Scalar Textures"): how many
// marks each splat carries, where they sit and which vector each follows; and the octree's
// direction error.
#include "octree/ClassifiedGrid.h"
#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "octree/View.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>

namespace texsplat::octree {
namespace {

// An n³ grid (spacing `spacing`) whose voxels `isFilled(i, j, k)` have unit extinction and the
// vector `vectorAt(i, j, k)`.
template <class IsFilled, class VectorAt>
std::shared_ptr<ClassifiedGrid> vectorGrid(std::uint64_t n, IsFilled isFilled, VectorAt vectorAt,
                                           glm::dvec3 spacing = glm::dvec3(1.0)) {
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(n), spacing, glm::dvec3(0.0));
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

// The voxel whose cell holds `position` (spacing 1, origin 0).
glm::u64vec3 cellOf(glm::vec3 position) {
    return glm::u64vec3(glm::floor(position + 0.5f));
}

TEST(MarkEmission, aSplatCarriesItsVoxelsShareOfMarksUpToTheCap) {
    MarkEmission emission;
    emission.marksPerVoxel = 0.25;
    EXPECT_DOUBLE_EQ(emission.expectedMarks(1), 0.25);
    EXPECT_DOUBLE_EQ(emission.expectedMarks(40), 10.0);
    EXPECT_DOUBLE_EQ(emission.expectedMarks(100000), MarkEmission::kMaxMarksPerSplat);
    emission.marksPerVoxel = 0.0;
    EXPECT_DOUBLE_EQ(emission.expectedMarks(1000), 0.0);
}

TEST(MarkEmission, voxelMarksSitInTheirCellWithTheVoxelsVectorAndAverageTheExpectation) {
    const auto grid = vectorGrid(16, kEverywhere, [](std::uint64_t i, std::uint64_t j, auto) {
        return glm::vec3(1.0f + static_cast<float>(i), static_cast<float>(j), -1.0f);
    });
    for (const double expected : {0.3, 1.0, 2.6}) {
        MarkEmission emission;
        emission.marksPerVoxel = expected;
        SplatList splats;
        emitVoxelSplats(*grid, View::orthographic({0.0, 0.0, -1.0}), splats, &emission);
        ASSERT_EQ(splats.size(), 4096u);
        ASSERT_TRUE(splats.hasMarks());
        std::size_t total = 0;
        for (std::size_t n = 0; n < splats.size(); ++n) {
            const glm::vec3 centre = splats.splats()[n].position;
            const std::size_t count = splats.markBegin(n + 1) - splats.markBegin(n);
            // The whole part always, one more with the fraction's probability.
            ASSERT_GE(count, static_cast<std::size_t>(std::floor(expected)));
            ASSERT_LE(count, static_cast<std::size_t>(std::ceil(expected)));
            total += count;
            for (std::size_t m = splats.markBegin(n); m < splats.markBegin(n + 1); ++m) {
                const SplatMark& mark = splats.marks()[m];
                EXPECT_EQ(cellOf(mark.position), cellOf(centre));
                EXPECT_EQ(mark.vector, glm::vec3(1.0f + centre.x, centre.y, -1.0f));
                EXPECT_EQ(mark.extinction, 1.0f);
                EXPECT_EQ(mark.color, glm::vec3(0.5f));
                EXPECT_GE(mark.phase, 0.0f);
                EXPECT_LT(mark.phase, 1.0f);
            }
        }
        // 4096 voxels: the mean is within a few standard deviations (at most 0.5 each).
        EXPECT_NEAR(static_cast<double>(total) / 4096.0, expected, 0.03) << expected;
    }
}

TEST(MarkEmission, marksFallAtRandomAcrossTheirCellsWithNoTraceOfTheGrid) {
    // Where in its cell each mark sits: uniform, so that the marks of all voxels together form no
    // lattice. The offsets' mean is near 0 and their variance near 1/12 on every axis.
    const auto grid =
        vectorGrid(24, kEverywhere, [](auto, auto, auto) { return glm::vec3(1.0f, 0.0f, 0.0f); });
    MarkEmission emission;
    emission.marksPerVoxel = 1.0;
    SplatList splats;
    emitVoxelSplats(*grid, View::orthographic({0.0, 0.0, -1.0}), splats, &emission);
    glm::dvec3 sum(0.0);
    glm::dvec3 squares(0.0);
    double phases = 0.0;
    for (std::size_t n = 0; n < splats.size(); ++n) {
        for (std::size_t m = splats.markBegin(n); m < splats.markBegin(n + 1); ++m) {
            const glm::dvec3 offset(splats.marks()[m].position - splats.splats()[n].position);
            sum += offset;
            squares += offset * offset;
            phases += splats.marks()[m].phase;
        }
    }
    const double count = static_cast<double>(splats.marks().size());
    ASSERT_EQ(count, 24.0 * 24.0 * 24.0);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(sum[axis] / count, 0.0, 0.01) << axis;
        EXPECT_NEAR(squares[axis] / count, 1.0 / 12.0, 0.004) << axis;
    }
    EXPECT_NEAR(phases / count, 0.5, 0.01);
}

TEST(MarkEmission, aVoxelDrawsTheSameMarksAtFullResolutionAndInACutAndForAnotherSeedOthers) {
    const auto grid = vectorGrid(8, kEverywhere, [](std::uint64_t i, auto, std::uint64_t k) {
        return glm::vec3(static_cast<float>(i) - 3.5f, 1.0f, static_cast<float>(k));
    });
    MarkEmission emission;
    emission.marksPerVoxel = 1.5;
    const View view = View::orthographic({0.3, -0.2, -1.0});
    SplatList full;
    emitVoxelSplats(*grid, view, full, &emission);
    const Octree octree(grid);
    SplatList cut;
    emitSplats(Cut::byError(octree, 0.0), view, cut, &emission);
    ASSERT_EQ(cut.size(), full.size());
    ASSERT_TRUE(cut.hasMarks());
    // Both orders are back to front for the same view, but may differ among equal depths: each
    // voxel's marks, found by its position, must be the same.
    std::size_t compared = 0;
    for (std::size_t a = 0; a < full.size(); ++a) {
        for (std::size_t b = 0; b < cut.size(); ++b) {
            if (cut.splats()[b].position != full.splats()[a].position) {
                continue;
            }
            ASSERT_EQ(cut.markBegin(b + 1) - cut.markBegin(b),
                      full.markBegin(a + 1) - full.markBegin(a));
            for (std::size_t m = 0; m < cut.markBegin(b + 1) - cut.markBegin(b); ++m) {
                EXPECT_EQ(cut.marks()[cut.markBegin(b) + m], full.marks()[full.markBegin(a) + m]);
            }
            ++compared;
        }
    }
    EXPECT_EQ(compared, full.size());
    emission.seed = 2;
    SplatList reseeded;
    emitVoxelSplats(*grid, view, reseeded, &emission);
    EXPECT_NE(reseeded.marks(), full.marks());
}

TEST(MarkEmission, aCoarseNodesMarksSitInItsNonEmptyVoxelsAtRandomWithTheirOwnVectors) {
    // A diagonal line of voxels in a 16³ grid, each with its own vector and extinction: the
    // root's marks must lie on the line (not in the empty rest of its block), follow the voxel
    // they sit in, and fall on each voxel as often (the descent weighs the children by their
    // voxels: the line's first voxel lies in a child of the root holding 8 of the 16).
    auto grid = vectorGrid(
        16, [](std::uint64_t i, std::uint64_t j, std::uint64_t k) { return i == j && j == k; },
        [](std::uint64_t i, auto, auto) {
            return glm::vec3(std::cos(0.4f * static_cast<float>(i)),
                             std::sin(0.4f * static_cast<float>(i)), 0.0f);
        });
    for (std::uint64_t i = 0; i < 16; ++i) {
        grid->setVoxel({i, i, i}, glm::vec3(0.1f * static_cast<float>(i)), 1.0f + i);
    }
    const Octree octree(grid);
    MarkEmission emission;
    emission.marksPerVoxel = 0.5; // 8 marks for the root's 16 voxels
    std::array<int, 16> hits{};
    std::size_t total = 0;
    for (std::uint32_t seed = 1; seed <= 100; ++seed) {
        emission.seed = seed;
        SplatList splats;
        emitSplats(Cut(octree), View::orthographic({0.0, 0.0, -1.0}), splats, &emission);
        ASSERT_EQ(splats.size(), 1u);
        ASSERT_EQ(splats.marks().size(), 8u);
        for (const SplatMark& mark : splats.marks()) {
            const glm::u64vec3 voxel = cellOf(mark.position);
            ASSERT_TRUE(voxel.x == voxel.y && voxel.y == voxel.z)
                << "a mark at (" << mark.position.x << ", " << mark.position.y << ", "
                << mark.position.z << "), outside the data";
            EXPECT_EQ(mark.vector, grid->vector(voxel));
            EXPECT_EQ(mark.extinction, 1.0f + static_cast<float>(voxel.x));
            EXPECT_EQ(mark.color, grid->voxel(voxel).r * glm::vec3(1.0f));
            ++hits[static_cast<std::size_t>(voxel.x)];
            ++total;
        }
    }
    // 800 marks over 16 voxels: 50 each, within a few standard deviations.
    for (std::size_t i = 0; i < 16; ++i) {
        EXPECT_NEAR(hits[i], 50, 25) << "voxel " << i;
    }
    EXPECT_EQ(total, 800u);
}

TEST(MarkEmission, voxelsWithoutAVectorHaveNoMarks) {
    // Combined splats keep voxels whose vector is zero (or masked out): they draw no marks.
    const auto grid = vectorGrid(4, kEverywhere, [](std::uint64_t i, auto, auto) {
        return i < 2 ? glm::vec3(0.0f) : glm::vec3(0.0f, 0.0f, 2.0f);
    });
    MarkEmission emission;
    emission.marksPerVoxel = 3.0;
    SplatList splats;
    emitVoxelSplats(*grid, View::orthographic({0.0, 0.0, -1.0}), splats, &emission);
    ASSERT_EQ(splats.size(), 64u);
    for (std::size_t n = 0; n < splats.size(); ++n) {
        const std::size_t count = splats.markBegin(n + 1) - splats.markBegin(n);
        EXPECT_EQ(count, splats.splats()[n].position.x < 2.0f ? 0u : 3u) << n;
    }
}

TEST(MarkEmission, theOctreeErrorCountsDirectionChangesNotOnlyOpacity) {
    // Same colour and extinction everywhere: without vectors the root is exact.
    const auto uniform =
        vectorGrid(4, kEverywhere, [](auto, auto, auto) { return glm::vec3(1.0f, 0.0f, 0.0f); });
    const auto turning = vectorGrid(4, kEverywhere, [](std::uint64_t i, auto, auto) {
        return i < 2 ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    });
    const auto opposed = vectorGrid(4, kEverywhere, [](std::uint64_t i, auto, auto) {
        return i < 2 ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(-1.0f, 0.0f, 0.0f);
    });
    const float uniformError = Octree(uniform).node(Octree(uniform).root()).error;
    const Octree turningTree(turning);
    const Octree opposedTree(opposed);
    const float turningError = turningTree.node(turningTree.root()).error;
    const float opposedError = opposedTree.node(opposedTree.root()).error;
    EXPECT_EQ(uniformError, 0.0f);
    // Half the voxels turned by 90 degrees: 1 - |(1, 1)/2| = 1 - 1/sqrt(2), times extinction 1.
    EXPECT_NEAR(turningError, 1.0f - 1.0f / std::sqrt(2.0f), 1e-6f);
    EXPECT_NEAR(opposedError, 1.0f, 1e-6f);
    EXPECT_GT(Cut::byError(turningTree, 0.1).splatCount(), 1u);
}

} // namespace
} // namespace texsplat::octree
