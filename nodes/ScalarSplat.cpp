#include "nodes/ScalarSplat.h"

#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/detail/SplatMemory.h"
#include "nodes/elements/TransferFunctionElement.h"
#include "nodes/elements/VolumeElement.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/Frame.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/KernelVolumeMedium.h"
#include "nodes/render/SplatView.h"
#include "nodes/render/VolumeLighting.h"
#include "nodes/render/detail/ClassificationCache.h"
#include "nodes/render/detail/ShadingCache.h"
#include "octree/Cut.h"
#include "octree/DepthSort.h"
#include "octree/MarkSource.h"
#include "octree/Refiner.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "octree/VoxelSplats.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/ModelMatrixElement.h"
#include "scenegraph/actions/RayCastAction.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

using Clock = std::chrono::steady_clock;

// Runs `step` and adds its wall time to `phase` of `statistics`.
template <class Step>
auto timed(sg::RenderStatistics& statistics, sg::RenderPhase phase, Step&& step) {
    const Clock::time_point start = Clock::now();
    struct AddTime {
        sg::RenderStatistics& statistics;
        sg::RenderPhase phase;
        Clock::time_point start;
        ~AddTime() {
            statistics.addTime(phase, std::chrono::duration<double>(Clock::now() - start).count());
        }
    } addTime{statistics, phase, start};
    return step();
}

} // namespace

ScalarSplat::ScalarSplat()
    : mCache(std::make_unique<render::detail::ClassificationCache>()),
      mShading(std::make_unique<render::detail::ShadingCache>()) {
    addField(size, "size", 1.6f,
             "Extent of each splat: its square reaches this many voxels from the centre (paper: "
             "1.6), > 0");
    addField(errorThreshold, "errorThreshold", 0.0f,
             "Octree cut: largest deviation a splat may stand for, as a fraction of the largest "
             "classified value (0: full resolution, 1: one splat)");
    addField(maxSplats, "maxSplats", 0,
             "Octree cut: at most this many splats, refined where the error is largest (0: no "
             "budget)");
}

ScalarSplat::~ScalarSplat() = default;

void ScalarSplat::checkFields() const {
    if (!std::isfinite(size.value()) || !(size.value() > 0.0f)) {
        throw DataError("size must be finite and > 0, got " + size.valueText());
    }
    if (!std::isfinite(errorThreshold.value()) || errorThreshold.value() < 0.0f) {
        throw DataError("errorThreshold must be finite and >= 0, got " +
                        errorThreshold.valueText());
    }
    if (maxSplats.value() < 0) {
        throw DataError("maxSplats must be >= 0, got " + maxSplats.valueText());
    }
}

std::pair<const VolumeData&, const TransferFunction&>
ScalarSplat::renderInputs(sg::State& state) const {
    detail::withNodeContext(*this, [this] { checkFields(); });
    const VolumeData* volume = state.get<VolumeElement>().volume;
    const TransferFunction* transfer = state.get<TransferFunctionElement>().transferFunction;
    if (!volume) {
        throw DataError(detail::nodeContext(*this) + ": no VolumeData before this node");
    }
    if (!transfer) {
        throw DataError(detail::nodeContext(*this) + ": no TransferFunction before this node");
    }
    return {*volume, *transfer};
}

