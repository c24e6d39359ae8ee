#pragma once

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/IndexBox.h"
#include "scenegraph/Error.h"

#include <memory>
#include <optional>
#include <string>

namespace texsplat::volume::detail {

/// @brief A dense grid whose voxel values are `field(world position of the voxel center)`: the
/// voxels of `geometry`, or with `region` (not empty, inside the grid) only those of that box,
/// placed where they lie in it (a brick of a distributed render).
/// @throws DataError when `region` is empty or reaches outside the grid.
template <typename T, typename Field>
std::shared_ptr<DenseGrid<T>> sampleGrid(const GridGeometry& geometry, const Field& field,
                                         const std::optional<IndexBox>& region = std::nullopt) {
    const IndexBox box = region.value_or(IndexBox::of(geometry));
    if (box.isEmpty() || box.intersection(IndexBox::of(geometry)) != box)
        throw DataError("region " + box.text() + " is not a box of voxels of the grid's " +
                        IndexBox::of(geometry).text());
    auto grid = std::make_shared<DenseGrid<T>>(boxGeometry(geometry, box));
    T* out = grid->values().data();
    for (std::int64_t k = box.lo.z; k < box.hi.z; ++k)
        for (std::int64_t j = box.lo.y; j < box.hi.y; ++j)
            for (std::int64_t i = box.lo.x; i < box.hi.x; ++i)
                *out++ = T(field(geometry.indexToWorld(glm::dvec3(i, j, k))));
    return grid;
}

/// @brief Spacing that puts `dims` samples on [low, high] with both ends sampled, as the
/// classic generators do; a one-voxel axis samples `low` only (spacing then is the full extent,
/// so the voxel's cell covers the domain).
inline glm::dvec3 endpointSpacing(const glm::i64vec3& dims, const glm::dvec3& low,
                                  const glm::dvec3& high) {
    glm::dvec3 spacing;
    for (int axis = 0; axis < 3; ++axis)
        spacing[axis] = dims[axis] > 1 ? (high[axis] - low[axis]) / double(dims[axis] - 1)
                                       : high[axis] - low[axis];
    return spacing;
}

/// @brief The geometry of a generator: `dims` samples over the box [low, high], ends included.
/// @throws DataError "<generator>: grid dimensions must be ..." for unusable dims.
inline GridGeometry generatorGeometry(const std::string& generator, const glm::i64vec3& dims,
                                      const glm::dvec3& low, const glm::dvec3& high) {
    try {
        return GridGeometry(dims, low, endpointSpacing(dims, low, high));
    } catch (const DataError& error) {
        throw DataError(generator + ": " + error.what());
    }
}

} // namespace texsplat::volume::detail
