// The SIMD compositing of one vector mark, for each Highway target: included inside the
// foreach_target translation units that draw marks (MarkSpans.cpp: vector splats;
// SplatSpans.cpp: combined splats, whose marks follow each scalar splat).
#if defined(TEXSPLAT_RENDER_CPU_MARK_SPANS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef TEXSPLAT_RENDER_CPU_MARK_SPANS_INL_H_
#undef TEXSPLAT_RENDER_CPU_MARK_SPANS_INL_H_
#else
#define TEXSPLAT_RENDER_CPU_MARK_SPANS_INL_H_
#endif

#include <hwy/highway.h>

#include "nodes/render/cpu/MarkRaster.h"

#include <algorithm>
#include <cfloat>

HWY_BEFORE_NAMESPACE();
namespace texsplat::render::cpu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Composites rows [first, last) of `mark` (MarkRaster, compositeMarks()) with vectors of `d`.
template <class D>
HWY_INLINE void CompositeMarkRows(D d, const MarkRaster& mark, const MarkStyle& style,
                                  ColorPlanes& planes, int first, int last) {
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto one = hn::Set(d, 1.0f);
    const auto zero = hn::Zero(d);
    const auto largest = hn::Set(d, FLT_MAX);
    const auto lane = hn::Iota(d, 0.0f);
    const bool particles = style.type == MarkType::Particles;
    constexpr float kTail = MarkDrawing::kParticleTail;
    const auto taperSlope = hn::Set(d, 0.5f * (1.0f - kTail));
    const auto taperBase = hn::Set(d, kTail + 0.5f * (1.0f - kTail));
    const bool depthTest = planes.hasDepth();
    const auto alpha = hn::Set(d, mark.alpha);
    const auto inverseRamp = hn::Set(d, mark.inverseRamp);
    const auto inverseHead = hn::Set(d, mark.inverseHead);
    const auto depth = hn::Set(d, mark.depth);
    // s = sx·x + s0 along (tail −1 to head 1), t = tx·x + t0 across, at pixel centre x + ½.
    const float sx = mark.axis[0] * mark.inverseLength;
    const float tx = -mark.axis[1] * mark.inverseWidth;
    const auto sStep = hn::Set(d, sx);
    const auto tStep = hn::Set(d, tx);
    const float dx0 = 0.5f - mark.centre[0];
    for (int row = first; row < last; ++row) {
        int begin = 0;
        int end = 0;
        markColumns(mark, row, planes.width(), begin, end);
        if (begin >= end) {
            continue;
        }
        const float dy = static_cast<float>(row) + 0.5f - mark.centre[1];
        const auto s0 = hn::Set(d, (mark.axis[0] * dx0 + mark.axis[1] * dy) * mark.inverseLength);
        const auto t0 = hn::Set(d, (-mark.axis[1] * dx0 + mark.axis[0] * dy) * mark.inverseWidth);
        float* redRow = planes.red(row);
        float* greenRow = planes.green(row);
        float* blueRow = planes.blue(row);
        float* alphaRow = planes.alpha(row);
        const float* depthRow = depthTest ? planes.depth(row) : nullptr;
        for (int column = begin; column < end; column += lanes) {
            const auto x = hn::Add(hn::Set(d, static_cast<float>(column)), lane);
            const auto s = hn::MulAdd(sStep, x, s0);
            const auto t = hn::MulAdd(tStep, x, t0);
            // markProfile(): the ramp along, the profile across.
            const auto rise = hn::Mul(hn::Add(s, one), inverseRamp);
            const auto fall = hn::Mul(hn::Sub(one, s), inverseHead);
            const auto ramp = hn::Min(hn::Max(hn::Min(rise, fall), zero), one);
            const auto taper = particles ? hn::MulAdd(s, taperSlope, taperBase) : one;
            const auto across = hn::Max(hn::NegMulAdd(t, t, taper), zero);
            const auto profile = hn::Mul(ramp, hn::Mul(across, across));
            auto a = hn::Mul(alpha, profile);
            if (depthTest) {
                a = hn::IfThenElseZero(hn::Lt(depth, hn::LoadU(d, depthRow + column)), a);
            }
            const auto transmitted = hn::Sub(one, a);
            const auto over = [&](float* plane, float colour, float blendColour) {
                auto c = hn::Set(d, colour);
                if (style.blend) {
                    c = hn::MulAdd(hn::Set(d, blendColour - colour), profile, c);
                }
                const auto destination = hn::LoadU(d, plane + column);
                hn::StoreU(hn::Min(hn::MulAdd(transmitted, destination, hn::Mul(c, a)), largest), d,
                           plane + column);
            };
            over(redRow, mark.color[0], style.blendColor[0]);
            over(greenRow, mark.color[1], style.blendColor[1]);
            over(blueRow, mark.color[2], style.blendColor[2]);
            hn::StoreU(hn::MulAdd(transmitted, hn::LoadU(d, alphaRow + column), a), d,
                       alphaRow + column);
        }
    }
}

// Composites rows [first, last) of `mark`: eight lanes for marks no wider than eight pixels
// (most, at a few pixels per voxel), up to sixteen for wider ones.
HWY_INLINE void CompositeMark(const MarkRaster& mark, const MarkStyle& style, ColorPlanes& planes,
                              int first, int last) {
    using Wide = hn::CappedTag<float, 16>;
    using Narrow = hn::CappedTag<float, 8>;
    const float width =
        2.0f * (mark.halfLength * std::abs(mark.axis[0]) + mark.halfWidth * std::abs(mark.axis[1]));
    if (width <= static_cast<float>(hn::MaxLanes(Narrow()))) {
        CompositeMarkRows(Narrow(), mark, style, planes, first, last);
    } else {
        CompositeMarkRows(Wide(), mark, style, planes, first, last);
    }
}

} // namespace texsplat::render::cpu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif // include guard toggled per Highway target
