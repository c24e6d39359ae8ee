#include "nodes/render/Frame.h"

#include "octree/Splat.h"
#include "octree/VoxelSplats.h"

#include <glm/geometric.hpp>

namespace texsplat::render {

const std::shared_ptr<const octree::SplatList>& FrameSplats::list() const {
    return splats ? splats : voxels->list();
}

std::size_t FrameSplats::splatCount() const {
    return splats ? splats->size() : static_cast<std::size_t>(voxels->count());
}

std::vector<float> FrameSplats::cameraDepths() const {
    const octree::SplatList& all = *list();
    std::vector<float> depths;
    depths.reserve(all.size());
    for (const octree::Splat& splat : all.splats()) {
        const glm::vec3 camera(localToCamera * glm::vec4(splat.position, 1.0f));
        depths.push_back(view.isPerspective ? glm::length(camera) : -camera.z);
    }
    return depths;
}

} // namespace texsplat::render
