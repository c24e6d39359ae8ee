#include "nodes/OrthographicCamera.h"

#include "SceneNodesTestSupport.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::nodes {
namespace {

using test::errorOf;

TEST(OrthographicCamera, projectionMatrixMatchesTheBoxFormula) {
    const auto camera = OrthographicCamera::create();
    EXPECT_EQ(camera->height.value(), 2.0f);
    camera->height = 4.0f;
    camera->nearDistance = 1.0f;
    camera->farDistance = 3.0f;
    glm::mat4 expected(1.0f);
    expected[0][0] = 0.25f; // 2 / (height * aspect)
    expected[1][1] = 0.5f;  // 2 / height
    expected[2][2] = -1.0f; // -2 / (far - near)
    expected[3][2] = -2.0f; // -(far + near) / (far - near)
    const glm::mat4 actual = camera->projectionMatrix(2.0f);
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            EXPECT_NEAR(actual[column][row], expected[column][row], 1e-6f);
        }
    }
}

TEST(OrthographicCamera, viewAllSetsTheHeightToTheSphereDiameter) {
    const auto camera = OrthographicCamera::create();
    camera->viewAll(sg::Box3(glm::vec3(-1.0f), glm::vec3(1.0f)), 2.0f);
    const float radius = std::sqrt(3.0f);
    EXPECT_NEAR(camera->height.value(), 2.0f * radius, 1e-5f);
    EXPECT_NEAR(camera->position.value().z, 2.0f * radius, 1e-5f);
    EXPECT_NEAR(camera->nearDistance.value(), radius, 1e-5f);
    EXPECT_NEAR(camera->farDistance.value(), 3.0f * radius, 1e-5f);
    EXPECT_NEAR(camera->focalDistance.value(), 2.0f * radius, 1e-5f);

    camera->viewAll(sg::Box3(glm::vec3(-1.0f), glm::vec3(1.0f)), 0.5f);
    EXPECT_NEAR(camera->height.value(), 4.0f * radius, 1e-5f); // the width must hold the sphere
}

TEST(OrthographicCamera, depthRangeMayReachBehindTheEye) {
    const auto camera = OrthographicCamera::create();
    camera->position = glm::vec3(0.0f);
    const DepthRange range = camera->depthRangeFor(sg::Box3(glm::vec3(-1.0f), glm::vec3(1.0f)));
    EXPECT_NEAR(range.nearDistance, -1.02001f, 1e-5f);
    EXPECT_NEAR(range.farDistance, 1.02001f, 1e-5f);
}

TEST(OrthographicCamera, reportsABadHeight) {
    const auto camera = OrthographicCamera::create();
    camera->height = -1.0f;
    EXPECT_EQ(errorOf<DataError>([&] { camera->projectionMatrix(1.0f); }),
              "OrthographicCamera: height must be finite and positive, got -1");
}

} // namespace
} // namespace texsplat::nodes
