#include "nodes/PerspectiveCamera.h"

#include "SceneNodesTestSupport.h"
#include "nodes/Transform.h"
#include "nodes/elements/CameraElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/Rotation.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace texsplat::nodes {
namespace {

using test::errorOf;

constexpr float kTolerance = 1e-5f;

void expectMatrixNear(const glm::mat4& actual, const glm::mat4& expected) {
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            EXPECT_NEAR(actual[column][row], expected[column][row], kTolerance)
                << "column " << column << " row " << row;
        }
    }
}

glm::vec3 toNdc(const glm::mat4& clipFromWorld, const glm::vec3& point) {
    const glm::vec4 clip = clipFromWorld * glm::vec4(point, 1.0f);
    return glm::vec3(clip) / clip.w;
}

TEST(PerspectiveCamera, hasInventorDefaults) {
    const auto camera = PerspectiveCamera::create();
    EXPECT_EQ(camera->position.value(), glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(camera->orientation.value(), sg::Rotation());
    EXPECT_EQ(camera->nearDistance.value(), 1.0f);
    EXPECT_EQ(camera->farDistance.value(), 10.0f);
    EXPECT_EQ(camera->focalDistance.value(), 5.0f);
    EXPECT_EQ(camera->aspectRatio.value(), 1.0f);
    EXPECT_EQ(camera->heightAngle.value(), glm::quarter_pi<float>());
    EXPECT_EQ(camera->viewDirection(), glm::vec3(0.0f, 0.0f, -1.0f));
}

TEST(PerspectiveCamera, viewMatrixIsTheInverseOfThePlacement) {
    const auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(5.0f, 0.0f, 0.0f);
    // A quarter turn about +y turns the view direction (0,0,-1) into (-1,0,0).
    camera->orientation = sg::Rotation(glm::vec3(0.0f, 1.0f, 0.0f), glm::half_pi<float>());
    // Hand-computed: x_cam = -z_world ... rows of R^T, then translation -R^T p.
    const glm::mat4 expected(glm::vec4(0, 0, 1, 0), glm::vec4(0, 1, 0, 0),
                             glm::vec4(-1, 0, 0, 0), glm::vec4(0, 0, -5, 1));
    expectMatrixNear(camera->viewMatrix(), expected);
    const glm::vec3 origin = glm::vec3(camera->viewMatrix() * glm::vec4(0, 0, 0, 1));
    EXPECT_NEAR(origin.z, -5.0f, kTolerance); // 5 units straight ahead
    EXPECT_NEAR(camera->viewDirection().x, -1.0f, kTolerance);
}

TEST(PerspectiveCamera, projectionMatrixMatchesTheFrustumFormula) {
    const auto camera = PerspectiveCamera::create();
    camera->heightAngle = glm::half_pi<float>(); // f = 1 / tan(pi/4) = 1
    camera->nearDistance = 1.0f;
    camera->farDistance = 3.0f;
    glm::mat4 expected(0.0f);
    expected[0][0] = 0.5f; // f / aspect
    expected[1][1] = 1.0f;
    expected[2][2] = -2.0f; // (far + near) / (near - far)
    expected[2][3] = -1.0f;
    expected[3][2] = -3.0f; // 2 far near / (near - far)
    expectMatrixNear(camera->projectionMatrix(2.0f), expected);
    expectMatrixNear(camera->projectionMatrix(2.0f, {1.0f, 3.0f}), expected);
}

TEST(PerspectiveCamera, nearAndFarPlanesMapToTheDepthRangeEnds) {
    const auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.0f);
    const glm::mat4 clip = camera->projectionMatrix(1.0f) * camera->viewMatrix();
    EXPECT_NEAR(toNdc(clip, {0, 0, -1}).z, -1.0f, kTolerance);
    EXPECT_NEAR(toNdc(clip, {0, 0, -10}).z, 1.0f, kTolerance);
}

