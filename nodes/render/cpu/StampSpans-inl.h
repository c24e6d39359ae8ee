// The SIMD compositing of one stamped splat (FootprintStamps), for each Highway target:
// included inside the foreach_target translation units that draw stamped splats (SplatSpans.cpp:
// a splat list's; VoxelSpans.cpp: a grid's voxels without a list). Both composite a splat alike,
// vector for vector, so the two draw the same image bit for bit.
#if defined(TEXSPLAT_RENDER_CPU_STAMP_SPANS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef TEXSPLAT_RENDER_CPU_STAMP_SPANS_INL_H_
#undef TEXSPLAT_RENDER_CPU_STAMP_SPANS_INL_H_
#else
#define TEXSPLAT_RENDER_CPU_STAMP_SPANS_INL_H_
#endif

#include <hwy/highway.h>

#include "nodes/render/cpu/FootprintStamps.h"
#include "nodes/render/cpu/MediumSpans-inl.h"

#include <algorithm>
#include <cfloat>
#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace texsplat::render::cpu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The vectors a stamp is composited with: up to 16 lanes, so that on AVX-512 two rows of an
// 8-column stamp share one vector.
using StampTag = hn::CappedTag<float, 16>;

// Where a stamped splat's rows lie: its stamp's first row to composite and, at the same row and
// the stamp's first column, its pixel in the red plane; the other planes (green, blue, alpha,
// depth) follow `planeStride` floats apart, rows `stride` apart.
struct StampRows {
    const float* weights;
    float* red;
    std::ptrdiff_t planeStride;
    std::ptrdiff_t stride;
    int columns; // floats of a stamp row (FootprintStamps::columns)
    int rows;    // rows to composite
};

// The window-space depth test of a stamped splat's pixels against the depth plane: the splat's
// z_ndc is depth[0]·x + depth[1]·y + depth[2] at pixel (x, y) (SplatRaster::depth); `column` and
// `row` are the pixel of StampRows' first.
struct StampDepth {
    const float* plane; // SplatRaster::depth
    int column;
    int row;
};

// dst = dst·(1 − τg) + C·g per plane (alpha: + τg = α), with g = f·φ(τf) the colour weight
// by φ's series (Medium::shortWeight(), PhiSeries()): one multiply-add a plane on the pixel's
// value, so that a splat waits on the one before it (whose stores it loads) for one operation.
// Otherwise (Expm1, or kClamp) α and the weight as Medium::attenuate() gives them and dst =
// min(C·w, FLT_MAX) + (1 − α)·dst, clamped with kClamp. `load(plane)` and `store(value, plane)`
// read and write plane 0 (red) to 3 (alpha) of the pixels.
template <bool kClamp, Depth kDepth, class DV, class Load, class Store>
HWY_INLINE void StampOver(DV dv, hn::Vec<DV> f, const Medium<DV>& medium, const Load& load,
                          const Store& store) {
    using V = hn::Vec<DV>;
    if constexpr (kDepth != Depth::Expm1 && !kClamp) {
        const V weight = kDepth == Depth::Short ? medium.shortWeight(f)
                                                : hn::Mul(f, PhiSeries(dv, hn::Mul(medium.tau, f)));
        const V transmitted = hn::NegMulAdd(medium.tau, weight, hn::Set(dv, 1.0f));
        const auto over = [&](int plane, V source) {
            store(hn::MulAdd(load(plane), transmitted, source), plane);
        };
        over(0, hn::Mul(medium.red, weight));
        over(1, hn::Mul(medium.green, weight));
        over(2, hn::Mul(medium.blue, weight));
        over(3, hn::Mul(medium.tau, weight));
    } else {
        V alpha;
        V weight;
        medium.template attenuate<kDepth>(dv, f, alpha, weight);
        const V transmitted = hn::Sub(hn::Set(dv, 1.0f), alpha);
        const auto over = [&](int plane, V source) {
            store(Clamp<kClamp>(dv, hn::MulAdd(transmitted, load(plane), source)), plane);
        };
        over(0, Clamp<kClamp>(dv, hn::Mul(medium.red, weight)));
        over(1, Clamp<kClamp>(dv, hn::Mul(medium.green, weight)));
        over(2, Clamp<kClamp>(dv, hn::Mul(medium.blue, weight)));
        over(3, alpha);
    }
}

