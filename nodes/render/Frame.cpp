#include "nodes/render/Frame.h"

#include "octree/Splat.h"

#include <glm/geometric.hpp>

namespace texsplat::render {

std::vector<float> FrameSplats::cameraDepths() const {
    std::vector<float> depths;
    depths.reserve(splats->size());
    for (const octree::Splat& splat : splats->splats()) {
        const glm::vec3 camera(localToCamera * glm::vec4(splat.position, 1.0f));
        depths.push_back(view.isPerspective ? glm::length(camera) : -camera.z);
    }
    return depths;
}

} // namespace texsplat::render
