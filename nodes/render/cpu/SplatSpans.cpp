// Compiled once per SIMD target by Highway's foreach_target; HWY_DYNAMIC_DISPATCH picks one.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "nodes/render/cpu/SplatSpans.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "nodes/render/cpu/MarkSpans-inl.h"
#include "nodes/render/cpu/MediumSpans-inl.h"
#include "nodes/render/cpu/SplatSpans.h"
#include "nodes/render/cpu/StampSpans-inl.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace texsplat::render::cpu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Bilinear lookups in an N×N texture padded by one texel (FootprintSampler) at
// square coordinates (a, b) ∈ [−1, 1]²: GL's texel coordinate (a/2 + ½)·N − ½, plus the border
// texel, clamped so that lanes off the square still read inside the texture.
template <class D> struct PaddedLookup {
    using V = hn::Vec<D>;
    using I = hn::Vec<hn::RebindToSigned<D>>;
    D d;
    I index; // the lower-left texel
    I above; // the texel above it
    V fs, ft;

    PaddedLookup(D tag, int resolution, int stride, V a, V b) : d(tag) {
        const hn::RebindToSigned<D> di;
        const V zero = hn::Zero(d);
        const float half = 0.5f * static_cast<float>(resolution);
        const V scale = hn::Set(d, half);
        const V offset = hn::Set(d, half + 0.5f);
        const V high = hn::Set(d, static_cast<float>(resolution) + 0.5f);
        const V s = hn::Min(hn::Max(hn::MulAdd(a, scale, offset), zero), high);
        const V t = hn::Min(hn::Max(hn::MulAdd(b, scale, offset), zero), high);
        const V s0 = hn::Floor(s);
        const V t0 = hn::Floor(t);
        fs = hn::Sub(s, s0);
        ft = hn::Sub(t, t0);
        index = hn::ConvertTo(di, hn::MulAdd(t0, hn::Set(d, static_cast<float>(stride)), s0));
        above = hn::Add(index, hn::Set(di, stride));
    }

    // The bilinear value of the texture at `values`.
    V operator()(const float* values) const {
        const hn::RebindToSigned<D> di;
        const I next = hn::Set(di, 1);
        const V f00 = hn::GatherIndex(d, values, index);
        const V f10 = hn::GatherIndex(d, values, hn::Add(index, next));
        const V f01 = hn::GatherIndex(d, values, above);
        const V f11 = hn::GatherIndex(d, values, hn::Add(above, next));
        const V bottom = hn::MulAdd(fs, hn::Sub(f10, f00), f00);
        const V top = hn::MulAdd(fs, hn::Sub(f11, f01), f01);
        return hn::MulAdd(ft, hn::Sub(top, bottom), bottom);
    }
};

// The footprint at square coordinates (a, b), before the length scale: the radial profile at
// a² + b², or the padded texture's bilinear lookup (see FootprintSampler).
template <bool kRadial, class D, class V>
HWY_INLINE V Footprint(D d, const FootprintSampler& sampler, V a, V b) {
    if constexpr (kRadial) {
        const hn::RebindToSigned<D> di;
        constexpr float kSamples = static_cast<float>(FootprintSampler::kProfileSamples);
        const V position = hn::Min(hn::Mul(hn::MulAdd(a, a, hn::Mul(b, b)),
                                           hn::Set(d, 0.5f * kSamples)),
                                   hn::Set(d, kSamples));
        const V floor = hn::Floor(position);
        const auto index = hn::ConvertTo(di, floor);
        const float* values = sampler.values.data();
        const V low = hn::GatherIndex(d, values, index);
        const V high = hn::GatherIndex(d, values, hn::Add(index, hn::Set(di, 1)));
        return hn::MulAdd(hn::Sub(position, floor), hn::Sub(high, low), low);
    } else {
        return PaddedLookup<D>(d, sampler.resolution, sampler.stride, a, b)(
            sampler.values.data());
    }
}

