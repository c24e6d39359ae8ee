#include "nodes/volume/detail/RawData.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/IndexBox.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"

#include <glm/gtc/type_ptr.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace texsplat::volume::detail {
namespace {

constexpr bool kHostIsLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

// Where a file's axes lie in the grid: file axis a (0 the fastest) is grid axis gridAxis[a],
// counted from its far end when reversed[a]; a voxel's components follow each other, or
// (componentBlocks) each component is a block of the whole grid after the other.
struct FileOrder {
    glm::ivec3 gridAxis{0, 1, 2};
    glm::bvec3 reversed{false};
    bool componentBlocks = false;
};

FileOrder fileOrderOf(const RawDataView& data) {
    if (data.order == RawOrder::ZFastest) {
        return {glm::ivec3(2, 1, 0), glm::bvec3(false), true};
    }
    return {data.axes.gridAxis, data.axes.reversed, false};
}

// The region's voxels and where each file voxel of it goes. Vectors are held as the vector
// grid holds them, so that the grid takes them without a copy.
class RegionTarget {
public:
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "a vector is three packed floats");

    RegionTarget(const RawHeader& layout, const IndexBox& region, const FileOrder& order)
        : mOrder(order), mDims(layout.dims), mRegion(region), mComponents(layout.components) {
        const auto voxels = static_cast<std::size_t>(region.voxelCount());
        if (mComponents == 1) {
            mScalars.resize(voxels);
        } else {
            mVectors.resize(voxels);
        }
        for (int axis = 0; axis < 3; ++axis) {
            const int grid = order.gridAxis[axis];
            mFileDims[axis] = mDims[grid];
            mFileLow[axis] = order.reversed[axis] ? mDims[grid] - region.hi[grid] : region.lo[grid];
            mFileHigh[axis] =
                order.reversed[axis] ? mDims[grid] - region.lo[grid] : region.hi[grid];
        }
    }

    const glm::i64vec3& fileDims() const { return mFileDims; }
    const glm::i64vec3& fileLow() const { return mFileLow; }
    const glm::i64vec3& fileHigh() const { return mFileHigh; }
    bool isGridOrder() const {
        return mOrder.gridAxis == glm::ivec3(0, 1, 2) && !glm::any(mOrder.reversed) &&
               !mOrder.componentBlocks;
    }

    // Whether file voxel `file` lies in the region.
    bool contains(const glm::i64vec3& file) const {
        return glm::all(glm::greaterThanEqual(file, mFileLow)) &&
               glm::all(glm::lessThan(file, mFileHigh));
    }

    // The slot of component `component` of file voxel `file` (in the region) in values().
    std::size_t slot(const glm::i64vec3& file, int component) const {
        glm::i64vec3 grid;
        for (int axis = 0; axis < 3; ++axis) {
            const int g = mOrder.gridAxis[axis];
            grid[g] = mOrder.reversed[axis] ? mDims[g] - 1 - file[axis] : file[axis];
        }
        const glm::i64vec3 local = grid - mRegion.lo;
        const glm::i64vec3 size = mRegion.dims();
        return static_cast<std::size_t>(
            (local.x + size.x * (local.y + size.y * local.z)) * mComponents + component);
    }

    // The values, a voxel's components after each other.
    float* values() {
        return mComponents == 1 ? mScalars.data() : glm::value_ptr(mVectors.front());
    }
    std::vector<float> takeScalars() { return std::move(mScalars); }
    std::vector<glm::vec3> takeVectors() { return std::move(mVectors); }

private:
    FileOrder mOrder;
    glm::i64vec3 mDims;
    IndexBox mRegion;
    int mComponents;
    glm::i64vec3 mFileDims{0};
    glm::i64vec3 mFileLow{0};
    glm::i64vec3 mFileHigh{0};
    std::vector<float> mScalars;
    std::vector<glm::vec3> mVectors;
};

