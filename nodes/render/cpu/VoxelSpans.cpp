// Compiled once per SIMD target by Highway's foreach_target; HWY_DYNAMIC_DISPATCH picks one.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "nodes/render/cpu/VoxelSpans.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/cache_control.h>
#include <hwy/highway.h>

#include "nodes/render/cpu/MediumSpans-inl.h"
#include "nodes/render/cpu/SplatSpans.h"
#include "nodes/render/cpu/StampSpans-inl.h"
#include "nodes/render/cpu/VoxelSpans.h"
#include "octree/SplatEmission.h"
#include "scenegraph/Assert.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

HWY_BEFORE_NAMESPACE();
namespace texsplat::render::cpu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Composites the splat of `voxel` (stored at `stored`) as compositeSplats() composites the
// list's splat of it, set up in full by the SplatSetup: for the rare splat across the near or
// far plane, clipped per pixel.
HWY_NOINLINE void CompositeVoxelAsListed(const VoxelRaster& voxels, glm::u64vec3 voxel,
                                         octree::ClassifiedGrid::StorageIndex stored,
                                         ColorPlanes& planes, int rowBegin, int rowEnd) {
    const SplatRaster raster =
        voxels.setup().orthographic(octree::voxelSplat(voxels.voxels().grid(), voxel, stored));
    const RowSpan rows = rowSpanOf(raster);
    compositeSplats(&raster, &rows, 1, &voxels.sampler(), &voxels.stamps(), nullptr, planes,
                    rowBegin, rowEnd);
}

// Composites a stamped splat of medium `value` at `rows` with the instantiation its clamps and
// optical depth call for (as compositeSplats() chooses it); with `depth`, tested against the
// depth plane. The common case, a thin splat that needs no clamp and no depth test, is
// composited inline by CompositeVoxelsIn().
HWY_NOINLINE void CompositeStampOf(const StampRows& rows, const glm::vec4& value, float peak,
                                   const StampDepth* depth) {
    const StampTag d;
    const float color[3] = {value.r, value.g, value.b};
    const Medium<StampTag> medium(d, color, value.w);
    const auto at = [&](auto clamp) {
        constexpr bool kClamp = decltype(clamp)::value;
        switch (DepthOf(value.w * peak)) {
        case Depth::Short:
            CompositeStamp<kClamp, Depth::Short>(d, rows, medium, depth);
            break;
        case Depth::Series:
            CompositeStamp<kClamp, Depth::Series>(d, rows, medium, depth);
            break;
        case Depth::Expm1:
            CompositeStamp<kClamp, Depth::Expm1>(d, rows, medium, depth);
            break;
        }
    };
    if (IsUnclamped(color, value.w, peak)) {
        at(std::false_type{});
    } else {
        at(std::true_type{});
    }
}

// A voxel's splat placed for a band: its medium, where its stamp's rows go, and how it is
// composited, in 16 bytes (the compositing reads a record a splat; the rare splat that is not
// thin keeps the rest in a PlacedDetail).
struct PlacedSplat {
    enum Kind : std::uint32_t {
        kThin,    // thin (IsThin()), no depth test: CompositeThinStamp() inline
        kStamped, // stamped otherwise: CompositeStampOf()
        kListed,  // across the near or far plane: CompositeVoxelAsListed()
    };
    // The stamp's first row to composite (its offset in FootprintStamps::values, below
    // kLargestTable), the rows to composite (at most kLargestSide) and the kind, packed.
    static constexpr int kRowsShift = 18;
    static constexpr int kKindShift = 24;
    static constexpr std::uint32_t kWeightsMask = (std::uint32_t{1} << kRowsShift) - 1;
    static constexpr std::uint32_t kRowsMask = (std::uint32_t{1} << (kKindShift - kRowsShift)) - 1;
    static_assert(FootprintStamps::kLargestTable <= std::size_t{1} << kRowsShift);
    static_assert(FootprintStamps::kLargestSide <= static_cast<int>(kRowsMask));

    const glm::vec4* value; // its medium, in the palette or the block (read as composited)
    std::uint32_t packed;   // weights | rows << kRowsShift | kind << kKindShift
    std::int32_t red;       // its pixel in the red plane, from the plane's first row

    Kind kind() const { return static_cast<Kind>(packed >> kKindShift); }
    std::uint32_t weights() const { return packed & kWeightsMask; }
    int rows() const { return static_cast<int>((packed >> kRowsShift) & kRowsMask); }
};