// The radial footprint at ρ = a² + b² from the sampler's cubic pieces in r = √ρ, looked up in
// registers: each coefficient's 16 values fill 16 / lanes vectors, one permute each and a
// select between them (on AVX-512, one permute of two vectors).
template <class D> class PieceLookup {
public:
    static constexpr std::size_t kLanes = hn::MaxLanes(D());
    static constexpr std::size_t kParts = (FootprintSampler::kPieces + kLanes - 1) / kLanes;
    using V = hn::Vec<D>;

    PieceLookup(D d, const FootprintSampler& sampler)
        : mPerRadius(hn::Set(d, sampler.piecesPerRadius)) {
        for (std::size_t k = 0; k < 4; ++k) {
            for (std::size_t part = 0; part < kParts; ++part) {
                mCoefficients[k][part] = hn::LoadU(d, sampler.pieces[k].data() + part * kLanes);
            }
        }
    }

    V operator()(D d, V rho) const {
        // The piece is p rounded to the nearest integer, found by adding 2^23: the sum's
        // mantissa holds it in its low bits (no float-to-int conversion and its overflow
        // fix-ups). Lanes beyond the reach (p > kPieces − 1, masked out by the caller) read
        // some piece.
        const V position = hn::Mul(hn::Sqrt(rho), mPerRadius);
        const V magic = hn::Set(d, 8388608.0f);
        const V shifted = hn::Add(position, magic);
        const V nearest = hn::Sub(shifted, magic);
        const V v = hn::Sub(position, nearest);
        const auto c = [&](std::size_t k) { return coefficient(d, k, shifted, nearest); };
        return hn::MulAdd(hn::MulAdd(hn::MulAdd(c(3), v, c(2)), v, c(1)), v, c(0));
    }

private:
    // Coefficient k of each lane's piece: `nearest` is the piece, `shifted` holds it in its low
    // mantissa bits.
    V coefficient(D d, std::size_t k, V shifted, V nearest) const {
        const hn::RebindToSigned<D> di;
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX3
        if constexpr (kParts == 2 && kLanes == 8) {
            // AVX-512 on 8 lanes: one two-table permute (vpermt2ps), which Highway 1.0 does not
            // offer, instead of two permutes and a select.
            const auto index = hn::And(hn::BitCast(di, shifted), hn::Set(di, 15));
            return V{_mm256_permutex2var_ps(mCoefficients[k][0].raw, index.raw,
                                            mCoefficients[k][1].raw)};
        }
#endif
        const auto lanes = hn::IndicesFromVec(
            d, hn::And(hn::BitCast(di, shifted), hn::Set(di, static_cast<int>(kLanes - 1))));
        V value = hn::TableLookupLanes(mCoefficients[k][0], lanes);
        for (std::size_t part = 1; part < kParts; ++part) {
            const auto inPart =
                hn::Gt(nearest, hn::Set(d, static_cast<float>(part * kLanes) - 0.5f));
            value =
                hn::IfThenElse(inPart, hn::TableLookupLanes(mCoefficients[k][part], lanes), value);
        }
        return value;
    }

private:
    V mPerRadius;
    V mCoefficients[4][kParts];
};

// 1/w to 14 bits, the same bits on 8 lanes as on 16: Highway's estimate on 8 lanes is AVX's
// 12-bit one even where AVX-512 has the 14-bit one, and a pixel must not depend on the width of
// its splat's box.
template <class D, class V> HWY_INLINE V ReciprocalEstimate(D /*d*/, V w) {
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX3
    if constexpr (hn::MaxLanes(D()) == 8) {
        return V{_mm256_rcp14_ps(w.raw)};
    }
#endif
    return hn::ApproximateReciprocal(w);
}

// What a batch's footprint is: a radial profile, radial cubic pieces or a texture.
enum class Kind { Radial, RadialPieces, Texture };

// What every splat of a batch shares.
template <class D> struct Batch {
    D d;
    const FootprintSampler* sampler;
    ColorPlanes& planes;
    bool depthTest;
    bool squareTest; // the square's edges cut the footprint (else its reach lies inside)
    std::optional<PieceLookup<D>> pieces;
    const FootprintStamps* stamps; // for the kStamped splats
};

