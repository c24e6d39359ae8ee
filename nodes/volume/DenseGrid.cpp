#include "nodes/volume/DenseGrid.h"

#include "scenegraph/Error.h"

#include <limits>
#include <new>
#include <string>
#include <utility>

namespace texsplat::volume {
namespace {

// A grid too large for memory is bad data (a header asking for 10^12 voxels), not a crash.
template <typename T>
std::vector<T> allocateVoxels(const GridGeometry& geometry, const T& fill) {
    const auto count = static_cast<std::uint64_t>(geometry.voxelCount());
    const std::string what = "a dense grid of " + std::to_string(count) + " voxels (" +
                             std::to_string(sizeof(T)) + " bytes each)";
    if (count > std::numeric_limits<std::size_t>::max() / sizeof(T))
        throw DataError(what + " does not fit in this platform's address space");
    try {
        return std::vector<T>(static_cast<std::size_t>(count), fill);
    } catch (const std::bad_alloc&) {
        throw DataError(what + " does not fit in memory");
    }
}

} // namespace

template <typename T>
DenseGrid<T>::DenseGrid(const GridGeometry& geometry, const T& fill)
    : Grid<T>(geometry, T(0.0f)), mValues(allocateVoxels(geometry, fill)) {}

template <typename T>
DenseGrid<T>::DenseGrid(const GridGeometry& geometry, std::vector<T> values)
    : Grid<T>(geometry, T(0.0f)), mValues(std::move(values)) {
    TEXSPLAT_ASSERT(mValues.size() == static_cast<std::size_t>(geometry.voxelCount()),
                    "DenseGrid: one value per voxel");
}

template <typename T>
T DenseGrid<T>::value(const glm::i64vec3& index) const {
    return voxels().value(index, this->background());
}

template <typename T>
bool DenseGrid<T>::isActive(const glm::i64vec3& index) const {
    return voxels().isActive(index);
}

template <typename T>
void DenseGrid<T>::forEachStored(const typename Grid<T>::VoxelVisitor& visit) const {
    voxels().forEachStored(visit);
}

template class DenseGrid<float>;
template class DenseGrid<glm::vec3>;

} // namespace texsplat::volume
