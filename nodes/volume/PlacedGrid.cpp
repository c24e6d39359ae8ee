#include "nodes/volume/PlacedGrid.h"

#include "scenegraph/Error.h"

#include <string>
#include <utility>

namespace texsplat::volume {

template <typename T>
PlacedGrid<T>::PlacedGrid(std::shared_ptr<const Grid<T>> placed, const GridGeometry& geometry)
    : Grid<T>(geometry, placed->background()), mPlaced(std::move(placed)) {
    const glm::i64vec3& dims = mPlaced->geometry().dims();
    if (geometry.dims() != dims)
        throw DataError("a placed grid must have the dimensions of the grid it places, " +
                        std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " +
                        std::to_string(dims.z));
}

template class PlacedGrid<float>;
template class PlacedGrid<glm::vec3>;

} // namespace texsplat::volume
