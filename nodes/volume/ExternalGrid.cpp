#include "nodes/volume/ExternalGrid.h"

#include "scenegraph/Error.h"

#include <cstdint>
#include <string>
#include <utility>

namespace texsplat::volume {

template <typename T>
ExternalGrid<T>::ExternalGrid(const GridGeometry& geometry, const T* values, std::size_t count,
                              std::shared_ptr<const void> owner)
    : Grid<T>(geometry, T(0.0f)), mValues(values), mOwner(std::move(owner)) {
    const auto expected = static_cast<std::uint64_t>(geometry.voxelCount());
    if (static_cast<std::uint64_t>(count) != expected) {
        throw DataError("ExternalGrid: " + std::to_string(count) + " values for a grid of " +
                        std::to_string(geometry.dims().x) + " x " +
                        std::to_string(geometry.dims().y) + " x " +
                        std::to_string(geometry.dims().z) + " = " + std::to_string(expected) +
                        " voxels");
    }
    if (values == nullptr) {
        throw DataError("ExternalGrid: the values are a null pointer");
    }
}

template <typename T>
std::shared_ptr<const ExternalGrid<T>> ExternalGrid<T>::owning(const GridGeometry& geometry,
                                                               std::vector<T> values) {
    auto owner = std::make_shared<const std::vector<T>>(std::move(values));
    return std::make_shared<const ExternalGrid>(geometry, owner->data(), owner->size(), owner);
}

template <typename T>
T ExternalGrid<T>::value(const glm::i64vec3& index) const {
    return voxels().value(index, this->background());
}

template <typename T>
bool ExternalGrid<T>::isActive(const glm::i64vec3& index) const {
    return voxels().isActive(index);
}

template <typename T>
void ExternalGrid<T>::forEachStored(const typename Grid<T>::VoxelVisitor& visit) const {
    voxels().forEachStored(visit);
}

template <typename T> std::size_t ExternalGrid<T>::memoryBytes() const {
    return static_cast<std::size_t>(this->geometry().voxelCount()) * sizeof(T);
}

template class ExternalGrid<float>;
template class ExternalGrid<glm::vec3>;

} // namespace texsplat::volume
