#include "nodes/TriangleMesh.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::nodes {
namespace {

TEST(TriangleMesh, computesAreaWeightedSmoothNormals) {
    TriangleMesh mesh;
    // Two triangles meeting at a right angle along the x axis: one in the floor (normal +z), one
    // twice as large in the wall (normal -y).
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}};
    mesh.indices = {0, 1, 2, 0, 1, 3};
    mesh.computeNormals();
    ASSERT_EQ(mesh.normals.size(), 4u);
    EXPECT_EQ(mesh.normals[2], glm::vec3(0, 0, 1));
    EXPECT_EQ(mesh.normals[3], glm::vec3(0, -1, 0));
    const glm::vec3 shared = glm::normalize(glm::vec3(0, -2, 1)); // the larger face weighs more
    EXPECT_NEAR(mesh.normals[0].y, shared.y, 1e-6f);
    EXPECT_NEAR(mesh.normals[0].z, shared.z, 1e-6f);
}

TEST(TriangleMesh, givesDegenerateVerticesADefaultNormal) {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    mesh.indices = {0, 1, 2};
    mesh.computeNormals();
    EXPECT_EQ(mesh.normals, std::vector<glm::vec3>(3, glm::vec3(0, 0, 1)));
}

TEST(TriangleMesh, appendsWithShiftedIndicesAndBounds) {
    TriangleMesh first;
    first.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    first.normals.assign(3, glm::vec3(0, 0, 1));
    first.colors.assign(3, glm::vec3(1));
    first.indices = {0, 1, 2};
    TriangleMesh both = first;
    TriangleMesh second = first;
    for (glm::vec3& position : second.positions) {
        position.z = 5.0f;
    }
    both.append(second);
    EXPECT_EQ(both.triangleCount(), 2u);
    EXPECT_EQ(both.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(both.positions.size(), both.colors.size());
    EXPECT_EQ(both.bounds(), sg::Box3(glm::vec3(0), glm::vec3(1, 1, 5)));
    EXPECT_TRUE(TriangleMesh().bounds().isEmpty());
    EXPECT_TRUE(TriangleMesh().isEmpty());
}

} // namespace
} // namespace texsplat::nodes
