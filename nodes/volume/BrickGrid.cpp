#include "nodes/volume/BrickGrid.h"

#include "nodes/volume/detail/ShiftedBlocks.h"
#include "scenegraph/Error.h"

#include <utility>

namespace texsplat::volume {

template <typename T>
BrickGrid<T>::BrickGrid(std::shared_ptr<const Grid<T>> voxels, const IndexBox& box,
                        std::shared_ptr<const WholeGrid> whole)
    : Grid<T>(box.isEmpty() ? GridGeometry(glm::i64vec3(1)) : boxGeometry(voxels->geometry(), box),
              voxels->background()),
      mVoxels(std::move(voxels)), mBox(box), mWhole(std::move(whole)) {
    if (box.isEmpty() || box.intersection(IndexBox::of(mVoxels->geometry())) != box) {
        throw DataError("brick " + box.text() + ": expected a non-empty box inside the grid's " +
                        IndexBox::of(mVoxels->geometry()).text());
    }
}

template <typename T>
void BrickGrid<T>::forEachStored(const typename Grid<T>::VoxelVisitor& visit) const {
    if (isWholeOfVoxels()) {
        mVoxels->forEachStored(visit);
        return;
    }
    mVoxels->forEachStored([&](const glm::i64vec3& index, const T& value) {
        if (mBox.contains(index)) {
            visit(index - mBox.lo, value);
        }
    });
}

template <typename T> std::uint64_t BrickGrid<T>::storedVoxelCount() const {
    return isWholeOfVoxels() ? mVoxels->storedVoxelCount()
                             : static_cast<std::uint64_t>(mBox.voxelCount());
}

template <typename T> std::vector<glm::i64vec3> BrickGrid<T>::occupiedBlocks() const {
    return isWholeOfVoxels() ? mVoxels->occupiedBlocks() : Grid<T>::occupiedBlocks();
}

template <typename T>
void BrickGrid<T>::readBlock(const glm::i64vec3& block, typename Grid<T>::VoxelBlock& out) const {
    if (isWholeOfVoxels()) {
        mVoxels->readBlock(block, out);
        return;
    }
    // A box that starts off the other grid's blocks (a block less its ghost cells).
    detail::readShiftedBlock(*mVoxels, mBox.lo, IndexBox::of(this->geometry()), block, out);
}

template <typename T> GridStatistics BrickGrid<T>::statistics() const {
    return isWholeOfVoxels() ? mVoxels->statistics() : Grid<T>::statistics();
}

template class BrickGrid<float>;
template class BrickGrid<glm::vec3>;

} // namespace texsplat::volume
