#pragma once

#include "nodes/Fwd.h"
#include "nodes/render/MarkDrawing.h"
#include "octree/DepthSort.h"
#include "octree/Splat.h"
#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"

#include <glm/mat4x4.hpp>

#include <memory>
#include <utility>
#include <vector>

namespace texsplat::sg {
class RayCastAction;
struct RenderStatistics;
} // namespace texsplat::sg

namespace texsplat::render {
class FrameAction;
struct CameraView;
struct FrameSplats;
struct SplatFootprint;
namespace detail {
class ClassificationCache;
class ShadingCache;
} // namespace detail
} // namespace texsplat::render

namespace texsplat::nodes {

/// @brief Base of the splat nodes (TextureSplat, GaussianSplat, and through VectorMarkSplat the
/// vector and combined splats): renders the current
/// VolumeData, classified by the current TransferFunction, as one splat per non-empty voxel or
/// per node of an octree cut, back to front for the camera, in a backend's splat pass.
///
/// Per frame: the scalar grid of the VolumeData (loaded on first use), classified into emission
/// C and extinction τ per unit length (cached with its octree until the volume's grid or the
/// transfer function changes; voxels that classify to zero make no splat; the grid's block value
/// ranges and histograms, octree::ValueRanges and octree::ValueHistograms, are made once per grid
/// and let a transfer-function edit skip the blocks it hides without a new data hierarchy, and
/// an interactive frame preview the edit from the blocks' means), ordered for the view
/// (see below), and drawn facing the eye from FrameAction's frame: by the GL backend as instanced
/// quads (render::GlRenderer), or by the CPU backend (render::cpu::CpuRenderer).
/// Optical properties are per unit length of the volume's local space; a Transform above the
/// node places the volume. Anisotropic spacing uses the ellipsoidal kernel h(S⁻¹x). A medium
/// whose TransferFunction shades (`shade`) draws the classified grid lit per voxel
/// (render::ShadedGrid, cached while the grid, its placement and the lighting shade alike; its
/// cuts come from the lit grid's octree); RayCastAction lights it per sample.
///
/// Order and resolution:
/// - `errorThreshold` 0 and `maxSplats` 0: every non-empty voxel, in octree::SliceOrder (back to
///   front per voxel cell, no sort), culled behind the eye for a perspective camera.
/// - `maxSplats` > 0: the octree cut the Laur–Hanrahan refiner reaches within that many splats,
///   starting from the `errorThreshold` cut (the root when 0); `errorThreshold` > 0 alone: the
///   threshold cut. Cuts are drawn in centre-depth order (octree::sortByDepth(), Westover's
///   order that Crawfis & Max used): the traversal's subtree order would draw the two sides of a
///   split plane that the eye lies on one after the other, and their overlapping kernels would
///   leave a seam down the plane.
/// - `errorThreshold` is relative: a fraction of the largest colour or extinction of any
///   classified voxel (octree::Octree::valueScale()). A node is splatted when no voxel it stands
///   for deviates from its mean by more than that fraction, in any channel; so the same
///   threshold gives the same cut whatever the transfer function's opacity scale. 0: full
///   resolution; 1 or more: one splat.
///
/// File format (fields common to the splat nodes):
/// @code
/// size            1.6   # the splat's extent: its quad reaches this many voxels from the centre
/// errorThreshold  0     # octree cut by error relative to the largest value (0: full resolution)
/// maxSplats       0     # octree cut by splat budget (0: no budget)
/// @endcode
class ScalarSplat : public sg::Declare<ScalarSplat, sg::Node> {
public:
    /// @brief The abstract type's name.
    static constexpr const char* kTypeName = "ScalarSplat";

    sg::SFFloat size;           ///< extent of the splat in voxels (paper: 1.6), > 0
    sg::SFFloat errorThreshold; ///< octree cut: largest error a splat may carry, as a fraction
                                ///< of the largest classified value, >= 0
    sg::SFInt32 maxSplats;      ///< octree cut: splat budget, >= 0 (0: none)

    ~ScalarSplat() override;

    /// @brief FrameAction: adds this frame's splats to the action's frame, for any backend
    /// (registered by registerNodeTypes()).
    /// @throws DataError naming the node when there is no camera, VolumeData or
    /// TransferFunction before it, or a field is out of range; what loading the volume throws.
    void collectFrame(render::FrameAction& action);

    /// @brief RayCastAction: queues the continuous medium these splats approximate (the same
    /// classified grid, reconstructed with the paper's kernel: render::KernelVolumeMedium) and
    /// the camera (registered by registerNodeTypes()).
    /// @throws as collectFrame().
    void rayCast(sg::RayCastAction& action);

    /// @brief Extends the box by the current VolumeData's bounds under this node's model matrix
    /// (a splat node under its own Transform draws the volume there); nothing without a volume.
    void getBoundingBox(sg::BoundingBoxAction& action) override;

    /// @brief Drops the footprint when a field that shapes it changes and the classification
    /// when one that classification reads changes, then notifies as every node does.
    void notify(const sg::Field* source) override;

    /// @brief The classified grid this node draws in the traversal state of `action` (a
    /// VolumeData and a TransferFunction before it), classified now unless the node holds it:
    /// what a render split over processes surveys in every brick before drawing it
    /// (nodes/distributed).
    /// @throws as collectFrame().
    std::shared_ptr<const octree::ClassifiedGrid> classifiedGrid(sg::Action& action);

