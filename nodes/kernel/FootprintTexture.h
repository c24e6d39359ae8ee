#pragma once

#include "nodes/kernel/RadialKernel.h"

#include <array>
#include <string>
#include <vector>

namespace texsplat::kernel {

/// @brief How much a footprint texture, sampled bilinearly, changes the one-layer sum of
/// footprints (the paper's figure 2) compared with the exact footprint.
struct TextureRipple {
    double max = 0.0;       ///< max of the layer sum of texture samples
    double min = 0.0;       ///< min of it
    double exactMax = 0.0;  ///< max of the exact layer sum on the same sample points
    double exactMin = 0.0;  ///< min of it
    double maxError = 0.0;  ///< max |texture sum − exact sum| (what the texture adds)
};

/// @brief The footprint f of a kernel tabulated on an N×N texture covering the splat's quad
/// [−E, E]², as the renderer uploads it (one float per texel; texel centres at
/// −E + (i + ½)·2E/N), and the texture's bilinear lookup with GL's CLAMP_TO_EDGE rule.
///
/// The extent E is a half-width in voxel units: the paper's "extent of 1.6" (section 3) is read
/// as the quad reaching 1.6 voxels from the centre, which covers the support t = 1.556 of the
/// kernel; a quad 1.6 voxels wide (E = 0.8) would cut the footprint at r = 0.8 and its layer sum
/// would ripple by ±30% (docs/kernel.md has the measurement).
class FootprintTexture {
public:
    /// @brief The paper's extent: the quad reaches 1.6 voxels from the splat centre.
    static constexpr double kPaperExtent = 1.6;

    /// @brief Tabulates kernel.footprint at resolution × resolution texel centres over
    /// [−extent, extent]². Throws DataError unless 2 ≤ resolution ≤ 8192 and extent is finite
    /// and positive.
    FootprintTexture(const RadialKernel& kernel, int resolution, double extent = kPaperExtent);

    /// @brief Texels per side.
    int resolution() const { return mResolution; }

    /// @brief The half-width E of the quad in voxel units.
    double extent() const { return mExtent; }

    /// @brief Row-major texels, row 0 at y = −E, each the footprint at the texel centre.
    const std::vector<float>& texels() const { return mTexels; }

    /// @brief The same texture with each texel rounded to one of 256 levels between 0 and the
    /// largest texel, as an 8-bit (RGBA8) upload would store it.
    FootprintTexture quantizedTo8Bits() const;

    /// @brief The bilinear lookup at (x, y) voxels from the splat centre: 0 outside the quad,
    /// texel indices clamped to the edge inside it (GL_LINEAR with GL_CLAMP_TO_EDGE).
    double sample(const std::array<double, 2>& point) const;

    /// @brief The layer sum Σ sample(x − i, y − j) over the unit lattice, on samplesPerSide² points
    /// of the cell [0, ½]², against the exact footprint sum on the same points.
    TextureRipple measureLayerRipple(const RadialKernel& kernel, int samplesPerSide = 64) const;

    /// @brief Writes the texture as a little-endian grayscale PFM ("Pf"; PFM stores rows bottom
    /// to top, which is row 0 first here) through a temporary file renamed into place. Throws
    /// IoError when the file cannot be written.
    void writePfm(const std::string& path) const;

private:
    FootprintTexture(int resolution, double extent, std::vector<float> texels);

    int mResolution;
    double mExtent;
    std::vector<float> mTexels;
};

} // namespace texsplat::kernel
