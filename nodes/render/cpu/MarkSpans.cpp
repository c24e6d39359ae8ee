// Compiled once per SIMD target by Highway's foreach_target; HWY_DYNAMIC_DISPATCH picks one.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "nodes/render/cpu/MarkSpans.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "nodes/render/cpu/MarkSpans-inl.h"

HWY_BEFORE_NAMESPACE();
namespace texsplat::render::cpu::HWY_NAMESPACE {

void CompositeMarks(const MarkRaster* marks, const RowSpan* rows, std::size_t count,
                    const MarkStyle& style, ColorPlanes& planes, int rowBegin, int rowEnd) {
    for (std::size_t i = 0; i < count; ++i) {
        const int first = std::max(rows[i].begin, rowBegin);
        const int last = std::min(rows[i].end, rowEnd);
        if (first < last) {
            CompositeMark(marks[i], style, planes, first, last);
        }
    }
}

} // namespace texsplat::render::cpu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace texsplat::render::cpu {

HWY_EXPORT(CompositeMarks);

void compositeMarks(const MarkRaster* marks, const RowSpan* rows, std::size_t count,
                    const MarkStyle& style, ColorPlanes& planes, int rowBegin, int rowEnd) {
    HWY_DYNAMIC_DISPATCH(CompositeMarks)(marks, rows, count, style, planes, rowBegin, rowEnd);
}

} // namespace texsplat::render::cpu
#endif