    /// @brief The octree over classifiedGrid(`action`), built now unless the node holds it.
    /// @throws as collectFrame().
    const octree::Octree& octree(sg::Action& action);

    /// @brief How far this node's splats draw from their centre, in voxels at size 1, for the
    /// current fields (SplatFootprint::reach()): what its cuts are refined and drawn for.
    double splatReach();

    /// @brief Whether the last frame drew every non-empty voxel (the full-resolution list, as
    /// `maxSplats` 0 and `errorThreshold` 0 do; also a budget that holds them all), so that a
    /// larger budget or none would draw the same splats. False before the first frame and after
    /// a preview of a transfer-function edit (FrameAction::setInteractive()).
    bool drewEveryVoxel() const { return mDrewEveryVoxel; }

    /// @brief Whether the last frame drew a preview of a transfer-function edit (an interactive
    /// frame, render::FrameAction::setInteractive()): the grid's block means, not its cut, so its
    /// splat count says nothing of how far a budget would refine.
    bool drewPreview() const { return mDrewPreview; }

protected:
    ScalarSplat();

    /// @brief What this node's splats look like for the current field values (called again
    /// after a field that shapes them changed): the backends' description of a splat.
    virtual render::SplatFootprint makeFootprint() const = 0;

    /// @brief The grid this node splats, classified through `cache` (which keeps it while its
    /// inputs stay the same): by default the VolumeData's scalar grid through the transfer
    /// function. `model` is the volume's model matrix.
    virtual std::shared_ptr<const octree::ClassifiedGrid>
    classify(render::detail::ClassificationCache& cache, sg::State& state,
             const VolumeData& volume, const TransferFunction& transfer,
             const glm::mat4& model) const;

    /// @brief For splats that draw marks (the footprint's hasMarks()): the marks of `classified`
    /// this frame draws for `batch` (its view set) in an image of `width` x `height` pixels,
    /// valid until the next call, with their expected number per voxel and the box they are cut
    /// to set in `batch.marks`; nothing (the default) for scalar splats.
    virtual const std::vector<octree::SplatMark>*
    frameMarks(const std::shared_ptr<const octree::ClassifiedGrid>& /*classified*/,
               render::FrameSplats& /*batch*/, int /*width*/, int /*height*/) {
        return nullptr;
    }

    /// @brief Whether an interactive frame may preview a transfer-function edit from the grid's
    /// block value histograms (ClassificationCache::preview()): where classify() is this base's,
    /// the scalar grid through the transfer function. Vector and combined splats classify their
    /// own way and have no preview.
    virtual bool previewsEdits() const { return true; }

    /// @brief Whether the splats stand for an emission-absorption medium that RayCastAction can
    /// integrate (scalar and combined splats); vector splats are marks, not a medium.
    virtual bool isMedium() const { return true; }

    /// @brief What the batch draws with this frame; only vector and combined batches read it.
    virtual render::MarkDrawing markDrawing() const { return {}; }

    /// @brief Whether a change of `field` leaves the footprint as it is (it changes which splats
    /// are drawn, or a per-frame drawing parameter). Here: the cut fields.
    virtual bool isDrawingField(const sg::Field* field) const;

    /// @brief Whether a change of `field` changes the classification (none here: the volume and
    /// transfer function are watched by the cache).
    virtual bool isClassificationField(const sg::Field* /*field*/) const { return false; }

    /// @brief Checks this node's own fields; throws DataError (without the node's name, which
    /// the caller adds) for the first one out of range. Overrides call the base first.
    virtual void checkFields() const;

private:
    /// @brief Checks the fields, then finds the VolumeData and TransferFunction of `state`;
    /// throws DataError naming this node when a field is out of range or one of them is missing.
    std::pair<const VolumeData&, const TransferFunction&> renderInputs(sg::State& state) const;

    /// @brief This frame's splats for `camera` in an image of `width` x `height` pixels:
    /// classified (cached), ordered and emitted as the fields say, the times added to
    /// `statistics`; classification and the octree build report
    /// to `action`'s work progress, which may cancel them. What every backend draws. Right
    /// after a transfer-function edit of a grid storing at least `previewVoxels` voxels, scalar
    /// splats draw the edit's preview (ClassificationCache::preview()) instead: the interactive
    /// frames' (render::FrameAction::previewMinimumVoxels(); the largest uint64 for others).
    render::FrameSplats frameSplats(sg::Action& action, const render::CameraView& camera, int width,
                                    int height, sg::RenderStatistics& statistics,
                                    std::uint64_t previewVoxels);

    /// @brief The footprint for the current fields, made once until a shaping field changes.
    std::shared_ptr<const render::SplatFootprint> footprint();

    /// @brief Whether this node draws a shaded medium through `transfer`: a medium (isMedium())
    /// whose transfer function shades (TransferFunction::shade). Vector marks are not shaded.
    bool isShadedBy(const TransferFunction& transfer) const;

    std::unique_ptr<render::detail::ClassificationCache> mCache;
    std::unique_ptr<render::detail::ShadingCache> mShading;
    std::shared_ptr<const render::SplatFootprint> mFootprint;
    std::shared_ptr<octree::SplatList> mSplatList; // the last frame's, refilled when free
    octree::DepthSorter mDepthSorter; // its buffers, kept while octree cuts are drawn
    bool mDrewEveryVoxel = false;
    bool mDrewPreview = false;
};

} // namespace texsplat::nodes
