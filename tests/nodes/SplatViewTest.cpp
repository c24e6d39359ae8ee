// The view a splat node refines its octree cut for: the camera's four sides in the volume's
// local space, widened by how far a splat reaches.
#include "nodes/render/SplatView.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::render {
namespace {

// A box of one voxel (edge 1) centred at `centre`.
bool unitBoxOutOfSight(const octree::View& view, glm::dvec3 centre) {
    return view.isOutOfSight(centre - 0.5, centre + 0.5);
}

// A square of extent 1.6 at its corner: how far a splat that turns reaches.
const double kSquareCorner = 1.6 * std::sqrt(2.0);

const glm::mat4 kLookDownZ =
    glm::lookAt(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));

TEST(SplatView, aPerspectiveCutSeesTheFrustumsSidesWidenedByTheSplatsReach) {
    // 60 degrees: at the origin (10 from the eye) the sides are ±10·tan 30° = ±5.77 away.
    const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 1.0f, 100.0f);
    const SplatView view =
        SplatView::fromMatrices(glm::mat4(1.0f), kLookDownZ, projection, glm::vec3(1.0f));
    const octree::View sighted = view.refinementView(kSquareCorner);
    EXPECT_FALSE(unitBoxOutOfSight(sighted, {0.0, 0.0, 0.0}));
    // Reach 1.6·√2 = 2.26 edges from the centre: 6.5 - 2.26 < 5.77.
    EXPECT_FALSE(unitBoxOutOfSight(sighted, {6.5, 0.0, 0.0}));
    // The box widened by 1.76 reaches 2.26 deeper too, where the sides are 12.26·tan 30° = 7.08
    // away: 9 - 2.26 < 7.08.
    EXPECT_FALSE(unitBoxOutOfSight(sighted, {9.0, 0.0, 0.0}));
    EXPECT_TRUE(unitBoxOutOfSight(sighted, {11.0, 0.0, 0.0}));
    EXPECT_TRUE(unitBoxOutOfSight(sighted, {0.0, -11.0, 0.0}));
    EXPECT_FALSE(unitBoxOutOfSight(sighted, {0.0, 9.0, -10.0})) << "farther away, wider";
    EXPECT_EQ(sighted.direction(), view.octreeView().direction()) << "ordering is unchanged";
    EXPECT_EQ(sighted.eye(), view.octreeView().eye());
    EXPECT_FALSE(unitBoxOutOfSight(view.octreeView(), {11.0, 0.0, 0.0})) << "ordering sees all";
}

TEST(SplatView, anOrthographicCutSeesItsBoxInTheVolumesLocalSpace) {
    const glm::mat4 projection = glm::ortho(-5.0f, 5.0f, -5.0f, 5.0f, 1.0f, 100.0f);
    // The volume sits 20 to the left of the world origin: its local x = 20 is seen at 0.
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(-20.0f, 0.0f, 0.0f));
    const SplatView view = SplatView::fromMatrices(model, kLookDownZ, projection, glm::vec3(1.0f));
    const octree::View sighted = view.refinementView(kSquareCorner);
    EXPECT_FALSE(unitBoxOutOfSight(sighted, {20.0, 0.0, 0.0}));
    EXPECT_TRUE(unitBoxOutOfSight(sighted, {0.0, 0.0, 0.0}));
    EXPECT_TRUE(unitBoxOutOfSight(sighted, {28.0, 0.0, 0.0})); // 28 - 2.26 > 25
    EXPECT_FALSE(unitBoxOutOfSight(sighted, {27.0, 0.0, 0.0}));
}

TEST(SplatView, coarserSpacingOnOneAxisWidensTheReach) {
    const glm::mat4 projection = glm::ortho(-5.0f, 5.0f, -5.0f, 5.0f, 1.0f, 100.0f);
    const SplatView even =
        SplatView::fromMatrices(glm::mat4(1.0f), kLookDownZ, projection, glm::vec3(1.0f));
    const SplatView uneven = SplatView::fromMatrices(glm::mat4(1.0f), kLookDownZ, projection,
                                                     glm::vec3(1.0f, 1.0f, 4.0f));
    // A box of edge 1 at x = 12: out of sight for an even spacing, but with voxels 4 long in z a
    // splat of the same box may reach 4 times as far.
    EXPECT_TRUE(unitBoxOutOfSight(even.refinementView(kSquareCorner), {12.0, 0.0, 0.0}));
    EXPECT_FALSE(unitBoxOutOfSight(uneven.refinementView(kSquareCorner), {12.0, 0.0, 0.0}));
}

} // namespace
} // namespace texsplat::render
