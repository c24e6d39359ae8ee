#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace texsplat::volume {

/// @brief One aerogel fiber: a solid cylinder from `start` to `end`, drawn by a scene as polygon
/// geometry embedded in the volume rendering (paper, Figure 7).
struct Fiber {
    /// @brief Center of one end cap.
    glm::dvec3 start{0.0};
    /// @brief Center of the other end cap.
    glm::dvec3 end{0.0, 0.0, 1.0};
    /// @brief Cylinder radius.
    double radius = 0.02;
};

/// @brief Parameters of generateAerogel(); the flow domain is the unit cube [0,1]^3.
struct AerogelParameters {
    /// @brief Samples along x, y and z on [0,1]^3, ends included.
    glm::i64vec3 dims{64, 64, 64};
    /// @brief Number of fibers (0 gives the undisturbed inflow).
    int fiberCount = 24;
    /// @brief Smallest fiber radius.
    double minRadius = 0.015;
    /// @brief Largest fiber radius.
    double maxRadius = 0.035;
    /// @brief Shortest fiber.
    double minLength = 0.5;
    /// @brief Longest fiber.
    double maxLength = 1.2;
    /// @brief Velocity of the flow far from every fiber.
    glm::dvec3 inflow{1.0, 0.0, 0.0};
    /// @brief Seed of the fiber placement.
    std::uint64_t seed = 1;
};

/// @brief Flow through an aerogel-like substrate: the velocity grid and the fibers.
struct AerogelField {
    /// @brief Flow velocity on [0,1]^3; zero inside fibers.
    VectorGridPtr velocity;
    /// @brief The fibers the flow goes around.
    std::vector<Fiber> fibers;
};

/// @brief Random fibers drawn from `seed`: centers uniform in the unit cube, directions uniform on
/// the sphere, lengths and radii uniform in their ranges.
/// @throws DataError when fiberCount is negative or a range is not positive and increasing.
std::vector<Fiber> aerogelFibers(const AerogelParameters& parameters);

/// @brief Velocity at `position`: the inflow plus, for each fiber, the doublet of 2D potential
/// flow past a cylinder (normal to its axis, faded beyond its ends), times a no-slip factor
/// 1 - exp(-(d/R)²) per fiber, d the distance to its surface. Zero inside any fiber and on its
/// surface. Not a Stokes solution; a plausible stand-in for the paper's aerogel data (Ladd and
/// Chandler, LLNL). Formula in docs/data.md.
glm::dvec3 aerogelVelocity(const glm::dvec3& position, const std::vector<Fiber>& fibers,
                           const glm::dvec3& inflow);

/// @brief The fibers and the velocity sampled on a dims grid over [0,1]^3 (the paper's Figure 7
/// volume-renders its magnitude; see magnitudeGrid()).
/// With `region` (a box of voxels inside the grid, not empty), only those voxels, placed where they
/// lie in the grid: a brick of a render split over processes.
/// @throws DataError for dims below 1, bad fiber parameters, a non-finite inflow, or a region
/// outside the grid.
AerogelField generateAerogel(const AerogelParameters& parameters,
                             const std::optional<IndexBox>& region = std::nullopt);

} // namespace texsplat::volume
