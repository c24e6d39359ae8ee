#include "octree/DepthSort.h"

#include "OctreeTestSupport.h"
#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"

#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using texsplat::octree::Cut;
using texsplat::octree::DepthSorter;
using texsplat::octree::Octree;
using texsplat::octree::Splat;
using texsplat::octree::SplatList;
using texsplat::octree::SplatMark;
using texsplat::octree::View;
using texsplat::octree::test::randomGrid;

namespace {

// The centre-distance criterion suited to each projection.
double centreDepth(const Splat& splat, const View& view) {
    const glm::dvec3 position(splat.position);
    return view.isPerspective() ? glm::distance(position, view.eye())
                                : glm::dot(position, view.direction());
}

// Whether the footprints (radius 1.6 voxels times the splat size) of two splats can overlap on
// the screen: compared perpendicular to the direction (orthographic) or as angles seen from the
// eye (perspective).
bool footprintsOverlap(const Splat& a, const Splat& b, const View& view) {
    const double radiusA = 1.6 * a.size;
    const double radiusB = 1.6 * b.size;
    const glm::dvec3 pa(a.position);
    const glm::dvec3 pb(b.position);
    if (!view.isPerspective()) {
        const glm::dvec3 apart = pb - pa;
        const glm::dvec3 across = apart - glm::dot(apart, view.direction()) * view.direction();
        return glm::length(across) < radiusA + radiusB;
    }
    const glm::dvec3 ua = glm::normalize(pa - view.eye());
    const glm::dvec3 ub = glm::normalize(pb - view.eye());
    const double angle = std::acos(std::clamp(glm::dot(ua, ub), -1.0, 1.0));
    return angle < std::asin(std::min(1.0, radiusA / glm::distance(pa, view.eye()))) +
                       std::asin(std::min(1.0, radiusB / glm::distance(pb, view.eye())));
}

// Pairs of overlapping splats where the nearer one comes first.
std::uint64_t centreOrderViolations(const SplatList& splats, const View& view) {
    std::uint64_t violations = 0;
    const auto& list = splats.splats();
    for (std::size_t i = 0; i < list.size(); ++i) {
        for (std::size_t j = i + 1; j < list.size(); ++j) {
            if (centreDepth(list[i], view) < centreDepth(list[j], view) - 1e-6 &&
                footprintsOverlap(list[i], list[j], view)) {
                ++violations;
            }
        }
    }
    return violations;
}

} // namespace

TEST(DepthSort, ordersByDecreasingCentreDepthLikeAStableSort) {
    const Octree octree(randomGrid(glm::u64vec3(12), 4, 0.3f, true, glm::dvec3(1.0),
                                   glm::dvec3(-6.0, -2.0, -9.0)));
    const Cut cut = Cut::byError(octree, 0.5);
    for (const View& view : {View::orthographic({0.6, -0.7, 0.4}),
                             View::perspective({3.0, 1.0, -4.0}, {0.0, 0.0, 1.0})}) {
        SplatList splats;
        emitSplats(cut, view, splats);
        std::vector<Splat> expected = splats.splats();
        std::stable_sort(expected.begin(), expected.end(), [&](const Splat& a, const Splat& b) {
            return static_cast<float>(centreDepth(a, view)) >
                   static_cast<float>(centreDepth(b, view));
        });
        sortByDepth(splats, view);
        ASSERT_EQ(splats.size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i) {
            EXPECT_EQ(splats.splats()[i].position, expected[i].position);
            EXPECT_EQ(splats.splats()[i].size, expected[i].size);
        }
    }
}

TEST(DepthSort, carriesEachSplatsMarksAlong) {
    // Splat i has i marks, mark j of it the phase i + j / 10.
    SplatList splats;
    for (int i = 0; i < 5; ++i) {
        Splat splat;
        splat.position = glm::vec3(0.0f, 0.0f, static_cast<float>((i * 3) % 5) - 2.0f);
        std::vector<SplatMark> marks(static_cast<std::size_t>(i));
        for (int j = 0; j < i; ++j) {
            marks[static_cast<std::size_t>(j)].phase = static_cast<float>(i) + 0.1f * j;
        }
        splats.add(splat, marks.data(), marks.size());
    }
    sortByDepth(splats, View::orthographic({0.0, 0.0, -1.0}));
    ASSERT_TRUE(splats.hasMarks());
    ASSERT_EQ(splats.marks().size(), 10u);
    for (std::size_t i = 0; i < splats.size(); ++i) {
        EXPECT_EQ(splats.splats()[i].position.z, static_cast<float>(i) - 2.0f);
        // Splat i of the sorted list came from splat s with (s * 3) % 5 == i.
        const int source = static_cast<int>((i * 2) % 5);
        ASSERT_EQ(splats.markBegin(i + 1) - splats.markBegin(i), static_cast<std::size_t>(source));
        for (int j = 0; j < source; ++j) {
            EXPECT_EQ(splats.marks()[splats.markBegin(i) + static_cast<std::size_t>(j)].phase,
                      static_cast<float>(source) + 0.1f * j);
        }
    }
}

