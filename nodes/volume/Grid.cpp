#include "nodes/volume/Grid.h"

#include "nodes/volume/detail/StatisticsAccumulator.h"

namespace texsplat::volume {

template <typename T>
void Grid<T>::forEachActive(const VoxelVisitor& visit) const {
    forEachStored([&visit](const glm::i64vec3& index, const T& value) {
        if (isFiniteValue(value))
            visit(index, value);
    });
}

template <typename T>
GridStatistics Grid<T>::statistics() const {
    detail::StatisticsAccumulator<T> statistics;
    forEachStored([&](const glm::i64vec3&, const T& value) { statistics.add(value); });
    return statistics.result();
}

template <typename T>
std::vector<glm::i64vec3> Grid<T>::occupiedBlocks() const {
    const glm::i64vec3 blocks = (mGeometry.dims() + (kBlockEdge - 1)) / kBlockEdge;
    std::vector<glm::i64vec3> result;
    result.reserve(static_cast<std::size_t>(blocks.x * blocks.y * blocks.z));
    glm::i64vec3 block;
    for (block.z = 0; block.z < blocks.z; ++block.z)
        for (block.y = 0; block.y < blocks.y; ++block.y)
            for (block.x = 0; block.x < blocks.x; ++block.x)
                result.push_back(block);
    return result;
}

template class Grid<float>;
template class Grid<glm::vec3>;

} // namespace texsplat::volume
