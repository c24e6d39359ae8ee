#pragma once

#include "nodes/ScalarSplat.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/fields/SFEnum.h"

#include <memory>

namespace texsplat::kernel {
class FootprintTexture;
class RadialKernel;
} // namespace texsplat::kernel

namespace texsplat::nodes {

/// @brief The reconstruction kernel whose footprint a TextureSplat carries.
enum class SplatKernel {
    Paper,    ///< the paper's piecewise cubic (Crawfis & Max 1993, section 2)
    Gaussian, ///< the Gaussian fitted to the same support, for comparison (figure 4a's kernel)
};

/// @brief Scene-file names of SplatKernel.
inline const sg::EnumNames kSplatKernelNames{{"PAPER", SplatKernel::Paper},
                                             {"GAUSSIAN", SplatKernel::Gaussian}};

/// @brief Texture splats (Crawfis & Max 1993, section 3, figure 4b): each splat is one square
/// facing the eye, carrying the kernel's footprint as a texture, composited back to front.
///
/// The footprint texture is tabulated at `textureResolution`² texels over the square
/// [−size, size]² voxels (nodes/kernel/FootprintTexture) and sampled bilinearly. At the default
/// 64² the one-layer sum of the paper's kernel through the GL pipeline stays within 0.02% of the
/// paper's figure 2 extremes (docs/results/rendering.md). `kernel GAUSSIAN` swaps only the
/// kernel, so the kernel and the drawing method (GaussianSplat) can be compared separately.
/// Everything else is ScalarSplat's.
///
/// File format:
/// @code
/// TextureSplat {
///     size               1.6
///     errorThreshold     0
///     maxSplats          0
///     kernel             PAPER   # PAPER, GAUSSIAN
///     textureResolution  64      # 2 .. 8192
/// }
/// @endcode
class TextureSplat : public sg::Declare<TextureSplat, ScalarSplat> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "TextureSplat";

    sg::SFEnum kernel;              ///< SplatKernel
    sg::SFInt32 textureResolution;  ///< footprint texels per side

    /// @brief The kernel `splatKernel` names: the paper's cubic, or the Gaussian fitted to its
    /// support.
    static std::shared_ptr<const texsplat::kernel::RadialKernel> radialKernel(
        SplatKernel splatKernel);

    /// @brief A TexturedSquare of `splatKernel`'s footprint at `resolution`² texels over
    /// [−extent, extent]² (what TextureSplat draws, and CombinedSplat under its marks).
    /// @throws DataError as kernel::FootprintTexture.
    static render::SplatFootprint squareFootprint(SplatKernel splatKernel, int resolution,
                                                  float extent);

protected:
    TextureSplat();

    render::SplatFootprint makeFootprint() const override;
};

} // namespace texsplat::nodes
