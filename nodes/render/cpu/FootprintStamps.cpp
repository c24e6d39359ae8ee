#include "nodes/render/cpu/FootprintStamps.h"

#include "nodes/render/cpu/SplatRaster.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

bool StampGeometry::operator==(const StampGeometry& other) const {
    return squareFromPixel[0][0] == other.squareFromPixel[0][0] &&
           squareFromPixel[0][1] == other.squareFromPixel[0][1] &&
           squareFromPixel[1][0] == other.squareFromPixel[1][0] &&
           squareFromPixel[1][1] == other.squareFromPixel[1][1] &&
           halfExtent[0] == other.halfExtent[0] && halfExtent[1] == other.halfExtent[1] &&
           lengthScale == other.lengthScale;
}

bool FootprintStamps::suits(const FootprintSampler& sampler, const StampGeometry& geometry) {
    // A stamp spans 2·halfExtent + 2 pixels at most (see the constructor).
    const auto fits = [](float reach) { return 2.0f * reach + 2.0f <= kLargestSide; };
    return sampler.isRadial && sampler.hasPieces && sampler.reach <= 1.0f &&
           fits(geometry.halfExtent[0]) && fits(geometry.halfExtent[1]);
}

FootprintStamps::FootprintStamps(const FootprintSampler& sampler, const StampGeometry& geometry) {
    const float(&squareFromPixel)[2][2] = geometry.squareFromPixel;
    const float(&halfExtent)[2] = geometry.halfExtent;
    const float lengthScale = geometry.lengthScale;
    // A centre q/phases (0 <= q < phases) past the centre of pixel c0 reaches the centres of
    // pixels c0 + ⌈q/phases − reach⌉ … c0 + ⌊q/phases + reach⌋.
    columnOffset = static_cast<int>(std::ceil(-halfExtent[0]));
    rowOffset = static_cast<int>(std::ceil(-halfExtent[1]));
    peak = sampler.peak * lengthScale;
    for (phaseBits = 4;; ++phaseBits) {
        const int count = phases();
        const double last = static_cast<double>(count - 1) / count;
        const int reachedColumns =
            static_cast<int>(std::floor(last + halfExtent[0])) - columnOffset + 1;
        columns = (reachedColumns + kLanes - 1) / kLanes * kLanes;
        rows = static_cast<int>(std::floor(last + halfExtent[1])) - rowOffset + 1;
        stampSize = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
        values.assign(stampSize * static_cast<std::size_t>(count * count), 0.0f);
        extents.assign(static_cast<std::size_t>(count * count), Extent{columns, 0, rows, 0});
        error = 0.0f;
        // The centres a stamp stands for lie within half a phase of its own, along each axis:
        // the footprint strays farthest from the stamp at the corners and edges of that square,
        // which lie on the grid of half phases, h/(2·phases()) for h = -1 … 2·phases() - 1
        // (stamp (qx, qy) at h = 2·qx, 2·qy). Per stamp pixel, the footprint at each of those
        // centres once, shared by the stamps around it.
        const int sides = 2 * count + 1;
        const double halfPhases = 2.0 * count; // half phases a pixel
        std::vector<float> around(static_cast<std::size_t>(sides * sides));
        const auto at = [&](int hx, int hy) -> float& {
            return around[static_cast<std::size_t>((hy + 1) * sides + hx + 1)];
        };
        for (int row = 0; row < rows; ++row) {
            for (int column = 0; column < columns; ++column) {
                for (int hy = -1; hy < 2 * count; ++hy) {
                    for (int hx = -1; hx < 2 * count; ++hx) {
                        const double x = column + columnOffset - hx / halfPhases;
                        const double y = row + rowOffset - hy / halfPhases;
                        at(hx, hy) = footprintAt(sampler, squareFromPixel, lengthScale, x, y);
                    }
                }
                for (int qy = 0; qy < count; ++qy) {
                    for (int qx = 0; qx < count; ++qx) {
                        const std::int32_t phase = phaseIndex(qx, qy);
                        const float value = at(2 * qx, 2 * qy);
                        values[static_cast<std::size_t>(phase) * stampSize +
                               static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                               static_cast<std::size_t>(column)] = value;
                        if (value != 0.0f) {
                            Extent& extent = extents[static_cast<std::size_t>(phase)];
                            extent.columnBegin = std::min(extent.columnBegin, column);
                            extent.columnEnd = std::max(extent.columnEnd, column + 1);
                            extent.rowBegin = std::min(extent.rowBegin, row);
                            extent.rowEnd = std::max(extent.rowEnd, row + 1);
                        }
                        for (int dy = -1; dy <= 1; ++dy) {
                            for (int dx = -1; dx <= 1; ++dx) {
                                error = std::max(
                                    error, std::abs(value - at(2 * qx + dx, 2 * qy + dy)));
                            }
                        }
                    }
                }
            }
        }
        const std::size_t doubled = values.size() * 4;
        if (error <= kTolerance * peak || doubled > kLargestTable) {
            return;
        }
    }
}

} // namespace texsplat::render::cpu