// Composites rows [first, last) of one splat; with kClamp, every sum is clamped to FLT_MAX
// (kUnclampedColour says when that is not needed); kDepth as the splat's optical depth allows.
template <Kind kKind, bool kClamp, Depth kDepth, class D>
HWY_INLINE void CompositeSplat(const Batch<D>& batch, const SplatRaster& splat, int first,
                               int last) {
    const D d = batch.d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto lane = hn::Iota(d, 0.0f);
    const auto one = hn::Set(d, 1.0f);
    const auto zero = hn::Zero(d);
    const auto clamp = [&](auto value) { return Clamp<kClamp>(d, value); };
    const FootprintSampler* sampler = batch.sampler;
    ColorPlanes& planes = batch.planes;
    const bool projective = (splat.flags & SplatRaster::kProjective) != 0;
    const bool clipped = (splat.flags & SplatRaster::kClipped) != 0;
    const Medium<D> medium(d, splat.color, splat.extinction);
    const auto lengthScale = hn::Set(d, splat.lengthScale);
    const auto reach = hn::Set(d, sampler != nullptr ? sampler->reach : 2.0f);
    const auto ax = hn::Set(d, splat.square[0]);
    const auto bx = hn::Set(d, splat.square[3]);
    const auto wx = hn::Set(d, splat.square[6]);
    const auto zx = hn::Set(d, splat.depth[0]);
    // Pixel columns of the box's first vector (whole numbers, exact in float), and the step.
    const auto firstX = hn::Add(hn::Set(d, static_cast<float>(splat.columnBegin)), lane);
    const auto nextX = hn::Set(d, static_cast<float>(lanes));
    for (int row = first; row < last; ++row) {
        const auto y = static_cast<float>(row);
        const auto a0 = hn::Set(d, splat.square[1] * y + splat.square[2]);
        const auto b0 = hn::Set(d, splat.square[4] * y + splat.square[5]);
        const auto w0 = hn::Set(d, splat.square[7] * y + splat.square[8]);
        const auto z0 = hn::Set(d, splat.depth[1] * y + splat.depth[2]);
        float* redRow = planes.red(row);
        float* greenRow = planes.green(row);
        float* blueRow = planes.blue(row);
        float* alphaRow = planes.alpha(row);
        const float* depthRow = batch.depthTest ? planes.depth(row) : nullptr;
        auto x = firstX;
        for (int column = splat.columnBegin; column < splat.columnEnd;
             column += lanes, x = hn::Add(x, nextX)) {
            auto a = hn::MulAdd(ax, x, a0);
            auto b = hn::MulAdd(bx, x, b0);
            auto inside = hn::Gt(one, zero); // all true
            if (projective) {
                const auto w = hn::MulAdd(wx, x, w0);
                inside = hn::Gt(w, zero);
                // 1/w: the estimate and one Newton step (relative error ~1e-7), cheaper than a
                // division.
                const auto estimate = ReciprocalEstimate(d, w);
                const auto inverseW =
                    hn::Mul(estimate, hn::NegMulAdd(w, estimate, hn::Set(d, 2.0f)));
                a = hn::Mul(a, inverseW);
                b = hn::Mul(b, inverseW);
            }
            constexpr bool kRadial = kKind == Kind::Radial || kKind == Kind::RadialPieces;
            if (!kRadial || batch.squareTest) {
                inside = hn::And(inside,
                                 hn::And(hn::Le(hn::Abs(a), one), hn::Le(hn::Abs(b), one)));
            }
            const auto rho = hn::MulAdd(a, a, hn::Mul(b, b));
            if constexpr (kRadial) {
                // Beyond the kernel's support the footprint is exactly 0: skip those pixels.
                inside = hn::And(inside, hn::Le(rho, reach));
            }
            if (clipped || batch.depthTest) {
                const auto z = hn::MulAdd(zx, x, z0);
                if (clipped) {
                    inside = hn::And(inside, hn::And(hn::Ge(z, hn::Neg(one)), hn::Le(z, one)));
                }
                if (batch.depthTest) {
                    const auto window = hn::MulAdd(z, hn::Set(d, 0.5f), hn::Set(d, 0.5f));
                    inside = hn::And(inside, hn::Lt(window, hn::LoadU(d, depthRow + column)));
                }
            }
            if (hn::AllFalse(d, inside)) {
                continue;
            }
            hn::Vec<D> footprint;
            if constexpr (kKind == Kind::RadialPieces) {
                footprint = (*batch.pieces)(d, rho);
            } else {
                footprint = Footprint<kKind == Kind::Radial>(d, *sampler, a, b);
            }
            const auto f =
                hn::IfThenElseZero(inside, hn::Mul(hn::Max(footprint, zero), lengthScale));
            hn::Vec<D> alpha;
            hn::Vec<D> weight;
            medium.template attenuate<kDepth>(d, f, alpha, weight);
            const auto transmitted = hn::Sub(one, alpha);
            const auto over = [&](float* plane, decltype(weight) source) {
                Over<kClamp>(d, plane, column, transmitted, source);
            };
            const auto colourRed = hn::Mul(medium.red, weight);
            const auto colourGreen = hn::Mul(medium.green, weight);
            const auto colourBlue = hn::Mul(medium.blue, weight);
            over(redRow, clamp(colourRed));
            over(greenRow, clamp(colourGreen));
            over(blueRow, clamp(colourBlue));
            over(alphaRow, alpha);
        }
    }
}

