#pragma once

#include "nodes/image/ImageRegion.h"
#include "nodes/image/Pixels.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace texsplat::image {

/// @brief A float RGBA image with premultiplied alpha and an optional float depth channel, as
/// the renderer's floating-point framebuffer produces it.
///
/// Conventions:
/// - Color is *premultiplied* by alpha (the splats are blended with the "over" operator on
///   premultiplied colors, Crawfis & Max 1993, section 3): over a background color c a pixel
///   (r, g, b, a) shows (r, g, b) + (1 − a)·c, so over black it shows (r, g, b). Values are the
///   display (sRGB) values that colour maps give, composited as they are (as matplotlib,
///   ParaView and VTK do), and may exceed 1 (emission) or be non-finite (a broken render); the
///   image stores them as they are and the statistics count the non-finite ones.
/// - Rows are stored top row first: pixel (x, y) is column x of row y, and y = 0 is the top of
///   the picture. OpenGL reads framebuffers bottom row first; call flipVertically() after such a
///   read-back.
/// - Depth, when present, is one float per pixel in whatever unit its producer documents; the
///   image does not interpret it. addDepth() starts it at +infinity (no surface).
class Image {
public:
    /// @brief The largest number of pixels an image may have (2²⁸: 4 GiB of RGBA floats), so a
    /// corrupt file header cannot make the reader allocate without bound.
    static constexpr std::size_t kMaxPixels = std::size_t{1} << 28;

    /// @brief Per-channel statistics over a region; non-finite pixels are counted, not averaged.
    struct Statistics {
        glm::dvec4 mean{0.0};    ///< mean of R, G, B, A over the finite pixels
        glm::dvec4 minimum{0.0}; ///< per-channel minimum over the finite pixels
        glm::dvec4 maximum{0.0}; ///< per-channel maximum over the finite pixels
        std::size_t finitePixels = 0;    ///< pixels whose four components are all finite
        std::size_t nonFinitePixels = 0; ///< pixels with at least one NaN or infinite component
    };

    /// @brief A width × height image of transparent black (0, 0, 0, 0), without depth.
    ///
    /// Throws DataError when a size is below 1 or the image would exceed kMaxPixels.
    Image(int width, int height);

    /// @brief A width × height image of `pixels` (premultiplied RGBA, top row first, width ×
    /// height of them), taken without a copy. Throws DataError as above, and when the count of
    /// pixels is not width × height.
    Image(int width, int height, Pixels pixels);

    /// @brief A width × height image whose pixels are left unset, for a producer that writes
    /// every one of them (a read-back): clearing them first would cost a pass over the image.
    /// Throws DataError as Image(width, height).
    static Image uncleared(int width, int height);

    /// @brief Number of columns.
    int width() const { return mWidth; }
    /// @brief Number of rows.
    int height() const { return mHeight; }
    /// @brief width() × height().
    std::size_t pixelCount() const { return mPixels.size(); }
    /// @brief The whole image as a region: (0, 0, width, height).
    ImageRegion bounds() const { return {0, 0, mWidth, mHeight}; }

    /// @brief The premultiplied RGBA value of pixel (x, y); y = 0 is the top row.
    const glm::vec4& pixel(int x, int y) const { return mPixels[index(x, y)]; }
    /// @brief Sets pixel (x, y) to a premultiplied RGBA value.
    void setPixel(int x, int y, const glm::vec4& rgba) { mPixels[index(x, y)] = rgba; }
    /// @brief All pixels, row by row from the top row, width() per row.
    const Pixels& pixels() const { return mPixels; }
    /// @brief Moves the pixels out, for a consumer that keeps them (a rank's layer for
    /// compositing), without a copy; the image is left without pixels or depth, 0 x 0.
    Pixels takePixels() &&;
    /// @brief The pixels as one writable array of pixelCount() values in the order of pixels(),
    /// for producers that fill an image in one go (a framebuffer read-back).
    glm::vec4* data() { return mPixels.data(); }
    /// @brief Sets every pixel to the premultiplied RGBA value `rgba`.
    void fill(const glm::vec4& rgba);

    /// @brief Whether the image has a depth channel.
    bool hasDepth() const { return !mDepth.empty(); }
    /// @brief Adds a depth channel filled with `clearValue` (replacing any existing one).
    void addDepth(float clearValue = std::numeric_limits<float>::infinity());
    /// @brief Depth of pixel (x, y); the image must have depth.
    float depth(int x, int y) const { return mDepth[depthIndex(x, y)]; }
    /// @brief Sets the depth of pixel (x, y); the image must have depth.
    void setDepth(int x, int y, float value) { mDepth[depthIndex(x, y)] = value; }
    /// @brief All depths in pixel order; empty when the image has no depth.
    const std::vector<float>& depths() const { return mDepth; }
    /// @brief The depths as one writable array of pixelCount() values; nullptr without depth.
    float* depthData() { return hasDepth() ? mDepth.data() : nullptr; }

    /// @brief Reverses the row order (color and depth), for framebuffers read bottom row first.
    void flipVertically();

    /// @brief Whether `region` is non-empty and lies inside the image.
    bool contains(const ImageRegion& region) const;
    /// @brief Throws DataError ("region 4,4 10x10 is not inside the 8x8 image") unless
    /// contains(region).
    void checkRegion(const ImageRegion& region) const;

    /// @brief Mean, minimum and maximum per channel over `region`, and the count of non-finite
    /// pixels there. When no pixel is finite, mean, minimum and maximum are NaN. Throws
    /// DataError when the region is not inside the image.
    Statistics statistics(const ImageRegion& region) const;
    /// @brief statistics() over the whole image.
    Statistics statistics() const { return statistics(bounds()); }

    /// @brief "WxH", the form sizes take in messages.
    std::string sizeString() const;

private:
    struct Unset {}; // uncleared()'s constructor
    Image(Unset tag, int width, int height);
    // width × height, after the constructors' checks (DataError).
    std::size_t checkedPixelCount() const;
    std::size_t index(int x, int y) const;
    std::size_t depthIndex(int x, int y) const;

    int mWidth;
    int mHeight;
    Pixels mPixels;
    std::vector<float> mDepth;
};

/// @brief Whether all four components of a pixel are finite.
bool isFinite(const glm::vec4& rgba);

} // namespace texsplat::image
