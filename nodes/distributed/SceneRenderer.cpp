#include "nodes/distributed/SceneRenderer.h"

#include "nodes/ScalarSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VectorMarkSplat.h"
#include "nodes/VolumeData.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/distributed/BrickSurvey.h"
#include "nodes/distributed/BrickTree.h"
#include "nodes/distributed/FrameWindow.h"
#include "nodes/distributed/RankAgreement.h"
#include "nodes/distributed/SplatPlacements.h"
#include "nodes/render/Frame.h"
#include "nodes/volume/ValueHistogram.h"
#include "octree/VoxelShadows.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/actions/Seconds.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

#include <sched.h>
#include <sys/resource.h>

namespace texsplat::distributed {
namespace {

using Clock = sg::TimingClock;
using sg::secondsSince;

constexpr std::array<std::string_view, kStepCount> kStepNames = {
    "split", "load", "gather", "classify", "order", "draw", "composite", "finish"};

constexpr const char* kCompositeAdvice = "render a smaller image";

// Runs `step` and adds its wall time to `seconds`.
template <class Work> auto timed(double& seconds, Work&& work) {
    struct AddTime {
        double& seconds;
        Clock::time_point start = Clock::now();
        ~AddTime() { seconds += secondsSince(start); }
    } addTime{seconds};
    return work();
}

// The slicing axis octree::SliceOrder picks for a local viewing direction (ties go to z, then y).
int sliceAxisOf(const glm::dvec3& direction) {
    const glm::dvec3 size = glm::abs(direction);
    int axis = 2;
    if (size.x > size[axis]) {
        axis = 0;
    }
    if (size.y > size[axis]) {
        axis = 1;
    }
    return axis;
}

// The voxels of a volume placed by `toPrimary` (its local space to the first volume's), of
// geometry `geometry`, whose centres lie in the first volume's voxels of `brick` (a brick of
// `primary`): per axis the voxels whose centre falls in a voxel cell of the brick; a brick on a
// face of the first volume's box takes what lies beyond it.
volume::IndexBox mappedRegion(const volume::IndexBox& brick, const volume::GridGeometry& primary,
                              const glm::dmat4& toPrimary, const volume::GridGeometry& geometry) {
    volume::IndexBox region;
    const double infinity = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        // Voxel i's centre at primary index coordinate slope * i + offset.
        const double slope =
            toPrimary[axis][axis] * geometry.spacing()[axis] / primary.spacing()[axis];
        const double offset = (toPrimary[axis][axis] * geometry.origin()[axis] +
                               toPrimary[3][axis] - primary.origin()[axis]) /
                              primary.spacing()[axis];
        const double low = brick.lo[axis] == 0 ? -infinity : double(brick.lo[axis]) - 0.5;
        const double high =
            brick.hi[axis] == primary.dims()[axis] ? infinity : double(brick.hi[axis]) - 0.5;
        // low <= slope * i + offset < high
        double first = 0.0;
        double end = 0.0;
        if (slope > 0.0) {
            first = std::ceil((low - offset) / slope);
            end = std::ceil((high - offset) / slope);
        } else {
            first = std::floor((high - offset) / slope) + 1.0;
            end = std::floor((low - offset) / slope) + 1.0;
        }
        const double count = double(geometry.dims()[axis]);
        region.lo[axis] = static_cast<std::int64_t>(std::clamp(first, 0.0, count));
        region.hi[axis] = static_cast<std::int64_t>(std::clamp(end, 0.0, count));
    }
    return region;
}

// Throws unless `toPrimary` only scales and moves along the axes: bricks are boxes of voxels in
// every volume only then.
void checkAxisAligned(const glm::dmat4& toPrimary, const nodes::VolumeData& volume,
                      const nodes::VolumeData& primary) {
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row) {
            const double scale =
                std::abs(toPrimary[column][column]) + std::abs(toPrimary[row][row]);
            if (row != column && std::abs(toPrimary[column][row]) > 1e-6 * scale) {
                throw DataError(nodes::detail::nodeContext(volume) + " is turned against " +
                                nodes::detail::nodeContext(primary) +
                                " by the transforms above their splat nodes: a render split "
                                "over processes splits volumes along common axes; render it in "
                                "one process");
            }
        }
    }
}