// Composites rows [first, last) of a stamped splat (SplatRaster::kStamped): its footprint is
// the stamp of its centre's nearest phase, nothing else per pixel but the depth test; pixels the
// footprint does not reach get α = 0 and keep their value (CompositeStamp()).
template <bool kClamp, Depth kDepth, class D>
HWY_INLINE void CompositeStampedSplat(const Batch<D>& batch, const SplatRaster& splat, int first,
                                      int last) {
    const StampTag d;
    const FootprintStamps& stamps = *batch.stamps;
    ColorPlanes& planes = batch.planes;
    const StampRows rows{stamps.values.data() +
                             static_cast<std::size_t>(splat.stampPhase) * stamps.stampSize +
                             static_cast<std::size_t>(first - splat.stampRow) *
                                 static_cast<std::size_t>(stamps.columns),
                         planes.red(first) + splat.stampColumn,
                         planes.planeStride(),
                         planes.stride(),
                         stamps.columns,
                         last - first};
    if (!batch.depthTest && IsThin(splat.color, splat.extinction, stamps.peak)) {
        CompositeThinStamp(d, rows, ThinMedium<StampTag>(d, splat.color, splat.extinction));
        return;
    }
    const StampDepth depth{splat.depth, splat.stampColumn, first};
    CompositeStamp<kClamp, kDepth>(d, rows, Medium<StampTag>(d, splat.color, splat.extinction),
                                   batch.depthTest ? &depth : nullptr);
}

// Whether no colour `splat` adds reaches kUnclampedColour (IsUnclamped()).
bool isUnclamped(const SplatRaster& splat, const FootprintSampler& sampler,
                 const FootprintStamps* stamps) {
    const bool stamped = (splat.flags & SplatRaster::kStamped) != 0;
    return IsUnclamped(splat.color, splat.extinction,
                       stamped ? stamps->peak : sampler.peak * splat.lengthScale);
}

// How α and the colour weight of `splat` are computed (DepthOf()).
Depth depthOf(const SplatRaster& splat, const FootprintSampler* sampler,
              const FootprintStamps* stamps) {
    if ((splat.flags & SplatRaster::kStamped) != 0) {
        return DepthOf(splat.extinction * stamps->peak);
    }
    return DepthOf(sampler != nullptr ? splat.extinction * splat.lengthScale * sampler->peak
                                      : HUGE_VALF);
}

// Composites one splat with the instantiation its clamps and optical depth call for.
template <Kind kKind, bool kClamp, class D>
HWY_INLINE void CompositeSplatAtDepth(const Batch<D>& batch, const SplatRaster& splat, int first,
                                      int last) {
    const auto at = [&](auto depth) {
        constexpr Depth kDepth = decltype(depth)::value;
        if constexpr (kKind == Kind::RadialPieces) { // only the paper's kernel is stamped
            if ((splat.flags & SplatRaster::kStamped) != 0) {
                CompositeStampedSplat<kClamp, kDepth>(batch, splat, first, last);
                return;
            }
        }
        CompositeSplat<kKind, kClamp, kDepth>(batch, splat, first, last);
    };
    switch (depthOf(splat, batch.sampler, batch.stamps)) {
    case Depth::Short:
        at(std::integral_constant<Depth, Depth::Short>{});
        break;
    case Depth::Series:
        at(std::integral_constant<Depth, Depth::Series>{});
        break;
    case Depth::Expm1:
        at(std::integral_constant<Depth, Depth::Expm1>{});
        break;
    }
}