// Reads the region's rows of a file that can seek: one read per run of values along the file's
// fastest axis (per component where components are blocks).
void readRows(const RawDataView& data, const FileOrder& order, RegionTarget& target,
              const ProgressCallback& progress) {
    const RawHeader& layout = data.layout;
    const std::streamoff start = data.in.tellg();
    const std::int64_t valueBytes = layout.bytesPerValue();
    const int components = layout.components;
    const int blocks = order.componentBlocks ? components : 1;
    const int perVoxel = order.componentBlocks ? 1 : components;
    const glm::i64vec3 dims = target.fileDims();
    const glm::i64vec3 low = target.fileLow();
    const glm::i64vec3 high = target.fileHigh();
    const std::int64_t run = high.x - low.x;
    const std::int64_t voxels = dims.x * dims.y * dims.z;
    const bool swapBytes = (layout.endian == RawEndian::Little) != kHostIsLittleEndian;
    std::vector<unsigned char> bytes(static_cast<std::size_t>(run * perVoxel * valueBytes));
    std::vector<float> decoded(static_cast<std::size_t>(run * perVoxel));
    const std::string message = "reading";
    reportProgress(progress, data.path, 0.0, message);
    for (std::int64_t z = low.z; z < high.z; ++z) {
        for (std::int64_t y = low.y; y < high.y; ++y) {
            for (int block = 0; block < blocks; ++block) {
                const std::int64_t first = (z * dims.y + y) * dims.x + low.x;
                const std::int64_t value =
                    order.componentBlocks ? block * voxels + first : first * components;
                data.in.seekg(start + static_cast<std::streamoff>(value * valueBytes));
                if (!data.in.read(reinterpret_cast<char*>(bytes.data()),
                                  static_cast<std::streamsize>(bytes.size()))) {
                    throw IoError(data.path + ": read failed at byte " +
                                  std::to_string(value * valueBytes) + " of the data");
                }
                const glm::i64vec3 file(low.x, y, z);
                if (target.isGridOrder()) {
                    decodeValues(layout.type, bytes.data(), decoded.size(), swapBytes,
                                 &target.values()[target.slot(file, 0)]);
                    continue;
                }
                decodeValues(layout.type, bytes.data(), decoded.size(), swapBytes, decoded.data());
                for (std::int64_t i = 0; i < run; ++i) {
                    for (int component = 0; component < perVoxel; ++component) {
                        target.values()[target.slot({low.x + i, y, z},
                                                    order.componentBlocks ? block : component)] =
                            decoded[static_cast<std::size_t>(i * perVoxel + component)];
                    }
                }
            }
        }
        reportProgress(progress, data.path, double(z - low.z + 1) / double(high.z - low.z),
                       message);
    }
}

// Streams every value of a file that cannot seek (gzip), keeping the region's.
void streamValues(const RawDataView& data, const FileOrder& order, RegionTarget& target,
                  const ProgressCallback& progress) {
    const int components = data.layout.components;
    const glm::i64vec3 dims = target.fileDims();
    const std::int64_t voxels = dims.x * dims.y * dims.z;
    readRawValues(data, progress, [&](std::int64_t first, const float* values, std::int64_t count) {
        for (std::int64_t i = 0; i < count; ++i) {
            const std::int64_t n = first + i;
            const std::int64_t voxel = order.componentBlocks ? n % voxels : n / components;
            const int component =
                static_cast<int>(order.componentBlocks ? n / voxels : n % components);
            const glm::i64vec3 file(voxel % dims.x, (voxel / dims.x) % dims.y,
                                    voxel / (dims.x * dims.y));
            if (target.contains(file)) {
                target.values()[target.slot(file, component)] = values[i];
            }
        }
    });
}

} // namespace

AnyGrid readRawRegion(const RawDataView& data, const IndexBox& region,
                      const ProgressCallback& progress) {
    const RawHeader& layout = data.layout;
    const GridGeometry whole(layout.dims, layout.origin, layout.spacing);
    if (region.isEmpty() || region.intersection(IndexBox::of(whole)) != region) {
        throw DataError(data.path + ": brick " + region.text() +
                        " is not a box of voxels of the "
                        "grid's " +
                        IndexBox::of(whole).text());
    }
    const GridGeometry geometry = boxGeometry(whole, region);
    checkGridFitsInMemory(data.path, geometry, layout.components);
    const FileOrder order = fileOrderOf(data);
    RegionTarget target(layout, region, order);
    if (data.in.tellg() != std::streampos(-1)) {
        readRows(data, order, target, progress);
    } else {
        streamValues(data, order, target, progress);
    }
    if (layout.components == 1) {
        return ScalarGridPtr(std::make_shared<DenseScalarGrid>(geometry, target.takeScalars()));
    }
    return VectorGridPtr(std::make_shared<DenseVectorGrid>(geometry, target.takeVectors()));
}

AnyGrid readRawGridRegion(const std::function<void(const RawDataDecoder&)>& with,
                          const IndexBox& region, const ProgressCallback& progress) {
    AnyGrid grid;
    with([&](const RawDataView& data) { grid = readRawRegion(data, region, progress); });
    return grid;
}

GridGeometry rawGridGeometry(const std::function<void(const RawDataDecoder&)>& with) {
    std::optional<GridGeometry> geometry;
    with([&](const RawDataView& data) {
        geometry.emplace(data.layout.dims, data.layout.origin, data.layout.spacing);
    });
    return *geometry;
}

} // namespace texsplat::volume::detail
