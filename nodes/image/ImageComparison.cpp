#include "nodes/image/ImageComparison.h"

#include "nodes/image/detail/Viridis.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace texsplat::image {
namespace {

constexpr float kNotSelected = -1.0f;
constexpr int kChannels = 4;

/// Running sums of one channel (or of the pooled color channels).
struct Accumulator {
    double sumOfSquares = 0.0;
    double samples = 0.0;
    ImageComparison::ChannelError error;

    void add(double difference, int x, int y, int channel) {
        sumOfSquares += difference * difference;
        samples += 1.0;
        const double magnitude = std::abs(difference);
        // Strictly greater: ties keep the first pixel in row order, so "where" is reproducible.
        if (magnitude > error.maxAbsError || error.maxX < 0) {
            error.maxAbsError = magnitude;
            error.maxX = x;
            error.maxY = y;
            error.maxChannel = channel;
        }
    }

    ImageComparison::ChannelError finish(double peak) const {
        ImageComparison::ChannelError result = error;
        result.rmse = std::sqrt(sumOfSquares / samples);
        result.psnr = result.rmse > 0.0 ? 20.0 * std::log10(peak / result.rmse)
                                        : std::numeric_limits<double>::infinity();
        return result;
    }
};

void checkOptions(const Image& reference, const Image& test, const ComparisonOptions& options) {
    if (reference.width() != test.width() || reference.height() != test.height())
        throw DataError("image sizes differ: reference " + reference.sizeString() + ", test " +
                        test.sizeString());
    if (options.region)
        reference.checkRegion(*options.region);
    if (!options.mask.empty() && options.mask.size() != reference.pixelCount())
        throw DataError("mask has " + std::to_string(options.mask.size()) + " entries, but the " +
                        reference.sizeString() + " images have " +
                        std::to_string(reference.pixelCount()) + " pixels");
    if (!(options.peak > 0.0) || !std::isfinite(options.peak))
        throw DataError("PSNR peak must be positive and finite, got " +
                        std::to_string(options.peak));
}

} // namespace

ImageComparison::ImageComparison(const Image& reference, const Image& test,
                                 const ComparisonOptions& options)
    : mWidth(reference.width()), mHeight(reference.height()), mPeak(options.peak) {
    checkOptions(reference, test, options);
    const ImageRegion region = options.region.value_or(reference.bounds());
    mPixelError.assign(reference.pixelCount(), kNotSelected);
    std::array<Accumulator, kChannels> channels;
    Accumulator rgb;
    std::size_t selected = 0;
    for (int y = region.y; y < region.y + region.height; ++y) {
        for (int x = region.x; x < region.x + region.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * mWidth + x;
            if (!options.mask.empty() && options.mask[i] == 0)
                continue;
            ++selected;
            const glm::vec4& a = reference.pixel(x, y);
            const glm::vec4& b = test.pixel(x, y);
            if (!isFinite(a) || !isFinite(b)) {
                ++mNonFinitePixels;
                mPixelError[i] = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            ++mComparedPixels;
            double colorSquares = 0.0;
            for (int c = 0; c < kChannels; ++c) {
                // In double: float differences of nearly equal values would lose the digits
                // that a small RMSE is made of.
                const double difference = static_cast<double>(b[c]) - a[c];
                channels[c].add(difference, x, y, c);
                if (c < 3) {
                    rgb.add(difference, x, y, c);
                    colorSquares += difference * difference;
                }
            }
            const double pixelError = std::sqrt(colorSquares / 3.0);
            mPixelError[i] = static_cast<float>(pixelError);
            mMaxPixelError = std::max(mMaxPixelError, pixelError);
        }
    }
    if (selected == 0)
        throw DataError("the mask selects no pixel to compare");
    if (mComparedPixels == 0)
        throw DataError("no pixel to compare: all " + std::to_string(mNonFinitePixels) +
                        " selected pixels are NaN or infinite in one of the images");
    for (int c = 0; c < kChannels; ++c)
        mChannels[c] = channels[c].finish(mPeak);
    mRgb = rgb.finish(mPeak);
}

const ImageComparison::ChannelError& ImageComparison::channel(int c) const {
    TEXSPLAT_ASSERT(c >= 0 && c < kChannels, "ImageComparison::channel(): channel is not 0..3");
    return mChannels[c];
}

Image ImageComparison::differenceImage(double scale) const {
    if (!std::isfinite(scale))
        throw DataError("difference image scale must be finite, got " + std::to_string(scale));
    if (scale <= 0.0)
        scale = mMaxPixelError;
    Image image(mWidth, mHeight);
    for (std::size_t i = 0; i < mPixelError.size(); ++i) {
        const float error = mPixelError[i];
        glm::vec4& pixel = image.data()[i];
        if (std::isnan(error)) {
            pixel = glm::vec4(1.0f, 0.0f, 1.0f, 1.0f);
        } else if (error >= 0.0f) {
            // All-equal images (scale 0) map every pixel to the bottom of the colormap.
            const double t = scale > 0.0 ? error / scale : 0.0;
            pixel = glm::vec4(detail::viridis(static_cast<float>(t)), 1.0f);
        }
    }
    return image;
}

} // namespace texsplat::image
