#pragma once

#include "nodes/render/VolumeLighting.h"
#include "nodes/render/VoxelGradients.h"
#include "octree/ClassifiedGrid.h"

#include <memory>

namespace texsplat::render {

/// @brief The grid of `gradients` with every non-empty voxel's colour lit by `lighting`
/// (VolumeLighting::shade() of its colour, extinction and gradient): pre-shaded colour, as VTK's
/// splatting mappers draw, so the backends draw a shaded volume as any other. Extinctions, the
/// empty voxels and the vectors (combined splats) stay as they are. Made in parallel over the
/// blocks.
std::shared_ptr<octree::ClassifiedGrid> shadedGrid(const VoxelGradients& gradients,
                                                   const VolumeLighting& lighting);

} // namespace texsplat::render
