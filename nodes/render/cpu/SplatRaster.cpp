#include "nodes/render/cpu/SplatRaster.h"

#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/RadialKernel.h"
#include "octree/Splat.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
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

// The cubic c0 + c1·v + c2·v² + c3·v³ through (v[j], y[j]), j < 4: the Vandermonde system
// solved with GLM's inverse (the nodes are distinct and within ½ of 0: well conditioned).
std::array<double, 4> cubicThrough(const double (&v)[4], const double (&y)[4]) {
    glm::dmat4 vandermonde; // column k holds v^k, row j belongs to node j
    for (int j = 0; j < 4; ++j) {
        double power = 1.0;
        for (int k = 0; k < 4; ++k, power *= v[j]) {
            vandermonde[k][j] = power;
        }
    }
    const glm::dvec4 c = glm::inverse(vandermonde) * glm::dvec4(y[0], y[1], y[2], y[3]);
    return {c[0], c[1], c[2], c[3]};
}

// Fits `sampler.pieces` to the footprint f(extent·r) over r ∈ [0, √reach] and measures how far
// they stray from it. In p = r·piecesPerRadius ∈ [0, kPieces − 1], piece i covers p ∈ [i − ½,
// i + ½] (the end pieces only their halves inside), in v = p − i, so that the SIMD loop finds it
// by rounding p. Each is the cubic through the kernel at four evenly spaced points of its
// interval, so neighbours meet; the coefficients are rounded to float before the error is
// measured, as the loop evaluates them. In r rather than ρ = r²: the paper's kernel has a |r|³
// term, a cusp in ρ at the centre that cubics in ρ follow only to 8e-5 of the peak.
void fitPieces(FootprintSampler& sampler, const kernel::RadialKernel& kernel, double extent) {
    constexpr int kPieces = FootprintSampler::kPieces;
    const double perRadius = (kPieces - 1) / std::sqrt(static_cast<double>(sampler.reach));
    const auto exact = [&](double position) {
        return kernel.footprint(extent * position / perRadius);
    };
    double error = 0.0;
    for (int piece = 0; piece < kPieces; ++piece) {
        const double low = std::max(piece - 0.5, 0.0) - piece;
        const double high = std::min(piece + 0.5, kPieces - 1.0) - piece;
        double v[4];
        double y[4];
        for (int node = 0; node < 4; ++node) {
            v[node] = low + (high - low) * node / 3.0;
            y[node] = exact(piece + v[node]);
        }
        const std::array<double, 4> c = cubicThrough(v, y);
        for (std::size_t k = 0; k < 4; ++k) {
            sampler.pieces[k][static_cast<std::size_t>(piece)] = static_cast<float>(c[k]);
        }
        constexpr int kChecks = 48;
        for (int check = 0; check <= kChecks; ++check) {
            const double at = low + (high - low) * check / kChecks;
            error = std::max(error, std::abs(sampler.piece(piece, static_cast<float>(at)) -
                                             exact(piece + at)));
        }
    }
    sampler.piecesPerRadius = static_cast<float>(perRadius);
    sampler.pieceError = static_cast<float>(error);
    sampler.hasPieces = error <= FootprintSampler::kPieceTolerance * sampler.peak;
}

} // namespace

