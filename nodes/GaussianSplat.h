#pragma once

#include "nodes/ScalarSplat.h"

namespace texsplat::nodes {

/// @brief The paper's baseline (Crawfis & Max 1993, figure 4a; Laur & Hanrahan's polygonal
/// splats as SGI Explorer drew them): each splat a polygonal Gaussian, a fan of
/// `radialSamples` × `azimuthSamples` vertices (the centre and rings out to `size` voxels)
/// carrying the Gaussian's footprint, Gouraud shaded. The Gaussian is the one fitted to the
/// paper's support (kernel::KernelOptimizer::fitGaussian), the same as TextureSplat's
/// `kernel GAUSSIAN`, so the polygon and the texture can be told apart. Everything else is
/// ScalarSplat's.
///
/// File format:
/// @code
/// GaussianSplat {
///     size            1.6
///     errorThreshold  0
///     maxSplats       0
///     radialSamples   3   # >= 2, the centre included
///     azimuthSamples  7   # >= 3
/// }
/// @endcode
class GaussianSplat : public sg::Declare<GaussianSplat, ScalarSplat> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "GaussianSplat";

    sg::SFInt32 radialSamples;  ///< vertices along a radius, the centre included
    sg::SFInt32 azimuthSamples; ///< vertices around each ring

protected:
    GaussianSplat();

    render::SplatFootprint makeFootprint() const override;
};

} // namespace texsplat::nodes
