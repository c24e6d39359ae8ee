#include "nodes/Transform.h"

#include "SceneNodesTestSupport.h"
#include "nodes/Coordinate3.h"
#include "nodes/IndexedFaceSet.h"
#include "scenegraph/Group.h"
#include "scenegraph/Rotation.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

namespace texsplat::nodes {
namespace {

constexpr float kTolerance = 1e-5f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected) {
    EXPECT_NEAR(actual.x, expected.x, kTolerance);
    EXPECT_NEAR(actual.y, expected.y, kTolerance);
    EXPECT_NEAR(actual.z, expected.z, kTolerance);
}

glm::vec3 apply(const Transform& transform, const glm::vec3& point) {
    return glm::vec3(transform.matrix() * glm::vec4(point, 1.0f));
}

const sg::Rotation kQuarterTurnZ(glm::vec3(0.0f, 0.0f, 1.0f), glm::half_pi<float>());

TEST(Transform, defaultsToIdentity) {
    EXPECT_EQ(Transform::create()->matrix(), glm::mat4(1.0f));
}

TEST(Transform, rotatesAndScalesAboutTheCenter) {
    const auto transform = Transform::create();
    transform->rotation = kQuarterTurnZ;
    transform->center = glm::vec3(1.0f, 0.0f, 0.0f);
    expectNear(apply(*transform, {2.0f, 0.0f, 0.0f}), {1.0f, 1.0f, 0.0f});
    expectNear(apply(*transform, {1.0f, 0.0f, 0.0f}), {1.0f, 0.0f, 0.0f}); // the fixed point
}

TEST(Transform, scalesAlongTheScaleOrientationAxes) {
    const auto transform = Transform::create();
    transform->scaleFactor = glm::vec3(2.0f, 1.0f, 1.0f);
    transform->scaleOrientation = kQuarterTurnZ; // the scale's x axis is world y
    expectNear(apply(*transform, {0.0f, 1.0f, 0.0f}), {0.0f, 2.0f, 0.0f});
    expectNear(apply(*transform, {1.0f, 0.0f, 0.0f}), {1.0f, 0.0f, 0.0f});
}

TEST(Transform, composesInInventorOrder) {
    // Scale about the center, then rotate about it, then translate (SoTransform::getMatrix).
    const auto transform = Transform::create();
    transform->translation = glm::vec3(1.0f, 2.0f, 3.0f);
    transform->rotation = kQuarterTurnZ;
    transform->scaleFactor = glm::vec3(2.0f);
    transform->center = glm::vec3(1.0f, 0.0f, 0.0f);
    // (2,0,0) - center = (1,0,0); scaled (2,0,0); rotated (0,2,0); + center (1,2,0); + t (2,4,3).
    expectNear(apply(*transform, {2.0f, 0.0f, 0.0f}), {2.0f, 4.0f, 3.0f});
}

sg::Node::Ptr unitSquare() {
    const auto group = sg::Group::create();
    const auto coordinates = Coordinate3::create();
    coordinates->point.setValue({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValue({0, 1, 2, 3, -1});
    group->addChild(coordinates);
    group->addChild(faces);
    return group;
}

TEST(Transform, transformsTheBoundingBoxOfWhatFollows) {
    const auto root = sg::Separator::create();
    const auto transform = Transform::create();
    transform->translation = glm::vec3(10.0f, 0.0f, 0.0f);
    transform->scaleFactor = glm::vec3(2.0f, 3.0f, 1.0f);
    root->addChild(transform);
    root->addChild(unitSquare());
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(),
              sg::Box3(glm::vec3(10.0f, 0.0f, 0.0f), glm::vec3(12.0f, 3.0f, 0.0f)));
}

TEST(Transform, staysInsideItsSeparatorAndAccumulates) {
    const auto root = sg::Separator::create();
    const auto inner = sg::Separator::create();
    const auto first = Transform::create();
    first->translation = glm::vec3(5.0f, 0.0f, 0.0f);
    const auto second = Transform::create();
    second->translation = glm::vec3(0.0f, 5.0f, 0.0f);
    inner->addChild(first);
    inner->addChild(second);
    inner->addChild(unitSquare()); // moved by both: (5,5) … (6,6)
    root->addChild(inner);
    root->addChild(unitSquare()); // not moved
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(), sg::Box3(glm::vec3(0.0f), glm::vec3(6.0f, 6.0f, 0.0f)));
}

} // namespace
} // namespace texsplat::nodes
