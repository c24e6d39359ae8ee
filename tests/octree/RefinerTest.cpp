#include "octree/Refiner.h"

#include "OctreeTestSupport.h"
#include "octree/CutTraversal.h"
#include "octree/Octree.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using texsplat::octree::ClassifiedGrid;
using texsplat::octree::Cut;
using texsplat::octree::NodeRef;
using texsplat::octree::Octree;
using texsplat::octree::RefineBudget;
using texsplat::octree::Refiner;
using texsplat::octree::View;
using texsplat::octree::test::randomGrid;

namespace {

RefineBudget splats(std::uint64_t maxSplats) {
    RefineBudget budget;
    budget.maxSplats = maxSplats;
    return budget;
}

// Looking along z, seeing x >= @p x only, splats reaching @p reach edges from their centre.
View seeingFrom(double x, double reach) {
    const glm::dvec4 everywhere(0.0, 0.0, 0.0, 1.0);
    return View::orthographic({0.0, 0.0, 1.0})
        .seeingOnly({glm::dvec4(1.0, 0.0, 0.0, -x), everywhere, everywhere, everywhere}, reach);
}

std::vector<NodeRef> nodesOf(const Cut& cut) {
    std::vector<NodeRef> nodes;
    traverseBackToFront(cut, View::orthographic({0.0, 0.0, 1.0}),
                        [&](const NodeRef& node) { nodes.push_back(node); });
    return nodes;
}

} // namespace

TEST(Refiner, meetsTheSplatBudgetAndStopsAtTheFirstSplitThatDoesNotFit) {
    const Octree octree(randomGrid(glm::u64vec3(16), 2));
    const View view = View::orthographic({1.0, 0.5, 0.2});
    std::uint64_t previous = 0;
    for (const std::uint64_t budget : {1u, 7u, 50u, 400u, 2000u}) {
        SCOPED_TRACE(budget);
        Refiner refiner(octree, view);
        refiner.refine(splats(budget));
        const Cut& cut = refiner.cut();
        EXPECT_LE(cut.splatCount(), budget);
        EXPECT_GE(cut.splatCount(), previous) << "a larger budget refines the same cut further";
        previous = cut.splatCount();
        EXPECT_EQ(nodesOf(cut).size(), cut.splatCount());
        ASSERT_FALSE(refiner.isComplete());
        // It stopped because the best remaining split does not fit; one split adds at most 7.
        EXPECT_EQ(refiner.refine(splats(budget)), 0u);
        EXPECT_GT(cut.splatCount() + 7, budget);
        EXPECT_EQ(refiner.refine(RefineBudget{budget + 7, 1}), 1u);
    }
}

TEST(Refiner, splitsTheLargestErrorTimesSizeFirst) {
    // Two 8^3 halves: the upper one varies, the lower one is uniform. The coarsest refinement
    // step splits the root, the next one the varying half, never the uniform half.
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(16, 8, 8), glm::dvec3(1.0),
                                                 glm::dvec3(0.0));
    for (std::uint64_t k = 0; k < 8; ++k) {
        for (std::uint64_t j = 0; j < 8; ++j) {
            for (std::uint64_t i = 0; i < 16; ++i) {
                const float value = i < 8 ? 0.5f : static_cast<float>((i + j + k) % 3) * 0.5f;
                grid->setVoxel({i, j, k}, glm::vec3(value), 1.0f);
            }
        }
    }
    const Octree octree(grid);
    Refiner refiner(octree, View::orthographic({0.0, 0.0, 1.0}));
    EXPECT_EQ(refiner.refine(RefineBudget{1000, 2}), 2u);
    const std::vector<NodeRef> nodes = nodesOf(refiner.cut());
    std::uint64_t uniformLeft = 0;
    for (const NodeRef& node : nodes) {
        if (octree.voxelBegin(node).x == 0) {
            EXPECT_EQ(node.level, 3) << "the uniform half stays one splat";
            EXPECT_EQ(refiner.priority(node), 0.0);
            ++uniformLeft;
        } else {
            EXPECT_EQ(node.level, 2);
        }
    }
    EXPECT_EQ(uniformLeft, 1u);
    EXPECT_EQ(nodes.size(), 9u);
}

TEST(Refiner, stepsAddUpToOneLargeRefinement) {
    const Octree octree(randomGrid({13, 16, 11}, 4));
    const View view = View::perspective({30.0, 20.0, -15.0}, {-1.0, -0.5, 1.0});
    Refiner stepped(octree, view);
    std::uint64_t steps = 0;
    while (!stepped.isComplete() && stepped.refine(RefineBudget{800, 5}) > 0) {
        ++steps;
    }
    Refiner once(octree, view);
    once.refine(splats(800));
    EXPECT_GT(steps, 10u);
    EXPECT_TRUE(stepped.cut() == once.cut()) << "the same cut, however it is reached";
    EXPECT_EQ(stepped.cut().splatCount(), once.cut().splatCount());
}

