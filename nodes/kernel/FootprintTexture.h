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

    /// @brief The largest extent, and the largest kernel support measureLayerRipple takes. The
    /// footprint is 0 beyond the support (1.556 for the paper's kernel, at most 4 for the
    /// optimizer's on the unit lattice), so a wider quad only wastes texels, while the ripple
    /// measurement's cost grows with the square of the reach: the whole `texsplat kernel --json
    /// --texture` run takes 0.1 s at E = 8 and took 8.5 s at E = 100 (about a day at 10⁴;
    /// beyond 2³¹ the reach overflowed an int).
    static constexpr double kMaxExtent = 8.0;

    /// @brief Throws DataError unless 0 < extent ≤ kMaxExtent.
    static void checkExtent(double extent);

    /// @brief Throws IoError("t.tif: unknown texture extension '.tif' (supported: .pfm, .exr,
    /// .png)") unless write() knows the format path's extension names, and for `.exr` in a
    /// build without OpenEXR.
    static void checkPath(const std::string& path);

    /// @brief Tabulates kernel.footprint at resolution × resolution texel centres over
    /// [−extent, extent]². Throws DataError unless 2 ≤ resolution ≤ 8192 and checkExtent(extent)
    /// passes.
    FootprintTexture(const RadialKernel& kernel, int resolution, double extent = kPaperExtent);

    /// @brief The footprint of the polygonal Gaussian splat (Crawfis & Max 1993, figure 4a) as a
    /// texture: the fan of a centre and `radialSamples − 1` rings of `azimuthSamples` vertices out
    /// to `extent`, each vertex carrying kernel.footprint there, interpolated linearly over its
    /// triangles (0 outside the fan), tabulated at texel centres over [−extent, extent]². What
    /// a backend without polygons draws for the fan: it interpolates the footprint where
    /// Gouraud shading interpolates the shaded colour, the same to first order in the opacity.
    /// Throws DataError as the constructor, or when radialSamples < 2 or azimuthSamples < 3.
    static FootprintTexture gouraudFan(const RadialKernel& kernel, double extent,
                                       int radialSamples, int azimuthSamples, int resolution);

    /// @brief Texels per side.
    int resolution() const { return mResolution; }

    /// @brief The half-width E of the quad in voxel units.
    double extent() const { return mExtent; }

    /// @brief How far from the centre, in voxels, the bilinear lookup is not 0: the farthest
    /// texel centre holding a value, plus a texel's diagonal, at most the quad's corner E·√2
    /// (found once, when the texture is made).
    double reach() const { return mReach; }

    /// @brief Row-major texels, row 0 at y = −E, each the footprint at the texel centre.
    const std::vector<float>& texels() const { return mTexels; }

    /// @brief The same texture with each texel rounded to one of 256 levels between 0 and the
    /// largest texel, as an 8-bit (RGBA8) upload would store it.
    FootprintTexture quantizedTo8Bits() const;

    /// @brief The bilinear lookup at (x, y) voxels from the splat centre: 0 outside the quad,
    /// texel indices clamped to the edge inside it (GL_LINEAR with GL_CLAMP_TO_EDGE).
    double sample(const std::array<double, 2>& point) const;

    /// @brief The layer sum Σ sample(x − i, y − j) over the unit lattice, on samplesPerSide² points
    /// of the cell [0, ½]², against the exact footprint sum on the same points. Throws DataError
    /// when the kernel's support exceeds kMaxExtent.
    TextureRipple measureLayerRipple(const RadialKernel& kernel, int samplesPerSide = 64) const;

    /// @brief Writes the texture in the format the extension of path names (any case), all at
    /// once (scenegraph/AtomicFile.h):
    /// - `.pfm`: little-endian grayscale floats ("Pf"; PFM stores rows bottom to top, which is
    ///   row 0 first here), each texel f;
    /// - `.exr`: float RGBA with R = G = B = A = f, so any channel reads f back; as a
    ///   premultiplied image (nodes/image/Image.h) that is white with coverage f, what a splat
    ///   drawn with the texture as its alpha shows;
    /// - `.png`: the same image in 8 bits: PNG keeps straight alpha, so it is white (where f > 0)
    ///   with alpha round(255 f), as an RGBA8 upload of f would store it (f is clamped to
    ///   [0, 1]; the paper's kernel peaks at f(0) = 0.70).
    /// Rows of the images run from y = +E at the top. Throws IoError, and writes nothing, for
    /// another extension (checkPath), for `.exr` in a build without OpenEXR
    /// (image::isExrSupported) or when the file cannot be written.
    void write(const std::string& path) const;

private:
    FootprintTexture(int resolution, double extent, std::vector<float> texels);


    // reach() of the texels.
    double farthestReach() const;

    int mResolution;
    double mExtent;
    std::vector<float> mTexels;
    double mReach = 0.0;
};

} // namespace texsplat::kernel
