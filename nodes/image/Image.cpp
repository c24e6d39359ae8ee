#include "nodes/image/Image.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace texsplat::image {

Image::Image(int width, int height) : mWidth(width), mHeight(height) {
    mPixels.assign(checkedPixelCount(), glm::vec4(0.0f));
}

Image::Image(int width, int height, Pixels pixels) : mWidth(width), mHeight(height) {
    const std::size_t count = checkedPixelCount();
    if (pixels.size() != count)
        throw DataError("image size " + sizeString() + " needs " + std::to_string(count) +
                        " pixels, got " + std::to_string(pixels.size()));
    mPixels = std::move(pixels);
}

std::size_t Image::checkedPixelCount() const {
    if (mWidth < 1 || mHeight < 1)
        throw DataError("image size " + sizeString() +
                        " is empty: width and height must be at least 1");
    const auto count = static_cast<std::size_t>(mWidth) * static_cast<std::size_t>(mHeight);
    if (count > kMaxPixels)
        throw DataError("image size " + sizeString() + " is too large: at most " +
                        std::to_string(kMaxPixels) + " pixels");
    return count;
}

std::size_t Image::index(int x, int y) const {
    TEXSPLAT_ASSERT(x >= 0 && x < mWidth && y >= 0 && y < mHeight,
                    "Image::pixel(): coordinates outside the image");
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(mWidth) +
           static_cast<std::size_t>(x);
}

std::size_t Image::depthIndex(int x, int y) const {
    TEXSPLAT_ASSERT(hasDepth(), "Image::depth(): the image has no depth channel");
    return index(x, y);
}

Image::Image(Unset /*tag*/, int width, int height) : mWidth(width), mHeight(height) {
    mPixels.resize(checkedPixelCount());
}

Image Image::uncleared(int width, int height) { return Image(Unset{}, width, height); }

Pixels Image::takePixels() && {
    mWidth = 0;
    mHeight = 0;
    mDepth.clear();
    return std::move(mPixels);
}

void Image::fill(const glm::vec4& rgba) { std::fill(mPixels.begin(), mPixels.end(), rgba); }

void Image::addDepth(float clearValue) { mDepth.assign(mPixels.size(), clearValue); }

void Image::flipVertically() {
    const auto rowLength = static_cast<std::ptrdiff_t>(mWidth);
    for (int top = 0, bottom = mHeight - 1; top < bottom; ++top, --bottom) {
        std::swap_ranges(mPixels.begin() + top * rowLength, mPixels.begin() + (top + 1) * rowLength,
                         mPixels.begin() + bottom * rowLength);
        if (hasDepth())
            std::swap_ranges(mDepth.begin() + top * rowLength,
                             mDepth.begin() + (top + 1) * rowLength,
                             mDepth.begin() + bottom * rowLength);
    }
}

bool Image::contains(const ImageRegion& region) const {
    // Compared as differences so that huge widths cannot overflow x + width.
    return region.width >= 1 && region.height >= 1 && region.x >= 0 && region.y >= 0 &&
           region.x < mWidth && region.y < mHeight && region.width <= mWidth - region.x &&
           region.height <= mHeight - region.y;
}

void Image::checkRegion(const ImageRegion& region) const {
    if (!contains(region))
        throw DataError("region " + std::to_string(region.x) + "," + std::to_string(region.y) +
                        " " + std::to_string(region.width) + "x" + std::to_string(region.height) +
                        " is not inside the " + sizeString() + " image");
}

Image::Statistics Image::statistics(const ImageRegion& region) const {
    checkRegion(region);
    Statistics result;
    glm::dvec4 sum(0.0);
    glm::dvec4 minimum(std::numeric_limits<double>::infinity());
    glm::dvec4 maximum(-std::numeric_limits<double>::infinity());
    for (int y = region.y; y < region.y + region.height; ++y) {
        for (int x = region.x; x < region.x + region.width; ++x) {
            const glm::vec4& value = pixel(x, y);
            if (!isFinite(value)) {
                ++result.nonFinitePixels;
                continue;
            }
            const glm::dvec4 v(value);
            sum += v;
            minimum = glm::min(minimum, v);
            maximum = glm::max(maximum, v);
            ++result.finitePixels;
        }
    }
    if (result.finitePixels == 0) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        result.mean = result.minimum = result.maximum = glm::dvec4(nan);
        return result;
    }
    result.mean = sum / static_cast<double>(result.finitePixels);
    result.minimum = minimum;
    result.maximum = maximum;
    return result;
}

std::string Image::sizeString() const {
    return std::to_string(mWidth) + "x" + std::to_string(mHeight);
}

bool isFinite(const glm::vec4& rgba) {
    return std::isfinite(rgba.r) && std::isfinite(rgba.g) && std::isfinite(rgba.b) &&
           std::isfinite(rgba.a);
}

} // namespace texsplat::image