TEST(Refiner, unlimitedBudgetReachesTheZeroErrorCut) {
    const Octree octree(randomGrid({5, 7, 3}, 8));
    Refiner refiner(octree, View::orthographic({0.2, 0.3, -1.0}));
    refiner.refine(RefineBudget{});
    EXPECT_TRUE(refiner.isComplete());
    EXPECT_TRUE(refiner.cut() == Cut::byError(octree, 0.0));
}

TEST(Refiner, continuesFromAThresholdCut) {
    const Octree octree(randomGrid(glm::u64vec3(16), 10));
    const Cut start = Cut::byError(octree, 0.7);
    Refiner refiner(start, View::orthographic({0.0, 1.0, 0.0}));
    EXPECT_EQ(refiner.cut().splatCount(), start.splatCount());
    refiner.refine(splats(start.splatCount() + 100));
    EXPECT_GT(refiner.cut().splatCount(), start.splatCount());
    EXPECT_LE(refiner.cut().splatCount(), start.splatCount() + 100);
}

TEST(Refiner, neverSplitsNodesBehindTheEye) {
    const Octree octree(randomGrid(glm::u64vec3(16), 10));
    // The eye looks away from the whole grid: nothing is worth refining.
    Refiner refiner(octree, View::perspective({-5.0, 8.0, 8.0}, {-1.0, 0.0, 0.0}));
    EXPECT_TRUE(refiner.isComplete());
    EXPECT_EQ(refiner.refine(RefineBudget{}), 0u);
    EXPECT_EQ(refiner.cut().splatCount(), 1u);
}

TEST(Refiner, spendsTheBudgetOnWhatIsInSight) {
    const Octree octree(randomGrid(glm::u64vec3(32), 12));
    const View along = View::orthographic({0.0, 0.0, 1.0});
    // Sight: x <= 6 of the 32 voxels (cells from -0.5 to 31.5), splats reaching an edge.
    const View::Sides sides{glm::dvec4(1.0, 0.0, 0.0, 1000.0), glm::dvec4(-1.0, 0.0, 0.0, 6.0),
                            glm::dvec4(0.0, 1.0, 0.0, 1000.0), glm::dvec4(0.0, -1.0, 0.0, 1000.0)};
    const View sighted = along.seeingOnly(sides, 1.0);
    const auto inSight = [&](const Cut& cut) {
        std::size_t count = 0;
        for (const NodeRef& node : nodesOf(cut)) {
            count += sighted.isOutOfSight(octree.cellMin(node), octree.cellMax(node)) ? 0 : 1;
        }
        return count;
    };
    constexpr std::uint64_t kBudget = 3000;
    Refiner plain(octree, along);
    plain.refine(splats(kBudget));
    Refiner refiner(octree, sighted);
    refiner.refine(splats(kBudget));
    EXPECT_GT(inSight(refiner.cut()), inSight(plain.cut()) * 3 / 2);
    // No node whose subtree is out of sight is split: each node of the cut out of sight has a
    // parent whose subtree is in sight.
    std::size_t outOfSight = 0;
    for (const NodeRef& node : nodesOf(refiner.cut())) {
        if (sighted.isOutOfSight(octree.cellMin(node), octree.cellMax(node))) {
            ++outOfSight;
            const glm::u64vec3 parent = node.coord / std::uint64_t{2};
            const glm::dvec3 low = octree.cellMin(NodeRef{0, parent, node.level + 1});
            const glm::dvec3 high = octree.cellMax(NodeRef{0, parent, node.level + 1});
            EXPECT_FALSE(sighted.isSubtreeOutOfSight(low, high)) << "level " << node.level;
        }
    }
    EXPECT_GT(outOfSight, 0u) << "the test needs nodes out of sight";
    // The budget counts the splats drawn, those in sight: the cut holds more nodes than the
    // budget, and its traversal for the view visits exactly the counted ones.
    EXPECT_EQ(refiner.splatsInSight(), inSight(refiner.cut()));
    EXPECT_LE(refiner.splatsInSight(), kBudget);
    EXPECT_GT(refiner.splatsInSight() + 8, kBudget) << "stopped by the budget";
    EXPECT_GT(refiner.cut().splatCount(), kBudget);
    std::uint64_t visited = 0;
    traverseBackToFront(refiner.cut(), sighted, [&](const NodeRef& node) {
        ++visited;
        EXPECT_FALSE(sighted.isOutOfSight(octree.cellMin(node), octree.cellMax(node)));
    });
    EXPECT_EQ(visited, refiner.splatsInSight());
    // What the queue reaches, refineAtOnce() reaches.
    EXPECT_TRUE(Refiner::refineAtOnce(Cut(octree), sighted, kBudget) == refiner.cut());
}

