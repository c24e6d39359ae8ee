#include "octree/SplatEmission.h"

#include "OctreeTestSupport.h"
#include "octree/Cut.h"
#include "octree/CutTraversal.h"
#include "octree/MarkSource.h"
#include "octree/Octree.h"
#include "octree/Refiner.h"
#include "octree/Splat.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>

#include <vector>

using texsplat::octree::ClassifiedGrid;
using texsplat::octree::Cut;
using texsplat::octree::MarkSource;
using texsplat::octree::NodeRef;
using texsplat::octree::Octree;
using texsplat::octree::Splat;
using texsplat::octree::SplatList;
using texsplat::octree::SplatMark;
using texsplat::octree::View;
using texsplat::octree::test::randomGrid;

TEST(SplatEmission, emitsOneSplatPerCutNodeInTraversalOrder) {
    const Octree octree(randomGrid({13, 16, 11}, 4, 0.2f, true, {1.0, 0.5, 2.0}, {3.0, 0.0, 0.0}));
    const Cut cut = Cut::byError(octree, 0.55);
    const View view = View::orthographic({0.4, -1.0, 0.3});
    SplatList splats;
    emitSplats(cut, view, splats);
    std::vector<NodeRef> nodes;
    traverseBackToFront(cut, view, [&](const NodeRef& node) { nodes.push_back(node); });
    ASSERT_EQ(splats.size(), cut.splatCount());
    ASSERT_EQ(splats.size(), nodes.size());
    EXPECT_FALSE(splats.hasMarks());
    bool coarse = false;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Splat& splat = splats.splats()[i];
        const glm::u64vec3 extent = octree.voxelEnd(nodes[i]) - octree.voxelBegin(nodes[i]);
        EXPECT_EQ(splat.position, glm::vec3(octree.center(nodes[i])));
        EXPECT_EQ(splat.size, static_cast<float>(std::max({extent.x, extent.y, extent.z})));
        EXPECT_EQ(splat.color, octree.node(nodes[i]).meanColor);
        EXPECT_EQ(splat.extinction, octree.node(nodes[i]).meanExtinction);
        coarse = coarse || splat.size > 1.0f;
    }
    EXPECT_TRUE(coarse) << "the cut has coarse nodes";
}

TEST(SplatEmission, coarseSplatOfAFullNodeIsSizedByItsLevel) {
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(4), glm::dvec3(0.5),
                                                 glm::dvec3(1.0));
    grid->setVoxel({0, 0, 0}, glm::vec3(0.8f), 1.6f);
    const Octree octree(grid);
    SplatList splats;
    emitSplats(Cut(octree), View::orthographic({0.0, 0.0, 1.0}), splats);
    ASSERT_EQ(splats.size(), 1u);
    const Splat& root = splats.splats()[0];
    EXPECT_EQ(root.size, 4.0f);
    EXPECT_EQ(root.position, glm::vec3(1.75f));
    EXPECT_FLOAT_EQ(root.color.x, 0.8f / 64.0f);
    EXPECT_FLOAT_EQ(root.extinction, 1.6f / 64.0f);
}

TEST(SplatEmission, voxelSplatsSkipEmptyVoxelsAndFollowTheSliceOrder) {
    const auto grid = randomGrid({5, 7, 3}, 3, 0.4f, false, {1.0, 2.0, 0.5});
    const View view = View::orthographic({0.0, 0.0, -1.0});
    SplatList splats;
    emitVoxelSplats(*grid, view, splats);
    std::uint64_t nonEmpty = 0;
    for (std::uint64_t index = 0; index < grid->voxelCount(); ++index) {
        nonEmpty += grid->isEmptyVoxel(grid->coordinates(index)) ? 0 : 1;
    }
    ASSERT_EQ(splats.size(), nonEmpty);
    float previousZ = -1.0f;
    for (const Splat& splat : splats.splats()) {
        EXPECT_EQ(splat.size, 1.0f);
        EXPECT_GT(splat.extinction, 0.0f);
        EXPECT_GE(splat.position.z, previousZ) << "looking down -z, low z is far";
        previousZ = splat.position.z;
    }
}

