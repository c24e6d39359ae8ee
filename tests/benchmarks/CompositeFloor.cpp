// compositeFloor() (CompositeFloor.h); compiled once per SIMD target by Highway's
// foreach_target, like the loop it bounds.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/benchmarks/CompositeFloor.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "CompositeFloor.h"

HWY_BEFORE_NAMESPACE();
namespace texsplat::microbench::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Composites every row vector of `splats`' pixel boxes, in order, into `planes`.
void CompositeFloor(const render::cpu::SplatRaster* splats, std::size_t count,
                    const render::cpu::FootprintStamps& stamps,
                    render::cpu::ColorPlanes& planes) {
    const hn::CappedTag<float, 8> d;
    const auto one = hn::Set(d, 1.0f);
    const auto c2 = hn::Set(d, -0.5f);
    const auto c3 = hn::Set(d, 1.0f / 6.0f);
    const auto c4 = hn::Set(d, -1.0f / 24.0f);
    const int lanes = static_cast<int>(hn::Lanes(d));
    for (std::size_t s = 0; s < count; ++s) {
        const render::cpu::SplatRaster& splat = splats[s];
        const auto tau = hn::Set(d, splat.extinction);
        const auto red = hn::Set(d, splat.color[0]);
        const auto green = hn::Set(d, splat.color[1]);
        const auto blue = hn::Set(d, splat.color[2]);
        const int first = splat.columnBegin / lanes * lanes;
        // The stamp of the splat's phase alone, not the blend of the four around it.
        const float* stamp =
            stamps.values.data() + static_cast<std::size_t>(splat.stampPhase) * stamps.stampSize +
            static_cast<std::size_t>(render::cpu::FootprintStamps::kPad + first -
                                     splat.stampColumn);
        for (int row = splat.rowBegin; row < splat.rowEnd; ++row) {
            const float* weights =
                stamp + static_cast<std::size_t>(row - splat.stampRow) * stamps.stride;
            float* r = planes.red(row);
            float* g = planes.green(row);
            float* b = planes.blue(row);
            float* a = planes.alpha(row);
            for (int column = first, offset = 0; column < splat.columnEnd;
                 column += lanes, offset += lanes) {
                const auto x = hn::Mul(tau, hn::LoadU(d, weights + offset));
                const auto alpha = hn::Mul(
                    x, hn::MulAdd(x, hn::MulAdd(x, hn::MulAdd(x, c4, c3), c2), one));
                const auto keep = hn::Sub(one, alpha);
                hn::Store(hn::MulAdd(hn::Load(d, r + column), keep, hn::Mul(red, alpha)), d,
                          r + column);
                hn::Store(hn::MulAdd(hn::Load(d, g + column), keep, hn::Mul(green, alpha)), d,
                          g + column);
                hn::Store(hn::MulAdd(hn::Load(d, b + column), keep, hn::Mul(blue, alpha)), d,
                          b + column);
                hn::Store(hn::MulAdd(hn::Load(d, a + column), keep, alpha), d, a + column);
            }
        }
    }
}

} // namespace texsplat::microbench::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace texsplat::microbench {

HWY_EXPORT(CompositeFloor);

void compositeFloor(const render::cpu::SplatRaster* splats, std::size_t count,
                    const render::cpu::FootprintStamps& stamps,
                    render::cpu::ColorPlanes& planes) {
    HWY_DYNAMIC_DISPATCH(CompositeFloor)(splats, count, stamps, planes);
}

} // namespace texsplat::microbench
#endif // HWY_ONCE
