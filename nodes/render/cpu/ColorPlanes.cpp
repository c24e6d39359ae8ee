#include "nodes/render/cpu/ColorPlanes.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace texsplat::render::cpu {
namespace {

// Floats per 4 KiB page and per cache line.
constexpr std::ptrdiff_t kPageFloats = 1024;
constexpr std::ptrdiff_t kLineFloats = 16;
// Floats cleared by one task: 64 KiB, a piece of work worth a task and a whole number of pages.
constexpr std::ptrdiff_t kPieceFloats = 16 * kPageFloats;

} // namespace

ColorPlanes::ColorPlanes(int width, int height, const glm::vec4& background, bool withDepth)
    : mWidth(width), mHeight(height),
      mStride((width + 2 * kPadding + kLineFloats - 1) / kLineFloats * kLineFloats),
      mHasDepth(withDepth) {
    const std::ptrdiff_t values = static_cast<std::ptrdiff_t>(mStride) * height;
    mPlaneStride = (values + kPageFloats - 1) / kPageFloats * kPageFloats + kLineFloats;
    mValues.resize(static_cast<std::size_t>(mPlaneStride * (withDepth ? 5 : 4)));
    clear(background);
}

void ColorPlanes::clear(const glm::vec4& background) {
    const int planes = mHasDepth ? 5 : 4;
    const std::ptrdiff_t piecesPerPlane = (mPlaneStride + kPieceFloats - 1) / kPieceFloats;
    tbb::parallel_for(std::ptrdiff_t{0}, planes * piecesPerPlane, [&](std::ptrdiff_t piece) {
        const int index = static_cast<int>(piece / piecesPerPlane);
        const std::ptrdiff_t begin = piece % piecesPerPlane * kPieceFloats;
        std::fill_n(plane(index) + begin, std::min(kPieceFloats, mPlaneStride - begin),
                    index < 4 ? background[index] : 1.0f);
    });
}

void ColorPlanes::copyRows(image::Image& image, int rowBegin, int rowEnd, bool withDepth) const {
    glm::vec4* pixel = image.data() + static_cast<std::ptrdiff_t>(rowBegin) * mWidth;
    for (int row = rowBegin; row < rowEnd; ++row) {
        const float* r = red(row);
        const float* g = green(row);
        const float* b = blue(row);
        const float* a = alpha(row);
        for (int column = 0; column < mWidth; ++column) {
            *pixel++ = glm::vec4(r[column], g[column], b[column], a[column]);
        }
    }
    if (withDepth && mHasDepth) {
        float* depthOut = image.depthData() + static_cast<std::ptrdiff_t>(rowBegin) * mWidth;
        for (int row = rowBegin; row < rowEnd; ++row) {
            depthOut = std::copy_n(depth(row), mWidth, depthOut);
        }
    }
}

image::Image ColorPlanes::toImage(bool withDepth) const {
    image::Image result = image::Image::uncleared(mWidth, mHeight);
    if (withDepth) {
        result.addDepth(1.0f);
    }
    copyRows(result, 0, mHeight, withDepth);
    return result;
}

} // namespace texsplat::render::cpu