TEST(Refiner, aSplitWhoseChildrenAreAllOutOfSightDrawsOneSplatFewer) {
    // Eight voxels along x, cells from -0.5 to 7.5, and sight from x = 13.5 on: the root's splat
    // (edge 8, reach 8) reaches in, its two children's (edge 4, reach 4) do not. The full
    // resolution image has nothing of them, so the root is split and nothing is drawn.
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(8, 1, 1), glm::dvec3(1.0),
                                                 glm::dvec3(0.0));
    for (std::uint64_t i = 0; i < 8; ++i) {
        grid->setVoxel({i, 0, 0}, glm::vec3(0.1f * static_cast<float>(i + 1)), 1.0f);
    }
    const Octree octree(grid);
    const View view = seeingFrom(13.5, 1.0);
    Refiner refiner(octree, view);
    EXPECT_EQ(refiner.splatsInSight(), 1u);
    EXPECT_EQ(refiner.refine(splats(1)), 1u) << "a split that lowers the count always fits";
    EXPECT_EQ(refiner.cut().splatCount(), 2u);
    EXPECT_EQ(refiner.splatsInSight(), 0u);
    EXPECT_TRUE(refiner.isComplete());
    std::size_t drawn = 0;
    traverseBackToFront(refiner.cut(), view, [&](const NodeRef&) { ++drawn; });
    EXPECT_EQ(drawn, 0u);
    EXPECT_TRUE(Refiner::refineAtOnce(Cut(octree), view, 1) == refiner.cut());
    EXPECT_TRUE(Refiner::refineAtOnce(Cut(octree), view, 0) == refiner.cut())
        << "it fits even a budget of nothing";
}

TEST(Refiner, aThinChildClippedAtTheGridsFaceIsDrawnWhereItsParentsSplatIsNot) {
    // 5³ voxels: the root (edge 5, centre x = 2) has an upper-x child one voxel thick (x = 4)
    // and 4 voxels across, whose splat (reach 1.63 · 4 from x = 4) reaches x = 10.52, past the
    // root's own splat (1.63 · 5 from x = 2: 10.15). Sight from x = 10.3 on: the root's splat is
    // out of sight, its subtree is not.
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(5), glm::dvec3(1.0),
                                                 glm::dvec3(0.0));
    for (std::uint64_t k = 0; k < 5; ++k) {
        for (std::uint64_t j = 0; j < 5; ++j) {
            for (std::uint64_t i = 0; i < 5; ++i) {
                grid->setVoxel({i, j, k}, glm::vec3(0.1f * static_cast<float>(i + j + k + 1)),
                               1.0f);
            }
        }
    }
    const Octree octree(grid);
    const View view = seeingFrom(10.3, 1.63);
    const NodeRef root = octree.root();
    ASSERT_TRUE(view.isOutOfSight(octree.cellMin(root), octree.cellMax(root)));
    ASSERT_FALSE(view.isSubtreeOutOfSight(octree.cellMin(root), octree.cellMax(root)));
    EXPECT_EQ(Refiner(octree, view).splatsInSight(), 0u);
    EXPECT_GT(Refiner(octree, view).priority(root), 0.0) << "its subtree shows";
    // The root split: its three children at x = 4 that are 4 voxels across show, the others
    // (the one-voxel corner and the four at x < 4) do not.
    Cut cut(octree);
    cut.split(root);
    const auto inSight = [&](const NodeRef& node) {
        return !view.isOutOfSight(octree.cellMin(node), octree.cellMax(node));
    };
    std::uint64_t counted = 0;
    for (const NodeRef& node : nodesOf(cut)) {
        counted += inSight(node) ? 1 : 0;
    }
    EXPECT_EQ(counted, 3u);
    EXPECT_EQ(Refiner(cut, view).splatsInSight(), counted);
    std::uint64_t drawn = 0;
    traverseBackToFront(cut, view, [&](const NodeRef& node) {
        EXPECT_TRUE(inSight(node));
        ++drawn;
    });
    EXPECT_EQ(drawn, counted) << "the traversal does not prune the root on its own splat";
    // Refined on, they go too: their children's splats (1.63 · 2 from x = 4) do not reach.
    Refiner refiner(octree, view);
    refiner.refine(splats(100));
    EXPECT_EQ(refiner.splatsInSight(), 0u);
    EXPECT_TRUE(refiner.cut().isSplit(root));
    EXPECT_TRUE(Refiner::refineAtOnce(Cut(octree), view, 100) == refiner.cut());
}

