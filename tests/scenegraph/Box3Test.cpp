#include "scenegraph/Box3.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

TEST(Box3, startsEmptyAndGrows) {
    Box3 box;
    EXPECT_TRUE(box.isEmpty());
    EXPECT_EQ(box.size(), glm::vec3(0.0f));
    box.extendBy(glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_FALSE(box.isEmpty());
    EXPECT_EQ(box.size(), glm::vec3(0.0f));
    box.extendBy(Box3(glm::vec3(-1.0f), glm::vec3(0.0f)));
    EXPECT_EQ(box.min(), glm::vec3(-1.0f));
    EXPECT_EQ(box.max(), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(box.center(), glm::vec3(0.0f, 0.5f, 1.0f));
    box.extendBy(Box3());
    EXPECT_EQ(box.max(), glm::vec3(1.0f, 2.0f, 3.0f));
}

TEST(Box3, cornersAreNumberedByTheirAxesBits) {
    const Box3 box(glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(4.0f, 5.0f, 6.0f));
    EXPECT_EQ(box.corner(0), box.min());
    EXPECT_EQ(box.corner(1), glm::vec3(4.0f, 2.0f, 3.0f));
    EXPECT_EQ(box.corner(2), glm::vec3(1.0f, 5.0f, 3.0f));
    EXPECT_EQ(box.corner(4), glm::vec3(1.0f, 2.0f, 6.0f));
    EXPECT_EQ(box.corner(7), box.max());
}

TEST(Box3, transformedBoundsTheMappedCorners) {
    const Box3 box(glm::vec3(-1.0f), glm::vec3(1.0f));
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 0, 1));
    const Box3 turned = box.transformed(turn);
    EXPECT_NEAR(turned.max().x, std::sqrt(2.0f), 1e-6f);
    EXPECT_NEAR(turned.min().y, -std::sqrt(2.0f), 1e-6f);
    EXPECT_NEAR(turned.max().z, 1.0f, 1e-6f);
    const glm::mat4 scaleMove =
        glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, 0.0f, 0.0f)), glm::vec3(2.0f));
    EXPECT_EQ(box.transformed(scaleMove),
        Box3(glm::vec3(3.0f, -2.0f, -2.0f), glm::vec3(7.0f, 2.0f, 2.0f)));
    EXPECT_TRUE(Box3().transformed(scaleMove).isEmpty());
    EXPECT_EQ(Box3(), Box3());
}

} // namespace
} // namespace texsplat::sg
