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
/// Rows are `stride()` floats apart, at least kPadding floats more than the width, so a SIMD
/// loop may run past the last column of a row (into padding nobody reads) without a tail.
class ColorPlanes {
public:
    /// @brief The widest SIMD vector in floats (AVX-512), the padding after each row.
    static constexpr int kPadding = 16;

    /// @brief `width` x `height` planes cleared to `background`, with a depth plane cleared to
    /// 1 when `withDepth`.
    ColorPlanes(int width, int height, const glm::vec4& background, bool withDepth);

    int width() const { return mWidth; }   ///< columns
    int height() const { return mHeight; } ///< rows
    int stride() const { return mStride; } ///< floats from one row to the next
    bool hasDepth() const { return !mDepth.empty(); } ///< whether there is a depth plane

    float* red(int row) { return mRed.data() + offset(row); }     ///< row `row`, top first
    float* green(int row) { return mGreen.data() + offset(row); } ///< row `row`, top first
    float* blue(int row) { return mBlue.data() + offset(row); }   ///< row `row`, top first
    float* alpha(int row) { return mAlpha.data() + offset(row); } ///< row `row`, top first
    float* depth(int row) { return mDepth.data() + offset(row); } ///< needs hasDepth()

    /// @brief The planes as an image (RGBA interleaved, top row first), with the depth plane
    /// when there is one and `withDepth` (1 where nothing opaque is, as GL reads back).
    image::Image toImage(bool withDepth) const;

    /// @brief Bytes the planes hold.
    std::size_t byteSize() const;

private:
    std::size_t offset(int row) const { return static_cast<std::size_t>(row) * mStride; }

    int mWidth;
    int mHeight;
    int mStride;
    using Plane = std::vector<float, detail::CacheLineAllocator<float>>;
    Plane mRed, mGreen, mBlue, mAlpha, mDepth;
};

} // namespace texsplat::render::cpu
