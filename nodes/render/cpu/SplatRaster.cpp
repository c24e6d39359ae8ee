#include "nodes/render/cpu/SplatRaster.h"

#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/RadialKernel.h"
#include "octree/Splat.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace texsplat::render::cpu {
namespace {

// Clamps a pixel coordinate to [low, high] before it becomes an int (it may be huge or NaN).
std::int32_t toPixel(double value, int low, int high) {
    if (!(value > low)) {
        return low;
    }
    return value < high ? static_cast<std::int32_t>(value) : high;
}

// The facing frame of detail/SplatShaders.h's splatFrame() for the line of sight `sight`, in the
// same float arithmetic: e = sight / spacing, the square's axes u, v in voxel space.
struct SquareFrame {
    glm::vec3 u;
    glm::vec3 v;
    float eLength;
};

SquareFrame squareFrame(const SplatView& view, const glm::vec3& sight) {
    const glm::vec3 e = sight / view.spacing;
    const float eLength = glm::length(e);
    const glm::vec3 axis = e / eLength;
    const glm::vec3 helper =
        std::abs(axis.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 u = glm::normalize(glm::cross(helper, axis));
    return {u, glm::cross(axis, u), eLength};
}

} // namespace

FootprintSampler::FootprintSampler(const SplatFootprint& footprint) {
    if (footprint.shape == SplatShape::TexturedSquare && footprint.kernel) {
        isRadial = true;
        values.resize(kProfileSamples + 2);
        for (int i = 0; i <= kProfileSamples + 1; ++i) {
            const double rho = 2.0 * std::min(i, kProfileSamples) / kProfileSamples;
            values[static_cast<std::size_t>(i)] =
                static_cast<float>(footprint.kernel->footprint(footprint.extent * std::sqrt(rho)));
        }
        peak = *std::max_element(values.begin(), values.end());
        return;
    }
    const kernel::FootprintTexture& texture = *footprint.texture;
    resolution = texture.resolution();
    stride = resolution + 2;
    values.resize(static_cast<std::size_t>(stride) * static_cast<std::size_t>(stride));
    const std::vector<float>& source = texture.texels();
    for (int row = 0; row < stride; ++row) {
        const int sourceRow = std::clamp(row - 1, 0, resolution - 1);
        for (int column = 0; column < stride; ++column) {
            const int sourceColumn = std::clamp(column - 1, 0, resolution - 1);
            values[static_cast<std::size_t>(row) * stride + column] =
                source[static_cast<std::size_t>(sourceRow) * resolution + sourceColumn];
        }
    }
    peak = *std::max_element(values.begin(), values.end());
}

SplatSetup::SplatSetup(const SplatView& view, float extent, int width, int height)
    : mView(view), mExtent(extent), mWidth(width), mHeight(height) {
    const glm::mat4& m = view.localToClip;
    // Clip space → homogeneous pixel (x·W, y·W, W, z), rows top first: x = (X/W + 1)·width/2,
    // y = (1 − Y/W)·height/2.
    const float halfWidthF = 0.5f * static_cast<float>(width);
    const float halfHeightF = 0.5f * static_cast<float>(height);
    for (int column = 0; column < 4; ++column) {
        const glm::vec4 clip = m[column];
        const float rows[4] = {halfWidthF * (clip.x + clip.w), halfHeightF * (clip.w - clip.y),
                               clip.w, clip.z};
        for (int row = 0; row < 4; ++row) {
            mPixelFromLocal[row][column] = rows[row];
            if (column < 3) {
                mPixelFromVoxel[row][column] = rows[row] * view.spacing[column];
            }
        }
    }
    mIsAffine = !view.isPerspective && m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f &&
                m[3][3] == 1.0f;
    if (!mIsAffine) {
        return;
    }
    const SquareFrame frame = squareFrame(view, view.direction);
    const glm::vec4 cu = m * glm::vec4(view.spacing * frame.u * extent, 0.0f);
    const glm::vec4 cv = m * glm::vec4(view.spacing * frame.v * extent, 0.0f);
    const float halfWidth = 0.5f * static_cast<float>(width);
    const float halfHeight = 0.5f * static_cast<float>(height);
    const float p00 = halfWidth * cu.x, p01 = halfWidth * cv.x;
    const float p10 = -halfHeight * cu.y, p11 = -halfHeight * cv.y;
    const float determinant = p00 * p11 - p01 * p10;
    if (!std::isfinite(determinant) || determinant == 0.0f) {
        mIsAffine = false; // let the general path find the degenerate square
        return;
    }
    mPixelFromSquare[0][0] = p00;
    mPixelFromSquare[0][1] = p01;
    mPixelFromSquare[1][0] = p10;
    mPixelFromSquare[1][1] = p11;
    mSquareFromPixel[0][0] = p11 / determinant;
    mSquareFromPixel[0][1] = -p01 / determinant;
    mSquareFromPixel[1][0] = -p10 / determinant;
    mSquareFromPixel[1][1] = p00 / determinant;
    mHalfExtent[0] = std::abs(p00) + std::abs(p01);
    mHalfExtent[1] = std::abs(p10) + std::abs(p11);
    for (int axis = 0; axis < 2; ++axis) {
        mDepthGradient[axis] =
            cu.z * mSquareFromPixel[0][axis] + cv.z * mSquareFromPixel[1][axis];
    }
    mDepthReach = std::abs(cu.z) + std::abs(cv.z);
    mLengthScale = 1.0f / frame.eLength;
}

SplatRaster SplatSetup::operator()(const octree::Splat& splat) const {
    return mIsAffine ? orthographic(splat) : general(splat);
}

SplatRaster SplatSetup::orthographic(const octree::Splat& splat) const {
    SplatRaster raster{};
    const glm::mat4& m = mView.localToClip;
    const glm::vec4 c0 = m * glm::vec4(splat.position, 1.0f);
    const float size = splat.size;
    if (c0.z - size * mDepthReach > 1.0f || c0.z + size * mDepthReach < -1.0f) {
        return raster;
    }
    const float centreX = 0.5f * static_cast<float>(mWidth) * (c0.x + 1.0f);
    const float centreY = 0.5f * static_cast<float>(mHeight) * (1.0f - c0.y);
    const float reachX = size * mHalfExtent[0];
    const float reachY = size * mHalfExtent[1];
    raster.columnBegin = toPixel(std::floor(centreX - reachX), 0, mWidth);
    raster.columnEnd = toPixel(std::ceil(centreX + reachX) + 1.0, 0, mWidth);
    raster.rowBegin = toPixel(std::floor(centreY - reachY), 0, mHeight);
    raster.rowEnd = toPixel(std::ceil(centreY + reachY) + 1.0, 0, mHeight);
    if (raster.isEmpty()) {
        return raster;
    }
    // (a, b) at pixel centre (x + ½, y + ½): S⁻¹/size · (x + ½ − centreX, y + ½ − centreY).
    const float dx = 0.5f - centreX;
    const float dy = 0.5f - centreY;
    for (int row = 0; row < 2; ++row) {
        const float sx = mSquareFromPixel[row][0] / size;
        const float sy = mSquareFromPixel[row][1] / size;
        raster.square[3 * row] = sx;
        raster.square[3 * row + 1] = sy;
        raster.square[3 * row + 2] = sx * dx + sy * dy;
    }
    raster.square[8] = 1.0f;
    raster.depth[0] = mDepthGradient[0];
    raster.depth[1] = mDepthGradient[1];
    raster.depth[2] = c0.z + mDepthGradient[0] * dx + mDepthGradient[1] * dy;
    raster.color[0] = splat.color.r;
    raster.color[1] = splat.color.g;
    raster.color[2] = splat.color.b;
    raster.extinction = splat.extinction;
    raster.lengthScale = size * mLengthScale;
    const bool crossesPlanes =
        c0.z - size * mDepthReach < -1.0f || c0.z + size * mDepthReach > 1.0f;
    raster.flags = crossesPlanes ? SplatRaster::kClipped : 0;
    return raster;
}

SplatRaster SplatSetup::general(const octree::Splat& splat) const {
    SplatRaster raster{};
    const glm::vec3& c = splat.position;
    glm::vec3 sight = mView.direction;
    if (mView.isPerspective) {
        const glm::vec3 toCentre = c - mView.eye;
        const float distance = glm::length(toCentre);
        if (distance > 0.0f) {
            sight = toCentre / distance;
        }
    }
    const SquareFrame frame = squareFrame(mView, sight);
    const float reach = mExtent * splat.size;
    // Rows of the homogeneous pixel (x·W, y·W, W) and z_clip: of the centre, and per unit of the
    // square's a and b.
    float h0[4], hu[4], hv[4];
    for (int row = 0; row < 4; ++row) {
        const float* p = mPixelFromLocal[row];
        const float* q = mPixelFromVoxel[row];
        h0[row] = p[0] * c.x + p[1] * c.y + p[2] * c.z + p[3];
        hu[row] = reach * (q[0] * frame.u.x + q[1] * frame.u.y + q[2] * frame.u.z);
        hv[row] = reach * (q[0] * frame.v.x + q[1] * frame.v.y + q[2] * frame.v.z);
    }
    // Square (a, b, 1) → (x·W, y·W, W) is the matrix [hu hv h0]; its inverse by the adjugate.
    const float c00 = hv[1] * h0[2] - h0[1] * hv[2];
    const float c01 = h0[1] * hu[2] - hu[1] * h0[2];
    const float c02 = hu[1] * hv[2] - hv[1] * hu[2];
    const float determinant = hu[0] * c00 + hv[0] * c01 + h0[0] * c02;
    if (!std::isfinite(determinant) || determinant == 0.0f) {
        return raster; // edge-on or degenerate: no pixel
    }
    const float s = 1.0f / determinant;
    float inverse[3][3] = {
        {c00 * s, (h0[0] * hv[2] - hv[0] * h0[2]) * s, (hv[0] * h0[1] - h0[0] * hv[1]) * s},
        {c01 * s, (hu[0] * h0[2] - h0[0] * hu[2]) * s, (h0[0] * hu[1] - hu[0] * h0[1]) * s},
        {c02 * s, (hv[0] * hu[2] - hu[0] * hv[2]) * s, (hu[0] * hv[1] - hv[0] * hu[1]) * s}};
    // Evaluated at pixel centres (x + ½, y + ½): fold the half into the constant column.
    for (float(&row)[3] : inverse) {
        row[2] += 0.5f * (row[0] + row[1]);
    }
    for (int column = 0; column < 3; ++column) {
        raster.square[column] = inverse[0][column];
        raster.square[3 + column] = inverse[1][column];
        raster.square[6 + column] = inverse[2][column];
        // z_clip = (hu, hv, h0)_z · (a, b, 1), and (a, b, 1)/W = inverse · pixel.
        raster.depth[column] =
            hu[3] * inverse[0][column] + hv[3] * inverse[1][column] + h0[3] * inverse[2][column];
    }

    // The pixels the square may cover, from its corners; GL clips it at the near and far planes.
    float low[2] = {static_cast<float>(mWidth), static_cast<float>(mHeight)};
    float high[2] = {0.0f, 0.0f};
    bool behindEye = false;
    int beforeNear = 0;
    int beyondFar = 0;
    for (const float a : {-1.0f, 1.0f}) {
        for (const float b : {-1.0f, 1.0f}) {
            const float w = h0[2] + a * hu[2] + b * hv[2];
            const float z = h0[3] + a * hu[3] + b * hv[3];
            beforeNear += z < -w ? 1 : 0;
            beyondFar += z > w ? 1 : 0;
            if (!(w > 0.0f)) {
                behindEye = true;
                continue;
            }
            const float inverseW = 1.0f / w;
            const float x = (h0[0] + a * hu[0] + b * hv[0]) * inverseW;
            const float y = (h0[1] + a * hu[1] + b * hv[1]) * inverseW;
            low[0] = std::min(low[0], x);
            low[1] = std::min(low[1], y);
            high[0] = std::max(high[0], x);
            high[1] = std::max(high[1], y);
        }
    }
    if (beforeNear == 4 || beyondFar == 4) {
        return raster;
    }
    if (behindEye) {
        // Part of the square is behind the eye: its visible part may reach any pixel.
        low[0] = low[1] = 0.0f;
        high[0] = static_cast<float>(mWidth);
        high[1] = static_cast<float>(mHeight);
    }
    raster.columnBegin = toPixel(std::floor(low[0]), 0, mWidth);
    raster.columnEnd = toPixel(std::ceil(high[0]) + 1.0, 0, mWidth);
    raster.rowBegin = toPixel(std::floor(low[1]), 0, mHeight);
    raster.rowEnd = toPixel(std::ceil(high[1]) + 1.0, 0, mHeight);
    raster.color[0] = splat.color.r;
    raster.color[1] = splat.color.g;
    raster.color[2] = splat.color.b;
    raster.extinction = splat.extinction;
    raster.lengthScale = splat.size / frame.eLength;
    raster.flags = (mView.isPerspective ? SplatRaster::kProjective : 0) |
                   (beforeNear > 0 || beyondFar > 0 || behindEye ? SplatRaster::kClipped : 0);
    return raster;
}

} // namespace texsplat::render::cpu
