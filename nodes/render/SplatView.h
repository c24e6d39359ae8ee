#pragma once

#include "octree/View.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace texsplat::render {

/// @brief How one batch of splats is seen: the matrices and, in the volume's local space (the
/// space of the splat centres), the eye or viewing direction the splats turn to face and the
/// voxel spacing that shapes their footprint.
///
/// Optical properties are per unit length of that local space, so a Transform that scales a
/// volume changes its size on screen, not its optical depth.
struct SplatView {
    /// @brief Local (volume) space to clip space: projection · view · model.
    glm::mat4 localToClip{1.0f};
    /// @brief Whether the projection is perspective (splats face the eye) or orthographic
    /// (splats face along `direction`).
    bool isPerspective = false;
    /// @brief Eye position, local space (perspective).
    glm::vec3 eye{0.0f};
    /// @brief Unit viewing direction, local space.
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    /// @brief Voxel spacing along x, y, z, local units (the splat list's size 1).
    glm::vec3 spacing{1.0f};

    /// @brief The view of a volume with voxel `spacing` placed by `model`, seen through a camera
    /// with world-to-camera `view` and camera-to-clip `projection` matrices (OpenGL
    /// conventions; `projection[3][3] == 0` means perspective).
    /// @throws DataError when a matrix is singular or not finite, or a spacing is not finite
    /// and positive.
    static SplatView fromMatrices(const glm::mat4& model, const glm::mat4& view,
                                  const glm::mat4& projection, const glm::vec3& spacing);

    /// @brief The same view as the octree orders splats for it (local space).
    octree::View octreeView() const;

    /// @brief octreeView() seeing only the four sides of the view volume (local space), for
    /// splats that draw up to `reach` voxels from their centre at size 1
    /// (SplatFootprint::reach()): what a cut is refined and drawn for, so that its splits go
    /// where they show and what shows nothing is left out (octree::Refiner, octree::emitSplats).
    /// @throws DataError when `reach` is negative or not finite.
    octree::View refinementView(double reach) const;
};

} // namespace texsplat::render