// The rest of a placed splat that is not thin, at the same index.
struct PlacedDetail {
    std::int32_t column;                        // kStamped: the stamp's first column
    std::int32_t first;                         // kStamped: the first row composited
    std::uint64_t coordinate;                   // the voxel's inner coordinate
    octree::ClassifiedGrid::StorageIndex block; // its block's storage
};

// Where the voxels of one row go in one band: their splats placed (placeRun()) before any is
// composited, so that the reads of the voxels' blocks (all over the caches) do not wait on each
// other or on the compositing. A splat keeps a pointer to its medium: the compositing reads it
// (a palette's entry, all over the caches too) while the splats before it are still stored.
template <octree::ClassifiedGrid::Storage kStorage> class RowPlacer {
public:
    using StorageIndex = octree::ClassifiedGrid::StorageIndex;
    // The most lanes of a vector of doubles.
    static constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
    static_assert(kMaxLanes <= 8, "a vector's mask bits fit in a byte");

    RowPlacer(const VoxelRaster& voxels, ColorPlanes& planes, int rowBegin, int rowEnd)
        : mVoxels(voxels), mGrid(voxels.voxels().grid()), mStamps(voxels.stamps()),
          mRowBegin(rowBegin), mRowEnd(rowEnd), mWidth(voxels.width()),
          mReach(voxels.setup().depthReach()), mPeak(mStamps.peak), mStride(planes.stride()),
          mDepthTest(planes.hasDepth()),
          mThinEntries(voxels.thinEntries().data()) {
        const octree::SliceOrder& order = voxels.voxels().order();
        const int inner = order.axes()[2];
        const float* positions = voxels.positions(inner);
        const auto count = static_cast<std::size_t>(mGrid.dims()[inner]);
        // kMaxLanes more each side, the ends repeated: a vector of a run's positions is one
        // load wherever the run lies (placeLanes()).
        mInnerPositions.assign(count + 2 * kMaxLanes, double(positions[0]));
        std::copy(positions, positions + count, mInnerPositions.begin() + kMaxLanes);
        std::fill(mInnerPositions.begin() + kMaxLanes + count, mInnerPositions.end(),
                  double(positions[count - 1]));
        constexpr std::uint64_t kSize = octree::ClassifiedGrid::kBlockSize;
        mInnerStride = inner == 0 ? 1 : inner == 1 ? kSize : kSize * kSize;
        const int sliceAxis = order.axes()[0];
        const std::vector<std::uint64_t>& slices = order.axisOrder(sliceAxis);
        mSliceAscending = slices.size() < 2 || slices[1] > slices[0];
        const auto sliceStride = static_cast<std::ptrdiff_t>(
            sliceAxis == 0 ? 1 : sliceAxis == 1 ? kSize : kSize * kSize);
        mNextSlice = mSliceAscending ? sliceStride : -sliceStride;
        // placeLanes() writes a splat for each lane and keeps those it places: room for a
        // vector past the row's voxels.
        mPlaced.resize(count + kMaxLanes);
        mDetails.resize(count + kMaxLanes);
        TEXSPLAT_ASSERT(mStamps.values.size() <= FootprintStamps::kLargestTable,
                        "RowPlacer: a stamp's offset does not fit its PlacedSplat bits");
        TEXSPLAT_ASSERT(planes.planeStride() <= std::ptrdiff_t{INT32_MAX},
                        "RowPlacer: a pixel's offset does not fit PlacedSplat::red");
        // The stamps' extents, a byte each (at most kLargestSide): one gather a vector.
        mPackedExtents.reserve(mStamps.extents.size());
        for (const FootprintStamps::Extent& extent : mStamps.extents) {
            mPackedExtents.push_back(
                static_cast<std::int32_t>(static_cast<std::uint32_t>(extent.columnBegin) |
                                          static_cast<std::uint32_t>(extent.columnEnd) << 8 |
                                          static_cast<std::uint32_t>(extent.rowBegin) << 16 |
                                          static_cast<std::uint32_t>(extent.rowEnd) << 24));
        }
    }

    // Starts row `row` of slice `slice` (octree::SliceOrder's coordinates).
    void startRow(std::uint64_t slice, std::uint64_t row) {
        mRow = mVoxels.rowPlace(slice, row);
        // Whether the next slice's voxels of this row lie in the same blocks.
        const std::uint64_t within = slice % octree::ClassifiedGrid::kBlockSize;
        mPrefetch = mSliceAscending ? within + 1 < octree::ClassifiedGrid::kBlockSize
                                    : within > 0;
        // The row's window depths lie between those of its ends (with a margin for the sums'
        // rounding): where they are well inside the near and far planes, no splat is tested.
        double ends[2];
        for (int end = 0; end < 2; ++end) {
            const std::size_t at = end == 0 ? kMaxLanes : mInnerPositions.size() - 1 - kMaxLanes;
            ends[end] = centre(2, mInnerPositions[at]);
        }
        const double low = std::min(ends[0], ends[1]);
        const double high = std::max(ends[0], ends[1]);
        mNearPlanes = !(low - mReach > -1.0 + 1e-6 && high + mReach < 1.0 - 1e-6);
        mCount = 0;
    }

    // Places the `count` voxels of a run of the row within one block (inner coordinates
    // `coordinates`, storage `block` + `rowOffset` + (c mod 8)·innerStride) whose splats reach
    // the band: a vector of them at a time (placeLanes()) in a row far from the near and far
    // planes, else (and from a vector with a centre too far out for an int on) one at a time.
    void placeRun(StorageIndex block, std::uint64_t rowOffset, const std::uint64_t* coordinates,
                  std::size_t count) {
        Run run{block, rowOffset, mInnerStride, nullptr, nullptr};
        if constexpr (kStorage == Storage::Direct) {
            run.values = mGrid.directBlock(block);
            if (mPrefetch) {
                hwy::Prefetch(run.values + static_cast<std::ptrdiff_t>(rowOffset) + mNextSlice);
            }
        } else {
            run.values = mGrid.palette().data();
            run.indices = mGrid.paletteBlock(block);
            // The band reads each voxel once: the next slice's indices of the row, read in a
            // slice's time, are fetched now rather than waited for then.
            if (mPrefetch) {
                hwy::Prefetch(run.indices + static_cast<std::ptrdiff_t>(rowOffset) + mNextSlice);
            }
        }
        // The cursor in a local, not mCount: the compiler keeps it in a register across the
        // stores of the placed splats, which it cannot tell apart from the members.
        PlacedSplat* out = mPlaced.data() + mCount;
        std::size_t i = 0;
        if (!mNearPlanes) {
            const hn::ScalableTag<double> dd;
            const std::size_t lanes = hn::Lanes(dd);
            for (; i < count; i += lanes) {
                PlacedSplat* end =
                    placeLanes(dd, run, coordinates + i, std::min(lanes, count - i), out);
                if (end == nullptr) {
                    break;
                }
                out = end;
            }
        }
        for (; i < count; ++i) {
            out = placeOne(run, coordinates[i], out);
        }
        mCount = static_cast<std::size_t>(out - mPlaced.data());
    }

    // Forgets the row's placed splats.
    void clear() { mCount = 0; }

    // The row's placed splats, in order.
    const PlacedSplat* placed() const { return mPlaced.data(); }
    // The details of the row's placed splats that are not thin, at the same indices.
    const PlacedDetail* details() const { return mDetails.data(); }
    std::size_t count() const { return mCount; }

private:
    using Storage = octree::ClassifiedGrid::Storage;

    // The block a run reads: its storage, the row's offset in it, and the media (Direct: the
    // block's; Palette: the palette, and the block's indices into it).
    struct Run {
        StorageIndex block;
        std::uint64_t rowOffset;
        std::uint64_t innerStride;
        const glm::vec4* values;
        const std::uint16_t* indices;
    };

    // A voxel's medium, and (Palette) its entry in the palette.
    struct VoxelMedium {
        const glm::vec4* value;
        std::uint16_t entry;
    };

    // The medium of the run's voxel of inner coordinate `c` (set where it is empty too); false
    // where it is empty.
    bool mediumOf(const Run& run, std::uint64_t c, VoxelMedium& medium) const {
        constexpr std::uint64_t kSize = octree::ClassifiedGrid::kBlockSize;
        const std::uint64_t at = run.rowOffset + (c % kSize) * run.innerStride;
        if constexpr (kStorage == Storage::Direct) {
            medium.value = run.values + at;
            return *medium.value != glm::vec4(0.0f);
        } else {
            medium.entry = run.indices[at];
            medium.value = run.values + medium.entry;
            return medium.entry != 0;
        }
    }

    // Whether a splat of `medium` is thin (IsThin()): of a palette's entry, as the frame's
    // VoxelRaster found it.
    bool isThin(const VoxelMedium& medium) const {
        if constexpr (kStorage == Storage::Direct) {
            const glm::vec4& value = *medium.value;
            const float color[3] = {value.r, value.g, value.b};
            return IsThin(color, value.w, mPeak);
        } else {
            return mThinEntries[medium.entry] != 0;
        }
    }

    // Places the voxel of inner coordinate `c` at `out` (SplatSetup::orthographic() of its
    // splat, near and far planes and all): the end of the placed splats.
    HWY_INLINE PlacedSplat* placeOne(const Run& run, std::uint64_t c, PlacedSplat* out) {
        VoxelMedium medium;
        if (!mediumOf(run, c, medium)) {
            return out;
        }
        const double p = mInnerPositions[kMaxLanes + c];
        if (mNearPlanes) {
            const double z = centre(2, p);
            if (z - mReach > 1.0 || z + mReach < -1.0) {
                return out;
            }
            if (z - mReach < -1.0 || z + mReach > 1.0) {
                return recordListed(run, medium.value, c, out);
            }
        }
        const double phases = mStamps.phases();
        FootprintStamps::Place place;
        if (!mStamps.placeInPhases(std::floor((centre(0, p) - 0.5) * phases + 0.5),
                                   std::floor((centre(1, p) - 0.5) * phases + 0.5), place)) {
            return recordListed(run, medium.value, c, out);
        }
        const FootprintStamps::Extent& extent =
            mStamps.extents[static_cast<std::size_t>(place.phase)];
        const int first = std::max(place.row + extent.rowBegin, mRowBegin);
        const int last = std::min(place.row + extent.rowEnd, mRowEnd);
        if (first >= last || place.column + extent.columnEnd <= 0 ||
            place.column + extent.columnBegin >= mWidth) {
            return out;
        }
        return record(run, medium, c, place, first, last, out);
    }

    // Places the `count` (at most a vector's) voxels of inner coordinates `coordinates` (a
    // run: consecutive, ascending or descending) of a row far from the near and far planes at
    // `out` as placeOne() does, the centres, their stamps and their rows in the band one voxel
    // per lane of `dd`: the end of the placed splats, or null, with none placed, where a centre
    // is too far out for an int (placeOne() lists its splat). The positions are one load, the
    // stamps' extents one gather; every lane's splat is written and kept where it is shown and
    // not empty, so no branch waits on a voxel's medium.
    template <class DD>
    HWY_INLINE PlacedSplat* placeLanes(DD dd, const Run& run, const std::uint64_t* coordinates,
                                       std::size_t count, PlacedSplat* out) {
        const hn::Rebind<std::int32_t, DD> di;
        const std::size_t lanes = hn::Lanes(dd);
        const std::uint64_t c0 = coordinates[0];
        const bool descending = count > 1 && coordinates[1] < c0;
        TEXSPLAT_ASSERT(descending ? c0 - coordinates[count - 1] == count - 1
                                   : coordinates[count - 1] - c0 == count - 1,
                        "RowPlacer::placeLanes(): a run's coordinates are not consecutive");
        const double* positions = mInnerPositions.data() + kMaxLanes + c0;
        const auto p = descending ? hn::Reverse(dd, hn::LoadU(dd, positions - (lanes - 1)))
                                  : hn::LoadU(dd, positions);
        // centre() and placeInPhases()'s sums: the products are exact (a float's by a float's
        // in double, and by a power of two), so a contracted multiply-add rounds as they do.
        const auto nearest = [&](int k) {
            auto sum = hn::MulAdd(hn::Set(dd, mRow.step[k]), p, hn::Set(dd, mRow.head[k]));
            if (mRow.tailed) {
                sum = hn::Add(sum, hn::Set(dd, mRow.tail[k]));
            }
            const auto half = hn::Set(dd, 0.5);
            return hn::Floor(hn::MulAdd(hn::Sub(sum, half), hn::Set(dd, mStamps.phases()), half));
        };
        const auto x = nearest(0);
        const auto y = nearest(1);
        const auto limit = hn::Set(dd, FootprintStamps::kPhaseLimit);
        if (!hn::AllTrue(dd, hn::And(hn::Lt(hn::Abs(x), limit), hn::Lt(hn::Abs(y), limit)))) {
            return nullptr;
        }
        // FootprintStamps::placeInPhases() and the rows of the band, per lane.
        const auto wholeX = hn::DemoteTo(di, x);
        const auto wholeY = hn::DemoteTo(di, y);
        const int bits = mStamps.phaseBits;
        const auto mask = hn::Set(di, mStamps.phases() - 1);
        const auto column =
            hn::Add(hn::ShiftRightSame(wholeX, bits), hn::Set(di, mStamps.columnOffset));
        const auto row = hn::Add(hn::ShiftRightSame(wholeY, bits), hn::Set(di, mStamps.rowOffset));
        const auto phase =
            hn::Add(hn::ShiftLeftSame(hn::And(wholeY, mask), bits), hn::And(wholeX, mask));
        const auto extent = hn::GatherIndex(di, mPackedExtents.data(), phase);
        const auto byte = hn::Set(di, 0xff);
        const auto columnBegin = hn::And(extent, byte);
        const auto columnEnd = hn::And(hn::ShiftRight<8>(extent), byte);
        const auto first = hn::Max(hn::Add(row, hn::And(hn::ShiftRight<16>(extent), byte)),
                                   hn::Set(di, mRowBegin));
        const auto last =
            hn::Min(hn::Add(row, hn::ShiftRight<24>(extent)), hn::Set(di, mRowEnd));
        const auto inImage = hn::And(hn::Gt(hn::Add(column, columnEnd), hn::Zero(di)),
                                     hn::Lt(hn::Add(column, columnBegin), hn::Set(di, mWidth)));
        const auto shown = hn::And(hn::Lt(first, last), inImage);
        // The stamp's first row composited and its first pixel, as addresses a lane: the
        // loop below only copies them (where the compiler would pair their scalings in slow
        // 64-bit vector multiplies). The stamps hold at most kLargestTable floats: an int; a
        // pixel's offset is exact in a double.
        // The stamp's first row composited and its first pixel, as offsets a lane (PlacedSplat):
        // the loop below only copies them. The stamps hold at most kLargestTable floats, a
        // plane fewer than 2^31 (the constructor's checks).
        const auto weights =
            hn::Add(hn::Mul(phase, hn::Set(di, static_cast<std::int32_t>(mStamps.stampSize))),
                    hn::Mul(hn::Sub(first, row), hn::Set(di, mStamps.columns)));
        const auto packed =
            hn::Or(weights, hn::ShiftLeft<PlacedSplat::kRowsShift>(hn::Sub(last, first)));
        const auto pixel =
            hn::Add(hn::Mul(first, hn::Set(di, static_cast<std::int32_t>(mStride))), column);
        HWY_ALIGN std::int32_t packedAt[kMaxLanes], redAt[kMaxLanes], columns[kMaxLanes],
            firsts[kMaxLanes];
        hn::Store(packed, di, packedAt);
        hn::Store(column, di, columns);
        hn::Store(first, di, firsts);
        hn::Store(pixel, di, redAt);
        std::uint8_t shownBits[8] = {};
        hn::StoreMaskBits(di, shown, shownBits);
        // In locals: the compiler cannot tell the members from the stores below.
        const bool depthTest = mDepthTest;
        PlacedDetail* details = mDetails.data() + (out - mPlaced.data());
        for (std::size_t lane = 0; lane < count; ++lane) {
            VoxelMedium medium;
            const bool nonEmpty = mediumOf(run, coordinates[lane], medium);
            const bool thin = !depthTest && isThin(medium);
            PlacedSplat& splat = *out;
            splat.value = medium.value;
            splat.packed = static_cast<std::uint32_t>(packedAt[lane]) |
                           (thin ? std::uint32_t{PlacedSplat::kThin}
                                 : std::uint32_t{PlacedSplat::kStamped})
                               << PlacedSplat::kKindShift;
            splat.red = redAt[lane];
            if (!thin) {
                PlacedDetail& detail = *details;
                detail.column = columns[lane];
                detail.first = firsts[lane];
                detail.coordinate = coordinates[lane];
                detail.block = run.block;
            }
            const unsigned placed = ((shownBits[0] >> lane) & 1u) & static_cast<unsigned>(nonEmpty);
            out += placed;
            details += placed;
        }
        return out;
    }

    // Records at `out` the splat of `medium` of the voxel of inner coordinate `c`, stamped at
    // `place`, rows [first, last) of it in the band: the end of the placed splats.
    PlacedSplat* record(const Run& run, const VoxelMedium& medium, std::uint64_t c,
                        const FootprintStamps::Place& place, int first, int last,
                        PlacedSplat* out) {
        PlacedSplat& splat = *out;
        splat.value = medium.value;
        const auto weights = static_cast<std::uint32_t>(
            static_cast<std::size_t>(place.phase) * mStamps.stampSize +
            static_cast<std::size_t>(first - place.row) *
                static_cast<std::size_t>(mStamps.columns));
        splat.packed = weights | static_cast<std::uint32_t>(last - first)
                                     << PlacedSplat::kRowsShift;
        splat.red = static_cast<std::int32_t>(first * mStride + place.column);
        if (!mDepthTest && isThin(medium)) {
            splat.packed |= std::uint32_t{PlacedSplat::kThin} << PlacedSplat::kKindShift;
        } else {
            splat.packed |= std::uint32_t{PlacedSplat::kStamped} << PlacedSplat::kKindShift;
            PlacedDetail& detail = mDetails[static_cast<std::size_t>(out - mPlaced.data())];
            detail.column = place.column;
            detail.first = first;
            detail.coordinate = c;
            detail.block = run.block;
        }
        return out + 1;
    }

    // Records at `out` the splat of medium `value` of the voxel of inner coordinate `c` as
    // listed: the end of the placed splats.
    PlacedSplat* recordListed(const Run& run, const glm::vec4* value, std::uint64_t c,
                              PlacedSplat* out) {
        PlacedSplat& splat = *out;
        splat.value = value;
        splat.packed = std::uint32_t{PlacedSplat::kListed} << PlacedSplat::kKindShift;
        PlacedDetail& detail = mDetails[static_cast<std::size_t>(out - mPlaced.data())];
        detail.coordinate = c;
        detail.block = run.block;
        return out + 1;
    }

    // Coordinate k of the centre (SplatSetup::centreOf(), summed as RowPlace says) of the
    // row's voxel at inner position `p`.
    double centre(int k, double p) const {
        const double head = mRow.head[k] + mRow.step[k] * p;
        return mRow.tailed ? head + mRow.tail[k] : head;
    }

    const VoxelRaster& mVoxels;
    const octree::ClassifiedGrid& mGrid;
    const FootprintStamps& mStamps;
    int mRowBegin;
    int mRowEnd;
    int mWidth;
    double mReach;
    float mPeak;
    std::ptrdiff_t mStride;
    bool mDepthTest;
    std::uint64_t mInnerStride = 1;
    // The voxel centres' inner coordinate, per voxel index, kMaxLanes on: a vector's room
    // before the first and after the last.
    std::vector<double> mInnerPositions;
    std::vector<std::int32_t> mPackedExtents; // per stamp, its Extent a byte a field
    bool mSliceAscending = true;  // the slices come in ascending coordinate
    std::ptrdiff_t mNextSlice = 0; // storage from a voxel to the next slice's in its block
    bool mPrefetch = false;        // the row's next slice lies in the same blocks
    VoxelRaster::RowPlace mRow{};
    bool mNearPlanes = true; // a splat of the row may come near the near or far plane
    std::vector<PlacedSplat> mPlaced;
    std::vector<PlacedDetail> mDetails; // per placed splat that is not thin
    std::size_t mCount = 0;
    const std::uint8_t* mThinEntries; // Palette: VoxelRaster::thinEntries()
};

