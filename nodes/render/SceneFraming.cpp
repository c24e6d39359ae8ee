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

#include <algorithm>
#include <cmath>

namespace texsplat::render {

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

} // namespace texsplat::render