TEST(DepthSort, overlappingSplatsComeFarthestCentreFirst) {
    // Full resolution: the traversal orders cells exactly, but under oblique views kernels that
    // reach past their cells overlap out of centre order; the sort repairs that.
    const Octree octree(randomGrid(glm::u64vec3(10), 8, 0.2f, false));
    const Cut cut = Cut::byError(octree, 0.0);
    for (const View& view : {View::orthographic({0.7, 0.5, 0.6}),
                             View::perspective({-8.0, 4.0, 20.0}, {1.0, 0.0, -1.0}),
                             View::perspective({4.2, 5.1, 4.9}, {0.0, 1.0, 0.0})}) {
        SplatList splats;
        emitSplats(cut, view, splats);
        EXPECT_GT(centreOrderViolations(splats, view), 0u);
        sortByDepth(splats, view);
        EXPECT_EQ(centreOrderViolations(splats, view), 0u);
    }
}

namespace {

// @p count splats whose depths along z take only @p depths values (so most of them tie), each
// carrying its index in the list (colour red) and, with marks, i % 3 marks whose phase is i.
SplatList tiedSplats(std::size_t count, int depths, bool withMarks) {
    SplatList splats;
    for (std::size_t i = 0; i < count; ++i) {
        Splat splat;
        splat.position = glm::vec3(static_cast<float>(i % 7), 0.0f,
                                   static_cast<float>((i * 7919) % static_cast<std::size_t>(depths)));
        splat.color.r = static_cast<float>(i);
        if (withMarks) {
            SplatMark mark;
            mark.phase = static_cast<float>(i);
            const std::vector<SplatMark> marks(i % 3, mark);
            splats.add(splat, marks.data(), marks.size());
        } else {
            splats.add(splat);
        }
    }
    return splats;
}

// The indices (colour red) of @p splats after a std::stable_sort by decreasing depth.
std::vector<float> stableSortedIndices(const SplatList& splats, const View& view) {
    std::vector<Splat> sorted = splats.splats();
    std::stable_sort(sorted.begin(), sorted.end(), [&](const Splat& a, const Splat& b) {
        return static_cast<float>(centreDepth(a, view)) >
               static_cast<float>(centreDepth(b, view));
    });
    std::vector<float> indices;
    for (const Splat& splat : sorted) {
        indices.push_back(splat.color.r);
    }
    return indices;
}

std::vector<float> indicesOf(const SplatList& splats) {
    std::vector<float> indices;
    for (const Splat& splat : splats.splats()) {
        indices.push_back(splat.color.r);
    }
    return indices;
}

} // namespace

TEST(DepthSorter, sortsTiesAcrossChunksStablyOnAnyNumberOfThreads) {
    // 100 000 splats make four chunks of the parallel radix passes; 37 depths make long runs of
    // ties that cross the chunks' borders.
    const View view = View::orthographic({0.0, 0.0, 1.0});
    const SplatList unsorted = tiedSplats(100000, 37, true);
    const std::vector<float> expected = stableSortedIndices(unsorted, view);
    for (const int threads : {1, 2, 7}) {
        SplatList splats = unsorted;
        tbb::task_arena(threads).execute([&] { DepthSorter().sort(splats, view); });
        EXPECT_EQ(indicesOf(splats), expected) << threads << " threads";
        ASSERT_TRUE(splats.hasMarks());
        for (std::size_t i = 0; i < splats.size(); ++i) {
            const auto source = static_cast<std::size_t>(expected[i]);
            ASSERT_EQ(splats.markBegin(i + 1) - splats.markBegin(i), source % 3);
            for (std::size_t m = splats.markBegin(i); m < splats.markBegin(i + 1); ++m) {
                ASSERT_EQ(splats.marks()[m].phase, expected[i]);
            }
        }
    }
}

TEST(DepthSorter, keepsItsBuffersAndSortsEachListAnew) {
    // One sorter, as a splat node keeps it: lists shrinking, growing, losing and gaining their
    // marks, each sorted as a fresh sortByDepth() sorts it.
    DepthSorter sorter;
    const View view = View::perspective({3.0, -2.0, -5.0}, {0.0, 0.0, 1.0});
    for (const auto& [count, withMarks] : {std::pair<std::size_t, bool>{70000, false},
                                           {5, true},
                                           {0, false},
                                           {40000, true},
                                           {33000, false}}) {
        SplatList splats = tiedSplats(count, 11, withMarks);
        SplatList expected = splats;
        sortByDepth(expected, view);
        const std::uint64_t revision = splats.revision();
        sorter.sort(splats, view);
        EXPECT_EQ(indicesOf(splats), indicesOf(expected)) << count << " splats";
        EXPECT_EQ(splats.hasMarks(), withMarks && count > 0);
        EXPECT_EQ(splats.marks(), expected.marks());
        EXPECT_GT(splats.revision(), revision) << "a backend must see the list changed";
        EXPECT_EQ(indicesOf(expected), stableSortedIndices(tiedSplats(count, 11, withMarks), view));
    }
    EXPECT_GE(sorter.memoryBytes(), 70000u * 2 * sizeof(std::uint64_t)) << "the keys are kept";
}
