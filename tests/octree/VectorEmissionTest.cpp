// Vector splats at emission (Crawfis & Max 1993, "Combined Vector and Scalar Textures"): the
// octree's mean vectors and direction error, and each splat's table row and column.
#include "octree/ClassifiedGrid.h"
#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "octree/View.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <set>

namespace texsplat::octree {
namespace {

// A 4x4x4 grid of unit extinction whose vectors are `vector(i, j, k)`.
template <class VectorAt> std::shared_ptr<ClassifiedGrid> vectorGrid(VectorAt vectorAt) {
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(4), glm::dvec3(1.0), glm::dvec3(0.0));
    grid->enableVectors();
    for (std::uint64_t k = 0; k < 4; ++k) {
        for (std::uint64_t j = 0; j < 4; ++j) {
            for (std::uint64_t i = 0; i < 4; ++i) {
                grid->setVoxel({i, j, k}, glm::vec3(0.5f), 1.0f);
                grid->setVector({i, j, k}, vectorAt(i, j, k));
            }
        }
    }
    return grid;
}

// Looking down -z from the eye at z = 10 (camera space is the world rotated by nothing).
VectorEmission topDown(int columns = 8) {
    VectorEmission emission;
    emission.columns = columns;
    emission.localToCamera =
        glm::lookAt(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return emission;
}

TEST(VectorEmission, aVectorAlongTheViewAxisPicksTheLastColumnAndTiltingMovesItMonotonically) {
    const VectorEmission emission = topDown(8);
    EXPECT_EQ(vectorSplat(emission, glm::vec3(0.0f), {0.0f, 0.0f, 1.0f}, 0).column, 7);
    EXPECT_EQ(vectorSplat(emission, glm::vec3(0.0f), {0.0f, 0.0f, -3.0f}, 0).column, 7);
    EXPECT_EQ(vectorSplat(emission, glm::vec3(0.0f), {2.0f, 0.0f, 0.0f}, 0).column, 0);
    int previous = -1;
    for (int degrees = 0; degrees <= 90; degrees += 5) {
        const float angle = glm::radians(static_cast<float>(degrees));
        const int column =
            vectorSplat(emission, glm::vec3(0.0f), {std::cos(angle), 0.0f, std::sin(angle)}, 0)
                .column;
        EXPECT_GE(column, previous) << degrees << " degrees out of the image plane";
        previous = column;
    }
    EXPECT_EQ(previous, 7);
}

TEST(VectorEmission, aPerspectiveColumnIsMeasuredAlongTheLineOfSightThroughTheSplat) {
    VectorEmission emission = topDown(8);
    emission.isPerspective = true;
    // Off the axis, a vector pointing at the eye is along the line of sight there, not along z.
    const glm::vec3 position(6.0f, 0.0f, 0.0f);
    const glm::vec3 toEye = glm::vec3(0.0f, 0.0f, 10.0f) - position;
    EXPECT_EQ(vectorSplat(emission, position, toEye, 0).column, 7);
    EXPECT_LT(vectorSplat(emission, position, {0.0f, 0.0f, 1.0f}, 0).column, 7);
}

TEST(VectorEmission, zeroHugeAndNanVectorsGetAColumnInRange) {
    const VectorEmission emission = topDown(8);
    const float huge = std::numeric_limits<float>::max();
    EXPECT_EQ(vectorSplat(emission, glm::vec3(0.0f), glm::vec3(0.0f), 0).column, 0);
    EXPECT_EQ(vectorSplat(emission, glm::vec3(0.0f), {huge, 0.0f, huge}, 0).column, 5); // 45 degrees: 0.71 of 7
    EXPECT_EQ(vectorSplat(emission, glm::vec3(0.0f), {1e-40f, 0.0f, 0.0f}, 0).column, 0);
    EXPECT_EQ(tableColumn(std::nanf(""), 8), 0);
    EXPECT_EQ(tableColumn(2.0f, 8), 7);
    EXPECT_EQ(tableColumn(1.0f, 1), 0);
}

TEST(VectorEmission, rowsAreReproducibleSpreadAndDependOnTheSeed) {
    VectorEmission emission = topDown();
    std::set<int> rows;
    int moved = 0;
    for (std::uint64_t key = 0; key < 256; ++key) {
        const int row = vectorSplat(emission, glm::vec3(0.0f), {1.0f, 0.0f, 0.0f}, key).row;
        EXPECT_EQ(row, vectorSplat(emission, glm::vec3(0.0f), {1.0f, 0.0f, 0.0f}, key).row);
        EXPECT_LT(row, emission.rows);
        rows.insert(row);
        VectorEmission other = emission;
        other.seed = 2;
        moved += vectorSplat(other, glm::vec3(0.0f), {1.0f, 0.0f, 0.0f}, key).row != row;
    }
    EXPECT_EQ(rows.size(), 16u);
    EXPECT_GT(moved, 200);
}

TEST(VectorEmission, voxelSplatsCarryTheirVectorsAndCutsTheNodesMeanVector) {
    const auto grid = vectorGrid([](std::uint64_t i, std::uint64_t j, std::uint64_t) {
        return glm::vec3(1.0f + static_cast<float>(i), static_cast<float>(j), 0.0f);
    });
    const VectorEmission emission = topDown();
    SplatList voxels;
    emitVoxelSplats(*grid, View::orthographic({0.0, 0.0, -1.0}), voxels, &emission);
    ASSERT_EQ(voxels.size(), 64u);
    ASSERT_TRUE(voxels.hasVectors());
    for (std::size_t n = 0; n < voxels.size(); ++n) {
        const glm::vec3 position = voxels.splats()[n].position;
        EXPECT_EQ(voxels.vectors()[n].vector, glm::vec3(1.0f + position.x, position.y, 0.0f));
    }
    const Octree octree(grid);
    SplatList root;
    emitSplats(Cut(octree), View::orthographic({0.0, 0.0, -1.0}), root, &emission);
    ASSERT_EQ(root.size(), 1u);
    EXPECT_EQ(root.vectors()[0].vector, glm::vec3(2.5f, 1.5f, 0.0f));
    EXPECT_EQ(octree.meanVector(octree.root()), glm::vec3(2.5f, 1.5f, 0.0f));
}

TEST(VectorEmission, theOctreeErrorCountsDirectionChangesNotOnlyOpacity) {
    // Same colour and extinction everywhere: without vectors the root is exact.
    const auto uniform = vectorGrid([](auto, auto, auto) { return glm::vec3(1.0f, 0.0f, 0.0f); });
    const auto turning = vectorGrid([](std::uint64_t i, auto, auto) {
        return i < 2 ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    });
    const auto opposed = vectorGrid([](std::uint64_t i, auto, auto) {
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