render::FrameSplats ScalarSplat::frameSplats(sg::Action& action, const render::CameraView& camera,
                                             int width, int height,
                                             sg::RenderStatistics& statistics,
                                             std::uint64_t previewVoxels) {
    sg::State& state = action.state();
    mDrewEveryVoxel = false;
    mDrewPreview = false;
    mCache->setWorkProgress(action.workProgress());
    const auto inputs = renderInputs(state);
    const VolumeData& volume = inputs.first;
    const TransferFunction& transfer = inputs.second;
    // Loading counts as such, not as classification.
    timed(statistics, sg::RenderPhase::Load, [&] {
        withMemoryStage("reading the volume of " + detail::nodeContext(volume), 0,
                        detail::kSplatMemoryAdvice, [&] { volume.load(action.workProgress()); });
    });
    const bool withMarks = footprint()->hasMarks();
    // Vector splats draw marks, which follow the image, not a cut (octree::MarkSource).
    const bool mayCut = isMedium() && (errorThreshold.value() > 0.0f || maxSplats.value() > 0);
    const bool isShaded = isShadedBy(transfer);
    // Each stage's allocation is estimated and refused before it is made: the classified grid
    // now (every stored voxel may be visible), the octree, the splats and the shading once the
    // classified grid has counted the voxels that are.
    const detail::SplatMemory classifiedMemory = detail::withNodeContext(*this, [&] {
        const detail::SplatMemory estimate = detail::estimateClassification(volume, withMarks);
        detail::checkClassificationMemory(estimate);
        return estimate;
    });
    const glm::mat4& model = state.get<sg::ModelMatrixElement>().matrix;
    const render::detail::ClassificationCache::Builds before = mCache->builds();
    // The classified grid, timed, its allocation named by `stage` if it fails.
    const auto classifying = [&](const char* stage, const auto& make) {
        return timed(statistics, sg::RenderPhase::Classify, [&] {
            return detail::withNodeContext(*this, [&] {
                return withMemoryStage(stage, classifiedMemory.classified,
                                       detail::kSplatMemoryAdvice, make);
            });
        });
    };
    // An interactive frame right after a transfer-function edit of a large grid draws the
    // blocks' means from their value histograms (a grid 8 times coarser, made without reading a
    // voxel) instead of classifying every block again; the next frame that is not interactive
    // is exact. The histograms (once per grid) and the means take a 64th and a 512th of what the
    // classified grid would: the frame's estimate bounds them.
    std::shared_ptr<const octree::ClassifiedGrid> classified;
    if (previewsEdits() && volume.scalarGrid()->storedVoxelCount() >= previewVoxels) {
        classified = classifying("previewing the edit", [&] {
            return mCache->preview(volume.scalarGrid(), transfer);
        });
    }
    const bool isPreview = classified != nullptr;
    if (!isPreview) {
        classified = classifying(
            "classifying", [&] { return classify(*mCache, state, volume, transfer, model); });
    }
    mDrewPreview = isPreview;
    // A budget that holds every non-empty voxel draws them all, in slice order: the
    // full-resolution image is within the budget, and its order costs about a quarter of an
    // octree cut's as fine (the viewer's last refinement steps of a big volume).
    const bool fullResolution = !mayCut || (errorThreshold.value() == 0.0f &&
                                            static_cast<std::uint64_t>(maxSplats.value()) >=
                                                classified->nonEmptyVoxelCount());
    const detail::SplatMemory memory = detail::withNodeContext(*this, [&] {
        const detail::SplatMemory estimate = detail::estimateSplats(
            classifiedMemory, classified->memoryBytes() + mCache->dataSummaryBytes(),
            classified->nonEmptyVoxelCount(), withMarks, mayCut,
            static_cast<std::uint64_t>(maxSplats.value()), !fullResolution || withMarks,
            isShaded ? detail::shadingBytesFor(*classified) : 0);
        detail::checkSplatMemory(estimate);
        return estimate;
    });
    // A shaded medium draws the classified grid lit per voxel (pre-shaded colour), cached while
    // the grid, its placement and the lighting shade alike; its cuts are the lit grid's.
    const std::shared_ptr<const octree::ClassifiedGrid> unshaded = classified;
    if (isShaded) {
        const render::VolumeLighting lighting = render::VolumeLighting::current(state, camera,
                                                                                transfer);
        classified = timed(statistics, sg::RenderPhase::Classify, [&] {
            return detail::withNodeContext(*this, [&] {
                return withMemoryStage("shading", memory.shading, detail::kSplatMemoryAdvice,
                                       [&] { return mShading->shaded(unshaded, model, lighting); });
            });
        });
    } else {
        mShading->clear();
    }
    const auto tree = [&]() -> const octree::Octree& {
        if (isShaded) {
            return mShading->octree(action.workProgress());
        }
        return isPreview ? mCache->previewOctree() : mCache->octree();
    };
    mDrewEveryVoxel = fullResolution && !isPreview;
    render::FrameSplats result;
    result.view = render::SplatView::fromMatrices(model, camera.view, camera.projection,
                                                  glm::vec3(classified->spacing()));
    result.localToCamera = camera.view * model;
    result.marks = markDrawing();
    const std::vector<octree::SplatMark>* const marks =
        timed(statistics, sg::RenderPhase::Order,
              [&] { return frameMarks(classified, result, width, height); });
    result.footprint = timed(statistics, sg::RenderPhase::Classify, [this] { return footprint(); });
    // The list of the last frame, refilled when the frame that drew it is gone: the same pages,
    // no allocation or zeroing per frame (about a twentieth of a Marschner-Lobb 128^3 CPU frame).
    if (!mSplatList || mSplatList.use_count() > 1) {
        mSplatList = std::make_shared<octree::SplatList>();
    }
    const std::shared_ptr<octree::SplatList> splats = mSplatList;
    if (!fullResolution) {
        // The octree is part of the cached classification; build it outside the ordering time.
        timed(statistics, sg::RenderPhase::Classify, [&] {
            detail::withNodeContext(*this, [&] {
                withMemoryStage("building the octree", memory.octree, detail::kSplatMemoryAdvice,
                                [&] { tree(); });
            });
        });
    }
    const auto emit = [&] {
        // The view with its sides: splats go where they show (blocks out of sight make none,
        // and a cut is not refined there); the order is octreeView()'s.
        const octree::View order = result.view.refinementView(result.footprint->reach());
        if (marks && !isMedium()) {
            mDepthSorter = {};
            octree::emitMarkSplats(*marks, order, *splats);
            return;
        }
        if (fullResolution) {
            mDepthSorter = {}; // slice order needs no sort
            if (marks == nullptr) {
                // No list: the backend walks the voxels in slice order (or lists them into
                // the node's list where it needs one).
                result.voxels =
                    std::make_shared<const octree::VoxelSplats>(classified, order, splats);
                return;
            }
            octree::emitVoxelSplats(*classified, order, *splats, marks);
            return;
        }
        octree::Cut cut = errorThreshold.value() > 0.0f
                              ? octree::Cut::byRelativeError(tree(), errorThreshold.value())
                              : octree::Cut(tree());
        if (maxSplats.value() > 0) {
            cut = octree::Refiner::cutOfBudget(std::move(cut), order,
                                               static_cast<std::uint64_t>(maxSplats.value()));
        }
        octree::emitSplats(cut, order, *splats);
        // The traversal keeps subtrees contiguous: where the eye lies on a split plane the two
        // sides' splats overlap on screen at every depth, and drawing one side wholly before the
        // other leaves a bright seam down the plane. Centre depth interleaves them.
        mDepthSorter.sort(*splats, order);
        if (marks) {
            octree::attachMarksByDepth(*marks, order, *splats);
        }
    };
    timed(statistics, sg::RenderPhase::Order, [&] {
        detail::withNodeContext(*this, [&] {
            withMemoryStage("emitting splats", memory.splats, detail::kSplatMemoryAdvice, emit);
        });
    });
    const render::detail::ClassificationCache::Builds& after = mCache->builds();
    statistics.builds.valueRanges += after.valueRanges - before.valueRanges;
    statistics.builds.classifications += after.classifications - before.classifications;
    statistics.builds.octrees += after.octrees - before.octrees;
    statistics.builds.valueHistograms += after.valueHistograms - before.valueHistograms;
    statistics.builds.previews += after.previews - before.previews;
    if (!result.voxels) {
        result.splats = splats;
    }
    statistics.splats += result.splatCount();
    statistics.previewed += isPreview ? 1 : 0;
    sg::FrameMemory& bytes = statistics.memory;
    const volume::VectorGridPtr vectorGrid = withMarks ? volume.vectorGrid() : nullptr;
    bytes.grids += vectorGrid ? vectorGrid->memoryBytes() : volume.scalarGrid()->memoryBytes();
    bytes.classified += classified->memoryBytes() + mCache->dataSummaryBytes();
    if (isShaded) {
        bytes.classified += unshaded->memoryBytes() + mShading->gradientBytes();
    }
    bytes.octree += fullResolution ? 0 : tree().memoryBytes();
    // A batch of voxels holds no list unless its backend makes one (which counts it then).
    bytes.splats += (result.voxels ? 0 : splats->memoryBytes()) + mDepthSorter.memoryBytes();
    return result;
}