TEST(SplatEmission, voxelSplatsBehindTheEyeAreCulled) {
    const auto grid = randomGrid({6, 6, 6}, 3, 0.0f, false);
    SplatList splats;
    emitVoxelSplats(*grid, View::perspective({2.5, 2.0, 2.0}, {1.0, 0.0, 0.0}), splats);
    EXPECT_EQ(splats.size(), 3u * 36u) << "only the voxels with x > 2.5";
    for (const Splat& splat : splats.splats()) {
        EXPECT_GT(splat.position.x, 2.5f);
    }
}

TEST(SplatEmission, voxelSplatsRefillAListThatHeldACut) {
    // A list is refilled frame after frame without clearing it: voxel splats written over a
    // cut's coarse splats must not keep their sizes.
    const auto grid = randomGrid({19, 23, 17}, 5, 0.3f, true, {1.0, 0.8, 1.2});
    const Octree octree(grid);
    const View view = View::perspective({-20.0, 30.0, 40.0}, {0.4, -0.5, -0.7});
    SplatList fresh;
    emitVoxelSplats(*grid, view, fresh);
    SplatList refilled;
    emitSplats(Cut::byError(octree, 0.5), view, refilled);
    ASSERT_TRUE(std::any_of(refilled.splats().begin(), refilled.splats().end(),
                            [](const Splat& splat) { return splat.size > 1.0f; }));
    emitVoxelSplats(*grid, view, refilled);
    ASSERT_EQ(refilled.size(), fresh.size());
    EXPECT_EQ(std::memcmp(refilled.splats().data(), fresh.splats().data(),
                          fresh.size() * sizeof(Splat)),
              0);
}

TEST(SplatEmission, voxelSplatsAreTheSameForAnyNumberOfThreads) {
    // Slices are emitted in parallel: the list must be the serial walk's, splat for splat.
    const glm::u64vec3 dims(37, 29, 41);
    auto grid = std::make_shared<ClassifiedGrid>(dims, glm::dvec3(1.0, 0.7, 1.3), glm::dvec3(0.0));
    grid->enableVectors();
    for (std::uint64_t k = 0; k < dims.z; ++k) {
        for (std::uint64_t j = 0; j < dims.y; ++j) {
            for (std::uint64_t i = 0; i < dims.x; ++i) {
                if ((i * 7 + j * 3 + k * 5) % 4 == 0 || (i > 20 && j < 9)) {
                    continue; // empty voxels, and empty blocks
                }
                const float shade = static_cast<float>((i + 2 * j + 3 * k) % 11) / 11.0f;
                grid->setVoxel({i, j, k}, glm::vec3(shade, 0.5f, 1.0f - shade), 0.1f + shade);
                grid->setVector({i, j, k}, glm::vec3(shade - 0.5f, 1.0f, 0.25f * shade));
            }
        }
    }
    const View view = View::perspective({-9.0, 40.0, 12.0}, {0.4, -0.8, 0.1});
    std::vector<SplatMark> marks;
    MarkSource(grid).drawMarks(5, 0.7, marks);
    const auto emitWith = [&](int threads) {
        SplatList splats;
        tbb::task_arena(threads).execute([&] { emitVoxelSplats(*grid, view, splats, &marks); });
        return splats;
    };
    const SplatList serial = emitWith(1);
    ASSERT_GT(serial.size(), 1000u);
    EXPECT_GT(serial.marks().size(), serial.size() / 2);
    for (const int threads : {2, 7}) {
        const SplatList parallel = emitWith(threads);
        ASSERT_EQ(parallel.size(), serial.size()) << threads << " threads";
        EXPECT_EQ(std::memcmp(parallel.splats().data(), serial.splats().data(),
                              serial.size() * sizeof(Splat)),
                  0)
            << threads << " threads";
        EXPECT_EQ(parallel.marks(), serial.marks()) << threads << " threads";
        EXPECT_EQ(parallel.markBegins(), serial.markBegins()) << threads << " threads";
    }
}