// Whether a TransferFunction of `root` takes its range from the data's percentiles.
bool usesPercentiles(sg::Node& root) {
    sg::SearchAction search;
    search.setType(nodes::TransferFunction::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.setSearchingAll(true);
    search.apply(root);
    for (const sg::Path& path : search.paths()) {
        const auto& transfer = static_cast<const nodes::TransferFunction&>(*path.tail());
        if (transfer.rangeMode.as<nodes::RangeMode>() == nodes::RangeMode::Percentile) {
            return true;
        }
    }
    return false;
}

int cpusOfProcess() {
    cpu_set_t cpus;
    CPU_ZERO(&cpus);
    if (sched_getaffinity(0, sizeof cpus, &cpus) != 0) {
        return 0;
    }
    return std::max(1, CPU_COUNT(&cpus));
}

double peakMebibytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

} // namespace

std::string_view toString(Step step) {
    return kStepNames[static_cast<std::size_t>(step)];
}

// The bricks for the current view: the k-d tree, kept while the first volume and the slicing
// axis stay the same, and the ranks' order for the camera.
struct SceneRenderer::Split {
    std::unique_ptr<BrickTree> tree;
    bool isGiven = false; // setBricks()'s, kept whatever the view
    glm::i64vec3 dims{0};
    int sliceAxis = -1;
    std::vector<int> backToFront;
};

SceneRenderer::SceneRenderer(MPI_Comm comm, const render::SceneRenderOptions& options,
                             Compositing compositing)
    : mComm(comm), mOptions(options), mCompositing(compositing), mLocal([&] {
          // Each brick is drawn over nothing; rank 0 lays the composite over the background.
          render::SceneRenderOptions local = options;
          local.background = glm::vec4(0.0f);
          // The CPUs the launcher gave this rank (mpirun binds ranks to cores), not the machine's.
          if (local.threads == 0) {
              local.threads = cpusOfProcess();
          }
          return local;
      }()),
      mSplit(std::make_unique<Split>()) {
    MPI_Comm_rank(comm, &mRank);
    MPI_Comm_size(comm, &mSize);
    mLocal.setFrameEdit([this](render::Frame& frame) {
        mMeshes.meshes = frame.meshes;
        mFootprint = splatFootprint(frame);
        if (mFootprint.width <= 0) {
            // Nothing to draw: one pixel of nothing.
            frame.splats.clear();
            frame.meshes.clear();
            cropFrame(frame, {0, 0, 1, 1});
            return;
        }
        cropFrame(frame, mFootprint);
        frame.meshesHideOnly = true;
    });
}

SceneRenderer::~SceneRenderer() = default;

void SceneRenderer::prepareBricks(sg::Node& scene) {
    for (nodes::VolumeData* volume : findVolumes(scene)) {
        volume->setBrick(volume::IndexBox{});
    }
}

void SceneRenderer::setBricks(const std::vector<volume::IndexBox>& bricks) {
    if (bricks.empty()) {
        mSplit->tree.reset();
        mSplit->isGiven = false;
        return;
    }
    if (static_cast<int>(bricks.size()) != mSize) {
        throw DataError("bricks: expected one per rank (" + std::to_string(mSize) + "), got " +
                        std::to_string(bricks.size()));
    }
    mSplit->tree = std::make_unique<BrickTree>(BrickTree::of(bricks));
    mSplit->isGiven = true;
}

void SceneRenderer::setWorkProgress(sg::WorkProgress progress) {
    if (mRank == 0) {
        mProgress = progress;
        mLocal.setWorkProgress(std::move(progress));
    }
}

// The cut fields surveyed nodes had before the frame set this rank's share: set back when the
// frame ends, however it ends.
struct SceneRenderer::SurveyedFields {
    struct Saved {
        nodes::ScalarSplat* splat;
        float errorThreshold;
        int maxSplats;
    };
    std::vector<Saved> saved;

