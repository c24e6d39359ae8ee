#include "nodes/render/SceneFraming.h"

#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/render/CameraView.h"
#include "scenegraph/Coordinates.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/fields/ValueFormat.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace texsplat::render {
namespace {

void checkFinite(float value, const char* name, const char* expected) {
    if (!std::isfinite(value)) {
        throw DataError(std::string(name) + ": expected " + expected + ", got " +
                        sg::formatFloat(value));
    }
}

void checkViewChange(const ViewChange& change) {
    checkFinite(change.azimuth, "azimuth", "degrees");
    checkFinite(change.elevation, "elevation", "degrees");
    if (!(change.zoom > 0.0f) || !std::isfinite(change.zoom)) {
        throw DataError("zoom: expected a magnification > 0, got " + sg::formatFloat(change.zoom));
    }
    if (change.direction) {
        const glm::vec3& direction = *change.direction;
        if (direction == glm::vec3(0.0f) || !std::isfinite(direction.x) ||
            !std::isfinite(direction.y) || !std::isfinite(direction.z)) {
            throw DataError("direction: expected three finite numbers x,y,z not all zero, got " +
                            sg::formatFloat(direction.x) + "," + sg::formatFloat(direction.y) +
                            "," + sg::formatFloat(direction.z));
        }
    }
}

} // namespace

void changeView(nodes::Camera& camera, const ViewChange& change) {
    checkViewChange(change);
    const float distance = camera.focalDistance.value();
    glm::quat orientation = camera.orientation.value().quaternion();
    const glm::vec3 focus =
        camera.position.value() + orientation * glm::vec3(0.0f, 0.0f, -1.0f) * distance;
    if (change.direction) {
        orientation = rotationLookingAlong(*change.direction).quaternion();
    }
    orientation = glm::angleAxis(glm::radians(change.azimuth), orientation * glm::vec3(0, 1, 0)) *
                  orientation;
    orientation =
        glm::angleAxis(glm::radians(change.elevation), orientation * glm::vec3(1, 0, 0)) *
        orientation;
    camera.orientation.setValue(sg::Rotation(glm::axis(orientation), glm::angle(orientation)));
    camera.position.setValue(focus - orientation * glm::vec3(0.0f, 0.0f, -1.0f) * distance);
    if (auto* perspective = dynamic_cast<nodes::PerspectiveCamera*>(&camera)) {
        // tan() below would wrap an angle outside (0, pi) into it (7 became 0.72).
        sg::withNodeLocation(camera, [perspective] { perspective->checkHeightAngle(); });
        const float half = 0.5f * perspective->heightAngle.value();
        perspective->heightAngle.setValue(2.0f * std::atan(std::tan(half) / change.zoom));
    } else if (auto* orthographic = dynamic_cast<nodes::OrthographicCamera*>(&camera)) {
        orthographic->height.setValue(orthographic->height.value() / change.zoom);
    }
}

nodes::Camera* findCamera(sg::Node& scene) {
    sg::SearchAction search;
    search.setType(nodes::Camera::classType());
    search.setInterest(sg::SearchAction::Interest::First);
    search.apply(scene);
    return search.paths().empty()
               ? nullptr
               : static_cast<nodes::Camera*>(search.paths().front().tail().get());
}

sg::Node::Ptr framedScene(const sg::Node::Ptr& scene, float aspect, const Framing& framing) {
    if (findCamera(*scene) != nullptr) {
        return scene;
    }
    if (framing.direction == glm::vec3(0.0f)) {
        throw DataError(framing.name + ": cannot frame it looking along a zero direction");
    }
    nodes::Camera::Ptr camera;
    if (framing.camera == FramingCamera::Perspective) {
        camera = nodes::PerspectiveCamera::create();
    } else {
        camera = nodes::OrthographicCamera::create();
    }
    camera->orientation.setValue(rotationLookingAlong(framing.direction));
    sg::BoundingBoxAction box;
    box.setWorkProgress(framing.progress);
    box.apply(*scene);
    if (box.boundingBox().isEmpty()) {
        throw DataError(framing.name +
                        ": nothing to frame (the scene has no geometry and no camera)");
    }
    const sg::Box3& bounds = box.boundingBox();
    float largest = 0.0f;
    for (int axis = 0; axis < 3; ++axis) {
        largest = std::max({largest, std::abs(bounds.min()[axis]), std::abs(bounds.max()[axis])});
    }
    if (!(largest <= sg::kMaxCoordinate)) {
        throw DataError(framing.name + ": cannot frame the scene: its bounding box reaches " +
                        sg::formatFloat(largest) + ", beyond " +
                        sg::formatFloat(static_cast<float>(sg::kMaxCoordinate)) +
                        ", the largest coordinate texsplat draws in single precision (a "
                        "Transform that scales too much?)");
    }
    camera->viewAll(bounds, aspect);
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(camera);
    root->addChild(scene);
    return root;
}

sg::Node::Ptr viewedScene(const sg::Node::Ptr& scene, float aspect, Framing framing,
                          const ViewChange& change) {
    checkViewChange(change);
    if (nodes::Camera* camera = findCamera(*scene)) {
        changeView(*camera, change);
        return scene;
    }
    if (change.direction) {
        framing.direction = *change.direction;
    }
    sg::Node::Ptr root = framedScene(scene, aspect, framing);
    ViewChange orbit = change;
    orbit.direction.reset();
    changeView(*findCamera(*root), orbit);
    return root;
}

} // namespace texsplat::render