TEST(SplatEmission, cutSplatsAreTheSerialTraversalsForAnyNumberOfThreads) {
    // Pieces of the traversal are emitted in parallel and laid end to end: the list must be the
    // one-thread traversal's, splat for splat, for coarse and fine cuts, culled or not.
    auto grid = randomGrid({45, 38, 29}, 11, 0.25f, true, {1.0, 0.6, 1.4}, {-3.0, 2.0, 0.5});
    const Octree octree(grid);
    const std::vector<View> views{
        View::orthographic({0.4, -1.0, 0.3}),
        View::perspective({-30.0, 50.0, 70.0}, {0.5, -0.6, -0.7}),
        View::perspective({18.0, 14.0, 20.0}, {0.3, 0.8, -0.2}), // the eye inside: culled nodes
        // Sides through the grid: nodes out of sight left out, subtrees and single voxels.
        View::perspective({-30.0, 50.0, 70.0}, {0.5, -0.6, -0.7})
            .seeingOnly({glm::dvec4(1.0, 0.0, 0.0, -10.0), glm::dvec4(0.0, -1.0, 0.5, 30.0),
                         glm::dvec4(0.0, 0.0, 0.0, 1.0), glm::dvec4(0.0, 0.0, 0.0, 1.0)},
                        1.1),
    };
    for (std::size_t v = 0; v < views.size(); ++v) {
        const View& view = views[v];
        for (const std::uint64_t budget : {1u, 300u, 6000u, 40000u}) {
            const Cut cut = texsplat::octree::Refiner::refineAtOnce(Cut(octree), view, budget);
            std::vector<NodeRef> nodes;
            traverseBackToFront(cut, view, [&](const NodeRef& node) { nodes.push_back(node); });
            const auto emitWith = [&](int threads) {
                SplatList splats;
                tbb::task_arena(threads).execute([&] { emitSplats(cut, view, splats); });
                return splats;
            };
            const SplatList serial = emitWith(1);
            ASSERT_EQ(serial.size(), nodes.size()) << "view " << v << ", budget " << budget;
            if (view.hasSides() && budget >= 6000) {
                EXPECT_LT(nodes.size(), cut.splatCount()) << "nodes out of sight are left out";
            }
            for (std::size_t i = 0; i < nodes.size(); ++i) {
                ASSERT_EQ(serial.splats()[i].position, glm::vec3(octree.center(nodes[i])))
                    << "view " << v << ", budget " << budget << ", splat " << i;
            }
            for (const int threads : {2, 7}) {
                const SplatList parallel = emitWith(threads);
                ASSERT_EQ(parallel.size(), serial.size()) << threads << " threads";
                if (serial.isEmpty()) {
                    continue; // the root alone, behind the eye (no data to compare)
                }
                EXPECT_EQ(std::memcmp(parallel.splats().data(), serial.splats().data(),
                                      serial.size() * sizeof(Splat)),
                          0)
                    << "view " << v << ", budget " << budget << ", " << threads << " threads";
            }
        }
    }
}

// The example of docs/octree.md, compiled here so that it cannot rot.
TEST(SplatEmission, documentationExample) {
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(64, 64, 32), glm::dvec3(1.0),
                                                 glm::dvec3(0.0));
    grid->setVoxel({10, 20, 5}, {0.2f, 0.1f, 0.0f}, 0.5f); // normally from a TransferFunction
    const Octree octree(grid);                             // build once, rebuild on change

    const View view = View::perspective({32.0, -100.0, 16.0}, {0.0, 1.0, 0.0});
    texsplat::octree::Refiner refiner(octree, view);       // coarse first ...
    refiner.refine({/*maxSplats=*/5000, /*maxSplits=*/100}); // ... then refine while idle

    SplatList splats;
    emitSplats(refiner.cut(), view, splats); // back to front, ready to upload
    EXPECT_EQ(splats.size(), refiner.cut().splatCount());
}
