#pragma once

#include <cstdint>

namespace texsplat::volume {

/// @brief Value range and voxel counts of a grid, as Grid::statistics() measures them.
///
/// For vector grids the range is that of the vector magnitudes. Non-finite voxels (a NaN or
/// infinite value, or a vector with such a component) are empty: they count in
/// `nonFiniteCount` and nowhere else.
struct GridStatistics {
    /// @brief Smallest finite value (0 when the grid holds none).
    double minimum = 0.0;
    /// @brief Largest finite value (0 when the grid holds none).
    double maximum = 0.0;
    /// @brief Voxels with a finite value: every voxel of a dense grid, the active voxels of a
    /// sparse one.
    std::int64_t finiteCount = 0;
    /// @brief Stored voxels whose value is NaN or infinite; they are treated as empty.
    std::int64_t nonFiniteCount = 0;
};

} // namespace texsplat::volume
