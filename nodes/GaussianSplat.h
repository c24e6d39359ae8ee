#pragma once

#include "nodes/ScalarSplat.h"

namespace texsplat::nodes {

/// @brief The paper's baseline (Crawfis & Max 1993, figure 4a; Laur & Hanrahan's polygonal
/// splats as SGI Explorer drew them): each splat a polygonal Gaussian, a fan of
/// `radialSamples` × `azimuthSamples` vertices (the centre and rings out to `size` voxels)
/// carrying the Gaussian's footprint, Gouraud shaded. The Gaussian is the one fitted to the
/// paper's support (kernel::KernelOptimizer::fitGaussian), the same as TextureSplat's
/// `kernel GAUSSIAN`, so the polygon and the texture can be told apart. Everything else is
/// ScalarSplat's. Each splat costs radialSamples × azimuthSamples vertices, so both are
/// bounded (radialSamples 2 to 64, azimuthSamples 3 to 256); a value outside throws DataError
/// naming the field and the range when the node is drawn.
///
/// File format:
/// @code
/// GaussianSplat {
///     size            1.6
///     errorThreshold  0
///     maxSplats       0
///     radialSamples   3   # 2 to 64, the centre included
///     azimuthSamples  7   # 3 to 256
/// }
/// @endcode
class GaussianSplat : public sg::Declare<GaussianSplat, ScalarSplat> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "GaussianSplat";

    sg::SFInt32 radialSamples;  ///< vertices along a radius, the centre included
    sg::SFInt32 azimuthSamples; ///< vertices around each ring

    /// @brief Allowed radialSamples: the centre and at least one ring.
    static constexpr int kMinRadialSamples = 2;
    /// @brief Largest radialSamples; far more than a splat of a few pixels shows.
    static constexpr int kMaxRadialSamples = 64;
    /// @brief Allowed azimuthSamples: at least a triangle around each ring.
    static constexpr int kMinAzimuthSamples = 3;
    /// @brief Largest azimuthSamples.
    static constexpr int kMaxAzimuthSamples = 256;

protected:
    GaussianSplat();

    /// @brief ScalarSplat's checks, then radialSamples and azimuthSamples within their ranges.
    void checkFields() const override;

    render::SplatFootprint makeFootprint() const override;
};

} // namespace texsplat::nodes
