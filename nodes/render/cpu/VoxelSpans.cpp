// Compiled once per SIMD target by Highway's foreach_target; HWY_DYNAMIC_DISPATCH picks one.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "nodes/render/cpu/VoxelSpans.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "nodes/render/cpu/MediumSpans-inl.h"
#include "nodes/render/cpu/SplatSpans.h"
#include "nodes/render/cpu/StampSpans-inl.h"
#include "nodes/render/cpu/VoxelSpans.h"
#include "octree/SplatEmission.h"

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
// composited.
struct PlacedSplat {
    enum Kind : std::uint32_t {
        kThin,    // thin (IsThin()), no depth test: CompositeThinStamp() inline
        kStamped, // stamped otherwise: CompositeStampOf()
        kListed,  // across the near or far plane: CompositeVoxelAsListed()
    };
    glm::vec4 value;
    const float* weights; // the stamp's first row to composite
    float* red;           // its pixel in the red plane
    std::int32_t rows;    // rows to composite
    std::int32_t column;  // the stamp's first column
    std::int32_t first;   // the first row composited
    Kind kind;
    std::uint64_t coordinate;                   // the voxel's inner coordinate
    octree::ClassifiedGrid::StorageIndex block; // kListed: its block's storage
};

// Where the voxels of one row go in one band: their splats placed (PlaceRun()) before any is
// composited, so that the reads of the voxels' media (from blocks and the palette, all over the
// caches) do not wait on each other or on the compositing.
template <octree::ClassifiedGrid::Storage kStorage> class RowPlacer {
public:
    RowPlacer(const VoxelRaster& voxels, ColorPlanes& planes, int rowBegin, int rowEnd)
        : mVoxels(voxels), mGrid(voxels.voxels().grid()), mStamps(voxels.stamps()),
          mRowBegin(rowBegin), mRowEnd(rowEnd), mWidth(voxels.width()),
          mReach(voxels.setup().depthReach()), mPeak(mStamps.peak), mStride(planes.stride()),
          mPlaneStride(planes.planeStride()), mRed(planes.red(0)), mDepthTest(planes.hasDepth()) {
        const int inner = voxels.voxels().order().axes()[2];
        mInnerPositions = voxels.positions(inner);
        constexpr std::uint64_t kSize = octree::ClassifiedGrid::kBlockSize;
        mInnerStride = inner == 0 ? 1 : inner == 1 ? kSize : kSize * kSize;
        mInnerEnds[0] = mInnerPositions[0];
        mInnerEnds[1] = mInnerPositions[mGrid.dims()[inner] - 1];
        mPlaced.resize(static_cast<std::size_t>(mGrid.dims()[inner]));
    }

    // Starts row `row` of slice `slice` (octree::SliceOrder's coordinates).
    void startRow(std::uint64_t slice, std::uint64_t row) {
        mRow = mVoxels.rowPlace(slice, row);
        // The row's window depths lie between those of its ends (with a margin for the sums'
        // rounding): where they are well inside the near and far planes, no splat is tested.
        double ends[2];
        for (int end = 0; end < 2; ++end) {
            const double head = mRow.head[2] + mRow.step[2] * mInnerEnds[end];
            ends[end] = mRow.tailed ? head + mRow.tail[2] : head;
        }
        const double low = std::min(ends[0], ends[1]);
        const double high = std::max(ends[0], ends[1]);
        mNearPlanes = !(low - mReach > -1.0 + 1e-6 && high + mReach < 1.0 - 1e-6);
        mCount = 0;
    }

    // Places the `count` voxels of a run of the row within one block (inner coordinates
    // `coordinates`, storage `block` + `rowOffset` + (c mod 8)·innerStride) whose splats reach
    // the band.
    void placeRun(octree::ClassifiedGrid::StorageIndex block, std::uint64_t rowOffset,
                  const std::uint64_t* coordinates, std::size_t count);

    // Forgets the row's placed splats.
    void clear() { mCount = 0; }

    // The row's placed splats, in order.
    const PlacedSplat* placed() const { return mPlaced.data(); }
    std::size_t count() const { return mCount; }

private:
    using Storage = octree::ClassifiedGrid::Storage;
    const VoxelRaster& mVoxels;
    const octree::ClassifiedGrid& mGrid;
    const FootprintStamps& mStamps;
    int mRowBegin;
    int mRowEnd;
    int mWidth;
    double mReach;
    float mPeak;
    std::ptrdiff_t mStride;
    std::ptrdiff_t mPlaneStride;
    float* mRed;
    bool mDepthTest;
    std::uint64_t mInnerStride = 1;
    const float* mInnerPositions = nullptr;
    double mInnerEnds[2]{}; // the inner positions of a row's first and last voxel
    VoxelRaster::RowPlace mRow{};
    bool mNearPlanes = true; // a splat of the row may come near the near or far plane
    std::vector<PlacedSplat> mPlaced;
    std::size_t mCount = 0;
};

