#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"

#include <optional>

namespace texsplat::volume {

/// @brief Parameters of generateTornado().
struct TornadoParameters {
    /// @brief Samples along x, y and z; the field is sampled on [0,1]^3, ends included.
    glm::i64vec3 dims{64, 64, 64};
    /// @brief Animation time; the funnel's center moves with it (the original passes frame
    /// numbers 0, 1, 2, ...).
    double time = 0.0;
};

/// @brief Crawfis's test tornado at one point of [0,1]^3: the vector field of the paper's
/// Figure 5, as in his public-domain `gen_tornado(xs, ys, zs, time, tornado)` (Roger A.
/// Crawfis, tornadoSrc.c, https://web.cse.ohio-state.edu/~crawfis.3/Data/Tornado/tornadoSrc.c).
///
/// For each z-slice a circle of center (xc, yc) = (0.5 + 0.1 sin(0.04 t + 10 z),
/// 0.5 + 0.1 cos(0.03 t + 3 z)) and radius r = 0.1 + 0.4 z² + 0.1 z sin(8 z) is the funnel wall;
/// r2 = 0.2 + 0.1 z damps the speed away from it (formula in docs/data.md). Evaluated in double;
/// the original used float, which differs in the 7th digit.
glm::dvec3 tornadoVelocity(const glm::dvec3& position, double time);

/// @brief The tornado sampled on a dims grid over [0,1]^3 (voxel i at x = i / (dims.x - 1), as
/// in the original), origin 0.
/// With `region` (a box of voxels inside the grid, not empty), only those voxels, placed where they
/// lie in the grid: a brick of a render split over processes.
/// @throws DataError for dims below 1 or a non-finite time, or a region outside the grid.
VectorGridPtr generateTornado(const TornadoParameters& parameters,
                              const std::optional<IndexBox>& region = std::nullopt);

} // namespace texsplat::volume