// CompositeVoxels() for a grid of `kStorage` (octree::ClassifiedGrid::storage()): row by row of
// each slice, the row's voxels placed, then composited in order.
template <octree::ClassifiedGrid::Storage kStorage>
void CompositeVoxelsIn(const VoxelRaster& voxels, ColorPlanes& planes, int rowBegin, int rowEnd) {
    const octree::VoxelSplats& batch = voxels.voxels();
    const octree::SliceOrder& order = batch.order();
    const std::array<int, 3>& axes = order.axes();
    const std::vector<std::uint64_t>& slices = order.axisOrder(axes[0]);
    const float peak = voxels.stamps().peak;
    const StampRows rowsOf{
        nullptr, nullptr, planes.planeStride(), planes.stride(), voxels.stamps().columns, 0};
    RowPlacer<kStorage> placer(voxels, planes, rowBegin, rowEnd);
    glm::u64vec3 rowVoxel(0);
    std::uint64_t placedRow = ~std::uint64_t{0};
    const float* stampValues = voxels.stamps().values.data();
    float* red = planes.red(0);
    const auto composite = [&] {
        const StampTag d;
        const PlacedSplat* placed = placer.placed();
        for (std::size_t i = 0; i < placer.count(); ++i) {
            const PlacedSplat& splat = placed[i];
            StampRows rows = rowsOf;
            rows.weights = stampValues + splat.weights();
            rows.red = red + splat.red;
            rows.rows = splat.rows();
            const PlacedSplat::Kind kind = splat.kind();
            if (kind == PlacedSplat::kThin) {
                const glm::vec4& value = *splat.value;
                const float color[3] = {value.r, value.g, value.b};
                CompositeThinStamp(d, rows, ThinMedium<StampTag>(d, color, value.w));
            } else if (kind == PlacedSplat::kStamped) {
                // As the list's splat: its depth plane from SplatSetup.
                const PlacedDetail& detail = placer.details()[i];
                glm::u64vec3 voxel = rowVoxel;
                voxel[axes[2]] = detail.coordinate;
                const SplatRaster raster = voxels.setup().orthographic(octree::voxelSplat(
                    voxels.voxels().grid(), voxel,
                    detail.block + octree::ClassifiedGrid::offsetInBlock(voxel)));
                const StampDepth depth{raster.depth, detail.column, detail.first};
                CompositeStampOf(rows, *splat.value, peak, planes.hasDepth() ? &depth : nullptr);
            } else {
                const PlacedDetail& detail = placer.details()[i];
                glm::u64vec3 voxel = rowVoxel;
                voxel[axes[2]] = detail.coordinate;
                CompositeVoxelAsListed(voxels, voxel,
                                       detail.block + octree::ClassifiedGrid::offsetInBlock(voxel),
                                       planes, rowBegin, rowEnd);
            }
        }
    };
    for (std::size_t slice = 0; slice < order.sliceCount(); ++slice) {
        const std::uint64_t a = slices[slice];
        order.forEachSegmentInSlice(
            slice, [&](std::uint64_t b) { return voxels.innerRange(a, b, rowBegin, rowEnd); },
            [&](glm::u64vec3 voxel, octree::ClassifiedGrid::StorageIndex block,
                const std::uint64_t* coordinates, std::size_t count) {
                const std::uint64_t b = voxel[axes[1]];
                if (b != placedRow) {
                    composite();
                    placedRow = b;
                    rowVoxel = voxel;
                    placer.startRow(a, b);
                }
                placer.placeRun(block, octree::ClassifiedGrid::offsetInBlock(voxel), coordinates,
                                count);
            });
        composite();
        placer.clear();
        placedRow = ~std::uint64_t{0};
    }
}

