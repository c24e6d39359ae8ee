#include "octree/VoxelSplats.h"

#include "scenegraph/MemoryLimit.h"

#include <string>
#include <utility>

namespace texsplat::octree {

VoxelSplats::VoxelSplats(std::shared_ptr<const ClassifiedGrid> grid, const View& view,
                         std::shared_ptr<SplatList> list)
    : mGrid(std::move(grid)), mView(view), mOrder(*mGrid, view), mDrawn(*mGrid, view),
      mStorage(std::move(list)) {
    constexpr std::uint64_t kSize = ClassifiedGrid::kBlockSize;
    const ClassifiedGrid& voxels = *mGrid;
    voxels.forEachBlock([&](glm::u64vec3 block, ClassifiedGrid::StorageIndex first) {
        if (!mOrder.isInSight(first)) {
            return;
        }
        const glm::u64vec3 begin = block * kSize;
        const glm::u64vec3 end = glm::min(begin + kSize, voxels.dims());
        if (!mDrawn.cullsBehindEye() ||
            mView.isBoxInFrontOfEye(voxels.toWorld(glm::dvec3(begin)),
                                    voxels.toWorld(glm::dvec3(end) - 1.0))) {
            mCount += voxels.storedBlockCount(first);
            return;
        }
        glm::u64vec3 voxel;
        for (voxel.z = begin.z; voxel.z < end.z; ++voxel.z) {
            for (voxel.y = begin.y; voxel.y < end.y; ++voxel.y) {
                for (voxel.x = begin.x; voxel.x < end.x; ++voxel.x) {
                    mCount +=
                        mDrawn.isDrawn(voxel, first + ClassifiedGrid::offsetInBlock(voxel)) ? 1 : 0;
                }
            }
        }
    });
}

const std::shared_ptr<const SplatList>& VoxelSplats::list() const {
    std::call_once(mListed, [&] {
        // A splat node's frame estimate left the list out (the CPU backend walks the voxels):
        // asked here, where a backend or a merge of batches needs it.
        checkMemory("listing the " + std::to_string(mCount) +
                            " splats of a full-resolution frame",
                        byteProduct(mCount, sizeof(Splat)),
                        "draw with --backend cpu, which walks the voxels without a list, give a "
                        "splat budget (maxSplats, or --max-splats), or a larger --memory-limit");
        if (!mStorage) {
            mStorage = std::make_shared<SplatList>();
        }
        emitVoxelSplats(mOrder, mDrawn, 0, mOrder.sliceCount(), *mStorage);
        mList = mStorage;
    });
    return mList;
}

std::uint64_t VoxelSplats::memoryBytes() const {
    return mStorage ? mStorage->memoryBytes() : 0;
}

} // namespace texsplat::octree
