#pragma once

#include "nodes/render/MarkDrawing.h"
#include "nodes/render/cpu/ColorPlanes.h"
#include "nodes/render/cpu/SplatSpans.h"

#include <cstddef>
#include <cstdint>

namespace texsplat::render {
struct ScreenMark;
}

namespace texsplat::render::cpu {

/// @brief One mark (render::ScreenMark) set up for rasterizing: the map from a pixel to the
/// mark's (s, t), its medium and the rows it may cover.
struct MarkRaster {
    float centre[2];       ///< pixels
    float axis[2];         ///< unit, towards the head
    float halfLength;      ///< pixels
    float halfWidth;       ///< pixels
    float inverseLength;   ///< 1 / halfLength
    float inverseWidth;    ///< 1 / halfWidth
    float head;            ///< the head's fall, a fraction of halfLength
    float inverseHead;     ///< 1 / head
    float inverseRamp;     ///< 1 / (2 − head)
    float depth;           ///< window depth [0, 1] of the mark, for the depth test
    float alpha;           ///< peak opacity
    float color[3];        ///< the mark's colour
    std::int32_t rowBegin; ///< rows [begin, end) it may cover, top first
    std::int32_t rowEnd;
};

/// @brief The raster of `mark` in an image of `width` x `height` pixels; rowBegin == rowEnd when
/// it covers no pixel (or draws nothing).
MarkRaster markRaster(const ScreenMark& mark, int width, int height);

/// @brief The columns [begin, end) of row `row` whose pixel centres lie on `mark`'s rectangle
/// (|s| <= 1, |t| <= 1), within [0, width); begin >= end when none does.
void markColumns(const MarkRaster& mark, int row, int width, int& begin, int& end);

/// @brief How a batch's marks are coloured besides their own colour.
struct MarkStyle {
    MarkType type = MarkType::Scratches; ///< the profile across the mark
    bool blend = false;                  ///< MarkOperator::Blend of vector splats
    float blendColor[3]{};               ///< what Blend mixes towards by the profile
};

/// @brief The marks that follow each splat of a compositeSplats() call (combined splats): splat
/// i's are marks[begins[i] .. begins[i + 1]).
struct FollowingMarks {
    const MarkRaster* marks = nullptr;     ///< set up
    const RowSpan* rows = nullptr;         ///< the rows of each
    const std::uint32_t* begins = nullptr; ///< count + 1 offsets, relative to `marks`
    MarkStyle style;                       ///< how they are coloured
};

/// @brief Composites `count` set-up marks in their order with premultiplied "over" into rows
/// [rowBegin, rowEnd) of `planes`, as the GL backend's mark pass (gl/detail/MarkShaders.h):
/// at each pixel centre on a mark, α = alpha · markProfile(type, s, t, head) and colour
/// C (Blend: C + (K − C)·profile), dst = C·α + (1 − α)·dst; with a depth plane, only in front of
/// the meshes. SIMD over adjacent pixels of a row (Highway, dispatched at run time); a pixel's
/// arithmetic does not depend on the rows' split among threads.
void compositeMarks(const MarkRaster* marks, const RowSpan* rows, std::size_t count,
                    const MarkStyle& style, ColorPlanes& planes, int rowBegin, int rowEnd);

} // namespace texsplat::render::cpu
