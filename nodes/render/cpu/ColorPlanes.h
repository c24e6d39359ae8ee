#pragma once

#include "nodes/image/Image.h"
#include "nodes/render/cpu/detail/CacheLineAllocator.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace texsplat::render::cpu {

/// @brief The CPU backend's render target: premultiplied RGBA as four float planes (structure of
/// arrays, so one SIMD vector holds one channel of adjacent pixels) and, when the frame has
/// meshes, a window-space depth plane as GL's depth buffer holds it ([0, 1], 1 = nothing).
///
/// Each row has kPadding floats before its first column and at least as many after its last, so
/// a SIMD loop may write a vector at any column within kPadding of the image (a stamp row that
/// starts left of it, a tail past its last column) into padding nobody reads. The planes lie in
/// one allocation, `planeStride()` floats apart: a whole number of 4 KiB pages and one cache line,
/// so that the same pixel of two planes never shares its address modulo 4 KiB (a load from one
/// plane right after a store to another at such an address waits for the store).
class ColorPlanes {
public:
    /// @brief Floats before and after each row: the widest stamp row (FootprintStamps).
    static constexpr int kPadding = 32;

    /// @brief `width` x `height` planes cleared to `background`, with a depth plane cleared to
    /// 1 when `withDepth`.
    ColorPlanes(int width, int height, const glm::vec4& background, bool withDepth);

    /// @brief Clears the planes to `background` (and the depth plane to 1), as a new object of
    /// the same size and depth would be, in the memory they hold: a frame after frame of the
    /// same size faults no page in. Pieces of the planes are cleared in parallel (in the calling
    /// task arena), so that a new object's pages are also faulted in by all its threads.
    void clear(const glm::vec4& background);

    int width() const { return mWidth; }   ///< columns
    int height() const { return mHeight; } ///< rows
    int stride() const { return mStride; } ///< floats from one row to the next
    /// @brief Floats from a pixel of one plane to the same pixel of the next (red, green, blue,
    /// alpha, depth).
    std::ptrdiff_t planeStride() const { return mPlaneStride; }
    bool hasDepth() const { return mHasDepth; } ///< whether there is a depth plane

    float* red(int row) { return plane(0) + offset(row); }               ///< row `row`, top first
    float* green(int row) { return plane(1) + offset(row); }             ///< row `row`, top first
    float* blue(int row) { return plane(2) + offset(row); }              ///< row `row`, top first
    float* alpha(int row) { return plane(3) + offset(row); }             ///< row `row`, top first
    float* depth(int row) { return plane(4) + offset(row); }             ///< needs hasDepth()
    const float* red(int row) const { return plane(0) + offset(row); }   ///< row `row`
    const float* green(int row) const { return plane(1) + offset(row); } ///< row `row`
    const float* blue(int row) const { return plane(2) + offset(row); }  ///< row `row`
    const float* alpha(int row) const { return plane(3) + offset(row); } ///< row `row`
    const float* depth(int row) const { return plane(4) + offset(row); } ///< needs hasDepth()

    /// @brief The planes as an image (RGBA interleaved, top row first), with the depth plane
    /// when there is one and `withDepth` (1 where nothing opaque is, as GL reads back).
    image::Image toImage(bool withDepth) const;

    /// @brief Rows [`rowBegin`, `rowEnd`) of toImage() written into `image` (of this size): what
    /// the threads of a band do once it is drawn.
    void copyRows(image::Image& image, int rowBegin, int rowEnd, bool withDepth) const;

    /// @brief Bytes the planes hold.
    std::size_t byteSize() const { return mValues.size() * sizeof(float); }

private:
    float* plane(int index) { return mValues.data() + index * mPlaneStride; }
    const float* plane(int index) const { return mValues.data() + index * mPlaneStride; }
    std::ptrdiff_t offset(int row) const {
        return static_cast<std::ptrdiff_t>(row) * mStride + kPadding;
    }

    int mWidth;
    int mHeight;
    int mStride;
    std::ptrdiff_t mPlaneStride;
    bool mHasDepth;
    std::vector<float, detail::CacheLineAllocator<float>> mValues;
};

} // namespace texsplat::render::cpu
