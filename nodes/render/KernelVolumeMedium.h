#pragma once

#include "nodes/kernel/KernelTable.h"
#include "nodes/render/VolumeLighting.h"
#include "nodes/render/VoxelGradients.h"
#include "octree/ClassifiedGrid.h"
#include "scenegraph/actions/RayCastAction.h"

#include <glm/ext/matrix_double3x3.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_int3_sized.hpp>
#include <glm/mat4x4.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace texsplat::render {

/// @brief The medium a splat node stands for, for sg::RayCastAction: the continuous fields the
/// splats approximate, reconstructed from the classified grid with the paper's kernel h
/// (Crawfis & Max 1993, section 2):
/// c(x) = Σ Cᵢ h(S⁻¹(x − xᵢ)) and τ(x) = Σ τᵢ h(S⁻¹(x − xᵢ)),
/// x in the volume's local space, S the voxel spacing (the ellipsoidal kernel the splats use
/// for anisotropic grids), Cᵢ and τᵢ per unit local length. A sample sums the at most 4×4×4
/// voxels within the support, with h from a KernelTable in r².
///
/// Empty-space skipping: the grid is cut into bricks of kBrickSize³ voxels; a brick of sample
/// positions is active when a non-empty voxel lies in it or in one of its 26 neighbours (the
/// support t < 2 voxels ≤ kBrickSize reaches no farther), and intervals() walks the bricks along
/// the ray (3D DDA) and hands out only runs of active ones, so outside them c = τ = 0 exactly.
///
/// Units: a ray's t is root-space length; samples are scaled by the local length per root
/// length along the ray, so a Transform that scales the volume changes its size on screen, not
/// its optical depth (as for the splats). The step for `stepVoxels` is that many voxels of
/// index space along the ray.
///
/// Shading (TransferFunction::shade): each sample's emission is lit by VolumeLighting::shade()
/// with the gradient reconstructed like c and τ, g(x) = Σ gᵢ h(S⁻¹(x − xᵢ)) from the voxels'
/// gradients gᵢ (VoxelGradients): per-sample shading, where the splats light each voxel
/// (ShadedGrid).
class KernelVolumeMedium final : public sg::RayCastMedium {
public:
    /// @brief Edge of an empty-space brick, in voxels.
    static constexpr std::int64_t kBrickSize = 8;

    /// @brief How a shaded medium is lit: the lighting, and the gradients of the medium's grid.
    struct Shading {
        VolumeLighting lighting;
        std::shared_ptr<const VoxelGradients> gradients;
    };

    /// @brief The medium of `grid` placed by `model` (local to root), reconstructed with `kernel`
    /// (which must outlive the medium; support below 2 voxels), lit by `shading` when given
    /// (its gradients must be `grid`'s).
    /// @throws DataError when `model` is singular or not finite, or the kernel's support is 2
    /// voxels or more.
    KernelVolumeMedium(std::shared_ptr<const octree::ClassifiedGrid> grid, const glm::mat4& model,
                       const kernel::KernelTable& kernel = kernel::KernelTable::paper(),
                       std::optional<Shading> shading = std::nullopt);

    void intervals(const sg::RayCastRay& ray, float tMin, float tMax, float stepVoxels,
                   std::vector<Interval>& out) const override;

    Sample sample(const sg::RayCastRay& ray, float t) const override;

    /// @brief Number of active bricks of sample positions.
    std::size_t activeBrickCount() const;

    /// @brief Number of bricks of sample positions.
    std::size_t brickCount() const { return mActive.size(); }

private:
    bool isActive(std::int64_t bx, std::int64_t by, std::int64_t bz) const;

    std::shared_ptr<const octree::ClassifiedGrid> mGrid;
    const kernel::KernelTable* mKernel;
    std::optional<Shading> mShading;
    glm::dmat3 mRootToIndex{1.0};   // linear part: root space to voxel index space
    glm::dvec3 mRootToIndexOffset{0.0};
    glm::dmat3 mRootToLocal{1.0};   // linear part of the inverse model matrix
    glm::i64vec3 mDims{0};
    glm::i64vec3 mBricks{0};        // bricks of sample positions per axis (voxel bricks + 2)
    std::vector<std::uint8_t> mActive;
};

} // namespace texsplat::render
