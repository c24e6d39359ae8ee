// The camera of a scene without one (framedScene: 30 degrees, a direction and an up), turning a
// camera into the other kind (ParaView's parallel projection switch), and orientations with an
// up direction.

#include "nodes/render/SceneFraming.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/render/CameraView.h"
#include "scenegraph/Error.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::render {
namespace {

using nodes::test::errorOf;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, const char* what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(actual[c], expected[c], 1e-5f) << what << " component " << c;
    }
}

TEST(SceneFraming, anUpDirectionIsUpInTheImage) {
    const glm::vec3 direction(1.0f, -2.0f, 0.5f);
    const glm::quat turn =
        rotationLookingAlong(direction, glm::vec3(0.0f, 0.0f, 3.0f)).quaternion();
    expectNear(turn * glm::vec3(0.0f, 0.0f, -1.0f), glm::normalize(direction), "view");
    // The image's up is z less its part along the view.
    const glm::vec3 view = glm::normalize(direction);
    const glm::vec3 up = glm::normalize(glm::vec3(0, 0, 1) - view.z * view);
    expectNear(turn * glm::vec3(0.0f, 1.0f, 0.0f), up, "up");
    // Along -z with +y up: no turn at all.
    expectNear(rotationLookingAlong({0, 0, -1}, {0, 1, 0}).quaternion() * glm::vec3(1, 0, 0),
               {1, 0, 0}, "identity");
    EXPECT_EQ(errorOf<DataError>([] { rotationLookingAlong({0, 0, -1}, {0, 0, 2}); }),
              "the up direction is parallel to the viewing direction: no up can be seen; give "
              "one across the view");
    EXPECT_EQ(errorOf<DataError>([] { rotationLookingAlong({0, 0, -1}, {0, 0, 0}); }),
              "the viewing direction and the up direction must be finite and not zero");
}

sg::Node::Ptr boxScene() {
    nodes::registerNodeTypes();
    return sg::SceneReader::readString("#Inventor V2.1 ascii\nSeparator {\n"
                                       "TransferFunction { }\n"
                                       "VolumeData { source BLOB resolution 8 8 8 }\n"
                                       "TextureSplat { }\n}\n",
                                       "box.iv");
}

TEST(SceneFraming, aSceneWithoutCameraIsFramedAtThirtyDegreesFromFurtherAway) {
    Framing framing;
    framing.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    framing.up = glm::vec3(0.0f, 0.0f, 1.0f);
    const sg::Node::Ptr scene = boxScene();
    sg::BoundingBoxAction box;
    box.apply(*scene);
    const sg::Node::Ptr root = framedScene(scene, 1.0f, framing);
    auto* camera = dynamic_cast<nodes::PerspectiveCamera*>(findCamera(*root));
    ASSERT_NE(camera, nullptr);
    EXPECT_FLOAT_EQ(camera->heightAngle.value(), glm::radians(30.0f));
    expectNear(camera->viewDirection(), {0, -1, 0}, "view");
    expectNear(camera->orientation.value().quaternion() * glm::vec3(0, 1, 0), {0, 0, 1}, "up");
    // The bounding sphere fits: the camera stands r / sin(15°), 3.9 radii, from its centre.
    const glm::vec3 centre = box.boundingBox().center();
    const float radius = 0.5f * glm::length(box.boundingBox().size());
    EXPECT_NEAR(camera->focalDistance.value(), radius / std::sin(glm::radians(15.0f)), 1e-3f);
    EXPECT_NEAR(glm::length(camera->position.value() - centre), camera->focalDistance.value(),
                1e-3f);
}

TEST(SceneFraming, aCameraTurnsIntoTheOtherKindSeeingTheSameAtItsFocalDistance) {
    auto perspective = nodes::PerspectiveCamera::create();
    perspective->position.setValue(glm::vec3(1.0f, 2.0f, 3.0f));
    perspective->orientation.setValue(sg::Rotation(glm::vec3(0, 1, 0), 0.3f));
    perspective->focalDistance.setValue(4.0f);
    perspective->nearDistance.setValue(0.5f);
    perspective->farDistance.setValue(9.0f);
    perspective->heightAngle.setValue(0.4f);
    const nodes::Camera::Ptr parallel = cameraOfKind(*perspective, FramingCamera::Orthographic);
    auto* orthographic = dynamic_cast<nodes::OrthographicCamera*>(parallel.get());
    ASSERT_NE(orthographic, nullptr);
    EXPECT_FLOAT_EQ(orthographic->height.value(), 2.0f * 4.0f * std::tan(0.2f));
    EXPECT_EQ(orthographic->position.value(), perspective->position.value());
    EXPECT_EQ(orthographic->orientation.value(), perspective->orientation.value());
    EXPECT_EQ(orthographic->nearDistance.value(), 0.5f);
    EXPECT_EQ(orthographic->farDistance.value(), 9.0f);
    EXPECT_EQ(orthographic->focalDistance.value(), 4.0f);
    const nodes::Camera::Ptr back = cameraOfKind(*orthographic, FramingCamera::Perspective);
    auto* again = dynamic_cast<nodes::PerspectiveCamera*>(back.get());
    ASSERT_NE(again, nullptr);
    EXPECT_NEAR(again->heightAngle.value(), 0.4f, 1e-6f);
    EXPECT_NE(cameraOfKind(*perspective, FramingCamera::Perspective).get(), perspective.get());
}

TEST(SceneFraming, aReplacedCameraIsReplacedWhereverTheSceneHoldsIt) {
    auto camera = nodes::PerspectiveCamera::create();
    const auto inner = sg::Separator::create();
    inner->addChild(camera);
    const auto root = sg::Separator::create();
    root->addChild(camera);
    root->addChild(inner);
    const nodes::Camera::Ptr replacement = cameraOfKind(*camera, FramingCamera::Orthographic);
    EXPECT_EQ(replaceCamera(*root, *camera, replacement), 2);
    EXPECT_EQ(root->child(0), replacement);
    EXPECT_EQ(inner->child(0), replacement);
}

} // namespace
} // namespace texsplat::render
