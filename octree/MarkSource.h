#pragma once

#include "octree/Fwd.h"
#include "octree/Splat.h"

#include <glm/ext/vector_uint3_sized.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::octree {

/// @brief Where the vector marks of a classified grid come from (Crawfis & Max 1993, "Combined
/// Vector and Scalar Textures": "tiny vector particles, or scratch marks"; docs/vector-splats.md):
/// marks drawn one by one at random among the grid's non-empty voxels, each at a random point of
/// its voxel's cell with the voxel's vector, extinction and colour.
///
/// Mark i of a seed's sequence depends on the seed and i alone, so a frame that needs more marks
/// (a closer view) keeps the ones drawn before and adds to them, and frame after frame the same
/// marks are drawn. Their count follows the image, not the grid: the marks a frame draws cover a
/// chosen part of the image (render::ScreenMarks), a few per pixel at most, so drawing them
/// costs what the picture needs however large the volume. Voxels are picked uniformly: a block
/// of the grid's storage at random, a voxel of it at random, again while it is empty (at most
/// kMaxTries times; a mark that finds none has a zero vector and draws nothing).
class MarkSource {
public:
    /// @brief How often one mark tries a random stored voxel before it gives up: enough for
    /// blocks holding a single non-empty voxel each (512 tries on average).
    static constexpr int kMaxTries = 8192;

    /// @brief The marks of `grid`'s non-empty voxels (the grid must have vectors).
    explicit MarkSource(std::shared_ptr<const ClassifiedGrid> grid);

    /// @brief The grid the marks are drawn from.
    [[nodiscard]] const ClassifiedGrid& grid() const { return *mGrid; }

    /// @brief Non-empty voxels of the grid.
    [[nodiscard]] std::uint64_t voxels() const { return mVoxels; }

    /// @brief Makes `marks` the first `count` marks of `seed`'s sequence, given that it holds
    /// the first marks.size() of them already (none, or what an earlier call left): a frame that
    /// needs more marks draws only the new ones, in parallel (the same for any number of
    /// threads), and one that needs fewer drops the last.
    void drawMarks(std::uint32_t seed, std::size_t count, std::vector<SplatMark>& marks) const;

private:
    std::shared_ptr<const ClassifiedGrid> mGrid;
    // The allocated blocks: coordinates and the storage index of their voxel (0, 0, 0).
    std::vector<glm::u64vec3> mBlocks;
    std::vector<std::uint64_t> mFirsts;
    std::uint64_t mVoxels = 0;
};

/// @brief Replaces the contents of `splats` by one splat for each of `marks` (at the mark's
/// position, size 1, the mark's colour and extinction) carrying that mark, back to front for
/// `view` (by centre depth, as sortByDepth()): the list of a batch that draws marks only
/// (VectorSplat), which merges by depth with other batches as any list does. Marks behind the
/// eye of a perspective view are left out.
void emitMarkSplats(const std::vector<SplatMark>& marks, const View& view, SplatList& splats);

/// @brief Gives the splats of `splats` (a scalar list, back to front for `view` by centre depth:
/// an octree cut after sortByDepth()) the marks of `marks`: each mark follows the last splat no
/// nearer than itself, so that it is drawn over what lies behind it and under what lies in front
/// (CombinedSplat). Marks nearer than every splat follow the last one.
void attachMarksByDepth(const std::vector<SplatMark>& marks, const View& view, SplatList& splats);

} // namespace texsplat::octree
