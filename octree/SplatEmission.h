#pragma once

#include "octree/Fwd.h"
#include "octree/Splat.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace texsplat::octree {

/// @brief What vector splats need at emission (Crawfis & Max 1993, "Combined Vector and Scalar
/// Textures"): the size of the splat table and how the volume is seen, so that each splat gets
/// its table row and column.
struct VectorEmission {
    int rows = 16;          ///< animation phases of the table, >= 1
    int columns = 8;        ///< foreshortening levels of the table, >= 1
    std::uint32_t seed = 1; ///< the random rows are reproducible from it
    /// @brief The volume's local space to camera space (the model-view matrix): vectors are
    /// directions there.
    glm::mat4 localToCamera{1.0f};
    /// @brief Whether the camera is perspective (the eye direction differs per splat).
    bool isPerspective = false;
};

/// @brief The table column for a vector whose unit camera-space direction has the component
/// @p towardEye along the direction to the eye: round(|towardEye| · (columns − 1)), so column
/// 0 lies in the image plane and the last one points at (or away from) the eye. NaN gives 0.
int tableColumn(float towardEye, int columns);

/// @brief The vector part of one splat at @p position (local space) carrying @p vector:
/// the column from the vector's camera-space direction (for a perspective camera, relative to
/// the line of sight through the splat, so splats near the image border are right too); a row
/// drawn at random from the seed and @p key (any number that names the splat's voxel or node
/// stably across frames), to which the renderer adds the animation phase. A zero vector gets
/// column 0 (it draws no marks).
SplatVector vectorSplat(const VectorEmission& emission, glm::vec3 position, glm::vec3 vector,
                        std::uint64_t key);

/// @brief Replaces the contents of @p splats by the splats of @p cut for @p view, back to front
/// (`traverseBackToFront()`): one splat per node, at the centre of the node's voxels, with the
/// node's mean colour and extinction, sized by the node's largest block edge in voxels (2^level
/// inside the grid; less where the block is clipped by the grid's far faces). For a view with
/// sides (View::seeingOnly()) the nodes out of sight are left out. With @p vectors (the grid
/// must have vectors) each splat also carries the node's mean vector (vectorSplat()).
void emitSplats(const Cut& cut, const View& view, SplatList& splats,
                const VectorEmission* vectors = nullptr);

/// @brief Replaces the contents of @p splats by one size-1 splat per non-empty voxel of
/// @p grid, back to front in `SliceOrder`; for a perspective view, voxels not in front of the
/// eye plane are culled, and for a view with sides (View::seeingOnly()) the blocks whose voxels'
/// splats are all out of sight (SliceOrder skips them). With @p vectors, as emitSplats().
void emitVoxelSplats(const ClassifiedGrid& grid, const View& view, SplatList& splats,
                     const VectorEmission* vectors = nullptr);

} // namespace texsplat::octree
