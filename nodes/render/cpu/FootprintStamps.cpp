#include "nodes/render/cpu/FootprintStamps.h"

#include "nodes/render/cpu/SplatRaster.h"

#include <algorithm>
#include <cmath>

namespace texsplat::render::cpu {
namespace {

// The footprint times `scale` at pixel offset (x, y) from the centre: the cubic pieces at
// r = √(a² + b²), 0 beyond the reach (as the exact lookup of SplatSpans.cpp).
float footprintAt(const FootprintSampler& sampler, const float (&squareFromPixel)[2][2],
                  float scale, double x, double y) {
    const auto a = static_cast<float>(squareFromPixel[0][0] * x + squareFromPixel[0][1] * y);
    const auto b = static_cast<float>(squareFromPixel[1][0] * x + squareFromPixel[1][1] * y);
    const float rho = a * a + b * b;
    if (!(rho <= sampler.reach)) {
        return 0.0f;
    }
    const float position = std::min(std::sqrt(rho) * sampler.piecesPerRadius,
                                     FootprintSampler::kPieces - 1.0f);
    const float nearest = std::nearbyint(position);
    return std::max(sampler.piece(static_cast<int>(nearest), position - nearest), 0.0f) * scale;
}

} // namespace

bool FootprintStamps::suits(const FootprintSampler& sampler, const float (&halfExtent)[2]) {
    // A stamp spans 2·halfExtent + 4 pixels at most (see the constructor).
    const auto fits = [](float reach) { return 2.0f * reach + 4.0f <= kLargestSide; };
    return sampler.isRadial && sampler.hasPieces && sampler.reach <= 1.0f &&
           fits(halfExtent[0]) && fits(halfExtent[1]);
}

FootprintStamps::FootprintStamps(const FootprintSampler& sampler,
                                 const float (&squareFromPixel)[2][2],
                                 const float (&halfExtent)[2], float lengthScale) {
    // A centre q/kPhases (q <= kPhases) past the centre of pixel c0 reaches pixels c0 − reach …
    // c0 + 1 + reach.
    columnOffset = static_cast<int>(std::floor(-halfExtent[0]));
    rowOffset = static_cast<int>(std::floor(-halfExtent[1]));
    columns = static_cast<int>(std::ceil(1.0f + halfExtent[0])) - columnOffset + 1;
    rows = static_cast<int>(std::ceil(1.0f + halfExtent[1])) - rowOffset + 1;
    stride = (kPad + columns + kPad + 15) / 16 * 16;
    stampSize = static_cast<std::size_t>(rows) * static_cast<std::size_t>(stride);
    values.assign(stampSize * (kPhases + 1) * (kPhases + 1), 0.0f);
    peak = sampler.peak * lengthScale;
    // The footprint with its centre (px, py) pixels past the centre of pixel (0, 0), at stamp
    // pixel (column, row).
    const auto exact = [&](double px, double py, int column, int row) {
        return footprintAt(sampler, squareFromPixel, lengthScale, column + columnOffset - px,
                           row + rowOffset - py);
    };
    for (int qy = 0; qy <= kPhases; ++qy) {
        for (int qx = 0; qx <= kPhases; ++qx) {
            float* stamp = values.data() + static_cast<std::size_t>(phaseIndex(qx, qy)) * stampSize;
            for (int row = 0; row < rows; ++row) {
                for (int column = 0; column < columns; ++column) {
                    stamp[static_cast<std::size_t>(row) * static_cast<std::size_t>(stride) +
                          static_cast<std::size_t>(kPad + column)] =
                        exact(static_cast<double>(qx) / kPhases, static_cast<double>(qy) / kPhases,
                              column, row);
                }
            }
        }
    }
    // The blend strays farthest midway between the stamps.
    extents.resize(static_cast<std::size_t>(kPhases) * kPhases);
    for (int qy = 0; qy < kPhases; ++qy) {
        for (int qx = 0; qx < kPhases; ++qx) {
            const std::int32_t phase = phaseIndex(qx, qy);
            Extent& extent = extents[static_cast<std::size_t>(qy * kPhases + qx)];
            extent = {columns, 0, rows, 0};
            for (int row = 0; row < rows; ++row) {
                for (int column = 0; column < columns; ++column) {
                    if (at(phase, column, row) != 0.0f || at(phase + 1, column, row) != 0.0f ||
                        at(phase + kPhases + 1, column, row) != 0.0f ||
                        at(phase + kPhases + 2, column, row) != 0.0f) {
                        extent.columnBegin = std::min(extent.columnBegin, column);
                        extent.columnEnd = std::max(extent.columnEnd, column + 1);
                        extent.rowBegin = std::min(extent.rowBegin, row);
                        extent.rowEnd = std::max(extent.rowEnd, row + 1);
                    }
                    const float footprint = exact((qx + 0.5) / kPhases, (qy + 0.5) / kPhases,
                                                  column, row);
                    error = std::max(
                        error, std::abs(blend(phase, 0.5f, 0.5f, column, row) - footprint));
                }
            }
        }
    }
}

float FootprintStamps::blend(std::int32_t phase, float fx, float fy, int column, int row) const {
    const float s00 = at(phase, column, row);
    const float s10 = at(phase + 1, column, row);
    const float s01 = at(phase + kPhases + 1, column, row);
    const float s11 = at(phase + kPhases + 2, column, row);
    const float bottom = fx * (s10 - s00) + s00;
    const float top = fx * (s11 - s01) + s01;
    return fy * (top - bottom) + bottom;
}

} // namespace texsplat::render::cpu
