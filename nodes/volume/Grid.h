#pragma once

#include "nodes/volume/GridGeometry.h"
#include "nodes/volume/GridStatistics.h"
#include "nodes/volume/WholeGrid.h"

#include <glm/glm.hpp>

#include <array>
#include <bitset>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <variant>
#include <vector>

namespace texsplat::volume {

/// @brief Whether a voxel value is usable: finite, or for vectors finite in every component.
inline bool isFiniteValue(float value) { return std::isfinite(value); }
/// @brief Whether a voxel value is usable: finite, or for vectors finite in every component.
inline bool isFiniteValue(const glm::vec3& value) {
    return std::isfinite(value.x) && std::isfinite(value.y) && std::isfinite(value.z);
}

/// @brief The one interface the splat, octree and ray-cast code read volumes through, whatever
/// the storage (DenseGrid for raw files and generators, SparseGrid for OpenVDB files).
///
/// A voxel is *non-empty* when it is stored (every voxel of a dense grid, an active voxel of a
/// sparse one) and its value is finite. Empty voxels produce no splats, so consumers iterate
/// the non-empty ones with forEachActive() and never see NaN or infinity: value() answers the
/// background for an empty voxel. Grids are filled by their source and then shared read-only
/// (`std::shared_ptr<const Grid>`); const member functions may be called from several threads.
template <typename T>
class Grid {
public:
    /// @brief The voxel value type: float for scalar grids, glm::vec3 for vector grids.
    using ValueType = T;
    /// @brief Receives one voxel: its index and its value.
    using VoxelVisitor = std::function<void(const glm::i64vec3& index, const T& value)>;

    virtual ~Grid() = default;
    Grid(const Grid&) = delete;
    Grid& operator=(const Grid&) = delete;

    /// @brief Dimensions, origin and spacing.
    const GridGeometry& geometry() const { return mGeometry; }
    /// @brief The value value() answers for empty voxels.
    const T& background() const { return mBackground; }

    /// @brief Random access: the value of voxel `index`, or background() when the voxel is
    /// empty. `index` must lie inside the grid.
    virtual T value(const glm::i64vec3& index) const = 0;
    /// @brief Whether voxel `index` is non-empty (stored and finite).
    virtual bool isActive(const glm::i64vec3& index) const = 0;
    /// @brief Calls `visit` for every stored voxel, finite or not, in storage order.
    virtual void forEachStored(const VoxelVisitor& visit) const = 0;
    /// @brief Bytes of voxel storage held (for sparse grids proportional to the active blocks).
    virtual std::size_t memoryBytes() const = 0;
    /// @brief Number of stored voxels, finite or not: a bound on the non-empty ones, which is
    /// what work on the grid's voxels costs. By default every voxel of the box (dense storage).
    virtual std::uint64_t storedVoxelCount() const {
        return static_cast<std::uint64_t>(mGeometry.voxelCount());
    }

    /// @brief Calls `visit` for every non-empty voxel (stored and finite), in storage order.
    void forEachActive(const VoxelVisitor& visit) const;

    /// @brief Edge length, in voxels, of the blocks readBlock() reads: block b holds the voxels
    /// 8b … 8b + 7 along each axis (clipped by the box), octree::ClassifiedGrid's blocks.
    static constexpr std::int64_t kBlockEdge = 8;
    /// @brief One block's voxels, x fastest: their values and which are non-empty.
    struct VoxelBlock {
        std::array<T, 512> values;   ///< unspecified where not non-empty
        std::bitset<512> nonEmpty;   ///< stored and finite (false beyond the box)
    };
    /// @brief The blocks that may hold a non-empty voxel, ordered by z, then y, then x: for
    /// work over whole blocks, in parallel (classification). By default every block of the box.
    virtual std::vector<glm::i64vec3> occupiedBlocks() const;
    /// @brief The voxels of block `block` (inside the box's blocks) into `out`.
    virtual void readBlock(const glm::i64vec3& block, VoxelBlock& out) const = 0;
    /// @brief Value range and counts; scans the stored voxels on each call, so cache the result.
    /// By default through forEachStored(); grids that can walk their values directly do.
    virtual GridStatistics statistics() const;
    /// @brief For a brick of a grid split over processes (BrickGrid): what it knows of the whole
    /// grid, which data ranges are taken from; nullptr (the default) for a grid that is whole.
    virtual const WholeGrid* whole() const { return nullptr; }

protected:
    /// @brief For subclasses: a grid with this geometry whose empty voxels read as `background`.
    Grid(const GridGeometry& geometry, const T& background)
        : mGeometry(geometry), mBackground(background) {}

private:
    GridGeometry mGeometry;
    T mBackground;
};

extern template class Grid<float>;
extern template class Grid<glm::vec3>;

/// @brief A grid of float values.
using ScalarGrid = Grid<float>;
/// @brief A grid of 3D vectors.
using VectorGrid = Grid<glm::vec3>;
/// @brief Shared read-only scalar grid, as nodes hold it.
using ScalarGridPtr = std::shared_ptr<const ScalarGrid>;
/// @brief Shared read-only vector grid, as nodes hold it.
using VectorGridPtr = std::shared_ptr<const VectorGrid>;
/// @brief What a file source yields: a scalar or a vector grid, decided by the file.
using AnyGrid = std::variant<ScalarGridPtr, VectorGridPtr>;

} // namespace texsplat::volume
