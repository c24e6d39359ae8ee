#include "nodes/volume/ArrayGrid.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/ExternalGrid.h"
#include "nodes/volume/NpyHeader.h"
#include "nodes/volume/detail/RawData.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"

#include <cstddef>
#include <utility>

namespace texsplat::volume {
namespace {

constexpr bool kHostIsLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

// Whether the array's values lie one after the other in C order.
bool isCContiguous(const ArrayLayout& array, std::int64_t itemBytes) {
    std::int64_t expected = itemBytes;
    for (std::size_t axis = array.shape.size(); axis-- > 0;) {
        if (array.shape[axis] != 1 && array.strides[axis] != expected) {
            return false;
        }
        expected *= array.shape[axis];
    }
    return true;
}

// Writes the array's values to `out` as floats, x fastest (components interleaved), each row of
// x decoded in one go where its values are adjacent.
void convertValues(const ArrayLayout& array, const RawHeader& type, const glm::i64vec3& dims,
                   int components, float* out) {
    const std::int64_t itemBytes = type.bytesPerValue();
    const bool swapBytes = (type.endian == RawEndian::Little) != kHostIsLittleEndian;
    const std::int64_t rowValues = dims.x * components;
    const std::int64_t xStride = array.strides[2];
    const std::int64_t componentStride = components == 3 ? array.strides[3] : itemBytes;
    const bool rowIsAdjacent =
        componentStride == itemBytes && (dims.x == 1 || xStride == itemBytes * components);
    const auto* base = static_cast<const unsigned char*>(array.data);
    for (std::int64_t z = 0; z < dims.z; ++z) {
        for (std::int64_t y = 0; y < dims.y; ++y, out += rowValues) {
            const unsigned char* row = base + z * array.strides[0] + y * array.strides[1];
            if (rowIsAdjacent) {
                detail::decodeValues(type.type, row, static_cast<std::size_t>(rowValues),
                                     swapBytes, out);
                continue;
            }
            for (std::int64_t x = 0; x < dims.x; ++x) {
                for (int c = 0; c < components; ++c) {
                    detail::decodeValues(type.type, row + x * xStride + c * componentStride, 1,
                                         swapBytes, out + x * components + c);
                }
            }
        }
    }
}

} // namespace

RawHeader arrayValueType(const std::string& descr, const std::string& source) {
    RawHeader type;
    parseNpyDescr(descr, source, type);
    return type;
}

AnyGrid gridFromArray(const ArrayLayout& array, const std::string& source,
                      std::shared_ptr<const void> owner, const glm::dvec3& origin,
                      const glm::dvec3& spacing) {
    const RawHeader type = arrayValueType(array.descr, source);
    const std::size_t axes = array.shape.size();
    const bool vectors = axes == 4 && array.shape[3] == 3;
    const std::string shape = "array of shape " + npyShapeText(array.shape);
    if (axes != 3 && !vectors) {
        throw DataError(source + ": " + shape +
                        " is not supported; expected (z, y, x) or (z, y, x, 3)");
    }
    const glm::i64vec3 dims(array.shape[2], array.shape[1], array.shape[0]);
    const GridGeometry geometry = [&] {
        try {
            return GridGeometry(dims, origin, spacing);
        } catch (const DataError& error) {
            throw DataError(source + ": " + shape + ": " + error.what());
        }
    }();
    if (array.strides.size() != axes || array.data == nullptr) {
        throw DataError(source + ": " + shape + " comes without " +
                        (array.data == nullptr ? "values" : "a stride per axis"));
    }
    const int components = vectors ? 3 : 1;
    const bool inPlace = type.type == RawValueType::Float32 &&
                         (type.endian == RawEndian::Little) == kHostIsLittleEndian &&
                         isCContiguous(array, type.bytesPerValue());
    const auto count = static_cast<std::size_t>(geometry.voxelCount());
    AnyGrid grid;
    GridStatistics statistics;
    if (inPlace && !vectors) {
        auto external = std::make_shared<const ExternalScalarGrid>(
            geometry, static_cast<const float*>(array.data), count, std::move(owner));
        statistics = external->statistics();
        grid = std::move(external);
    } else if (inPlace) {
        auto external = std::make_shared<const ExternalVectorGrid>(
            geometry, static_cast<const glm::vec3*>(array.data), count, std::move(owner));
        statistics = external->statistics();
        grid = std::move(external);
    } else {
        detail::checkGridFitsInMemory(source, geometry, components);
        if (vectors) {
            auto dense = std::make_shared<DenseVectorGrid>(geometry);
            static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "vectors are three floats");
            convertValues(array, type, dims, components,
                          reinterpret_cast<float*>(dense->values().data()));
            statistics = dense->statistics();
            grid = std::move(dense);
        } else {
            auto dense = std::make_shared<DenseScalarGrid>(geometry);
            convertValues(array, type, dims, components, dense->values().data());
            statistics = dense->statistics();
            grid = std::move(dense);
        }
    }
    detail::checkFiniteVoxels(source, statistics);
    return grid;
}

} // namespace texsplat::volume
