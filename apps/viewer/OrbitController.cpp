#include "apps/viewer/OrbitController.h"

#include "nodes/Camera.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace texsplat::apps {
namespace {

glm::quat quaternionOf(const nodes::Camera& camera) {
    return camera.orientation.value().quaternion();
}

void setOrientation(nodes::Camera& camera, const glm::quat& q) {
    const glm::quat unit = glm::normalize(q);
    camera.orientation.setValue(sg::Rotation(glm::axis(unit), glm::angle(unit)));
}

} // namespace

OrbitController::OrbitController(nodes::Camera& camera, const sg::Box3& sceneBox)
    : mCamera(camera), mSceneBox(sceneBox), mStart(placement()) {}

OrbitController::Placement OrbitController::placement() const {
    Placement result{mCamera.position.value(),  mCamera.orientation.value(),
                     mCamera.focalDistance.value(), mCamera.nearDistance.value(),
                     mCamera.farDistance.value(), 0.0f};
    if (const auto* orthographic = dynamic_cast<const nodes::OrthographicCamera*>(&mCamera)) {
        result.orthographicHeight = orthographic->height.value();
    }
    return result;
}

void OrbitController::orbit(const glm::vec2& pixels, float viewportHeight) {
    const float radiansPerPixel = glm::pi<float>() / std::max(viewportHeight, 1.0f);
    const glm::quat q = quaternionOf(mCamera);
    const glm::vec3 focus =
        mCamera.position.value() + mCamera.viewDirection() * mCamera.focalDistance.value();
    // Drag right: the scene turns right, i.e. the camera turns left about its own up axis.
    const glm::quat turn = glm::angleAxis(-pixels.x * radiansPerPixel, q * glm::vec3(0, 1, 0)) *
                           glm::angleAxis(-pixels.y * radiansPerPixel, q * glm::vec3(1, 0, 0));
    const glm::quat turned = glm::normalize(turn * q);
    setOrientation(mCamera, turned);
    mCamera.position.setValue(focus - (turned * glm::vec3(0, 0, -1)) *
                                          mCamera.focalDistance.value());
    fitClippingPlanes();
}

void OrbitController::pan(const glm::vec2& pixels, float viewportHeight) {
    // World units per pixel at the focal distance: the view's height there over its pixels.
    float viewHeight = 0.0f;
    if (const auto* orthographic = dynamic_cast<const nodes::OrthographicCamera*>(&mCamera)) {
        viewHeight = orthographic->height.value();
    } else if (const auto* perspective = dynamic_cast<const nodes::PerspectiveCamera*>(&mCamera)) {
        viewHeight = 2.0f * mCamera.focalDistance.value() *
                     std::tan(0.5f * perspective->heightAngle.value());
    }
    const float unitsPerPixel = viewHeight / std::max(viewportHeight, 1.0f);
    const glm::quat q = quaternionOf(mCamera);
    const glm::vec3 shift = (q * glm::vec3(1, 0, 0)) * (-pixels.x * unitsPerPixel) +
                            (q * glm::vec3(0, 1, 0)) * (pixels.y * unitsPerPixel);
    mCamera.position.setValue(mCamera.position.value() + shift);
    fitClippingPlanes();
}

void OrbitController::zoom(float steps) {
    const float factor = std::pow(0.9f, steps);
    if (auto* orthographic = dynamic_cast<nodes::OrthographicCamera*>(&mCamera)) {
        orthographic->height.setValue(orthographic->height.value() * factor);
        return;
    }
    const float distance = mCamera.focalDistance.value();
    const glm::vec3 focus = mCamera.position.value() + mCamera.viewDirection() * distance;
    // Never onto the focal point itself: the orbit needs a distance to turn about.
    const float closer = std::max(distance * factor, 1e-4f * glm::length(mSceneBox.size()) + 1e-6f);
    mCamera.focalDistance.setValue(closer);
    mCamera.position.setValue(focus - mCamera.viewDirection() * closer);
    fitClippingPlanes();
}

void OrbitController::reset() {
    mCamera.position.setValue(mStart.position);
    mCamera.orientation.setValue(mStart.orientation);
    mCamera.focalDistance.setValue(mStart.focalDistance);
    mCamera.nearDistance.setValue(mStart.nearDistance);
    mCamera.farDistance.setValue(mStart.farDistance);
    if (auto* orthographic = dynamic_cast<nodes::OrthographicCamera*>(&mCamera)) {
        orthographic->height.setValue(mStart.orthographicHeight);
    }
}

void OrbitController::fitClippingPlanes() {
    if (mSceneBox.isEmpty()) {
        return;
    }
    const nodes::DepthRange range = mCamera.depthRangeFor(mSceneBox);
    mCamera.nearDistance.setValue(range.nearDistance);
    mCamera.farDistance.setValue(range.farDistance);
}

} // namespace texsplat::apps
