#pragma once

#include "nodes/render/cpu/FootprintStamps.h"
#include "nodes/render/cpu/SplatRaster.h"
#include "octree/VoxelSplats.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace texsplat::render::cpu {

/// @brief A batch of voxel splats (octree::VoxelSplats) set up for compositing without a list,
/// band by band through every slice (compositeVoxels()): an orthographic view whose splats are
/// stamped (SplatSetup::stamps()).
///
/// Each voxel's splat is placed exactly as SplatSetup places the splat a list would hold for it
/// (octree::voxelSplat()): its centre from the same float position, summed in the same order
/// (SplatSetup::centreOf()), the terms a row of voxels shares summed once (RowPlace); so a band
/// composites the same splats on the same stamps in the same order as the list path would, and
/// the image is the same bit for bit.
class VoxelRaster {
public:
    /// @brief Splats of `voxels` set up by `setup` (affine, with stamps), whose footprint is
    /// `sampler` (for the rare splat that is not stamped: across the near or far plane, or too
    /// far out), in an image of `width` x `height` pixels. All must outlive this.
    VoxelRaster(const octree::VoxelSplats& voxels, const SplatSetup& setup,
                const FootprintSampler& sampler, int width, int height);

    const octree::VoxelSplats& voxels() const { return *mVoxels; }      ///< the batch
    const SplatSetup& setup() const { return *mSetup; }                 ///< its view
    const FootprintSampler& sampler() const { return *mSampler; }       ///< its footprint
    const FootprintStamps& stamps() const { return *mSetup->stamps(); } ///< its stamps
    int width() const { return mWidth; }                                ///< image columns
    int height() const { return mHeight; }                              ///< image rows

    /// @brief Where the splats of one row of voxels land: per coordinate k (pixel x, y and
    /// window depth z, SplatSetup::Centre), the sum of SplatSetup::centreOf() is head[k] +
    /// step[k]·p, p the voxel's position along the inner axis, then + tail[k] where `tailed`
    /// (the inner axis is not the last term of the sum).
    struct RowPlace {
        double head[3];
        double step[3];
        double tail[3];
        bool tailed;
    };

    /// @brief The RowPlace of the voxels of slice coordinate `slice` and row coordinate `row`
    /// (octree::SliceOrder's axes).
    RowPlace rowPlace(std::uint64_t slice, std::uint64_t row) const;

    /// @brief Per entry of the grid's palette (none without one), whether its stamped splats are
    /// thin (cpu::thinEntries()): found once for the frame's bands.
    const std::vector<std::uint8_t>& thinEntries() const { return mThinEntries; }

    /// @brief The voxel centres' coordinate along `axis` (local space, float as a list holds
    /// them: octree::voxelSplat()), per voxel index.
    const float* positions(int axis) const {
        return mPositions[static_cast<std::size_t>(axis)].data();
    }

    /// @brief The image rows [begin, end) that the grid's splats may reach (within the image; a
    /// bound with the margin of innerRange()): where bands have work.
    std::pair<int, int> rowRange() const;

    /// @brief The inner-axis coordinates [begin, end) of the voxels of slice coordinate `slice`
    /// and row coordinate `row` (octree::SliceOrder's axes) whose splats may reach image rows
    /// [`rowBegin`, `rowEnd`) within the image's columns: a bound with a margin for rounding (a
    /// voxel outside it has no pixel there; one inside may have none).
    std::pair<std::uint64_t, std::uint64_t> innerRange(std::uint64_t slice, std::uint64_t row,
                                                       int rowBegin, int rowEnd) const;

private:
    const octree::VoxelSplats* mVoxels;
    const SplatSetup* mSetup;
    const FootprintSampler* mSampler;
    int mWidth;
    int mHeight;
    std::array<std::vector<float>, 3> mPositions; // per axis: the voxel centres' coordinate
    // The centre's pixel x and y as affine functions of the voxel's index (for the bounds):
    // value[k] = mOrigin[k] + Σ mStep[k][axis] · index[axis].
    double mOrigin[2]{};
    double mStep[2][3]{};
    double mReach[2]{}; // pixels a splat reaches from its centre, x and y, with the margin
    std::vector<std::uint8_t> mThinEntries; // thinEntries()
};

} // namespace texsplat::render::cpu
