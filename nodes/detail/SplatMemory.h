#pragma once

#include "scenegraph/MemoryLimit.h"

#include <glm/ext/vector_int3_sized.hpp>

#include <cstdint>

namespace texsplat::nodes {
class VolumeData;
} // namespace texsplat::nodes

namespace texsplat::nodes::detail {

/// @brief What a splat node's frame allocates once its volume is loaded, estimated before
/// classifying, when nothing is known of the voxels but their number: an upper bound, since
/// transparent voxels make no splat but classifying is what finds them.
struct SplatMemory {
    glm::i64vec3 dims{0};         ///< voxels per axis of the grid classified
    std::uint64_t classified = 0; ///< the classified grid: colour and extinction (and vector);
                                  ///< for scalar splats also the grid's value ranges
    std::uint64_t octree = 0;     ///< the octree's records, when a cut is asked for
    std::uint64_t splats = 0;     ///< the splat list and its depth ordering

    /// @brief Everything together.
    [[nodiscard]] std::uint64_t total() const {
        return byteSum(byteSum(classified, octree), splats);
    }
};

/// @brief The estimate for `volume`'s grid (loaded; its vector field for vector splats).
/// `withOctree`: a cut is asked for (an error threshold or a budget); `maxSplats` > 0 bounds
/// the splats, else every voxel may be one.
SplatMemory estimateSplatMemory(const VolumeData& volume, bool withVectors, bool withOctree,
                                std::uint64_t maxSplats);

/// @brief Refuses a frame whose estimate exceeds the memory limit (texsplat::memoryLimit()),
/// before anything is allocated: throws ResourceError "classifying and splatting 1200x1200x1200
/// voxels would need <total>, more than the memory limit of …; the classified grid takes …, the
/// octree …, the splats …; <kSplatMemoryAdvice>".
void checkSplatMemory(const SplatMemory& memory);

/// @brief The ray-cast reference's part of the check: it classifies but makes no splats. Throws
/// ResourceError "classifying 1200x1200x1200 voxels for the ray-cast reference would need
/// <classified>, more than the memory limit of …; use a volume of lower resolution or a larger
/// --memory-limit".
void checkClassificationMemory(const SplatMemory& memory);

/// @brief What to do when a splat node's stages run out of memory.
inline constexpr const char* kSplatMemoryAdvice =
    "use a volume of lower resolution, a splat budget (maxSplats, or --max-splats) to bound "
    "the splats, or a larger --memory-limit";

} // namespace texsplat::nodes::detail