TEST(Refiner, anUnlimitedBudgetWithSplitsThatLowerTheCountEnds) {
    // 16 × 16 voxels, sight from x = 18 on, a reach of one edge: the root's split adds one (its
    // two children at x >= 8 reach x = 19.5), then each of those splits lowers the count (their
    // children reach 17.5 at most). An unlimited budget (RefineBudget's default, what forTime()
    // gives for no limit) plus the room those lowering splits leave wrapped round to 0, and the
    // search went back and forth between the two for ever.
    auto grid = std::make_shared<ClassifiedGrid>(glm::u64vec3(16, 16, 1), glm::dvec3(1.0),
                                                 glm::dvec3(0.0));
    for (std::uint64_t j = 0; j < 16; ++j) {
        for (std::uint64_t i = 0; i < 16; ++i) {
            grid->setVoxel({i, j, 0}, glm::vec3(0.05f * static_cast<float>(i + j + 1)), 1.0f);
        }
    }
    const Octree octree(grid);
    const View view = seeingFrom(18.0, 1.0);
    constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();
    Refiner queue(octree, view);
    queue.refine(RefineBudget{});
    EXPECT_EQ(queue.splatsInSight(), 0u);
    EXPECT_TRUE(Refiner::refineAtOnce(Cut(octree), view, kUnlimited) == queue.cut());
    EXPECT_TRUE(Refiner::refineAtOnce(Cut(octree), view, kUnlimited - 1) == queue.cut());
}

TEST(Refiner, isDeterministic) {
    const Octree first(randomGrid(glm::u64vec3(16), 31));
    const Octree second(randomGrid(glm::u64vec3(16), 31));
    const View view = View::perspective({8.0, 7.0, 6.0}, {1.0, 0.0, 0.0});
    Refiner a(first, view);
    Refiner b(first, view);
    Refiner c(second, view);
    a.refine(splats(777));
    b.refine(splats(777));
    c.refine(splats(777));
    EXPECT_TRUE(a.cut() == b.cut());
    std::vector<std::uint64_t> orderA;
    std::vector<std::uint64_t> orderC;
    traverseBackToFront(a.cut(), view, [&](const NodeRef& node) { orderA.push_back(node.index); });
    traverseBackToFront(c.cut(), view, [&](const NodeRef& node) { orderC.push_back(node.index); });
    EXPECT_EQ(orderA, orderC) << "rebuilding the octree from the same data gives the same cut";
}

TEST(Refiner, timeBudgetBecomesASplatBudget) {
    EXPECT_EQ(RefineBudget::forTime(0.02, 2.0e6).maxSplats, 40000u);
    EXPECT_EQ(RefineBudget::forTime(1.0e300, 1.0e300).maxSplats,
              std::numeric_limits<std::uint64_t>::max());
    try {
        (void)RefineBudget::forTime(-1.0, 1.0e6);
        FAIL() << "expected a DataError";
    } catch (const texsplat::DataError& error) {
        EXPECT_STREQ(error.what(), "RefineBudget: time budget needs finite seconds >= 0 and a "
                                   "finite rate > 0, got -1 s at 1e+06 splats/s");
    }
}