void CompositeVoxels(const VoxelRaster& voxels, ColorPlanes& planes, int rowBegin, int rowEnd) {
    if (voxels.voxels().grid().storage() == octree::ClassifiedGrid::Storage::Palette) {
        CompositeVoxelsIn<octree::ClassifiedGrid::Storage::Palette>(voxels, planes, rowBegin,
                                                                    rowEnd);
    } else {
        CompositeVoxelsIn<octree::ClassifiedGrid::Storage::Direct>(voxels, planes, rowBegin,
                                                                   rowEnd);
    }
}

std::vector<std::uint8_t> ThinEntries(const std::vector<glm::vec4>& palette, float peak) {
    std::vector<std::uint8_t> thin(palette.size());
    for (std::size_t entry = 0; entry < palette.size(); ++entry) {
        const glm::vec4& value = palette[entry];
        const float color[3] = {value.r, value.g, value.b};
        thin[entry] = IsThin(color, value.w, peak) ? 1 : 0;
    }
    return thin;
}

} // namespace texsplat::render::cpu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace texsplat::render::cpu {

HWY_EXPORT(CompositeVoxels);
HWY_EXPORT(ThinEntries);

void compositeVoxels(const VoxelRaster& voxels, ColorPlanes& planes, int rowBegin, int rowEnd) {
    HWY_DYNAMIC_DISPATCH(CompositeVoxels)(voxels, planes, rowBegin, rowEnd);
}

std::vector<std::uint8_t> thinEntries(const std::vector<glm::vec4>& palette, float peak) {
    return HWY_DYNAMIC_DISPATCH(ThinEntries)(palette, peak);
}

} // namespace texsplat::render::cpu
#endif
