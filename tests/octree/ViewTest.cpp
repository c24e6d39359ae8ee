#include "octree/View.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using texsplat::octree::View;

namespace {

template <typename Function> std::string errorOf(Function function) {
    try {
        function();
    } catch (const texsplat::DataError& error) {
        return error.what();
    }
    return "no error";
}

} // namespace

TEST(View, normalizesTheDirection) {
    const View view = View::orthographic({0.0, 3.0, 4.0});
    EXPECT_FALSE(view.isPerspective());
    EXPECT_DOUBLE_EQ(view.direction().y, 0.6);
    EXPECT_DOUBLE_EQ(view.direction().z, 0.8);
}

TEST(View, farSideFollowsTheDirectionOrTheEye) {
    const View orthographic = View::orthographic({-1.0, 0.0, 1.0});
    EXPECT_FALSE(orthographic.isUpperSideFar(0, 100.0));
    EXPECT_TRUE(orthographic.isUpperSideFar(2, -100.0));
    const View perspective = View::perspective({5.0, 5.0, 5.0}, {0.0, 0.0, 1.0});
    EXPECT_TRUE(perspective.isUpperSideFar(0, 6.0));
    EXPECT_FALSE(perspective.isUpperSideFar(0, 4.0));
}

TEST(View, boxesBehindTheEyePlane) {
    const View view = View::perspective({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0});
    EXPECT_TRUE(view.isBoxBehindEye({-1.0, -1.0, -3.0}, {1.0, 1.0, -0.5}));
    EXPECT_FALSE(view.isBoxBehindEye({-1.0, -1.0, -3.0}, {1.0, 1.0, 0.5}));
    EXPECT_FALSE(View::orthographic({0.0, 0.0, 1.0}).isBoxBehindEye(glm::dvec3(-2.0),
                                                                    glm::dvec3(-1.0)));
    EXPECT_DOUBLE_EQ(view.depth({3.0, 4.0, 2.0}), 2.0);
}

TEST(View, rejectsZeroOrNonFiniteVectors) {
    EXPECT_EQ(errorOf([] { (void)View::orthographic(glm::dvec3(0.0)); }),
              "View: direction must be finite and non-zero, got (0, 0, 0)");
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(errorOf([&] { (void)View::perspective({0.0, inf, 0.0}, {1.0, 0.0, 0.0}); }),
              "View: eye must be finite, got (0, inf, 0)");
}

TEST(View, normalizesHugeAndTinyDirections) {
    const View huge = View::orthographic({1.0e308, 1.0e308, 0.0});
    EXPECT_DOUBLE_EQ(huge.direction().x, std::sqrt(0.5));
    const View tiny = View::orthographic({0.0, 0.0, -1.0e-320});
    EXPECT_DOUBLE_EQ(tiny.direction().z, -1.0);
}

TEST(View, aNodeIsOutOfSightWhenItsSplatLiesWhollyOutsideASide) {
    const View plain = View::orthographic({0.0, 0.0, 1.0});
    // Sight: 0 <= x <= 10, 0 <= y <= 10; splats reach one edge from their centre.
    const View::Sides sides{glm::dvec4(1.0, 0.0, 0.0, 0.0), glm::dvec4(-1.0, 0.0, 0.0, 10.0),
                            glm::dvec4(0.0, 1.0, 0.0, 0.0), glm::dvec4(0.0, -1.0, 0.0, 10.0)};
    const View view = plain.seeingOnly(sides, 1.0);
    EXPECT_FALSE(view.isOutOfSight({2.0, 2.0, -5.0}, {4.0, 4.0, 5.0})) << "inside";
    EXPECT_FALSE(view.isOutOfSight({-3.0, 2.0, 0.0}, {1.0, 4.0, 1.0})) << "across a side";
    EXPECT_FALSE(view.isOutOfSight({10.4, 2.0, 0.0}, {11.4, 3.0, 1.0})) << "its splat reaches in";
    EXPECT_TRUE(view.isOutOfSight({10.6, 2.0, 0.0}, {11.6, 3.0, 1.0})) << "centre 1.1 away";
    EXPECT_TRUE(view.isOutOfSight({2.0, -4.0, 0.0}, {4.0, -2.5, 1.0})) << "edge 2, 2.0 away";
    // Voxels of edge 1 in a block: each reaches 1 from its centre, half a voxel past its cell.
    EXPECT_FALSE(view.isOutOfSight({10.4, 2.0, 0.0}, {18.4, 10.0, 8.0}, 1.0, 0.5));
    EXPECT_TRUE(view.isOutOfSight({10.6, 2.0, 0.0}, {18.6, 10.0, 8.0}, 1.0, 0.5));
    // The credit is at most half the reach: a reach of 0.5 edges still widens a cell by 0.25.
    const View near = plain.seeingOnly(sides, 0.5);
    EXPECT_FALSE(near.isOutOfSight({10.2, 2.0, 0.0}, {11.2, 3.0, 1.0}));
    EXPECT_TRUE(near.isOutOfSight({10.3, 2.0, 0.0}, {11.3, 3.0, 1.0}));
    EXPECT_FALSE(plain.isOutOfSight({100.0, 100.0, 0.0}, {101.0, 101.0, 1.0})) << "no sides";
    EXPECT_DOUBLE_EQ(view.direction().z, 1.0) << "ordering is unchanged";

    View::Sides unknown = sides;
    unknown[1] = glm::dvec4(std::nan(""), 0.0, 0.0, 10.0);
    EXPECT_FALSE(plain.seeingOnly(unknown, 0.0).isOutOfSight({11.5, 2.0, 0.0}, {12.5, 3.0, 1.0}))
        << "a plane that is not finite hides nothing";
    EXPECT_EQ(errorOf([&] { (void)plain.seeingOnly(sides, -1.0); }),
              "View: a splat's reach must be finite and >= 0, got -1.000000");
}

TEST(View, aBoxIsWhollyInSightWhenItLiesInsideEverySide) {
    const View plain = View::orthographic({0.0, 0.0, 1.0});
    const View::Sides sides{glm::dvec4(1.0, 0.0, 0.0, 0.0), glm::dvec4(-1.0, 0.0, 0.0, 10.0),
                            glm::dvec4(0.0, 1.0, 0.0, 0.0), glm::dvec4(0.0, -1.0, 0.0, 10.0)};
    const View view = plain.seeingOnly(sides, 1.0);
    EXPECT_TRUE(view.isWhollyInSight({0.0, 2.0, -5.0}, {10.0, 4.0, 5.0})) << "touching two sides";
    EXPECT_FALSE(view.isWhollyInSight({-0.5, 2.0, 0.0}, {4.0, 4.0, 1.0})) << "across a side";
    EXPECT_FALSE(view.isWhollyInSight({2.0, 9.0, 0.0}, {4.0, 10.5, 1.0})) << "across another";
    EXPECT_TRUE(plain.isWhollyInSight({100.0, 100.0, 0.0}, {101.0, 101.0, 1.0})) << "no sides";
    View::Sides unknown = sides;
    unknown[1] = glm::dvec4(std::nan(""), 0.0, 0.0, 10.0);
    EXPECT_FALSE(plain.seeingOnly(unknown, 0.0).isWhollyInSight({1.0, 1.0, 0.0}, {2.0, 2.0, 1.0}))
        << "a plane that is not finite: not known to be inside (and hides nothing)";
}
