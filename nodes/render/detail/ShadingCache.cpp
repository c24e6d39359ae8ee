#include "nodes/render/detail/ShadingCache.h"

#include "nodes/render/ShadedGrid.h"

namespace texsplat::render::detail {

std::shared_ptr<const octree::ClassifiedGrid>
ShadingCache::shaded(const std::shared_ptr<const octree::ClassifiedGrid>& classified,
                     const glm::mat4& model, const VolumeLighting& lighting) {
    if (classified != mClassified || model != mModel || !mGradients) {
        clear();
        mGradients = std::make_shared<const VoxelGradients>(classified, model);
        mClassified = classified;
        mModel = model;
        ++mBuilds.gradients;
    }
    if (!mShaded || !lighting.shadesAlike(mLighting)) {
        mOctree.reset();
        mShaded = shadedGrid(*mGradients, lighting);
        mLighting = lighting;
        ++mBuilds.shadings;
    }
    return mShaded;
}

const octree::Octree& ShadingCache::octree(const sg::WorkProgress& progress) {
    if (!mOctree) {
        mOctree = std::make_unique<octree::Octree>(mShaded, progress);
        ++mBuilds.octrees;
    }
    return *mOctree;
}

void ShadingCache::clear() {
    mOctree.reset();
    mShaded.reset();
    mGradients.reset();
    mClassified.reset();
}

} // namespace texsplat::render::detail