TEST(PerspectiveCamera, viewAllMovesBackToSeeTheBoundingSphere) {
    const auto camera = PerspectiveCamera::create();
    const sg::Box3 box(glm::vec3(-1.0f), glm::vec3(1.0f));
    camera->viewAll(box, 1.0f);
    const float radius = std::sqrt(3.0f);
    const float distance = radius / std::sin(0.5f * 0.785398f);
    EXPECT_NEAR(camera->position.value().z, distance, 1e-4f);
    EXPECT_NEAR(camera->position.value().x, 0.0f, kTolerance);
    EXPECT_NEAR(camera->nearDistance.value(), distance - radius, 1e-4f);
    EXPECT_NEAR(camera->farDistance.value(), distance + radius, 1e-4f);
    EXPECT_NEAR(camera->focalDistance.value(), distance, 1e-4f);
    EXPECT_EQ(camera->orientation.value(), sg::Rotation());

    // The sphere touches the top of the view: its tangent point from the eye is at NDC y = 1.
    const glm::mat4 clip = camera->projectionMatrix(1.0f) * camera->viewMatrix();
    const float tangentAngle = std::asin(radius / distance);
    const float tangentLength = distance * std::cos(tangentAngle);
    const glm::vec3 tangent =
        camera->position.value() +
        tangentLength * glm::vec3(0.0f, std::sin(tangentAngle), -std::cos(tangentAngle));
    EXPECT_NEAR(toNdc(clip, tangent).y, 1.0f, 1e-4f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 point(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
        const glm::vec3 ndc = toNdc(clip, point);
        EXPECT_LE(std::abs(ndc.x), 1.0f);
        EXPECT_LE(std::abs(ndc.y), 1.0f);
        EXPECT_LE(std::abs(ndc.z), 1.0f);
    }
}

TEST(PerspectiveCamera, viewAllKeepsOrientationAndFitsANarrowViewport) {
    const auto camera = PerspectiveCamera::create();
    camera->orientation = sg::Rotation(glm::vec3(1.0f, 1.0f, 0.0f), 0.7f);
    const sg::Box3 box(glm::vec3(10.0f, 0.0f, 0.0f), glm::vec3(14.0f, 2.0f, 1.0f));
    const float aspect = 0.5f;
    camera->viewAll(box, aspect);
    EXPECT_EQ(camera->orientation.value(), sg::Rotation(glm::vec3(1.0f, 1.0f, 0.0f), 0.7f));
    const glm::mat4 clip = camera->projectionMatrix(aspect) * camera->viewMatrix();
    const glm::vec3 centre = toNdc(clip, box.center());
    EXPECT_NEAR(centre.x, 0.0f, 1e-4f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-4f);
    // The horizontal half-angle is the narrower one: the distance follows from it.
    const float radius = 0.5f * glm::length(box.size());
    const float halfWidthAngle = std::atan(std::tan(0.5f * 0.785398f) * aspect);
    EXPECT_NEAR(glm::length(camera->position.value() - box.center()),
                radius / std::sin(halfWidthAngle), 1e-3f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 point(corner & 1 ? box.max().x : box.min().x,
                              corner & 2 ? box.max().y : box.min().y,
                              corner & 4 ? box.max().z : box.min().z);
        const glm::vec3 ndc = toNdc(clip, point);
        EXPECT_LE(std::abs(ndc.x), 1.0f);
        EXPECT_LE(std::abs(ndc.y), 1.0f);
        EXPECT_LE(std::abs(ndc.z), 1.0f);
    }
}

TEST(PerspectiveCamera, depthRangeEnclosesTheBox) {
    const auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.0f, 0.0f, 10.0f);
    const DepthRange range = camera->depthRangeFor(sg::Box3(glm::vec3(-1.0f), glm::vec3(1.0f)));
    // Depths 9 … 11, widened by 1 % of the extent plus a relative 1e-5.
    EXPECT_NEAR(range.nearDistance, 9.0f - 0.02011f, 1e-5f);
    EXPECT_NEAR(range.farDistance, 11.0f + 0.02011f, 1e-5f);
}

