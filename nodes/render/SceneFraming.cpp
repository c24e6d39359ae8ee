#include "nodes/render/SceneFraming.h"

#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/render/CameraView.h"
#include "scenegraph/Coordinates.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/fields/ValueFormat.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

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
    for (const auto& [vector, name] : {std::pair(&change.direction, "direction"),
                                       std::pair(&change.up, "up")}) {
        if (!*vector) {
            continue;
        }
        const glm::vec3& value = **vector;
        if (value == glm::vec3(0.0f) || !std::isfinite(value.x) || !std::isfinite(value.y) ||
            !std::isfinite(value.z)) {
            throw DataError(std::string(name) + ": expected three finite numbers x,y,z not all "
                                                "zero, got " +
                            sg::formatFloat(value.x) + "," + sg::formatFloat(value.y) + "," +
                            sg::formatFloat(value.z));
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
    if (change.direction || change.up) {
        const glm::vec3 direction =
            change.direction ? *change.direction : orientation * glm::vec3(0.0f, 0.0f, -1.0f);
        try {
            orientation = (change.up ? rotationLookingAlong(direction, *change.up)
                                     : rotationLookingAlong(direction))
                              .quaternion();
        } catch (const DataError& error) {
            throw DataError(std::string("up: ") + error.what());
        }
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
        auto perspective = nodes::PerspectiveCamera::create();
        perspective->heightAngle.setValue(kFramingHeightAngle);
        camera = perspective;
    } else {
        camera = nodes::OrthographicCamera::create();
    }
    try {
        camera->orientation.setValue(framing.up
                                         ? rotationLookingAlong(framing.direction, *framing.up)
                                         : rotationLookingAlong(framing.direction));
    } catch (const DataError& error) {
        throw DataError(framing.name + ": cannot frame it: " + error.what());
    }
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
    if (change.up) {
        framing.up = change.up;
    }
    sg::Node::Ptr root = framedScene(scene, aspect, framing);
    ViewChange orbit = change;
    orbit.direction.reset();
    orbit.up.reset();
    changeView(*findCamera(*root), orbit);
    return root;
}

nodes::Camera::Ptr cameraOfKind(const nodes::Camera& camera, FramingCamera kind) {
    const auto* perspective = dynamic_cast<const nodes::PerspectiveCamera*>(&camera);
    const auto* orthographic = dynamic_cast<const nodes::OrthographicCamera*>(&camera);
    const float distance = camera.focalDistance.value();
    nodes::Camera::Ptr result;
    if (kind == FramingCamera::Perspective) {
        auto made = nodes::PerspectiveCamera::create();
        if (perspective) {
            made->heightAngle.setValue(perspective->heightAngle.value());
        } else if (orthographic && distance > 0.0f) {
            made->heightAngle.setValue(
                2.0f * std::atan(0.5f * orthographic->height.value() / distance));
        }
        result = made;
    } else {
        auto made = nodes::OrthographicCamera::create();
        if (orthographic) {
            made->height.setValue(orthographic->height.value());
        } else if (perspective) {
            made->height.setValue(2.0f * distance *
                                  std::tan(0.5f * perspective->heightAngle.value()));
        }
        result = made;
    }
    result->viewportMapping.setValue(camera.viewportMapping.value());
    result->position.setValue(camera.position.value());
    result->orientation.setValue(camera.orientation.value());
    result->nearDistance.setValue(camera.nearDistance.value());
    result->farDistance.setValue(camera.farDistance.value());
    result->aspectRatio.setValue(camera.aspectRatio.value());
    result->focalDistance.setValue(distance);
    return result;
}

int replaceCamera(sg::Node& scene, const nodes::Camera& camera,
                  const nodes::Camera::Ptr& replacement) {
    sg::SearchAction search;
    search.setType(nodes::Camera::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.setSearchingAll(true);
    search.apply(scene);
    int replaced = 0;
    for (const sg::Path& path : search.paths()) {
        if (path.tail().get() != &camera || path.length() < 2) {
            continue; // another camera, or the scene is the camera itself: nothing holds it
        }
        auto& parent = static_cast<sg::Group&>(*path.node(path.length() - 2));
        if (const auto index = parent.findChild(camera)) {
            parent.replaceChild(*index, replacement);
            ++replaced;
        }
    }
    return replaced;
}

} // namespace texsplat::render
