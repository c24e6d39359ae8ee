#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace texsplat::volume {

/// @brief One term of a blob: amplitude * exp(-|p - center|² / (2 sigma²)).
struct GaussianTerm {
    /// @brief Center, inside [-0.5, 0.5]^3.
    glm::dvec3 center{0.0};
    /// @brief Standard deviation (world units).
    double sigma = 0.25;
    /// @brief Peak value.
    double amplitude = 1.0;
};

/// @brief Parameters of generateBlob().
struct BlobParameters {
    /// @brief Samples along x, y and z on [-1,1]^3, ends included.
    glm::i64vec3 dims{64, 64, 64};
    /// @brief How many Gaussians are summed.
    int termCount = 4;
    /// @brief Seed of the term placement; the same seed gives the same blob everywhere.
    std::uint64_t seed = 1;
};

/// @brief The Gaussians of a blob: centers uniform in [-0.5,0.5]^3, sigma uniform in
/// [0.15, 0.35], amplitude uniform in [0.5, 1], drawn from `seed`.
/// @throws DataError when termCount is below 1.
std::vector<GaussianTerm> blobTerms(const BlobParameters& parameters);

/// @brief Sum of the terms at `position`: a smooth, positive field.
double blobValue(const glm::dvec3& position, const std::vector<GaussianTerm>& terms);

/// @brief A smooth blob (sum of a few seeded Gaussians) sampled on a dims grid over [-1,1]^3:
/// a simple scalar field with soft boundaries and several overlapping lobes.
/// With `region` (a box of voxels inside the grid, not empty), only those voxels, placed where they
/// lie in the grid: a brick of a render split over processes.
/// @throws DataError for dims below 1, termCount below 1, or a region outside the grid.
ScalarGridPtr generateBlob(const BlobParameters& parameters,
                           const std::optional<IndexBox>& region = std::nullopt);

} // namespace texsplat::volume
