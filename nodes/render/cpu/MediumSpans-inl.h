// The emission–absorption of one vector of pixels, for each Highway target: φ's series, the
// "over" of a splat's medium, and which of them a splat needs. Included inside the foreach_target
// translation units that composite splats (SplatSpans.cpp, VoxelSpans.cpp).
#if defined(TEXSPLAT_RENDER_CPU_MEDIUM_SPANS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef TEXSPLAT_RENDER_CPU_MEDIUM_SPANS_INL_H_
#undef TEXSPLAT_RENDER_CPU_MEDIUM_SPANS_INL_H_
#else
#define TEXSPLAT_RENDER_CPU_MEDIUM_SPANS_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

HWY_BEFORE_NAMESPACE();
namespace texsplat::render::cpu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// φ(x) = (1 − e^(−x))/x = Σ (−x)^k/(k+1)!, k ≤ 8: below 1.2e-8 for 0 ≤ x ≤ ½. Estrin's
// scheme: four dependent multiply-adds instead of Horner's eight (the compositing's longest
// chain; 1.4× on thin splats, CpuRasterizerBenchmark). The terms from x² on take x no smaller
// than 1e-4, where they add below 2e-9, so that no power of a tiny x is a denormal: on x86 a
// denormal result costs a micro-code assist, which made a plain Estrin slower than Horner.
template <class D, class V> HWY_INLINE V PhiSeries(D d, V x) {
    const V clamped = hn::Max(x, hn::Set(d, 1e-4f));
    const auto term = [&](V at, float high, float low) {
        return hn::MulAdd(hn::Set(d, high), at, hn::Set(d, low));
    };
    const V x2 = hn::Mul(clamped, clamped);
    const V x4 = hn::Mul(x2, x2);
    const V low = hn::MulAdd(term(clamped, -1.0f / 24.0f, 1.0f / 6.0f), x2, term(x, -0.5f, 1.0f));
    const V high = hn::MulAdd(term(clamped, -1.0f / 40320.0f, 1.0f / 5040.0f), x2,
                              term(clamped, -1.0f / 720.0f, 1.0f / 120.0f));
    const V highest = hn::MulAdd(hn::Set(d, 1.0f / 362880.0f), x4, high);
    return hn::MulAdd(highest, x4, low);
}

// φ(x) for 0 ≤ x ≤ kShortSeriesDepth: the series to k = 4, below 1.4e-8 there (the first term
// left out, x⁵/720), as close as PhiSeries. Horner's rule, four multiply-adds against
// PhiSeries' eleven operations: every intermediate is near a coefficient, so a tiny x makes no
// denormal. Most splats of a volume are this thin (Marschner–Lobb 128³: all of them).
constexpr float kShortSeriesDepth = 0.1f;
template <class D, class V> HWY_INLINE V PhiShortSeries(D d, V x) {
    const V q =
        hn::MulAdd(hn::MulAdd(hn::MulAdd(hn::Set(d, 1.0f / 120.0f), x, hn::Set(d, -1.0f / 24.0f)),
                              x, hn::Set(d, 1.0f / 6.0f)),
                   x, hn::Set(d, -0.5f));
    return hn::MulAdd(q, x, hn::Set(d, 1.0f));
}

// How a splat's opacity α = 1 − e^(−x) and colour weight f·φ(x) are computed, from the largest
// optical depth x its footprint reaches: a short or a long series of φ, or Expm1.
enum class Depth { Short, Series, Expm1 };

// A colour below this (per unit of footprint) can be added to any pixel without a clamp: the
// sum of it and a pixel no larger than FLT_MAX rounds to at most FLT_MAX, whose half ulp
// (1e31) it stays below, so min(…, FLT_MAX) would change nothing.
constexpr float kUnclampedColour = 1e29f;

template <bool kClamp, class D, class V> HWY_INLINE V Clamp(D d, V value) {
    if constexpr (kClamp) {
        return hn::Min(value, hn::Set(d, FLT_MAX));
    } else {
        return value;
    }
}

// dst = source + transmitted · dst on `plane` at `column` (clamped with kClamp).
template <bool kClamp, class D, class V>
HWY_INLINE void Over(D d, float* plane, int column, V transmitted, V source) {
    const V destination = hn::LoadU(d, plane + column);
    hn::StoreU(Clamp<kClamp>(d, hn::MulAdd(transmitted, destination, source)), d, plane + column);
}

