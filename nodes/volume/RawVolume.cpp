#include "nodes/volume/RawVolume.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawHeader.h"
#include "nodes/volume/detail/RawData.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <vector>

namespace texsplat::volume {
namespace {

constexpr bool kHostIsLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
constexpr std::int64_t kChunkBytes = std::int64_t{1} << 22;

std::string sizeDescription(const RawHeader& header, const std::string& subject) {
    return subject + " " + std::to_string(header.dims.x) + " x " +
           std::to_string(header.dims.y) + " x " + std::to_string(header.dims.z) + " voxels x " +
           std::to_string(header.components) +
           (header.components == 1 ? " component x " : " components x ") +
           std::to_string(header.bytesPerValue()) + " bytes (" + toString(header.type) +
           ") = " + std::to_string(header.dataBytes()) + " bytes";
}

template <typename T>
void writeGrid(const std::string& path, const Grid<T>& grid, int components) {
    const GridGeometry& geometry = grid.geometry();
    RawHeader header;
    header.dims = geometry.dims();
    header.components = components;
    header.spacing = geometry.spacing();
    header.origin = geometry.origin();
    const std::string temporary = path + ".partial";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            throw IoError(path + ": cannot write file (" + std::strerror(errno) + ")");
        out << header.format();
        std::vector<float> row(static_cast<std::size_t>(geometry.dims().x * components));
        glm::i64vec3 index;
        for (index.z = 0; index.z < geometry.dims().z; ++index.z)
            for (index.y = 0; index.y < geometry.dims().y; ++index.y) {
                for (index.x = 0; index.x < geometry.dims().x; ++index.x) {
                    const T value = grid.value(index);
                    std::memcpy(&row[static_cast<std::size_t>(index.x * components)], &value,
                                sizeof(float) * components);
                }
                if constexpr (!kHostIsLittleEndian)
                    for (float& value : row)
                        std::reverse(reinterpret_cast<char*>(&value),
                                     reinterpret_cast<char*>(&value) + sizeof(float));
                out.write(reinterpret_cast<const char*>(row.data()),
                          static_cast<std::streamsize>(row.size() * sizeof(float)));
            }
        if (!out.flush()) {
            std::filesystem::remove(temporary);
            throw IoError(path + ": cannot write file (write failed)");
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary);
        throw IoError(path + ": cannot write file (" + error.message() + ")");
    }
}

} // namespace

