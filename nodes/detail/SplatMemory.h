#pragma once

#include "scenegraph/MemoryLimit.h"

#include <glm/ext/vector_int3_sized.hpp>

#include <cstdint>
#include <string>

namespace texsplat::nodes {
class VolumeData;
} // namespace texsplat::nodes

namespace texsplat::octree {
class ClassifiedGrid;
} // namespace texsplat::octree

namespace texsplat::nodes::detail {

/// @brief What a splat node's frame allocates once its volume is loaded, estimated in two steps
/// so that each is refused before it allocates and neither counts voxels that turn out
/// transparent (the frame was estimated as if every voxel were visible: 24 times too much for a
/// cloud that fills a twentieth of its box):
/// - before classifying, when nothing is known of the voxels but their number: the classified
///   grid, an upper bound (estimateClassification());
/// - once classified, when the non-empty voxels are counted: the octree and the splats, exact
///   bounds (estimateSplats()).
struct SplatMemory {
    glm::i64vec3 dims{0};         ///< voxels per axis of the grid classified
    std::uint64_t classified = 0; ///< the classified grid: colour and extinction (and vector);
                                  ///< for scalar splats also the grid's value ranges
    std::uint64_t octree = 0;     ///< the octree's records, when a cut is asked for
    std::uint64_t splats = 0;     ///< the splat list and its depth ordering
    std::uint64_t shading = 0;    ///< a shaded volume's gradients and lit copy of the grid

    /// @brief Everything together.
    [[nodiscard]] std::uint64_t total() const {
        return byteSum(byteSum(byteSum(classified, octree), splats), shading);
    }
};

/// @brief The classified grid's bound for `volume`'s grid (loaded; its vector field for vector
/// splats): each stored voxel may make one block of the box visible.
SplatMemory estimateClassification(const VolumeData& volume, bool withVectors);

/// @brief Refuses classifying when `memory.classified` exceeds the memory limit, before anything
/// is allocated: throws ResourceError "classifying 1200x1200x1200 voxels <purpose> would need
/// <classified>, more than the memory limit of …; <advice>" (`purpose` empty for a frame, " for
/// the ray-cast reference" for RayCastAction).
void checkClassificationMemory(const SplatMemory& memory, const std::string& purpose = {});

/// @brief `memory` with the octree and the splats of the classified grid, which holds
/// `nonEmptyVoxels` (what can become a splat) in `classifiedBytes`: `withOctree`, a cut is asked
/// for (an error threshold or a budget); `maxSplats` > 0 bounds the splats; `listed`, whether the
/// frame lists its splats (not for a full-resolution frame without marks: the CPU backend walks
/// its voxels, and octree::VoxelSplats::list() asks for a list where one is made);
/// `shadingBytes`, what shading the grid takes (shadingBytesFor(), 0 unshaded).
SplatMemory estimateSplats(SplatMemory memory, std::uint64_t classifiedBytes,
                           std::uint64_t nonEmptyVoxels, bool withVectors, bool withOctree,
                           std::uint64_t maxSplats, bool listed, std::uint64_t shadingBytes = 0);

/// @brief What shading `classified` takes (TransferFunction::shade): a gradient per voxel of its
/// allocated blocks and the lit copy of the grid.
std::uint64_t shadingBytesFor(const octree::ClassifiedGrid& classified);

/// @brief Refuses a frame whose estimate exceeds the memory limit, before the octree and the
/// splats are made: throws ResourceError "classifying and splatting 1200x1200x1200 voxels would
/// need <total>, more than the memory limit of …; the classified grid takes …, the octree …, the
/// splats … (, the shading …); <kSplatMemoryAdvice>".
void checkSplatMemory(const SplatMemory& memory);

/// @brief What to do when a splat node's stages run out of memory.
inline constexpr const char* kSplatMemoryAdvice =
    "use a volume of lower resolution, a splat budget (maxSplats, or --max-splats) to bound "
    "the splats, or a larger --memory-limit";

} // namespace texsplat::nodes::detail