namespace {

// A grid that is mirror-symmetric about its centre on every axis: symmetric views see many nodes
// of exactly equal priority, so the queue's ties decide which of them a budget splits.
std::shared_ptr<ClassifiedGrid> symmetricGrid(glm::u64vec3 dims) {
    auto grid = std::make_shared<ClassifiedGrid>(dims, glm::dvec3(1.0), glm::dvec3(0.0));
    const glm::dvec3 centre = (glm::dvec3(dims) - 1.0) * 0.5;
    for (std::uint64_t k = 0; k < dims.z; ++k) {
        for (std::uint64_t j = 0; j < dims.y; ++j) {
            for (std::uint64_t i = 0; i < dims.x; ++i) {
                const glm::dvec3 offset = glm::abs(glm::dvec3(i, j, k) - centre);
                const double ring = std::fmod(offset.x * 0.7 + offset.y * 1.3 + offset.z, 3.0);
                if (ring < 0.8) {
                    continue;
                }
                const auto value = static_cast<float>(ring);
                grid->setVoxel({i, j, k}, glm::vec3(value, 0.5f * value, 1.0f), value);
            }
        }
    }
    return grid;
}

// Every budget from 0 to past the finest cut (or a spread of them), from @p start: the cut at
// once and the cheaper way's are the queue's.
void expectRefineAtOnceLikeTheQueue(const Cut& start, const View& view, const std::string& what) {
    Refiner unlimited(start, view);
    unlimited.refine(RefineBudget{});
    const std::uint64_t finest = unlimited.cut().splatCount();
    const std::uint64_t step = std::max<std::uint64_t>(1, finest / 300);
    for (std::uint64_t budget = 0; budget <= finest + 1; budget += step) {
        Refiner queue(start, view);
        queue.refine(splats(budget));
        const Cut atOnce = Refiner::refineAtOnce(start, view, budget);
        ASSERT_TRUE(atOnce == queue.cut()) << what << ", budget " << budget;
        ASSERT_EQ(atOnce.splatCount(), queue.cut().splatCount()) << what << ", budget " << budget;
        // Whichever way it takes (the queue below a quarter of the records, else at once).
        ASSERT_TRUE(Refiner::cutOfBudget(start, view, budget) == queue.cut())
            << what << ", budget " << budget;
    }
}

} // namespace

TEST(Refiner, refineAtOnceMakesTheQueuesCutForEveryBudget) {
    const std::vector<std::pair<std::string, View>> views = {
        {"orthographic oblique", View::orthographic({0.3, -0.5, 0.8})},
        {"orthographic along z", View::orthographic({0.0, 0.0, 1.0})},
        {"perspective outside", View::perspective({-9.0, 4.0, 30.0}, {0.3, 0.0, -1.0})},
        {"perspective inside", View::perspective({5.2, 6.1, 4.9}, {0.0, 1.0, 0.0})},
        {"perspective on the axis", View::perspective({7.5, 7.5, -20.0}, {0.0, 0.0, 1.0})},
        // Sides through the grids: splits counted by the children in sight, none wasted.
        {"perspective seeing x >= 4, y <= 10",
         View::perspective({-9.0, 4.0, 30.0}, {0.3, 0.0, -1.0})
             .seeingOnly({glm::dvec4(1.0, 0.0, 0.0, -4.0), glm::dvec4(0.0, -1.0, 0.0, 10.0),
                          glm::dvec4(0.0, 0.0, 0.0, 1.0), glm::dvec4(0.0, 0.0, 0.0, 1.0)},
                         1.0)},
        {"orthographic seeing x + y >= 12, z <= 9",
         View::orthographic({0.3, -0.5, 0.8})
             .seeingOnly({glm::dvec4(1.0, 1.0, 0.0, -12.0), glm::dvec4(0.0, 0.0, -1.0, 9.0),
                          glm::dvec4(0.0, 0.0, 0.0, 1.0), glm::dvec4(0.0, 0.0, 0.0, 1.0)},
                         2.3)},
    };
    const std::vector<std::pair<std::string, std::shared_ptr<ClassifiedGrid>>> grids = {
        {"random 16^3", randomGrid(glm::u64vec3(16), 5)},
        {"random 37x5x20, one-voxel-thick splits", randomGrid(glm::u64vec3(37, 5, 20), 6, 0.5f)},
        {"random 9x1x13 anisotropic",
         randomGrid(glm::u64vec3(9, 1, 13), 7, 0.2f, false, glm::dvec3(0.5, 2.0, 1.0))},
        {"symmetric 16^3", symmetricGrid(glm::u64vec3(16))},
        {"symmetric 24x16x8", symmetricGrid(glm::u64vec3(24, 16, 8))},
    };
    for (const auto& [gridName, grid] : grids) {
        const Octree octree(grid);
        for (const auto& [viewName, view] : views) {
            expectRefineAtOnceLikeTheQueue(Cut(octree), view, gridName + ", " + viewName);
            expectRefineAtOnceLikeTheQueue(Cut::byRelativeError(octree, 0.5), view,
                                           gridName + ", " + viewName + ", from a threshold cut");
        }
    }
}

TEST(Refiner, refineAtOnceIsTheSameOnAnyNumberOfThreads) {
    const Octree octree(randomGrid(glm::u64vec3(64, 48, 40), 8));
    const View view = View::perspective({20.0, -60.0, 90.0}, {0.0, 0.6, -1.0});
    Refiner queue(octree, view);
    queue.refine(splats(30000));
    for (const int threads : {1, 2, 7}) {
        tbb::task_arena(threads).execute([&] {
            EXPECT_TRUE(Refiner::refineAtOnce(Cut(octree), view, 30000) == queue.cut())
                << threads << " threads";
        });
    }
}