// StampOver() of one vector of a row's pixels at `pixel` (red; the other planes `planeStride`
// floats apart).
template <bool kClamp, Depth kDepth, class DV>
HWY_INLINE void StampOverRow(DV dv, hn::Vec<DV> f, float* pixel, std::ptrdiff_t planeStride,
                             const Medium<DV>& medium) {
    StampOver<kClamp, kDepth>(
        dv, f, medium, [&](int plane) { return hn::LoadU(dv, pixel + plane * planeStride); },
        [&](hn::Vec<DV> value, int plane) { hn::StoreU(value, dv, pixel + plane * planeStride); });
}

#if HWY_TARGET != HWY_SCALAR
// StampOver() of two rows in one vector: the lower half of each at `pixel`, the upper at
// `pixel + stride`.
template <bool kClamp, Depth kDepth, class D>
HWY_INLINE void StampOverTwoRows(D d, hn::Vec<D> f, float* pixel, std::ptrdiff_t planeStride,
                                 std::ptrdiff_t stride, const Medium<D>& medium) {
    const hn::Half<D> half;
    StampOver<kClamp, kDepth>(
        d, f, medium,
        [&](int plane) {
            const float* at = pixel + plane * planeStride;
            return hn::Combine(d, hn::LoadU(half, at + stride), hn::LoadU(half, at));
        },
        [&](hn::Vec<D> value, int plane) {
            float* at = pixel + plane * planeStride;
            hn::StoreU(hn::LowerHalf(half, value), half, at);
            hn::StoreU(hn::UpperHalf(half, value), half, at + stride);
        });
}
#endif

// The footprint `f` of the lanes of a stamp row at pixel columns column… of `row` that pass the
// depth test against the depth plane's values at `plane` (the others 0: they keep their value).
template <class DV>
HWY_INLINE hn::Vec<DV> DepthTested(DV dv, hn::Vec<DV> f, const StampDepth& depth, int column,
                                   int row, const float* plane) {
    const auto x = hn::Add(hn::Set(dv, static_cast<float>(column)), hn::Iota(dv, 0.0f));
    const auto z0 = hn::Set(dv, depth.plane[1] * static_cast<float>(row) + depth.plane[2]);
    const auto window = hn::MulAdd(hn::MulAdd(hn::Set(dv, depth.plane[0]), x, z0),
                                   hn::Set(dv, 0.5f), hn::Set(dv, 0.5f));
    return hn::IfThenElseZero(hn::Lt(window, hn::LoadU(dv, plane)), f);
}

// Composites the rows of a stamped splat at `at` with `medium`: each row's columns in vectors of
// D's lanes (and a half vector where a row holds an odd number of halves), or with 16 lanes two
// rows of an 8-column stamp per vector; with `depth`, only the pixels in front of the depth
// plane. A pixel's arithmetic does not depend on which vector or lane holds it.
template <bool kClamp, Depth kDepth, class D>
HWY_INLINE void CompositeStamp(D d, const StampRows& at, const Medium<D>& medium,
                               const StampDepth* depth) {
    constexpr int kLanes = static_cast<int>(hn::MaxLanes(D()));
    const float* weights = at.weights;
    float* pixels = at.red;
    // One row's vectors at `weights` and `pixels` (stamp row `row` of the splat), from column
    // `column` on, with vectors of `dv`.
    const auto compositeRow = [&](auto dv, const Medium<decltype(dv)>& with, int row, int column) {
        constexpr int kStep = static_cast<int>(hn::MaxLanes(decltype(dv)()));
        for (; column + kStep <= at.columns; column += kStep) {
            auto f = hn::LoadU(dv, weights + column);
            if (depth != nullptr) {
                f = DepthTested(dv, f, *depth, depth->column + column, depth->row + row,
                                pixels + column + 4 * at.planeStride);
            }
            StampOverRow<kClamp, kDepth>(dv, f, pixels + column, at.planeStride, with);
        }
        return column;
    };
#if HWY_TARGET != HWY_SCALAR
    if constexpr (kLanes == 2 * FootprintStamps::kLanes) {
        const hn::Half<D> half;
        const Medium<hn::Half<D>> halfMedium = medium.lowerHalf(half);
        int row = 0;
        if (depth == nullptr && at.columns == FootprintStamps::kLanes) {
            for (; row + 1 < at.rows; row += 2) {
                StampOverTwoRows<kClamp, kDepth>(d, hn::LoadU(d, weights), pixels, at.planeStride,
                                                 at.stride, medium);
                weights += 2 * at.columns;
                pixels += 2 * at.stride;
            }
        }
        for (; row < at.rows; ++row) {
            compositeRow(half, halfMedium, row, compositeRow(d, medium, row, 0));
            weights += at.columns;
            pixels += at.stride;
        }
    } else
#endif
    {
        static_assert(FootprintStamps::kLanes % kLanes == 0, "stamp rows fill whole vectors");
        for (int row = 0; row < at.rows; ++row) {
            compositeRow(d, medium, row, 0);
            weights += at.columns;
            pixels += at.stride;
        }
    }
}

