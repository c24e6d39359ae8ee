#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"

#include <cstdint>
#include <optional>

namespace texsplat::volume {

/// @brief Parameters of generateJetStream(): a longitude/latitude/altitude box.
struct JetStreamParameters {
    /// @brief Samples along longitude, latitude and altitude, ends included.
    glm::i64vec3 dims{96, 48, 24};
    /// @brief West edge, degrees east (North America by default, as in the paper's Figure 8).
    double longitudeMin = -140.0;
    /// @brief East edge, degrees east.
    double longitudeMax = -50.0;
    /// @brief South edge, degrees north.
    double latitudeMin = 15.0;
    /// @brief North edge, degrees north.
    double latitudeMax = 65.0;
    /// @brief Top of the box in km (the bottom is the ground, 0 km).
    double altitudeMax = 16.0;
    /// @brief Time in days; the jets' meanders drift eastward with it.
    double time = 0.0;
    /// @brief Seed of the meander phases and the cloud noise.
    std::uint64_t seed = 1;
};

/// @brief A synthetic climate sample: wind (m/s; east, north, up) and percent cloudiness.
struct JetStreamField {
    /// @brief Wind vectors; world x = longitude (deg), y = latitude (deg), z = altitude (km).
    VectorGridPtr wind;
    /// @brief Percent cloudiness in [0, 100] on the same geometry; 0 is clear sky.
    ScalarGridPtr cloudiness;
};

/// @brief A plausible stand-in for the climate data of the paper's Figures 6 and 8 (which came
/// from PCMDI/ECMWF): a polar and a subtropical jet whose axes meander as Rossby waves drifting
/// east, Gaussian in latitude and altitude around their cores, over weak westerlies; clouds
/// along the polar front where the flow turns poleward, and in a tropical band, shaped by
/// seeded value noise and confined to the lower troposphere. Formulas in docs/data.md.
/// With `region` (a box of voxels inside the grid, not empty), only those voxels, placed where they
/// lie in the grid: a brick of a render split over processes.
/// @throws DataError for dims below 1, an empty or reversed box, a non-finite time, or a region
/// outside the grid.
JetStreamField generateJetStream(const JetStreamParameters& parameters,
                                 const std::optional<IndexBox>& region = std::nullopt);

} // namespace texsplat::volume
