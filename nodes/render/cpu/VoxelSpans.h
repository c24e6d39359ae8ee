#pragma once

#include "nodes/render/cpu/ColorPlanes.h"
#include "nodes/render/cpu/VoxelRaster.h"

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace texsplat::render::cpu {

/// @brief Composites the voxel splats of `voxels` that reach rows [rowBegin, rowEnd) of `planes`,
/// back to front, with premultiplied "over": every slice in turn, each row of voxels of a slice
/// whose splats may reach the band (VoxelRaster::innerRange()), each non-empty voxel placed on
/// its stamp and composited by CompositeStamp() (the list path's loop, vector for vector); the
/// rare splat that is not stamped (across the near or far plane) through compositeSplats(). No
/// list: the voxels are read from the classified grid as the band needs them, so a band of a few
/// dozen rows stays in the caches through all the slices (the reference splatter's "bands to
/// completion", ../shared/reference/cpu-splat).
///
/// The pixels of the band get exactly what compositeSplats() gives them from the list of the
/// same splats (octree::emitVoxelSplats()) set up by the same SplatSetup: the same splats, in the
/// same order, with the same arithmetic. Bands may be drawn in parallel.
void compositeVoxels(const VoxelRaster& voxels, ColorPlanes& planes, int rowBegin, int rowEnd);

/// @brief Per entry of `palette` (octree::ClassifiedGrid::palette()), 1 where a stamped splat
/// of its medium whose footprint (times its length scale) peaks at `peak` is thin, 0 elsewhere:
/// composited by the thin loop unless depth-tested, as compositeSplats() chooses it.
std::vector<std::uint8_t> thinEntries(const std::vector<glm::vec4>& palette, float peak);

} // namespace texsplat::render::cpu
