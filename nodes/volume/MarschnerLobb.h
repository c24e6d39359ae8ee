#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"

#include <optional>

namespace texsplat::volume {

/// @brief Parameters of generateMarschnerLobb(); the defaults are the standard test signal.
struct MarschnerLobbParameters {
    /// @brief Samples along x, y and z on [-1,1]^3, ends included (41^3 is the usual choice).
    glm::i64vec3 dims{41, 41, 41};
    /// @brief f_M, the frequency of the radial modulation.
    double modulationFrequency = 6.0;
    /// @brief alpha, the weight of the radial modulation.
    double alpha = 0.25;
};

/// @brief The Marschner–Lobb test signal (S. R. Marschner and R. J. Lobb, "An Evaluation of
/// Reconstruction Filters for Volume Rendering", IEEE Visualization 1994):
/// rho(x,y,z) = (1 - sin(pi z / 2) + alpha (1 + rho_r(sqrt(x² + y²)))) / (2 (1 + alpha)),
/// rho_r(r) = cos(2 pi f_M cos(pi r / 2)). Its values lie in [0, 1]; at the origin it is
/// (1 + 2 alpha) / (2 (1 + alpha)) when f_M is an integer.
double marschnerLobb(const glm::dvec3& position, double modulationFrequency, double alpha);

/// @brief The signal sampled on a dims grid over [-1,1]^3.
/// With `region` (a box of voxels inside the grid, not empty), only those voxels, placed where they
/// lie in the grid: a brick of a render split over processes.
/// @throws DataError for dims below 1, a non-finite f_M, alpha not finite and >= 0, or a region
/// outside the grid.
ScalarGridPtr generateMarschnerLobb(const MarschnerLobbParameters& parameters,
                                    const std::optional<IndexBox>& region = std::nullopt);

} // namespace texsplat::volume
