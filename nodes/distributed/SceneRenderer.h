#pragma once

#include "nodes/distributed/Compositor.h"
#include "nodes/image/Image.h"
#include "nodes/image/ImageRegion.h"
#include "nodes/render/BackendChoice.h"
#include "nodes/render/Frame.h"
#include "nodes/render/SceneRenderer.h"
#include "nodes/volume/IndexBox.h"
#include "scenegraph/Node.h"
#include "scenegraph/WorkProgress.h"

#include <mpi.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::distributed {

class BrickTree;
struct SplatSurvey;

/// @brief The steps of a distributed render, as `texsplat render --time-report` lists them.
enum class Step {
    Split,     ///< finding the splat nodes and the bricks for the view
    Load,      ///< reading or generating this rank's bricks
    Gather,    ///< the whole grids' figures over all ranks (data ranges)
    Classify,  ///< transfer function over the brick, octree build
    Order,     ///< the brick's splats back to front
    Draw,      ///< drawing the brick's screen footprint (upload and read back included)
    Composite, ///< compositing the ranks' images, waiting included
    Finish,    ///< rank 0: the meshes and the background under the composite
};

/// @brief Number of Step values.
inline constexpr std::size_t kStepCount = 8;

/// @brief Lower-case name of a step ("composite").
std::string_view toString(Step step);

/// @brief What the last render took and drew on one rank.
struct RankStatistics {
    std::array<double, kStepCount> seconds{}; ///< wall seconds per Step
    std::uint64_t voxels = 0;                 ///< voxels of this rank's bricks
    std::size_t splats = 0;                   ///< splats this rank drew
    image::ImageRegion footprint;             ///< the pixels this rank drew (its brick's)
    double peakMebibytes = 0.0;               ///< this process's peak resident memory
};

/// @brief Renders scenes split over the processes of an MPI communicator, sort-last
/// (docs/distributed.md): every rank holds the same scene; the volumes are split into as many
/// bricks as there are ranks by a k-d split (BrickTree) chosen for the view; each rank reads or
/// generates only its bricks' voxels (VolumeData::setBrick()), gathers with the others the
/// figures of the whole grids that classification needs (data ranges), draws its splats on its
/// bricks' screen footprint (render::SceneRenderer, on the CPU or GL backend), and the images are
/// composited with "over" in the bricks' visibility order (Compositor). Rank 0 gets the picture,
/// which is the one-process picture up to float rounding and the order of splats that overlap
/// across two bricks (docs/distributed.md says when that shows).
///
/// Every step ends with the ranks agreeing on its failure (agreeOnFailure()): a bad file or a
/// memory refusal on one rank throws on every rank, with that rank's message.
class SceneRenderer {
public:
    /// @brief A renderer over `comm` (which must stay valid while it lives) for images as
    /// `options` say: their background is what the composite is laid over, on rank 0; threads 0
    /// gives the CPU backend one thread per CPU the rank may run on (the cores mpirun bound it
    /// to), not one per CPU of the machine.
    /// @throws as render::SceneRenderer, on every rank.
    SceneRenderer(MPI_Comm comm, const render::SceneRenderOptions& options,
                  Compositing compositing = Compositing::RadixK);
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    /// @brief Makes every VolumeData of `scene` serve bricks (VolumeData::setBrick()), placed by
    /// the next render() and empty until then, so that framing the scene (its bounding box)
    /// reads the volumes' headers, not their voxels. Call it before giving the scene a camera.
    static void prepareBricks(sg::Node& scene);

    /// @brief Takes the ranks' bricks as given (`bricks[r]`: rank r's box of the first volume's
    /// voxels; a simulation's blocks, InSituRenderer) instead of splitting the volume, until
    /// called with none. Every rank calls it with the same boxes.
    /// @throws DataError when the boxes overlap or no visibility order exists for them
    /// (BrickTree::of()), or there is not one per rank.
    void setBricks(const std::vector<volume::IndexBox>& bricks);

    /// @brief Where loading, classification and the octree build report (rank 0's only).
    void setWorkProgress(sg::WorkProgress progress);

    /// @brief Renders `root`, which must hold a camera, split over the ranks: every rank calls
    /// it with its own copy of the same scene (a collective). Rank 0 gets the image
    /// (premultiplied float RGBA over the options' background, with the meshes' depth when
    /// `withDepth`); the other ranks get nothing.
    /// @throws on every rank, what any rank's step threw (agreeOnFailure()); DataError for a
    /// scene whose volumes cannot be split alike (one turned against another, or one volume
    /// drawn at two places).
    std::optional<image::Image> render(sg::Node& root, bool withDepth = false);

    /// @brief This rank's times and counts of the last render().
    const RankStatistics& statistics() const { return mStatistics; }

    /// @brief The ranks' bricks of the last render(), by rank, in the first volume's voxels.
    std::vector<volume::IndexBox> bricks() const;

    /// @brief This rank.
    int rank() const { return mRank; }
    /// @brief The number of ranks.
    int size() const { return mSize; }
    /// @brief How the images are composited.
    Compositing compositing() const { return mCompositing; }
    /// @brief What draws each brick: the backend's description.
    std::string description() const { return mLocal.description(); }
    /// @brief The backend the options' request resolved to, and why.
    const render::BackendChoice& backend() const { return mLocal.backend(); }

private:
    struct Split;
    struct SurveyedFields;

    // Places this rank's bricks in every volume of `root` for its camera.
    void placeBricks(sg::Node& root);
    // Loads every volume's brick and gathers the whole grids' figures.
    void gatherWholeGrids(sg::Node& root);
    // Merges the surveys' figures over the ranks and gives each node the whole's: marks' shadows,
    // cut thresholds and budgets (the fields set back when the result goes).
    void applySurveys(const std::vector<SplatSurvey>& surveys, SurveyedFields& restore);
    // This rank's share of a splat node's budget (a collective).
    int budgetShare(const SplatSurvey& survey, std::uint64_t budget) const;
    // This rank's image: its splats on its bricks' screen footprint.
    ImageLayer drawBrick(sg::Node& root);
    // Rank 0: the composite over the meshes and the background.
    image::Image finish(image::Pixels composite, bool withDepth);

    MPI_Comm mComm;
    int mRank = 0;
    int mSize = 1;
    render::SceneRenderOptions mOptions;
    Compositing mCompositing;
    render::SceneRenderer mLocal;
    std::unique_ptr<Split> mSplit;
    render::Frame mMeshes; // the last frame's meshes, uncropped (rank 0 draws them)
    image::ImageRegion mFootprint;
    sg::WorkProgress mProgress;
    RankStatistics mStatistics;
};

} // namespace texsplat::distributed
