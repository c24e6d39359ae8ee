#pragma once

#include "nodes/distributed/Compositor.h"
#include "nodes/distributed/SceneRenderer.h"
#include "nodes/image/Image.h"
#include "nodes/render/SceneRenderer.h"
#include "nodes/volume/Grid.h"
#include "nodes/volume/GridGeometry.h"
#include "scenegraph/Node.h"

#include <mpi.h>

#include <optional>

namespace texsplat::distributed {

/// @brief One rank's block of a grid that a simulation splits over its ranks, as it holds it.
struct LocalBlock {
    /// @brief The voxels this rank holds: a volume::ExternalGrid over the simulation's own array
    /// (no copy) or any grid. Its geometry places them: the same spacing as the whole grid, its
    /// origin the world position of its first voxel (ghost cells included). None (a null
    /// pointer): the rank owns no voxel.
    volume::AnyGrid voxels;
    /// @brief Ghost cells: how many layers of voxels at the block's low faces along x, y and z
    /// belong to other ranks (copies the simulation keeps of its neighbours'): not drawn here.
    glm::i64vec3 ghostLow{0};
    /// @brief The same at the block's high faces.
    glm::i64vec3 ghostHigh{0};
};

/// @brief What an in-situ render draws, and how the ranks' images are composited.
struct InSituOptions {
    render::SceneRenderOptions image;              ///< size, background, backend, threads
    Compositing compositing = Compositing::RadixK; ///< docs/distributed.md, "Compositing"
};

/// @brief Renders a simulation's data where it lives, from C++ (docs/distributed.md, "In situ"):
/// on every rank the simulation gives its own block of the grid, with or without ghost cells, in
/// its own decomposition; the ranks draw their blocks and composite the images in the blocks'
/// visibility order, and rank 0 gets the picture: the one-process picture of the whole grid.
///
/// Made once, kept across time steps: the backend, its caches and the blocks' visibility tree
/// serve every render(). Every call is a collective over the communicator.
class InSituRenderer {
public:
    /// @brief A renderer over `comm` (which must stay valid while it lives).
    /// @throws as render::SceneRenderer, on every rank.
    explicit InSituRenderer(MPI_Comm comm, const InSituOptions& options = {});

    /// @brief Renders `scene` seen through `camera` (a camera node, framing the whole grid:
    /// render::framedScene() on rank 0 gives one), with this rank's `block` of the grid
    /// `whole` as the data of the scene's VolumeData of source MEMORY (its one such node; the
    /// whole grid's data ranges, `range` DATA or PERCENTILE, are the whole grid's). The blocks
    /// less their ghost cells must not overlap; a rank may own no voxel.
    /// @return on rank 0 the image (premultiplied RGBA over the options' background); nothing on
    /// the other ranks.
    /// @throws on every rank (agreeOnFailure()), DataError for a block that does not lie on
    /// the whole grid's voxels or reaches outside it, blocks that overlap (ghost cells not
    /// declared) or have no visibility order, a scene without exactly one VolumeData of source
    /// MEMORY; what rendering throws.
    std::optional<image::Image> render(const LocalBlock& block, const volume::GridGeometry& whole,
                                       const sg::Node::Ptr& scene, const sg::Node::Ptr& camera);

    /// @brief This rank's times and counts of the last render().
    const RankStatistics& statistics() const { return mRenderer.statistics(); }

    /// @brief The renderer that draws and composites (its time report, bricks, backend).
    const SceneRenderer& renderer() const { return mRenderer; }

private:
    MPI_Comm mComm;
    SceneRenderer mRenderer;
    sg::Node::Ptr mRoot;
    sg::Node::Ptr mScene;
    sg::Node::Ptr mCamera;
};

/// @brief One in-situ frame (InSituRenderer::render()) with a renderer made for it: for a
/// single picture; keep an InSituRenderer to render every few time steps.
std::optional<image::Image> render(MPI_Comm comm, const LocalBlock& block,
                                   const volume::GridGeometry& whole, const sg::Node::Ptr& scene,
                                   const sg::Node::Ptr& camera, const InSituOptions& options = {});

} // namespace texsplat::distributed
