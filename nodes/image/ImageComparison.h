#pragma once

#include "nodes/image/Image.h"
#include "nodes/image/ImageRegion.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace texsplat::image {

/// @brief What ImageComparison compares: where, and the peak value PSNR is relative to.
struct ComparisonOptions {
    /// Compare only this rectangle (default: the whole image).
    std::optional<ImageRegion> region;
    /// Empty, or one entry per pixel (row by row, top row first): nonzero entries are compared.
    std::vector<std::uint8_t> mask;
    /// The peak signal of PSNR = 20·log10(peak / RMSE). 1 suits float images whose nominal range
    /// is [0, 1] (premultiplied color and alpha), whatever the 8-bit encoding of a PNG was.
    double peak = 1.0;
};

/// @brief Error statistics between a reference image and a test image of the same size:
/// RMSE, PSNR and the largest absolute difference (and where), per channel and over R, G, B
/// together, and a false-color difference image.
///
/// The values compared are the stored premultiplied floats (an image read from PNG is first
/// decoded to linear premultiplied floats). A pixel pair where either image has a NaN or
/// infinite component is *not* folded into the statistics, where one NaN would turn every
/// number into NaN: it is counted in nonFinitePixels(), shown in its own color in the
/// difference image, and reported by `texsplat compare`.
///
/// Typical use: the error of a splat rendering against the RayCastAction reference.
class ImageComparison {
public:
    /// @brief The error of one channel (or of R, G, B pooled) over the compared pixels.
    struct ChannelError {
        double rmse = 0.0; ///< √(mean of squared differences)
        /// 20·log10(peak / rmse) in dB; +infinity when rmse is 0 (identical values).
        double psnr = std::numeric_limits<double>::infinity();
        double maxAbsError = 0.0; ///< largest |test − reference|
        int maxX = -1;            ///< column of the first pixel (row by row) with maxAbsError
        int maxY = -1;            ///< row of that pixel (0 is the top row)
        int maxChannel = -1;      ///< channel of that difference (0..3 = R, G, B, A)
    };

    /// @brief Compares `test` against `reference`.
    ///
    /// Throws DataError when the sizes differ ("image sizes differ: reference 64x64, test
    /// 64x32"), when the region is not inside the images, the mask has the wrong size, the peak
    /// is not positive and finite, or no finite pixel pair is left to compare.
    ImageComparison(const Image& reference, const Image& test,
                    const ComparisonOptions& options = ComparisonOptions());

    /// @brief Error of channel `c` (0..3 = R, G, B, A).
    const ChannelError& channel(int c) const;
    /// @brief Error over R, G and B pooled: RMSE over all 3·N color differences, the largest
    /// of the three channels' absolute errors.
    const ChannelError& rgb() const { return mRgb; }

    /// @brief Pixel pairs that entered the statistics.
    std::size_t comparedPixels() const { return mComparedPixels; }
    /// @brief Selected pixel pairs left out because a component is NaN or infinite in either
    /// image.
    std::size_t nonFinitePixels() const { return mNonFinitePixels; }
    /// @brief The peak PSNR is relative to.
    double peak() const { return mPeak; }
    /// @brief Largest per-pixel color error √((ΔR² + ΔG² + ΔB²) / 3): the default top of the
    /// difference image's color scale.
    double maxPixelError() const { return mMaxPixelError; }

    /// @brief The per-pixel color error √((ΔR² + ΔG² + ΔB²) / 3) in false color.
    ///
    /// The error e maps linearly onto the viridis colormap, e = 0 to its dark violet end and
    /// e ≥ `scale` to its yellow end; `scale` ≤ 0 means maxPixelError() (the full range is
    /// used). Non-finite pairs are magenta (1, 0, 1); pixels outside the region or mask are
    /// transparent. The colors are viridis's own (display) values, as every image holds colour,
    /// so that a PNG of it holds exactly viridis's published values. Throws DataError for a NaN
    /// or infinite `scale`.
    Image differenceImage(double scale = 0.0) const;

private:
    int mWidth;
    int mHeight;
    double mPeak;
    std::array<ChannelError, 4> mChannels;
    ChannelError mRgb;
    std::size_t mComparedPixels = 0;
    std::size_t mNonFinitePixels = 0;
    double mMaxPixelError = 0.0;
    /// Per pixel: the color error, NaN for a non-finite pair, −1 where not selected.
    std::vector<float> mPixelError;
};

} // namespace texsplat::image