FootprintSampler::FootprintSampler(const SplatFootprint& footprint) {
    const bool square = footprint.shape == SplatShape::TexturedSquare ||
                        footprint.shape == SplatShape::CombinedMarks;
    if (square && footprint.kernel) {
        isRadial = true;
        values.resize(kProfileSamples + 2);
        for (int i = 0; i <= kProfileSamples + 1; ++i) {
            const double rho = 2.0 * std::min(i, kProfileSamples) / kProfileSamples;
            values[static_cast<std::size_t>(i)] =
                static_cast<float>(footprint.kernel->footprint(footprint.extent * std::sqrt(rho)));
        }
        peak = *std::max_element(values.begin(), values.end());
        // The last sample that is not 0, and the next: the profile is 0 from there on.
        int last = kProfileSamples;
        while (last > 0 && values[static_cast<std::size_t>(last)] == 0.0f) {
            --last;
        }
        reach = 2.0f * static_cast<float>(std::min(last + 1, kProfileSamples)) / kProfileSamples;
        fitPieces(*this, *footprint.kernel, footprint.extent);
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

SplatSetup::SplatSetup(const SplatView& view, float extent, int width, int height, float discRadius)
    : mView(view) {
    const glm::mat4& m = view.localToClip;
    mRows.extent = extent;
    mRows.discRadius = discRadius;
    mRows.width = width;
    mRows.height = height;
    mRows.isPerspective = view.isPerspective;
    for (int axis = 0; axis < 3; ++axis) {
        mRows.eye[axis] = view.eye[axis];
        mRows.direction[axis] = view.direction[axis];
        mRows.inverseSpacing[axis] = 1.0f / view.spacing[axis];
    }
    // Clip space → homogeneous pixel (x·W, y·W, W, z), rows top first: x = (X/W + 1)·width/2,
    // y = (1 − Y/W)·height/2.
    const float halfWidthF = 0.5f * static_cast<float>(width);
    const float halfHeightF = 0.5f * static_cast<float>(height);
    for (int column = 0; column < 4; ++column) {
        const glm::vec4 clip = m[column];
        const float rows[4] = {halfWidthF * (clip.x + clip.w), halfHeightF * (clip.w - clip.y),
                               clip.w, clip.z};
        for (int row = 0; row < 4; ++row) {
            mRows.pixelFromLocal[row][column] = rows[row];
            if (column < 3) {
                mRows.pixelFromVoxel[row][column] = rows[row] * view.spacing[column];
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
        mIsAffine = false; // the projective set-up finds the degenerate square
        return;
    }
    mUnit.squareFromPixel[0][0] = p11 / determinant;
    mUnit.squareFromPixel[0][1] = -p01 / determinant;
    mUnit.squareFromPixel[1][0] = -p10 / determinant;
    mUnit.squareFromPixel[1][1] = p00 / determinant;
    // The square's box, or the box of the ellipse the footprint's disc projects to where that
    // is smaller (ProjectiveRows::discRadius).
    mUnit.halfExtent[0] = std::abs(p00) + std::abs(p01);
    mUnit.halfExtent[1] = std::abs(p10) + std::abs(p11);
    if (discRadius > 0.0f) {
        mUnit.halfExtent[0] = std::min(mUnit.halfExtent[0], discRadius * std::hypot(p00, p01));
        mUnit.halfExtent[1] = std::min(mUnit.halfExtent[1], discRadius * std::hypot(p10, p11));
    }
    for (int axis = 0; axis < 2; ++axis) {
        mDepthGradient[axis] =
            cu.z * mUnit.squareFromPixel[0][axis] + cv.z * mUnit.squareFromPixel[1][axis];
    }
    mDepthReach = std::abs(cu.z) + std::abs(cv.z);
    mUnit.lengthScale = 1.0f / frame.eLength;
}

void SplatSetup::setUp(const octree::Splat* splats, std::size_t count, SplatRaster* out) const {
    if (!mIsAffine) {
        setUpProjective(mRows, splats, count, out);
        return;
    }
    for (std::size_t i = 0; i < count; ++i) {
        out[i] = orthographic(splats[i]);
    }
}

SplatRaster SplatSetup::orthographic(const octree::Splat& splat) const {
    // The centre's pixel and depth, by the rows of pixelFromLocal (W = 1 in an affine view),
    // written out: glm's mat4 × vec4 stayed a call at -O2, a fifth of the set-up's time.
    const Centre centre = centreOf(splat.position);
    const double size = splat.size;
    if (centre.z - size * mDepthReach > 1.0 || centre.z + size * mDepthReach < -1.0) {
        return {};
    }
    const bool crossesPlanes =
        centre.z - size * mDepthReach < -1.0 || centre.z + size * mDepthReach > 1.0;
    SplatRaster raster{};
    raster.flags = crossesPlanes ? SplatRaster::kClipped : 0;
    if (!(mStamps && size == 1.0 && !crossesPlanes && stamp(raster, centre))) {
        const double reachX = size * mUnit.halfExtent[0];
        const double reachY = size * mUnit.halfExtent[1];
        raster.columnBegin = toPixel(std::floor(centre.x - reachX), 0, mRows.width);
        raster.columnEnd = toPixel(std::ceil(centre.x + reachX) + 1.0, 0, mRows.width);
        raster.rowBegin = toPixel(std::floor(centre.y - reachY), 0, mRows.height);
        raster.rowEnd = toPixel(std::ceil(centre.y + reachY) + 1.0, 0, mRows.height);
    }
    if (raster.isEmpty()) {
        return {};
    }
    // (a, b) at pixel centre (x + ½, y + ½): S⁻¹/size · (x + ½ − centreX, y + ½ − centreY).
    const auto dx = static_cast<float>(0.5 - centre.x);
    const auto dy = static_cast<float>(0.5 - centre.y);
    for (int row = 0; row < 2; ++row) {
        // Most splats are voxels (size 1): no division, whose latency the set-up waited on.
        const float sx = size == 1.0 ? mUnit.squareFromPixel[row][0]
                                     : mUnit.squareFromPixel[row][0] / splat.size;
        const float sy = size == 1.0 ? mUnit.squareFromPixel[row][1]
                                     : mUnit.squareFromPixel[row][1] / splat.size;
        raster.square[3 * row] = sx;
        raster.square[3 * row + 1] = sy;
        raster.square[3 * row + 2] = sx * dx + sy * dy;
    }
    raster.square[8] = 1.0f;
    raster.depth[0] = mDepthGradient[0];
    raster.depth[1] = mDepthGradient[1];
    raster.depth[2] =
        static_cast<float>(centre.z) + mDepthGradient[0] * dx + mDepthGradient[1] * dy;
    raster.color[0] = splat.color.r;
    raster.color[1] = splat.color.g;
    raster.color[2] = splat.color.b;
    raster.extinction = splat.extinction;
    raster.lengthScale = splat.size * mUnit.lengthScale;
    return raster;
}

std::shared_ptr<const FootprintStamps>
SplatSetup::stampsFor(const FootprintSampler& sampler) const {
    if (!mIsAffine || !FootprintStamps::suits(sampler, mUnit)) {
        return nullptr;
    }
    auto stamps = std::make_shared<const FootprintStamps>(sampler, mUnit);
    if (!(stamps->error <= FootprintStamps::kTolerance * stamps->peak)) {
        return nullptr;
    }
    return stamps;
}

bool SplatSetup::stamp(SplatRaster& raster, const Centre& centre) const {
    FootprintStamps::Place place;
    if (!mStamps->place(centre.x, centre.y, place)) {
        return false;
    }
    raster.stampColumn = place.column;
    raster.stampRow = place.row;
    raster.stampPhase = place.phase;
    // The pixels the stamp reaches.
    const FootprintStamps::Extent& reach = mStamps->extents[static_cast<std::size_t>(place.phase)];
    raster.columnBegin = std::clamp(place.column + reach.columnBegin, 0, mRows.width);
    raster.columnEnd = std::clamp(place.column + reach.columnEnd, 0, mRows.width);
    raster.rowBegin = std::clamp(place.row + reach.rowBegin, 0, mRows.height);
    raster.rowEnd = std::clamp(place.row + reach.rowEnd, 0, mRows.height);
    raster.flags |= SplatRaster::kStamped;
    return true;
}

} // namespace texsplat::render::cpu