namespace detail {

void readRawValues(const RawDataView& data, const ProgressCallback& progress,
                   const RawValueChunk& chunk) {
    const RawHeader& header = data.layout;
    const std::int64_t valueBytes = header.bytesPerValue();
    const std::int64_t totalValues = header.dataBytes() / valueBytes;
    // Whole voxels per chunk, so a vector never straddles two chunks.
    const std::int64_t voxelBytes = valueBytes * header.components;
    const std::int64_t chunkValues = std::max<std::int64_t>(1, kChunkBytes / voxelBytes) *
                                     header.components;
    const bool swapBytes = (header.endian == RawEndian::Little) != kHostIsLittleEndian;
    std::vector<unsigned char> bytes;
    std::vector<float> values;
    const std::string message = "reading";
    reportProgress(progress, data.path, 0.0, message);
    for (std::int64_t done = 0; done < totalValues;) {
        const std::int64_t count = std::min(chunkValues, totalValues - done);
        bytes.resize(static_cast<std::size_t>(count * valueBytes));
        values.resize(static_cast<std::size_t>(count));
        if (!data.in.read(reinterpret_cast<char*>(bytes.data()),
                          static_cast<std::streamsize>(bytes.size())))
            throw IoError(data.path + ": read failed after " +
                          std::to_string(done * valueBytes) + " bytes of data");
        decodeValues(header.type, bytes.data(), values.size(), swapBytes, values.data());
        chunk(done, values.data(), count);
        done += count;
        reportProgress(progress, data.path, double(done) / double(totalValues), message);
    }
}

void withRawVolumeData(const std::string& path, const RawDataDecoder& use) {
    std::ifstream in = openForReading(path);
    const RawHeader header = RawHeader::parse(in, path);
    const std::int64_t dataStart = in.tellg();
    const std::int64_t available = fileSize(path) - dataStart;
    const std::int64_t needed = [&] {
        try {
            return header.dataBytes();
        } catch (const DataError& error) {
            throw DataError(path + ": " + error.what());
        }
    }();
    const std::string subject = "the header asks for";
    if (available < needed)
        throw DataError(path + ": truncated data: " + sizeDescription(header, subject) +
                        ", but only " + std::to_string(available) + " bytes follow it");
    if (available > needed)
        throw DataError(path + ": data size mismatch: " + sizeDescription(header, subject) +
                        ", but " + std::to_string(available) + " bytes follow it");
    use({in, path, header, RawOrder::XFastest, {}});
}

void withHeaderlessRawData(const std::string& path, const RawHeader& layout,
                           std::int64_t headerBytes, const RawDataDecoder& use) {
    std::ifstream in = openForReading(path);
    if (headerBytes < 0)
        throw DataError(path + ": headerBytes must be 0 or more, got " +
                        std::to_string(headerBytes));
    const std::int64_t size = fileSize(path);
    const std::int64_t needed = [&] {
        try {
            const std::int64_t dataBytes = layout.dataBytes();
            if (dataBytes > std::numeric_limits<std::int64_t>::max() - headerBytes)
                throw DataError("the file would exceed 2^63 bytes");
            return dataBytes + headerBytes;
        } catch (const DataError& error) {
            throw DataError(path + ": " + error.what());
        }
    }();
    if (size != needed)
        throw DataError(path + ": file size mismatch: " +
                        sizeDescription(layout, "the scene describes") + ", plus " +
                        std::to_string(headerBytes) + " header bytes = " +
                        std::to_string(needed) + " bytes, but the file has " +
                        std::to_string(size) + " bytes");
    in.seekg(static_cast<std::streamoff>(headerBytes));
    use({in, path, layout, RawOrder::XFastest, {}});
}

AnyGrid readRawGrid(const std::function<void(const RawDataDecoder&)>& with,
                    const ProgressCallback& progress) {
    AnyGrid grid;
    with([&](const RawDataView& data) {
        grid = readRawData(data.in, data.path, data.layout, data.order, progress, data.axes);
    });
    return grid;
}

} // namespace detail

AnyGrid readRawVolume(const std::string& path, const ProgressCallback& progress) {
    return detail::readRawGrid(
        [&](const detail::RawDataDecoder& use) { detail::withRawVolumeData(path, use); },
        progress);
}

AnyGrid readHeaderlessRawVolume(const std::string& path, const RawHeader& layout,
                                std::int64_t headerBytes, const ProgressCallback& progress) {
    return detail::readRawGrid(
        [&](const detail::RawDataDecoder& use) {
            detail::withHeaderlessRawData(path, layout, headerBytes, use);
        },
        progress);
}

