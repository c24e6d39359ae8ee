#pragma once

#include "nodes/render/VolumeLighting.h"
#include "nodes/render/VoxelGradients.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Octree.h"
#include "scenegraph/WorkProgress.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <memory>

namespace texsplat::render::detail {

/// A splat node's shaded volume (TransferFunction::shade), kept across frames: the gradients of
/// a classified grid (made again only for a new grid or model matrix), the grid lit by a
/// VolumeLighting (made again when the lighting shades differently: new coefficients or lights,
/// or a turned view where the shading depends on it, VolumeLighting::shadesAlike()), and the
/// octree over the lit grid (for cuts, built on first use after each lighting).
class ShadingCache {
public:
    /// How many times each structure was made since the cache was.
    struct Builds {
        std::uint64_t gradients = 0;
        std::uint64_t shadings = 0;
        std::uint64_t octrees = 0;
    };

    /// `classified` placed by `model` and lit by `lighting`, from the cache when still valid.
    std::shared_ptr<const octree::ClassifiedGrid>
    shaded(const std::shared_ptr<const octree::ClassifiedGrid>& classified, const glm::mat4& model,
           const VolumeLighting& lighting);

    /// The gradients of the last shaded() grid (what the ray caster interpolates per sample).
    const std::shared_ptr<const VoxelGradients>& gradients() const { return mGradients; }

    /// The octree over the last shaded() grid, built on first use (telling `progress`).
    const octree::Octree& octree(const sg::WorkProgress& progress);

    /// Bytes held besides the lit grid: the gradients.
    std::uint64_t gradientBytes() const { return mGradients ? mGradients->memoryBytes() : 0; }

    /// What was made so far.
    const Builds& builds() const { return mBuilds; }

    /// Forgets everything.
    void clear();

private:
    std::shared_ptr<const octree::ClassifiedGrid> mClassified;
    glm::mat4 mModel{1.0f};
    std::shared_ptr<const VoxelGradients> mGradients;
    VolumeLighting mLighting;
    std::shared_ptr<const octree::ClassifiedGrid> mShaded;
    std::unique_ptr<octree::Octree> mOctree;
    Builds mBuilds;
};

} // namespace texsplat::render::detail