std::shared_ptr<const octree::ClassifiedGrid> ScalarSplat::classifiedGrid(sg::Action& action) {
    sg::State& state = action.state();
    const auto inputs = renderInputs(state);
    mCache->setWorkProgress(action.workProgress());
    inputs.first.load(action.workProgress());
    const glm::mat4& model = state.get<sg::ModelMatrixElement>().matrix;
    return detail::withNodeContext(
        *this, [&] { return classify(*mCache, state, inputs.first, inputs.second, model); });
}

const octree::Octree& ScalarSplat::octree(sg::Action& action) {
    classifiedGrid(action);
    // withNodeContext() answers by value: the octree stays the cache's.
    return *detail::withNodeContext(*this, [&] { return &mCache->octree(); });
}

double ScalarSplat::splatReach() { return footprint()->reach(); }

std::shared_ptr<const render::SplatFootprint> ScalarSplat::footprint() {
    if (!mFootprint) {
        mFootprint = std::make_shared<const render::SplatFootprint>(
            detail::withNodeContext(*this, [this] { return makeFootprint(); }));
    }
    return mFootprint;
}

void ScalarSplat::collectFrame(render::FrameAction& action) {
    const render::CameraView camera =
        render::CameraView::current(action.state(), *this, action.aspectRatio());
    const std::uint64_t previewVoxels = action.isInteractive()
                                            ? action.previewMinimumVoxels()
                                            : std::numeric_limits<std::uint64_t>::max();
    action.frame().splats.push_back(frameSplats(action, camera, action.frame().width,
                                                action.frame().height, action.statistics(),
                                                previewVoxels));
}