// The smallest extinction of a thin splat (IsThin()): C/τ stays finite for the colours that
// need no clamp.
constexpr float kThinExtinction = 1e-20f;

// Whether a stamped splat of emission `color` and extinction `extinction`, whose footprint
// (times its length scale) reaches `peak`, is thin: its optical depth below kShortSeriesDepth,
// its medium absorbing (τ >= kThinExtinction) and needing no clamp, C/τ finite. Most splats of
// a volume are (Marschner–Lobb 128³: all of them); CompositeThinStamp() composites them.
inline bool IsThin(const float (&color)[3], float extinction, float peak) {
    return extinction * peak <= kShortSeriesDepth && extinction >= kThinExtinction &&
           IsUnclamped(color, extinction, peak) &&
           std::max({color[0], color[1], color[2]}) / extinction <= FLT_MAX;
}

// A thin splat's medium (IsThin()) for CompositeThinStamp(): α = 1 − e^(−τf) by its series in
// the footprint f itself, α = f·(k1 − f·(k2 − f·(k3 − f·k4))), k_i = τ^i/i! (three multiply-adds
// and a product; below 8.4e-8 for τf <= 0.1, the first term left out x⁵/120), and the colour
// C·α/τ from C/τ. The powers of a τ so small that they would be denormal (slow) are 0: below
// τf = 1e-8 they add less than 1e-16.
template <class D> struct ThinMedium {
    using V = hn::Vec<D>;
    V k1, k2, k3, k4;
    V red, green, blue; // C/τ

    ThinMedium(D d, const float (&color)[3], float extinction) {
        const float t = extinction;
        const float p = t > 1e-7f ? t : 0.0f;
        const float c2 = p * p * 0.5f;
        const float c3 = c2 * p * (1.0f / 3.0f);
        const float perTau = 1.0f / t;
        k1 = hn::Set(d, t);
        k2 = hn::Set(d, c2);
        k3 = hn::Set(d, c3);
        k4 = hn::Set(d, c3 * p * 0.25f);
        red = hn::Set(d, color[0] * perTau);
        green = hn::Set(d, color[1] * perTau);
        blue = hn::Set(d, color[2] * perTau);
    }

    ThinMedium(V c1, V c2, V c3, V c4, V r, V g, V b)
        : k1(c1), k2(c2), k3(c3), k4(c4), red(r), green(g), blue(b) {}

    // The lower half of each vector, for vectors of `half`'s lanes.
    template <class DHalf> ThinMedium<DHalf> lowerHalf(DHalf half) const {
        return ThinMedium<DHalf>(hn::LowerHalf(half, k1), hn::LowerHalf(half, k2),
                                 hn::LowerHalf(half, k3), hn::LowerHalf(half, k4),
                                 hn::LowerHalf(half, red), hn::LowerHalf(half, green),
                                 hn::LowerHalf(half, blue));
    }

    V alpha(V f) const {
        return hn::Mul(f, hn::NegMulAdd(f, hn::NegMulAdd(f, hn::NegMulAdd(f, k4, k3), k2), k1));
    }
};