namespace detail {
namespace {

template <typename Stored>
void decode(const unsigned char* bytes, std::size_t count, bool swapBytes, float* out) {
    unsigned char word[sizeof(Stored)];
    for (std::size_t i = 0; i < count; ++i, bytes += sizeof(Stored)) {
        std::memcpy(word, bytes, sizeof(Stored));
        if (swapBytes)
            std::reverse(word, word + sizeof(Stored));
        Stored value;
        std::memcpy(&value, word, sizeof(Stored));
        out[i] = static_cast<float>(value);
    }
}

} // namespace

void decodeValues(RawValueType type, const unsigned char* bytes, std::size_t count,
                  bool swapBytes, float* out) {
    switch (type) {
    case RawValueType::Float32: decode<float>(bytes, count, swapBytes, out); break;
    case RawValueType::Float64: decode<double>(bytes, count, swapBytes, out); break;
    case RawValueType::UInt8: decode<std::uint8_t>(bytes, count, swapBytes, out); break;
    case RawValueType::UInt16: decode<std::uint16_t>(bytes, count, swapBytes, out); break;
    case RawValueType::Int8: decode<std::int8_t>(bytes, count, swapBytes, out); break;
    case RawValueType::Int16: decode<std::int16_t>(bytes, count, swapBytes, out); break;
    case RawValueType::UInt32: decode<std::uint32_t>(bytes, count, swapBytes, out); break;
    case RawValueType::Int32: decode<std::int32_t>(bytes, count, swapBytes, out); break;
    }
}

AnyGrid readRawData(std::istream& in, const std::string& path, const RawHeader& layout,
                    RawOrder order, const ProgressCallback& progress, const FileAxes& axes) {
    TEXSPLAT_ASSERT(order == RawOrder::XFastest || axes.isIdentity(),
                    "readRawData(): file axes are for x-fastest files");
    const GridGeometry geometry(layout.dims, layout.origin, layout.spacing);
    const glm::i64vec3 dims = layout.dims;
    const std::int64_t voxels = geometry.voxelCount();
    // A compressed file (NRRD gzip) declares any size in a few bytes.
    detail::checkGridFitsInMemory(path, geometry, layout.components);
    // Our index of value number `n` of a file that stores z fastest (NumPy's Fortran order of a
    // (z, y, x[, component]) array: each component is a block of its own).
    const auto zFastest = [dims, voxels](std::int64_t n, std::int64_t& voxel, int& component) {
        component = static_cast<int>(n / voxels);
        const std::int64_t rest = n % voxels;
        const std::int64_t z = rest % dims.z;
        const std::int64_t y = (rest / dims.z) % dims.y;
        const std::int64_t x = rest / (dims.z * dims.y);
        voxel = x + dims.x * (y + dims.y * z);
    };
    // Our index of voxel number `n` of an XFastest file whose axes lie as `axes` says.
    const glm::i64vec3 fileDims(dims[axes.gridAxis[0]], dims[axes.gridAxis[1]],
                                dims[axes.gridAxis[2]]);
    const auto fromFileAxes = [&](std::int64_t n) {
        const glm::i64vec3 file(n % fileDims.x, (n / fileDims.x) % fileDims.y,
                                n / (fileDims.x * fileDims.y));
        glm::i64vec3 index;
        for (int axis = 0; axis < 3; ++axis)
            index[axes.gridAxis[axis]] =
                axes.reversed[axis] ? fileDims[axis] - 1 - file[axis] : file[axis];
        return index.x + dims.x * (index.y + dims.y * index.z);
    };
    const bool inGridOrder = order == RawOrder::XFastest && axes.isIdentity();
    AnyGrid result;
    if (layout.components == 1) {
        auto grid = std::make_shared<DenseScalarGrid>(geometry);
        float* target = grid->values().data();
        readRawValues({in, path, layout, order, axes}, progress,
                      [&](std::int64_t first, const float* values, std::int64_t count) {
                       if (inGridOrder) {
                           std::copy(values, values + count, target + first);
                           return;
                       }
                       if (order == RawOrder::XFastest) {
                           for (std::int64_t i = 0; i < count; ++i)
                               target[fromFileAxes(first + i)] = values[i];
                           return;
                       }
                       std::int64_t voxel = 0;
                       int component = 0;
                       for (std::int64_t i = 0; i < count; ++i) {
                           zFastest(first + i, voxel, component);
                           target[voxel] = values[i];
                       }
                   });
        detail::checkFiniteVoxels(path, grid->statistics());
        result = grid;
    } else {
        auto grid = std::make_shared<DenseVectorGrid>(geometry);
        glm::vec3* target = grid->values().data();
        readRawValues({in, path, layout, order, axes}, progress,
                      [&](std::int64_t first, const float* values, std::int64_t count) {
                       if (order == RawOrder::XFastest) {
                           for (std::int64_t i = 0; i < count; i += 3) {
                               const std::int64_t voxel = (first + i) / 3;
                               target[inGridOrder ? voxel : fromFileAxes(voxel)] =
                                   glm::vec3(values[i], values[i + 1], values[i + 2]);
                           }
                           return;
                       }
                       std::int64_t voxel = 0;
                       int component = 0;
                       for (std::int64_t i = 0; i < count; ++i) {
                           zFastest(first + i, voxel, component);
                           target[voxel][component] = values[i];
                       }
                   });
        detail::checkFiniteVoxels(path, grid->statistics());
        result = grid;
    }
    return result;
}

} // namespace detail

void writeRawVolume(const std::string& path, const ScalarGrid& grid) { writeGrid(path, grid, 1); }

void writeRawVolume(const std::string& path, const VectorGrid& grid) { writeGrid(path, grid, 3); }

} // namespace texsplat::volume
