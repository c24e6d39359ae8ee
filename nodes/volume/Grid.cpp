#include "nodes/volume/Grid.h"

#include <algorithm>
#include <limits>

namespace texsplat::volume {
namespace {

double magnitudeOf(float value) { return value; }
double magnitudeOf(const glm::vec3& value) { return glm::length(glm::dvec3(value)); }

} // namespace

template <typename T>
void Grid<T>::forEachActive(const VoxelVisitor& visit) const {
    forEachStored([&visit](const glm::i64vec3& index, const T& value) {
        if (isFiniteValue(value))
            visit(index, value);
    });
}

template <typename T>
GridStatistics Grid<T>::statistics() const {
    GridStatistics result;
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
    forEachStored([&](const glm::i64vec3&, const T& value) {
        if (!isFiniteValue(value)) {
            ++result.nonFiniteCount;
            return;
        }
        ++result.finiteCount;
        const double magnitude = magnitudeOf(value);
        lowest = std::min(lowest, magnitude);
        highest = std::max(highest, magnitude);
    });
    if (result.finiteCount > 0) {
        result.minimum = lowest;
        result.maximum = highest;
    }
    return result;
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