// A splat's medium in vectors: its emission C and extinction τ.
template <class D> struct Medium {
    using V = hn::Vec<D>;
    V red, green, blue, tau;
    // The short series of the colour weight in the footprint f itself, f·φ(τf) = f·(1 +
    // f·(−k1 + f·(k2 + f·(−k3 + f·k4)))), k_i = τ^i/(i + 1)!: PhiShortSeries() without the
    // product τf (four multiply-adds a vector). The powers of a τ so small that they would be
    // denormal (slow) are 0: below τ·f = 1e-6 they add less than 1e-12.
    V k1, k2, k3, k4;
    // C·f·φ(τf) = C·α/τ; below 1e-30 the medium is pure emission, C·f (φ = 1 − τf/2 + …).
    bool absorbs;

    Medium(D d, const float (&color)[3], float extinction)
        : red(hn::Set(d, color[0])), green(hn::Set(d, color[1])), blue(hn::Set(d, color[2])),
          tau(hn::Set(d, extinction)), absorbs(extinction > 1e-30f) {
        // By products alone (a division per splat cost more than its compositing's vectors).
        const float t = absorbs ? extinction : 0.0f;
        const float p = t > 1e-7f ? t : 0.0f;
        const float c2 = p * p * (1.0f / 6.0f);
        const float c3 = c2 * p * 0.25f;
        k1 = hn::Set(d, t * 0.5f);
        k2 = hn::Set(d, c2);
        k3 = hn::Set(d, c3);
        k4 = hn::Set(d, c3 * p * 0.2f);
    }

    Medium(V r, V g, V b, V t, V c1, V c2, V c3, V c4, bool absorbing)
        : red(r), green(g), blue(b), tau(t), k1(c1), k2(c2), k3(c3), k4(c4), absorbs(absorbing) {}

    // The lower half of each vector, for vectors of `half`'s lanes.
    template <class DHalf> Medium<DHalf> lowerHalf(DHalf half) const {
        return Medium<DHalf>(hn::LowerHalf(half, red), hn::LowerHalf(half, green),
                             hn::LowerHalf(half, blue), hn::LowerHalf(half, tau),
                             hn::LowerHalf(half, k1), hn::LowerHalf(half, k2),
                             hn::LowerHalf(half, k3), hn::LowerHalf(half, k4), absorbs);
    }

    // The colour weight f·φ(τf) of footprint f by the short series in f (kShortSeriesDepth).
    HWY_INLINE V shortWeight(V f) const {
        const V series = hn::MulAdd(
            hn::MulAdd(hn::MulAdd(hn::MulAdd(k4, f, hn::Neg(k3)), f, k2), f, hn::Neg(k1)), f,
            hn::Set(D(), 1.0f));
        return hn::Mul(f, series);
    }

    // α = 1 − e^(−τf) and the colour weight f·φ(τf) = α/τ of footprint f (times the length
    // scale), by φ's series as far as kDepth allows, else Expm1 (weight f where the medium does
    // not absorb; 1/τ correctly rounded, as a scalar division gives it).
    template <Depth kDepth> HWY_INLINE void attenuate(D d, V f, V& alpha, V& weight) const {
        const V opticalDepth = hn::Mul(tau, f);
        if constexpr (kDepth != Depth::Expm1) {
            const V phi = kDepth == Depth::Short ? PhiShortSeries(d, opticalDepth)
                                                 : PhiSeries(d, opticalDepth);
            alpha = hn::Mul(opticalDepth, phi);
            weight = hn::Mul(f, phi);
        } else {
            alpha = hn::Neg(hn::Expm1(d, hn::Neg(opticalDepth)));
            weight = absorbs ? hn::Mul(alpha, hn::Div(hn::Set(d, 1.0f), tau)) : f;
        }
    }
};

// Whether no colour a splat of `color` and `extinction` adds reaches kUnclampedColour (nor is
// NaN), where its footprint (times the length scale) is at most `largestFootprint`: its medium is
// finite and its colour times the largest footprint stays below it.
inline bool IsUnclamped(const float (&color)[3], float extinction, float largestFootprint) {
    const float largest = std::max({std::abs(color[0]), std::abs(color[1]), std::abs(color[2])});
    return largest * largestFootprint <= kUnclampedColour && extinction >= 0.0f &&
           extinction <= FLT_MAX;
}

// How α and the colour weight of a splat whose optical depth reaches at most `largest` are
// computed: the series of φ as far as they allow (thin splats), else Expm1.
inline Depth DepthOf(float largest) {
    return largest <= kShortSeriesDepth ? Depth::Short
           : largest <= 0.5f            ? Depth::Series
                                        : Depth::Expm1;
}

} // namespace texsplat::render::cpu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif // TEXSPLAT_RENDER_CPU_MEDIUM_SPANS_INL_H_