    SurveyedFields() = default;
    SurveyedFields(const SurveyedFields&) = delete;
    SurveyedFields& operator=(const SurveyedFields&) = delete;
    ~SurveyedFields() {
        for (const Saved& fields : saved) {
            fields.splat->errorThreshold.setValue(fields.errorThreshold);
            fields.splat->maxSplats.setValue(fields.maxSplats);
        }
    }
};

std::optional<image::Image> SceneRenderer::render(sg::Node& root, bool withDepth) {
    mStatistics = RankStatistics();
    auto& seconds = mStatistics.seconds;
    const auto at = [&](Step step) -> double& { return seconds[static_cast<std::size_t>(step)]; };
    timed(at(Step::Split), [&] { runAgreed(mComm, [&] { placeBricks(root); }); });
    gatherWholeGrids(root);
    // Octree cuts and marks follow figures of the whole data: each brick's, merged.
    const float aspect = float(mOptions.width) / float(mOptions.height);
    const std::vector<SplatSurvey> surveys = timed(at(Step::Classify), [&] {
        return runAgreed(mComm, [&] { return surveyBricks(root, aspect); });
    });
    SurveyedFields restore;
    applySurveys(surveys, restore);
    ImageLayer layer = runAgreed(mComm, [&] { return drawBrick(root); });
    const sg::RenderStatistics& frame = mLocal.statistics();
    at(Step::Load) += frame.time(sg::RenderPhase::Load);
    at(Step::Classify) += frame.time(sg::RenderPhase::Classify);
    at(Step::Order) = frame.time(sg::RenderPhase::Order);
    at(Step::Draw) = frame.time(sg::RenderPhase::Upload) + frame.time(sg::RenderPhase::Draw) +
                     frame.time(sg::RenderPhase::ReadBack);
    mStatistics.splats = frame.splats;
    mStatistics.footprint = layer.region;
    Compositor compositor(mComm, mOptions.width, mOptions.height, mCompositing);
    image::Pixels composite = timed(at(Step::Composite), [&] {
        runAgreed(mComm, [&] {
            checkMemory("compositing a " + std::to_string(mOptions.width) + "x" +
                            std::to_string(mOptions.height) + " image",
                        compositor.memoryBound(layer), kCompositeAdvice);
        });
        return compositor.composite(std::move(layer), mSplit->backToFront);
    });
    std::optional<image::Image> image = timed(at(Step::Finish), [&] {
        return runAgreed(mComm, [&]() -> std::optional<image::Image> {
            if (mRank != 0) {
                return std::nullopt;
            }
            return finish(std::move(composite), withDepth);
        });
    });
    mStatistics.peakMebibytes = peakMebibytes();
    return image;
}

