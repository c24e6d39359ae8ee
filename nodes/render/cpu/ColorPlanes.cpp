#include "nodes/render/cpu/ColorPlanes.h"

namespace texsplat::render::cpu {

ColorPlanes::ColorPlanes(int width, int height, const glm::vec4& background, bool withDepth)
    : mWidth(width), mHeight(height), mStride((width + 2 * kPadding - 1) / kPadding * kPadding) {
    const std::size_t size = static_cast<std::size_t>(mStride) * static_cast<std::size_t>(height);
    mRed.assign(size, background.r);
    mGreen.assign(size, background.g);
    mBlue.assign(size, background.b);
    mAlpha.assign(size, background.a);
    if (withDepth) {
        mDepth.assign(size, 1.0f);
    }
}

image::Image ColorPlanes::toImage(bool withDepth) const {
    image::Image result(mWidth, mHeight);
    glm::vec4* pixel = result.data();
    for (int row = 0; row < mHeight; ++row) {
        const std::size_t first = offset(row);
        for (int column = 0; column < mWidth; ++column) {
            const std::size_t i = first + static_cast<std::size_t>(column);
            *pixel++ = glm::vec4(mRed[i], mGreen[i], mBlue[i], mAlpha[i]);
        }
    }
    if (withDepth) {
        result.addDepth(1.0f);
        if (hasDepth()) {
            float* depth = result.depthData();
            for (int row = 0; row < mHeight; ++row) {
                for (int column = 0; column < mWidth; ++column) {
                    *depth++ = mDepth[offset(row) + static_cast<std::size_t>(column)];
                }
            }
        }
    }
    return result;
}

std::size_t ColorPlanes::byteSize() const {
    return (mRed.size() + mGreen.size() + mBlue.size() + mAlpha.size() + mDepth.size()) *
           sizeof(float);
}

} // namespace texsplat::render::cpu
