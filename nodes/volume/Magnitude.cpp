#include "nodes/volume/Magnitude.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/SparseGrid.h"

#include <algorithm>
#include <limits>

namespace texsplat::volume {
namespace {

float magnitudeOf(const glm::vec3& v) {
    if (!isFiniteValue(v))
        return std::numeric_limits<float>::quiet_NaN();
    // In double: the float sum of squares overflows for components above about 1.8e19.
    const double length = glm::length(glm::dvec3(v));
    return static_cast<float>(std::min(length, double(std::numeric_limits<float>::max())));
}

} // namespace

ScalarGridPtr magnitudeGrid(const VectorGrid& vectors) {
    if (const auto* sparse = dynamic_cast<const SparseVectorGrid*>(&vectors)) {
        auto result = std::make_shared<SparseScalarGrid>(
            vectors.geometry(), magnitudeOf(vectors.background()), sparse->blockOffset());
        sparse->forEachStored([&result](const glm::i64vec3& index, const glm::vec3& v) {
            result->setValue(index, magnitudeOf(v));
        });
        return result;
    }
    auto result = std::make_shared<DenseScalarGrid>(vectors.geometry());
    vectors.forEachStored([&result](const glm::i64vec3& index, const glm::vec3& v) {
        result->setValue(index, magnitudeOf(v));
    });
    return result;
}

} // namespace texsplat::volume