void SceneRenderer::placeBricks(sg::Node& root) {
    const float aspect = float(mOptions.width) / float(mOptions.height);
    const std::vector<SplatPlacement> placements = findSplatPlacements(root, aspect);
    const std::vector<nodes::VolumeData*> volumes = findVolumes(root);
    mStatistics.voxels = 0;
    if (placements.empty()) {
        // No splats: no volume is drawn, and the ranks' (empty) images go in any order.
        for (nodes::VolumeData* volume : volumes) {
            volume->setBrick(volume::IndexBox{});
        }
        mSplit->backToFront.resize(static_cast<std::size_t>(mSize));
        std::iota(mSplit->backToFront.begin(), mSplit->backToFront.end(), 0);
        return;
    }
    const SplatPlacement& primary = placements.front();
    const volume::GridGeometry whole =
        sg::withNodeLocation(*primary.volume, [&] { return primary.volume->wholeGeometry(); });
    const glm::dmat4 toPrimary = glm::inverse(glm::dmat4(primary.model));
    // The eye in the first volume's voxels: the bricks' order and the slicing axis follow it.
    const render::CameraView& camera = primary.camera;
    const glm::dvec3 eye(toPrimary * glm::inverse(glm::dmat4(camera.view)) *
                         glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 direction = glm::dmat3(toPrimary) * glm::dvec3(camera.viewDirection);
    Viewpoint view;
    view.isPerspective = camera.projection[3][3] == 0.0f;
    view.eye = whole.worldToIndex(eye);
    view.direction = direction / whole.spacing();
    const int sliceAxis = sliceAxisOf(direction);
    if (!mSplit->isGiven &&
        (!mSplit->tree || mSplit->dims != whole.dims() || mSplit->sliceAxis != sliceAxis)) {
        mSplit->tree = std::make_unique<BrickTree>(
            BrickTree::split(volume::IndexBox::of(whole), mSize, sliceAxis));
        mSplit->dims = whole.dims();
        mSplit->sliceAxis = sliceAxis;
    }
    mSplit->backToFront = mSplit->tree->backToFront(view);
    const volume::IndexBox& brick = mSplit->tree->bricks()[static_cast<std::size_t>(mRank)];
    // Each volume's voxels in this brick: the same box for the first one and for volumes read
    // along a splat node's (its mask), the voxels whose centres lie in it for others.
    std::map<nodes::VolumeData*, volume::IndexBox> regions;
    const auto assign = [&](nodes::VolumeData* volume, const volume::IndexBox& region) {
        const auto [where, isNew] = regions.emplace(volume, region);
        if (!isNew && where->second != region) {
            throw DataError(nodes::detail::nodeContext(*volume) +
                            " is drawn at two places: a render split over processes splits each "
                            "volume once; give each place its own VolumeData");
        }
    };
    for (const SplatPlacement& placement : placements) {
        const glm::dmat4 toFirst = toPrimary * glm::dmat4(placement.model);
        volume::IndexBox region = brick;
        if (placement.volume != primary.volume || placement.model != primary.model) {
            checkAxisAligned(toFirst, *placement.volume, *primary.volume);
            region =
                mappedRegion(brick, whole, toFirst, sg::withNodeLocation(*placement.volume, [&] {
                                 return placement.volume->wholeGeometry();
                             }));
        }
        assign(placement.volume, region);
        for (nodes::VolumeData* companion : placement.companions) {
            assign(companion, region);
        }
    }
    for (nodes::VolumeData* volume : volumes) {
        const auto found = regions.find(volume);
        const volume::IndexBox region = found != regions.end() ? found->second : volume::IndexBox{};
        volume->setBrick(region);
        mStatistics.voxels += static_cast<std::uint64_t>(region.voxelCount());
    }
}

void SceneRenderer::gatherWholeGrids(sg::Node& root) {
    auto& seconds = mStatistics.seconds;
    const std::vector<nodes::VolumeData*> volumes = findVolumes(root);
    // Every rank loads its bricks; the figures of each grid, in the same order on every rank.
    std::vector<std::vector<volume::AnyGrid>> grids;
    std::vector<volume::GridStatistics> local;
    timed(seconds[static_cast<std::size_t>(Step::Load)], [&] {
        runAgreed(mComm, [&] {
            for (nodes::VolumeData* volume : volumes) {
                // Errors point into the scene file, as a traversal's do.
                grids.push_back(
                    sg::withNodeLocation(*volume, [&] { return volume->brickGrids(mProgress); }));
                const bool isEmpty = volume->brick()->isEmpty();
                for (const volume::AnyGrid& grid : grids.back()) {
                    local.push_back(
                        isEmpty ? volume::GridStatistics{}
                                : std::visit([](const auto& typed) { return typed->statistics(); },
                                             grid));
                }
            }
        });
    });
    timed(seconds[static_cast<std::size_t>(Step::Gather)], [&] {
        const std::size_t count = local.size();
        std::vector<double> minimum(count);
        std::vector<double> maximum(count);
        std::vector<std::int64_t> counts(2 * count);
        for (std::size_t i = 0; i < count; ++i) {
            const bool any = local[i].finiteCount > 0;
            minimum[i] = any ? local[i].minimum : std::numeric_limits<double>::infinity();
            maximum[i] = any ? local[i].maximum : -std::numeric_limits<double>::infinity();
            counts[2 * i] = local[i].finiteCount;
            counts[2 * i + 1] = local[i].nonFiniteCount;
        }
        const int size = static_cast<int>(count);
        MPI_Allreduce(MPI_IN_PLACE, minimum.data(), size, MPI_DOUBLE, MPI_MIN, mComm);
        MPI_Allreduce(MPI_IN_PLACE, maximum.data(), size, MPI_DOUBLE, MPI_MAX, mComm);
        MPI_Allreduce(MPI_IN_PLACE, counts.data(), 2 * size, MPI_INT64_T, MPI_SUM, mComm);
        std::vector<volume::WholeGrid> wholes(count);
        for (std::size_t i = 0; i < count; ++i) {
            volume::GridStatistics& statistics = wholes[i].statistics;
            statistics.finiteCount = counts[2 * i];
            statistics.nonFiniteCount = counts[2 * i + 1];
            statistics.minimum = statistics.finiteCount > 0 ? minimum[i] : 0.0;
            statistics.maximum = statistics.finiteCount > 0 ? maximum[i] : 0.0;
        }
        if (usesPercentiles(root)) {
            // The percentiles' histograms over the whole ranges, added up over the ranks.
            std::vector<std::vector<std::uint64_t>> histograms(count);
            runAgreed(mComm, [&] {
                std::size_t next = 0;
                for (std::size_t v = 0; v < volumes.size(); ++v) {
                    for (const volume::AnyGrid& grid : grids[v]) {
                        const volume::GridStatistics& statistics = wholes[next].statistics;
                        std::vector<std::uint64_t>& histogram = histograms[next++];
                        histogram.assign(volume::WholeGrid::kHistogramBins, 0);
                        if (statistics.minimum < statistics.maximum &&
                            !volumes[v]->brick()->isEmpty()) {
                            histogram = std::visit(
                                [&](const auto& typed) {
                                    return volume::valueHistogram(
                                        *typed, statistics.minimum, statistics.maximum,
                                        volume::WholeGrid::kHistogramBins);
                                },
                                grid);
                        }
                    }
                }
            });
            for (std::size_t i = 0; i < count; ++i) {
                MPI_Allreduce(MPI_IN_PLACE, histograms[i].data(),
                              static_cast<int>(histograms[i].size()), MPI_UINT64_T, MPI_SUM, mComm);
                wholes[i].histogram = std::move(histograms[i]);
            }
        }
        runAgreed(mComm, [&] {
            std::size_t next = 0;
            for (std::size_t v = 0; v < volumes.size(); ++v) {
                std::vector<std::shared_ptr<const volume::WholeGrid>> figures;
                for (std::size_t g = 0; g < grids[v].size(); ++g) {
                    figures.push_back(std::make_shared<const volume::WholeGrid>(wholes[next++]));
                }
                volumes[v]->setWholeGrids(figures);
            }
        });
    });
}

void SceneRenderer::applySurveys(const std::vector<SplatSurvey>& surveys, SurveyedFields& restore) {
    for (const SplatSurvey& survey : surveys) {
        if (survey.drawsMarks) {
            // The whole grid's columns: a column holds a voxel when some brick's does.
            std::array<std::uint64_t, 3> columns{};
            for (std::size_t axis = 0; axis < 3; ++axis) {
                std::vector<std::uint64_t> bits = survey.columns[axis];
                MPI_Allreduce(MPI_IN_PLACE, bits.data(), static_cast<int>(bits.size()),
                              MPI_UINT64_T, MPI_BOR, mComm);
                for (const std::uint64_t word : bits) {
                    columns[axis] += static_cast<std::uint64_t>(__builtin_popcountll(word));
                }
            }
            std::uint64_t voxels = survey.voxels;
            MPI_Allreduce(MPI_IN_PLACE, &voxels, 1, MPI_UINT64_T, MPI_SUM, mComm);
            auto whole = std::make_shared<nodes::VectorMarkSplat::WholeVolume>();
            whole->shadows =
                std::make_shared<const octree::VoxelShadows>(columns, voxels, survey.spacing);
            whole->centre = survey.wholeCentre;
            whole->low = glm::vec3(survey.wholeLow);
            whole->high = glm::vec3(survey.wholeHigh);
            whole->offset = survey.offset;
            static_cast<nodes::VectorMarkSplat*>(survey.splat)->setWholeVolume(std::move(whole));
        }
        if (survey.cuts) {
            nodes::ScalarSplat& splat = *survey.splat;
            restore.saved.push_back(
                {&splat, splat.errorThreshold.value(), splat.maxSplats.value()});
            // A relative threshold is relative to the whole grid's largest value.
            double scale = survey.valueScale;
            MPI_Allreduce(MPI_IN_PLACE, &scale, 1, MPI_DOUBLE, MPI_MAX, mComm);
            if (splat.errorThreshold.value() > 0.0f && survey.valueScale > 0.0) {
                splat.errorThreshold.setValue(
                    static_cast<float>(splat.errorThreshold.value() * scale / survey.valueScale));
            }
            const int budget = splat.maxSplats.value();
            if (budget > 0) {
                splat.maxSplats.setValue(budgetShare(survey, std::uint64_t(budget)));
            }
        }
    }
}

int SceneRenderer::budgetShare(const SplatSurvey& survey, std::uint64_t budget) const {
    // One process refines the whole octree's cut, largest priority first, until the budget is
    // spent: every node is split whose priority exceeds the last split's. The bricks split
    // theirs at the priority where their cuts add up to the budget, found by bisection over
    // its logarithm; each brick's share is its cut there.
    double highest = survey.largestPriority;
    MPI_Allreduce(MPI_IN_PLACE, &highest, 1, MPI_DOUBLE, MPI_MAX, mComm);
    double low = std::log(std::max(highest, 1e-300)) - 60.0; // splits everything worth it
    double high = std::log(std::max(highest, 1e-300));       // splits nothing
    constexpr int kSteps = 40;
    for (int step = 0; step < kSteps; ++step) {
        const double middle = 0.5 * (low + high);
        std::uint64_t splats = cutSize(survey, std::exp(middle), budget);
        MPI_Allreduce(MPI_IN_PLACE, &splats, 1, MPI_UINT64_T, MPI_SUM, mComm);
        (splats > budget ? low : high) = middle;
    }
    const std::uint64_t share = cutSize(survey, std::exp(high), budget);
    return static_cast<int>(std::clamp<std::uint64_t>(share, 1, budget));
}

ImageLayer SceneRenderer::drawBrick(sg::Node& root) {
    mMeshes = render::Frame();
    image::Image drawn = mLocal.render(root);
    // The compositing needs the memory more than a next frame its planes.
    mLocal.releaseFrameBuffers();
    ImageLayer layer;
    if (mFootprint.width > 0) {
        layer.region = mFootprint;
        layer.pixels = std::move(drawn).takePixels();
    }
    return layer;
}

image::Image SceneRenderer::finish(image::Pixels composite, bool withDepth) {
    if (mMeshes.meshes.empty()) {
        // The composite over the background, in place: no second image of the frame's size.
        image::Image image(mOptions.width, mOptions.height, std::move(composite));
        const glm::vec4 background = mOptions.background;
        glm::vec4* pixels = image.data();
        for (std::size_t i = 0; i < image.pixels().size(); ++i) {
            pixels[i] += (1.0f - pixels[i].a) * background;
        }
        if (withDepth) {
            image.addDepth(1.0f); // no mesh anywhere
        }
        return image;
    }
    // The meshes (opaque, under every splat in front of them, which the bricks kept) over the
    // background, then the composite over them.
    mMeshes.width = mOptions.width;
    mMeshes.height = mOptions.height;
    mMeshes.background = mOptions.background;
    image::Image image = mLocal.draw(mMeshes, withDepth);
    glm::vec4* pixels = image.data();
    for (std::size_t i = 0; i < composite.size(); ++i) {
        pixels[i] = composite[i] + (1.0f - composite[i].a) * pixels[i];
    }
    return image;
}

std::vector<volume::IndexBox> SceneRenderer::bricks() const {
    return mSplit->tree ? mSplit->tree->bricks() : std::vector<volume::IndexBox>{};
}

} // namespace texsplat::distributed