TEST(PerspectiveCamera, depthRangeKeepsNearPositiveInsideTheBox) {
    const auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.0f);
    const DepthRange range = camera->depthRangeFor(sg::Box3(glm::vec3(-1.0f), glm::vec3(1.0f)));
    EXPECT_NEAR(range.farDistance, 1.0f + 0.02001f, 1e-5f);
    EXPECT_NEAR(range.nearDistance, range.farDistance / 1000.0f, 1e-7f);
}

TEST(PerspectiveCamera, depthRangeOfABoxBehindTheCameraIsTheFieldsRange) {
    const auto camera = PerspectiveCamera::create();
    camera->position = glm::vec3(0.0f, 0.0f, -10.0f);
    const DepthRange range = camera->depthRangeFor(sg::Box3(glm::vec3(-1.0f), glm::vec3(1.0f)));
    EXPECT_EQ(range.nearDistance, 1.0f);
    EXPECT_EQ(range.farDistance, 10.0f);
}

TEST(PerspectiveCamera, viewAllOfAPointFramesAUnitSphere) {
    const auto camera = PerspectiveCamera::create();
    camera->viewAll(sg::Box3(glm::vec3(2.0f), glm::vec3(2.0f)), 1.0f);
    EXPECT_NEAR(camera->farDistance.value() - camera->nearDistance.value(), 2.0f, 1e-4f);
}

TEST(PerspectiveCamera, reportsBadInput) {
    const auto camera = PerspectiveCamera::create();
    camera->setName("eye");
    EXPECT_EQ(errorOf<DataError>([&] { camera->projectionMatrix(0.0f); }),
              "PerspectiveCamera 'eye': the viewport aspect ratio must be finite and positive, "
              "got 0");
    EXPECT_EQ(errorOf<DataError>([&] { camera->viewAll(sg::Box3(), 1.0f); }),
              "PerspectiveCamera 'eye': viewAll(): the bounding box is empty (there is nothing "
              "to frame)");
    EXPECT_EQ(errorOf<DataError>([&] { camera->depthRangeFor(sg::Box3()); }),
              "PerspectiveCamera 'eye': depthRangeFor(): the bounding box is empty (there is "
              "nothing to frame)");
    EXPECT_EQ(errorOf<DataError>([&] { camera->projectionMatrix(1.0f, {5.0f, 5.0f}); }),
              "PerspectiveCamera 'eye': farDistance must be finite and greater than "
              "nearDistance, got nearDistance 5, farDistance 5");
    EXPECT_EQ(errorOf<DataError>([&] { camera->projectionMatrix(1.0f, {0.0f, 5.0f}); }),
              "PerspectiveCamera 'eye': nearDistance must be positive for a perspective "
              "projection, got 0");
    camera->heightAngle = 3.5f;
    EXPECT_EQ(errorOf<DataError>([&] { camera->projectionMatrix(1.0f); }),
              "PerspectiveCamera 'eye': heightAngle must lie strictly between 0 and pi radians, "
              "got 3.5");
}

TEST(PerspectiveCamera, putsItselfAndItsModelMatrixIntoTheState) {
    const auto root = sg::Separator::create();
    const auto transform = Transform::create();
    transform->translation = glm::vec3(1.0f, 2.0f, 3.0f);
    const auto camera = PerspectiveCamera::create();
    const auto probe = test::StateProbe::create();
    CameraElement seen;
    probe->visit = [&](sg::Action& action) { seen = action.state().get<CameraElement>(); };
    root->addChild(transform);
    root->addChild(camera);
    root->addChild(probe);
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(seen.camera, camera.get());
    EXPECT_EQ(glm::vec3(seen.modelMatrix[3]), glm::vec3(1.0f, 2.0f, 3.0f));
}

} // namespace
} // namespace texsplat::nodes