// dst = dst·(1 − α) + (C/τ)·α on the four planes of a thin splat: one multiply-add a plane on
// the pixel's value, so that a splat waits on the one before it (whose stores it loads) for one
// operation. `load(plane)` and `store(value, plane)` read and write plane 0 (red) to 3 (alpha).
template <class DV, class Load, class Store>
HWY_INLINE void ThinOver(DV dv, hn::Vec<DV> f, const ThinMedium<DV>& medium, const Load& load,
                         const Store& store) {
    using V = hn::Vec<DV>;
    const V alpha = medium.alpha(f);
    const V transmitted = hn::Sub(hn::Set(dv, 1.0f), alpha);
    store(hn::MulAdd(load(0), transmitted, hn::Mul(medium.red, alpha)), 0);
    store(hn::MulAdd(load(1), transmitted, hn::Mul(medium.green, alpha)), 1);
    store(hn::MulAdd(load(2), transmitted, hn::Mul(medium.blue, alpha)), 2);
    store(hn::MulAdd(load(3), transmitted, alpha), 3);
}

// ThinOver() of the row of `columns` floats at `weights` onto the pixels at `pixel` (red; the
// other planes `planeStride` floats apart), in vectors of `dv`.
template <class DV>
HWY_INLINE void ThinRow(DV dv, const float* weights, int columns, float* pixel,
                        std::ptrdiff_t planeStride, const ThinMedium<DV>& medium) {
    constexpr int kStep = static_cast<int>(hn::MaxLanes(DV()));
    for (int column = 0; column < columns; column += kStep) {
        float* at = pixel + column;
        ThinOver(
            dv, hn::LoadU(dv, weights + column), medium,
            [&](int plane) { return hn::LoadU(dv, at + plane * planeStride); },
            [&](hn::Vec<DV> value, int plane) { hn::StoreU(value, dv, at + plane * planeStride); });
    }
}

// Composites the rows of a thin stamped splat (IsThin()) at `at`: each row's columns in vectors
// of D's lanes (and a half vector where a row holds an odd number of halves), or with 16 lanes
// two rows of an 8-column stamp per vector. A pixel's arithmetic does not depend on which
// vector or lane holds it.
template <class D>
HWY_INLINE void CompositeThinStamp(D d, const StampRows& at, const ThinMedium<D>& medium) {
    constexpr int kLanes = static_cast<int>(hn::MaxLanes(D()));
    const float* weights = at.weights;
    float* pixels = at.red;
    const std::ptrdiff_t planeStride = at.planeStride;
    const std::ptrdiff_t stride = at.stride;
#if HWY_TARGET != HWY_SCALAR
    if constexpr (kLanes == 2 * FootprintStamps::kLanes) {
        const hn::Half<D> half;
        const ThinMedium<hn::Half<D>> halfMedium = medium.lowerHalf(half);
        int row = 0;
        if (at.columns == FootprintStamps::kLanes) {
            for (; row + 1 < at.rows; row += 2) {
                ThinOver(
                    d, hn::LoadU(d, weights), medium,
                    [&](int plane) {
                        const float* pixel = pixels + plane * planeStride;
                        return hn::Combine(d, hn::LoadU(half, pixel + stride),
                                           hn::LoadU(half, pixel));
                    },
                    [&](hn::Vec<D> value, int plane) {
                        float* pixel = pixels + plane * planeStride;
                        hn::StoreU(hn::LowerHalf(half, value), half, pixel);
                        hn::StoreU(hn::UpperHalf(half, value), half, pixel + stride);
                    });
                weights += 2 * FootprintStamps::kLanes;
                pixels += 2 * stride;
            }
            if (row < at.rows) {
                ThinRow(half, weights, FootprintStamps::kLanes, pixels, planeStride, halfMedium);
            }
            return;
        }
        // Rows of 16 floats or more: whole vectors, and a half one for a last 8.
        const int whole = at.columns / kLanes * kLanes;
        for (; row < at.rows; ++row) {
            ThinRow(d, weights, whole, pixels, planeStride, medium);
            if (whole < at.columns) {
                ThinRow(half, weights + whole, at.columns - whole, pixels + whole, planeStride,
                        halfMedium);
            }
            weights += at.columns;
            pixels += stride;
        }
    } else
#endif
    {
        static_assert(FootprintStamps::kLanes % kLanes == 0, "stamp rows fill whole vectors");
        for (int row = 0; row < at.rows; ++row) {
            ThinRow(d, weights, at.columns, pixels, planeStride, medium);
            weights += at.columns;
            pixels += stride;
        }
    }
}

} // namespace texsplat::render::cpu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif // TEXSPLAT_RENDER_CPU_STAMP_SPANS_INL_H_
