#include "nodes/render/cpu/MarkRaster.h"

#include "nodes/render/ScreenMarks.h"

#include <algorithm>
#include <cmath>

namespace texsplat::render::cpu {
namespace {

// `value` rounded to an int within [low, high] (NaN gives low).
std::int32_t toPixel(double value, int low, int high) {
    return value >= low ? static_cast<std::int32_t>(std::min(value, double(high))) : low;
}

// Narrows [low, high] to the offsets dx with |c·dx + e| <= reach.
void narrow(float c, float e, float reach, float& low, float& high) {
    if (std::abs(c) < 1e-12f) {
        if (std::abs(e) > reach) {
            low = 1.0f;
            high = 0.0f;
        }
        return;
    }
    const float a = (-reach - e) / c;
    const float b = (reach - e) / c;
    low = std::max(low, std::min(a, b));
    high = std::min(high, std::max(a, b));
}

} // namespace

MarkRaster markRaster(const ScreenMark& mark, int width, int height) {
    MarkRaster raster{};
    if (mark.isEmpty() || width <= 0 || height <= 0) {
        return raster;
    }
    raster.centre[0] = mark.centre[0];
    raster.centre[1] = mark.centre[1];
    raster.axis[0] = mark.axis[0];
    raster.axis[1] = mark.axis[1];
    raster.halfLength = mark.halfLength;
    raster.halfWidth = mark.halfWidth;
    raster.inverseLength = 1.0f / mark.halfLength;
    raster.inverseWidth = 1.0f / mark.halfWidth;
    raster.head = mark.head;
    raster.inverseHead = 1.0f / mark.head;
    raster.inverseRamp = 1.0f / (2.0f - mark.head);
    raster.depth = 0.5f * mark.depth + 0.5f;
    raster.alpha = mark.alpha;
    for (int channel = 0; channel < 3; ++channel) {
        raster.color[channel] = mark.color[channel];
    }
    // Rows whose centres (y + ½) may lie on the mark's box.
    const double reach = mark.reachY();
    raster.rowBegin = toPixel(std::ceil(mark.centre[1] - reach - 0.5), 0, height);
    raster.rowEnd = toPixel(std::floor(mark.centre[1] + reach - 0.5) + 1.0, 0, height);
    if (raster.rowBegin >= raster.rowEnd) {
        raster.rowBegin = raster.rowEnd = 0;
    }
    return raster;
}

void markColumns(const MarkRaster& mark, int row, int width, int& begin, int& end) {
    const float dy = static_cast<float>(row) + 0.5f - mark.centre[1];
    // u = ax·dx + ay·dy along, v = −ay·dx + ax·dy across: |u| <= halfLength, |v| <= halfWidth.
    float low = -1e30f;
    float high = 1e30f;
    narrow(mark.axis[0], mark.axis[1] * dy, mark.halfLength, low, high);
    narrow(-mark.axis[1], mark.axis[0] * dy, mark.halfWidth, low, high);
    if (!(low <= high)) {
        begin = end = 0;
        return;
    }
    // Columns whose centres x + ½ = centre + dx lie in [low, high].
    begin = toPixel(std::ceil(mark.centre[0] + low - 0.5), 0, width);
    end = toPixel(std::floor(mark.centre[0] + high - 0.5) + 1.0, 0, width);
}

} // namespace texsplat::render::cpu
