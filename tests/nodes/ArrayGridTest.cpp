// A program's array described as NumPy describes it (a Python program's, docs/python.md): read in
// place when it is C-ordered float32, else converted once; refused as the .npy reader refuses it.
#include "nodes/volume/ArrayGrid.h"

#include "SceneNodesTestSupport.h"
#include "nodes/volume/ExternalGrid.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace texsplat::volume {
namespace {

using nodes::test::errorOf;

// A C-ordered (z, y, x) array of `values` with `itemBytes` per value.
ArrayLayout cOrder(const void* values, const char* descr, std::vector<std::int64_t> shape,
                   std::int64_t itemBytes) {
    ArrayLayout array{values, descr, shape, std::vector<std::int64_t>(shape.size())};
    std::int64_t step = itemBytes;
    for (std::size_t axis = shape.size(); axis-- > 0;) {
        array.strides[axis] = step;
        step *= shape[axis];
    }
    return array;
}

std::vector<float> ramp(std::size_t count) {
    std::vector<float> values(count);
    for (std::size_t i = 0; i < count; ++i)
        values[i] = static_cast<float>(i);
    return values;
}

const ScalarGrid& scalar(const AnyGrid& grid) { return *std::get<ScalarGridPtr>(grid); }

TEST(ArrayGrid, readsACOrderFloat32ArrayInPlace) {
    const std::vector<float> values = ramp(2 * 3 * 4);
    const AnyGrid grid = gridFromArray(cOrder(values.data(), "<f4", {2, 3, 4}, 4), "volume",
                                       nullptr, glm::dvec3(1, 2, 3), glm::dvec3(0.5));
    const auto* external = dynamic_cast<const ExternalScalarGrid*>(&scalar(grid));
    ASSERT_NE(external, nullptr);
    EXPECT_EQ(external->data(), values.data());
    EXPECT_EQ(external->geometry().dims(), glm::i64vec3(4, 3, 2));
    EXPECT_EQ(external->geometry().origin(), glm::dvec3(1, 2, 3));
    EXPECT_EQ(external->geometry().spacing(), glm::dvec3(0.5));
    EXPECT_EQ(external->value({3, 2, 1}), 23.0f);
}

TEST(ArrayGrid, convertsOtherTypesAndLayoutsOnceToTheSameValues) {
    const std::vector<float> values = ramp(2 * 3 * 4);
    std::vector<std::int16_t> shorts(values.begin(), values.end());
    std::vector<double> doubles(values.begin(), values.end());
    // Fortran order: x slowest in memory, z fastest.
    std::vector<float> fortran(values.size());
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 4; ++x)
                fortran[z + 2 * (y + 3 * x)] = values[x + 4 * (y + 3 * z)];
    // Big-endian float32.
    std::vector<std::uint32_t> big(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &values[i], 4);
        big[i] = __builtin_bswap32(bits);
    }
    const ArrayLayout layouts[] = {
        cOrder(shorts.data(), "<i2", {2, 3, 4}, 2),
        cOrder(doubles.data(), "<f8", {2, 3, 4}, 8),
        ArrayLayout{fortran.data(), "<f4", {2, 3, 4}, {4, 8, 24}},
        cOrder(big.data(), ">f4", {2, 3, 4}, 4),
        // The z axis reversed: NumPy's a[::-1], a view with a negative stride.
        ArrayLayout{values.data() + 12, "<f4", {2, 3, 4}, {-48, 16, 4}},
    };
    for (const ArrayLayout& array : layouts) {
        const AnyGrid grid = gridFromArray(array, "volume");
        EXPECT_EQ(dynamic_cast<const ExternalScalarGrid*>(&scalar(grid)), nullptr) << array.descr;
        const bool reversed = array.strides[0] < 0;
        for (int z = 0; z < 2; ++z)
            for (int y = 0; y < 3; ++y)
                for (int x = 0; x < 4; ++x)
                    EXPECT_EQ(scalar(grid).value({x, y, z}),
                              values[x + 4 * (y + 3 * (reversed ? 1 - z : z))])
                        << array.descr << " at " << x << "," << y << "," << z;
    }
}

TEST(ArrayGrid, readsVectorsOfThreeComponents) {
    const std::vector<float> values = ramp(2 * 2 * 2 * 3);
    const AnyGrid inPlace = gridFromArray(cOrder(values.data(), "<f4", {2, 2, 2, 3}, 4), "wind");
    const VectorGrid& vectors = *std::get<VectorGridPtr>(inPlace);
    EXPECT_NE(dynamic_cast<const ExternalVectorGrid*>(&vectors), nullptr);
    EXPECT_EQ(vectors.value({1, 0, 1}), glm::vec3(15, 16, 17));
    std::vector<double> doubles(values.begin(), values.end());
    const AnyGrid converted = gridFromArray(cOrder(doubles.data(), "<f8", {2, 2, 2, 3}, 8), "wind");
    EXPECT_EQ(std::get<VectorGridPtr>(converted)->value({1, 0, 1}), glm::vec3(15, 16, 17));
}

TEST(ArrayGrid, refusesWhatTheNpyReaderRefusesWithItsMessages) {
    const std::vector<float> values(64, 1.0f);
    EXPECT_EQ(errorOf<DataError>([&] {
                  gridFromArray(cOrder(values.data(), "<f4", {4, 16}, 4), "volume");
              }),
              "volume: array of shape (4, 16) is not supported; expected (z, y, x) or "
              "(z, y, x, 3)");
    EXPECT_EQ(errorOf<DataError>([&] {
                  gridFromArray(cOrder(values.data(), "<f4", {2, 2, 4, 4}, 4), "volume");
              }),
              "volume: array of shape (2, 2, 4, 4) is not supported; expected (z, y, x) or "
              "(z, y, x, 3)");
    EXPECT_EQ(errorOf<DataError>([&] { arrayValueType("<c8", "volume"); }),
              "volume: data type '<c8' is not supported; expected <f4, <f8, |u1, |i1, <u2, <i2, "
              "<u4 or <i4 (or > for big endian)");
    EXPECT_EQ(errorOf<DataError>([&] {
                  gridFromArray(cOrder(values.data(), "<f4", {0, 4, 4}, 4), "volume");
              }),
              "volume: array of shape (0, 4, 4): grid dimensions must be at least 1 voxel each, "
              "got 4 x 4 x 0");
    const std::vector<float> nan(8, std::numeric_limits<float>::quiet_NaN());
    EXPECT_EQ(errorOf<DataError>([&] {
                  gridFromArray(cOrder(nan.data(), "<f4", {2, 2, 2}, 4), "volume");
              }).rfind("volume: all 8 voxels are NaN or infinite", 0),
              0u);
}

} // namespace
} // namespace texsplat::volume
