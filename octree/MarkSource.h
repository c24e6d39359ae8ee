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
/// marks at random among the grid's non-empty voxels, each at a random point of its voxel's cell
/// with the voxel's vector, extinction and colour.
///
/// Marks are drawn per cell of kCellSize³ voxels of the whole grid (the grid itself, or the grid
/// a brick of a render split over processes is part of: `offset`): candidate j of a cell sits in
/// a random voxel of the cell and is a mark when that voxel is the grid's and not empty, and the
/// cell has candidates 0 … ⌊λ⌋, the last one only with probability frac(λ), λ = marks per voxel
/// × kCellSize³. Everything about a candidate depends on the seed, the cell and j alone. So:
/// - each non-empty voxel has `marksPerVoxel` marks on average, wherever it lies;
/// - a frame that needs more marks per voxel (a closer view) keeps the marks drawn before and
///   adds to them, and frame after frame the same marks are drawn;
/// - the bricks of a grid split over processes draw, together, exactly the whole grid's marks
///   (each those of its own voxels), so the split picture is the one-process picture.
/// The count follows the image, not the grid: the caller asks for the marks per voxel that cover
/// a chosen part of the image (render::ScreenMarks), a few per pixel at most; a frame costs the
/// grid's non-empty cells and the candidates, not its voxels.
class MarkSource {
public:
    /// @brief The side of the cells of the whole grid that marks are drawn per, in voxels (the
    /// ClassifiedGrid's blocks, when the grid is the whole).
    static constexpr std::uint64_t kCellSize = 8;

    /// @brief The marks of `grid`'s non-empty voxels (the grid must have vectors); `offset`: the
    /// index in the whole grid of `grid`'s voxel (0, 0, 0) when it is a brick of it.
    explicit MarkSource(std::shared_ptr<const ClassifiedGrid> grid,
                        glm::u64vec3 offset = glm::u64vec3(0));

    /// @brief The grid the marks are drawn from.
    [[nodiscard]] const ClassifiedGrid& grid() const { return *mGrid; }

    /// @brief Non-empty voxels of the grid.
    [[nodiscard]] std::uint64_t voxels() const { return mVoxels; }

    /// @brief Makes `marks` the marks of `seed` at `marksPerVoxel` marks per non-empty voxel on
    /// average (about marksPerVoxel · voxels() of them), in the order of the whole grid's cells
    /// (z slowest), then of their candidates: the same for any number of threads.
    void drawMarks(std::uint32_t seed, double marksPerVoxel, std::vector<SplatMark>& marks) const;

private:
    std::shared_ptr<const ClassifiedGrid> mGrid;
    glm::u64vec3 mOffset;
    // The whole grid's cells that hold a non-empty voxel of the grid, ordered z, y, x.
    std::vector<glm::u64vec3> mCells;
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