void ScalarSplat::rayCast(sg::RayCastAction& action) {
    const auto inputs = renderInputs(action.state());
    if (!isMedium()) {
        log(LogLevel::Warning, detail::nodeContext(*this) +
                                   ": draws marks, not a medium; the ray-cast reference leaves "
                                   "it out");
        return;
    }
    const VolumeData& volume = inputs.first;
    const TransferFunction& transfer = inputs.second;
    const render::CameraView camera =
        render::CameraView::current(action.state(), *this, action.aspectRatio());
    volume.load(action.workProgress());
    const volume::ScalarGridPtr grid = volume.scalarGrid();
    mCache->setWorkProgress(action.workProgress());
    const bool isShaded = isShadedBy(transfer);
    const std::shared_ptr<const octree::ClassifiedGrid> classified =
        detail::withNodeContext(*this, [&] {
            const detail::SplatMemory memory = detail::estimateClassification(volume, false);
            detail::checkClassificationMemory(memory, " for the ray-cast reference");
            return withMemoryStage("classifying", memory.classified, detail::kSplatMemoryAdvice,
                                   [&] { return mCache->classified(grid, transfer); });
        });
    const glm::mat4& model = action.state().get<sg::ModelMatrixElement>().matrix;
    // A shaded medium is lit per sample, by the gradient interpolated from the voxels' (the
    // splats light each voxel): the reference of what the splats approximate.
    std::optional<render::KernelVolumeMedium::Shading> shading;
    if (isShaded) {
        shading.emplace();
        shading->lighting = render::VolumeLighting::current(action.state(), camera, transfer);
        detail::withNodeContext(*this, [&] {
            const std::uint64_t bytes = detail::shadingBytesFor(*classified);
            checkMemory("shading the ray-cast reference's " +
                            std::to_string(classified->nonEmptyVoxelCount()) + " voxels",
                        bytes, detail::kSplatMemoryAdvice);
            withMemoryStage("shading", bytes, detail::kSplatMemoryAdvice,
                            [&] { mShading->shaded(classified, model, shading->lighting); });
        });
        shading->gradients = mShading->gradients();
    }
    auto medium = detail::withNodeContext(*this, [&] {
        return std::make_shared<render::KernelVolumeMedium>(
            classified, model, kernel::KernelTable::paper(), std::move(shading));
    });
    action.setCamera(camera.view, camera.projection);
    action.addMedium(std::move(medium));
}

std::shared_ptr<const octree::ClassifiedGrid>
ScalarSplat::classify(render::detail::ClassificationCache& cache, sg::State& /*state*/,
                      const VolumeData& volume, const TransferFunction& transfer,
                      const glm::mat4& /*model*/) const {
    return cache.classified(volume.scalarGrid(), transfer);
}

bool ScalarSplat::isShadedBy(const TransferFunction& transfer) const {
    return isMedium() && transfer.shade.value();
}

bool ScalarSplat::isDrawingField(const sg::Field* field) const {
    return field == &errorThreshold || field == &maxSplats;
}

void ScalarSplat::getBoundingBox(sg::BoundingBoxAction& action) {
    if (const VolumeData* volume = action.state().get<VolumeElement>().volume) {
        action.extendBy(volume->bounds());
    }
}

void ScalarSplat::notify(const sg::Field* source) {
    if (!isDrawingField(source)) {
        mFootprint.reset();
    }
    if (isClassificationField(source)) {
        mCache->invalidate();
    }
    sg::Node::notify(source);
}

} // namespace texsplat::nodes