template <Kind kKind>
void CompositeSplatsWith(const SplatRaster* splats, const RowSpan* rows, std::size_t count,
                         const FootprintSampler* sampler, const FootprintStamps* stamps,
                         const FollowingMarks* marks, ColorPlanes& planes, int rowBegin,
                         int rowEnd) {
    // Up to 16 lanes (AVX-512: 1.1× eight on 9–10-pixel-wide boxes), and 8 for boxes no wider:
    // half-width vectors issue on three ports of AVX-512 instead of two (Marschner–Lobb 128³ in
    // perspective, three quarters of its boxes 7–8 pixels wide: 1.16×, CpuRasterizerBenchmark).
    using Wide = hn::CappedTag<float, 16>;
    using Narrow = hn::CappedTag<float, 8>;
    constexpr int kNarrowColumns = static_cast<int>(hn::MaxLanes(Narrow()));
    const bool squareTest = sampler == nullptr || sampler->reach > 1.0f;
    const auto batchOf = [&](auto d) {
        Batch<decltype(d)> batch{d,          sampler,      planes, planes.hasDepth(),
                                 squareTest, std::nullopt, stamps};
        if constexpr (kKind == Kind::RadialPieces) {
            batch.pieces.emplace(d, *sampler);
        }
        return batch;
    };
    const Batch<Wide> wide = batchOf(Wide());
    const Batch<Narrow> narrow = batchOf(Narrow());
    for (std::size_t i = 0; i < count; ++i) {
        const int first = std::max(rows[i].begin, rowBegin);
        const int last = std::min(rows[i].end, rowEnd);
        if (first < last) {
            const SplatRaster& splat = splats[i];
            // Clamps only where they change something (seven of a pixel's operations).
            const bool clamp = !isUnclamped(splat, *sampler, stamps);
            const auto composite = [&](const auto& batch) {
                if (clamp) {
                    CompositeSplatAtDepth<kKind, true>(batch, splat, first, last);
                } else {
                    CompositeSplatAtDepth<kKind, false>(batch, splat, first, last);
                }
            };
            if (splat.columnEnd - splat.columnBegin <= kNarrowColumns ||
                (splat.flags & SplatRaster::kStamped) != 0) {
                composite(narrow);
            } else {
                composite(wide);
            }
        }
        if (marks != nullptr) {
            for (std::uint32_t m = marks->begins[i]; m < marks->begins[i + 1]; ++m) {
                const int markFirst = std::max(marks->rows[m].begin, rowBegin);
                const int markLast = std::min(marks->rows[m].end, rowEnd);
                if (markFirst < markLast) {
                    CompositeMark(marks->marks[m], marks->style, planes, markFirst, markLast);
                }
            }
        }
    }
}

void CompositeSplats(const SplatRaster* splats, const RowSpan* rows, std::size_t count,
                     const FootprintSampler* sampler, const FootprintStamps* stamps,
                     const FollowingMarks* marks, ColorPlanes& planes, int rowBegin, int rowEnd) {
    const auto with = [&](auto kind) {
        CompositeSplatsWith<decltype(kind)::value>(splats, rows, count, sampler, stamps, marks,
                                                   planes, rowBegin, rowEnd);
    };
    if (sampler->hasPieces) {
        with(std::integral_constant<Kind, Kind::RadialPieces>{});
    } else if (sampler->isRadial) {
        with(std::integral_constant<Kind, Kind::Radial>{});
    } else {
        with(std::integral_constant<Kind, Kind::Texture>{});
    }
}

const char* CompositeTarget() { return hwy::TargetName(HWY_TARGET); }

} // namespace texsplat::render::cpu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace texsplat::render::cpu {

HWY_EXPORT(CompositeSplats);
HWY_EXPORT(CompositeTarget);

void compositeSplats(const SplatRaster* splats, const RowSpan* rows, std::size_t count,
                     const FootprintSampler* sampler, const FootprintStamps* stamps,
                     const FollowingMarks* marks, ColorPlanes& planes, int rowBegin, int rowEnd) {
    HWY_DYNAMIC_DISPATCH(CompositeSplats)
    (splats, rows, count, sampler, stamps, marks, planes, rowBegin, rowEnd);
}

const char* compositeTarget() { return HWY_DYNAMIC_DISPATCH(CompositeTarget)(); }

} // namespace texsplat::render::cpu
#endif