template <octree::ClassifiedGrid::Storage kStorage>
void RowPlacer<kStorage>::placeRun(octree::ClassifiedGrid::StorageIndex block,
                                   std::uint64_t rowOffset, const std::uint64_t* coordinates,
                                   std::size_t count) {
    constexpr std::uint64_t kSize = octree::ClassifiedGrid::kBlockSize;
    const float* const stampValues = mStamps.values.data();
    const auto columns = static_cast<std::size_t>(mStamps.columns);
    const FootprintStamps::Extent* extents = mStamps.extents.data();
    // The block's media, or its indices into the palette.
    const glm::vec4* values = nullptr;
    const std::uint16_t* indices = nullptr;
    if constexpr (kStorage == Storage::Direct) {
        values = mGrid.directBlock(block);
    } else {
        values = mGrid.palette().data();
        indices = mGrid.paletteBlock(block);
    }
    // Members in locals: the compiler keeps them in registers across the stores below.
    const VoxelRaster::RowPlace row = mRow;
    const std::uint64_t innerStride = mInnerStride;
    const bool nearPlanes = mNearPlanes;
    const double reach = mReach;
    const FootprintStamps& stamps = mStamps;
    const double phases = stamps.phases();
    const float* const innerPositions = mInnerPositions;
    const int rowBegin = mRowBegin;
    const int rowEnd = mRowEnd;
    const int width = mWidth;
    const float peak = mPeak;
    const bool depthTest = mDepthTest;
    const std::size_t stampSize = mStamps.stampSize;
    const std::ptrdiff_t stride = mStride;
    float* const red = mRed;
    PlacedSplat* const placed = mPlaced.data();
    std::size_t placedCount = mCount;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint64_t c = coordinates[i];
        const std::uint64_t at = rowOffset + (c % kSize) * innerStride;
        PlacedSplat& splat = placed[placedCount];
        if constexpr (kStorage == Storage::Direct) {
            splat.value = values[at];
            if (splat.value == glm::vec4(0.0f)) {
                continue;
            }
        } else {
            if (indices[at] == 0) {
                continue;
            }
            splat.value = values[indices[at]];
        }
        splat.coordinate = c;
        // SplatSetup::orthographic() of the voxel's splat (SplatSetup::centreOf(), summed as
        // RowPlace says).
        const double p = innerPositions[c];
        const auto centre = [&](int k) {
            const double head = row.head[k] + row.step[k] * p;
            return row.tailed ? head + row.tail[k] : head;
        };
        if (nearPlanes) {
            const double z = centre(2);
            if (z - reach > 1.0 || z + reach < -1.0) {
                continue;
            }
            if (z - reach < -1.0 || z + reach > 1.0) {
                splat.kind = PlacedSplat::kListed;
                splat.block = block;
                ++placedCount;
                continue;
            }
        }
        FootprintStamps::Place place;
        if (!stamps.placeInPhases(std::floor((centre(0) - 0.5) * phases + 0.5),
                                  std::floor((centre(1) - 0.5) * phases + 0.5), place)) {
            splat.kind = PlacedSplat::kListed;
            splat.block = block;
            ++placedCount;
            continue;
        }
        const FootprintStamps::Extent& extent = extents[place.phase];
        const int first = std::max(place.row + extent.rowBegin, rowBegin);
        const int last = std::min(place.row + extent.rowEnd, rowEnd);
        if (first >= last || place.column + extent.columnEnd <= 0 ||
            place.column + extent.columnBegin >= width) {
            continue;
        }
        splat.weights = stampValues + static_cast<std::size_t>(place.phase) * stampSize +
                        static_cast<std::size_t>(first - place.row) * columns;
        splat.red = red + first * stride + place.column;
        splat.rows = last - first;
        splat.column = place.column;
        splat.first = first;
        const float color[3] = {splat.value.r, splat.value.g, splat.value.b};
        if (!depthTest && IsThin(color, splat.value.w, peak)) {
            splat.kind = PlacedSplat::kThin;
        } else {
            splat.kind = PlacedSplat::kStamped;
            splat.block = block;
        }
        ++placedCount;
    }
    mCount = placedCount;
}

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
    const auto composite = [&] {
        const StampTag d;
        const PlacedSplat* placed = placer.placed();
        for (std::size_t i = 0; i < placer.count(); ++i) {
            const PlacedSplat& splat = placed[i];
            StampRows rows = rowsOf;
            rows.weights = splat.weights;
            rows.red = splat.red;
            rows.rows = splat.rows;
            if (splat.kind == PlacedSplat::kThin) {
                const float color[3] = {splat.value.r, splat.value.g, splat.value.b};
                CompositeThinStamp(d, rows, ThinMedium<StampTag>(d, color, splat.value.w));
            } else if (splat.kind == PlacedSplat::kStamped) {
                // As the list's splat: its depth plane from SplatSetup.
                glm::u64vec3 voxel = rowVoxel;
                voxel[axes[2]] = splat.coordinate;
                const SplatRaster raster = voxels.setup().orthographic(
                    octree::voxelSplat(voxels.voxels().grid(), voxel,
                                       splat.block + octree::ClassifiedGrid::offsetInBlock(voxel)));
                const StampDepth depth{raster.depth, splat.column, splat.first};
                CompositeStampOf(rows, splat.value, peak, planes.hasDepth() ? &depth : nullptr);
            } else {
                glm::u64vec3 voxel = rowVoxel;
                voxel[axes[2]] = splat.coordinate;
                CompositeVoxelAsListed(voxels, voxel,
                                       splat.block + octree::ClassifiedGrid::offsetInBlock(voxel),
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

} // namespace texsplat::render::cpu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace texsplat::render::cpu {

HWY_EXPORT(CompositeVoxels);

void compositeVoxels(const VoxelRaster& voxels, ColorPlanes& planes, int rowBegin, int rowEnd) {
    HWY_DYNAMIC_DISPATCH(CompositeVoxels)(voxels, planes, rowBegin, rowEnd);
}

} // namespace texsplat::render::cpu
#endif
