#include "nodes/bench/BenchRunner.h"

#include "nodes/Camera.h"
#include "nodes/NodeTypes.h"
#include "nodes/ScalarSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VectorMarkSplat.h"
#include "nodes/VolumeData.h"
#include "nodes/image/Image.h"
#include "nodes/image/ImageComparison.h"
#include "nodes/render/Frame.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/SplatView.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Cut.h"
#include "octree/DepthSort.h"
#include "octree/Octree.h"
#include "octree/Refiner.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/actions/Path.h"
#include "scenegraph/actions/RayCastAction.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/actions/Seconds.h"

#ifdef TEXSPLAT_WITH_GL
#include "nodes/bench/FillRateCeiling.h"
#include "nodes/bench/detail/SamplesPassed.h"
#include "nodes/render/gl/GlRenderer.h"
#include "scenegraph/gl/Context.h"
#endif

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>

namespace texsplat::bench {
namespace {

using Clock = sg::TimingClock;
using sg::secondsSince;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string backendName(render::Backend backend) {
    return backend == render::Backend::Gl ? "gl" : "cpu";
}

std::string sizeText(const glm::ivec2& size) {
    return std::to_string(size.x) + "x" + std::to_string(size.y);
}

image::Image imageFromRgba(const std::vector<float>& rgba, const glm::ivec2& size) {
    image::Image result(size.x, size.y);
    std::memcpy(static_cast<void*>(result.data()), rgba.data(), rgba.size() * sizeof(float));
    return result;
}

// RMSE and PSNR over R, G, B pooled.
void compare(const image::Image& reference, const image::Image& test, double& rmse,
             double& psnr) {
    const image::ImageComparison comparison(reference, test);
    rmse = comparison.rgb().rmse;
    psnr = comparison.rgb().psnr;
}

// What a splat node of the benchmark scene draws, computed the way ScalarSplat does it (the
// scene has no Transform, so the model matrix is the identity).
struct SplatSource {
    std::shared_ptr<const octree::ClassifiedGrid> classified;
    render::SplatView view;
    std::optional<octree::Octree> octree;
};

// Every voxel's splat. Without the view's sides, so the list holds what any method's splats
// reach; the benchmark's camera frames the whole volume anyway.
void emitVoxels(const SplatSource& source, octree::SplatList& splats) {
    octree::emitVoxelSplats(*source.classified, source.view.octreeView(), splats);
}

#ifdef TEXSPLAT_WITH_GL
// The octree cut of at most `maxSplats` splats that draw up to `reach` voxels from their centre,
// as the method's node makes it: the list the GL fill-rate ceiling draws for a method with a
// budget.
void emitCut(SplatSource& source, std::size_t maxSplats, double reach,
             octree::SplatList& splats) {
    if (!source.octree) {
        source.octree.emplace(source.classified);
    }
    const octree::View order = source.view.refinementView(reach);
    const octree::Cut cut = octree::Refiner::cutOfBudget(octree::Cut(*source.octree), order,
                                                         maxSplats);
    octree::emitSplats(cut, order, splats);
    octree::sortByDepth(splats, order); // as ScalarSplat draws a cut
}
#endif

std::string budgetText(double budget) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", budget);
    return text;
}

// The splat nodes of a user's scene and what each traversal of them draws at full resolution,
// so that a budget can be set as a fraction of it.
class SceneSplatNodes {
public:
    SceneSplatNodes(sg::Node& root, const std::string& name) : mRoot(root) {
        sg::SearchAction search;
        search.setType(nodes::ScalarSplat::classType());
        search.setInterest(sg::SearchAction::Interest::All);
        search.apply(root);
        for (const sg::Path& path : search.paths()) {
            mNodes.push_back(&static_cast<nodes::ScalarSplat&>(*path.tail()));
        }
        if (mNodes.empty()) {
            throw DataError("bench: " + name + " has no splat node (TextureSplat, GaussianSplat, "
                            "VectorSplat, CombinedSplat) to measure");
        }
    }

    // One frame at full resolution: the splats of each traversal of a splat node.
    void countFullResolution(const glm::ivec2& size) {
        setBudget(1.0);
        render::FrameAction action(size.x, size.y);
        const render::Frame& frame = action.collect(mRoot);
        mFullSplats.clear();
        for (const render::FrameSplats& splats : frame.splats) {
            mFullSplats.push_back(splats.splatCount());
        }
    }

    // Every node's maxSplats at `fraction` of what it draws at full resolution (1: no budget).
    // The frame lists the traversals in the order the search found them; where they differ (a
    // node under a Switch that is off) each node gets the fraction of the frame's mean.
    void setBudget(double fraction) {
        std::size_t total = 0;
        for (const std::size_t splats : mFullSplats) {
            total += splats;
        }
        const bool matched = mFullSplats.size() == mNodes.size();
        for (nodes::ScalarSplat* node : mNodes) {
            node->errorThreshold.setValue(0.0f);
            node->maxSplats.setValue(0);
        }
        if (fraction >= 1.0) {
            return;
        }
        for (std::size_t i = 0; i < mNodes.size(); ++i) {
            const double full = matched ? static_cast<double>(mFullSplats[i])
                                        : static_cast<double>(total) /
                                              static_cast<double>(std::max<std::size_t>(
                                                  mFullSplats.size(), 1));
            const int budget = static_cast<int>(
                std::clamp(std::round(fraction * full), 1.0, static_cast<double>(INT_MAX)));
            // A node used twice (DEF/USE) keeps the larger of its traversals' budgets.
            mNodes[i]->maxSplats.setValue(std::max(mNodes[i]->maxSplats.value(), budget));
        }
    }

private:
    sg::Node& mRoot;
    std::vector<nodes::ScalarSplat*> mNodes; // per traversal, in traversal order
    std::vector<std::size_t> mFullSplats;    // per traversal, at full resolution
};

} // namespace

BenchRunner::BenchRunner(BenchOptions options) : mOptions(std::move(options)) {
    if (mOptions.sizes.empty()) {
        throw DataError("bench: needs at least one image size");
    }
    if (mOptions.warmup < 1 || mOptions.repeat < 1) {
        throw DataError("bench: warm-up and repeat must be at least 1, got " +
                        std::to_string(mOptions.warmup) + " and " +
                        std::to_string(mOptions.repeat));
    }
}

void BenchRunner::report(const std::string& stage, double fractionDone) const {
    if (mProgress) {
        mProgress(stage, fractionDone);
    }
}

std::vector<BenchResult> BenchRunner::run() {
    if (mOptions.datasets.empty() || mOptions.methods.empty()) {
        throw DataError("bench: needs at least one dataset, size and method");
    }
    const bool withGl = std::find(mOptions.backends.begin(), mOptions.backends.end(),
                                  render::Backend::Gl) != mOptions.backends.end();
#ifdef TEXSPLAT_WITH_GL
    if (withGl && !gl::Context::current()) {
        throw GlError("bench: no current GL context");
    }
#else
    if (withGl) {
        throw Error("bench: this texsplat was built without GL (TEXSPLAT_WITH_GL=OFF)");
    }
#endif
    nodes::registerNodeTypes();
    std::vector<BenchResult> results;
    for (const BenchDataset& dataset : mOptions.datasets) {
        for (const glm::ivec2& size : mOptions.sizes) {
            runOne(dataset, size, results);
        }
    }
    return results;
}

void BenchRunner::runOne(const BenchDataset& dataset, const glm::ivec2& size,
                         std::vector<BenchResult>& results) {
    const std::string where = dataset.name() + " " + sizeText(size);
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    report(where + ": load and classify", 0.0);
    // The reference ray casts the scene with the full-quality node; each method replaces it.
    const sg::Separator::Ptr root =
        dataset.scene(BenchMethod().makeNode(0), aspect, mOptions.camera);
    auto& camera = static_cast<nodes::Camera&>(*root->child(0));
    auto& transfer = static_cast<nodes::TransferFunction&>(*root->child(1));
    const auto& volume = static_cast<const nodes::VolumeData&>(*root->child(2));

    SplatSource source;
    source.classified = transfer.classify(*volume.scalarGrid());
    source.view = render::SplatView::fromMatrices(glm::mat4(1.0f), camera.viewMatrix(),
                                                  camera.projectionMatrix(aspect),
                                                  glm::vec3(source.classified->spacing()));
    octree::SplatList fullList;
    emitVoxels(source, fullList);
    report(where + ": load and classify", 1.0);

    const std::optional<image::Image> reference = referenceImage(*root, size, where);
    // Shaded methods are compared with the reference shaded per sample, made when one is run.
    std::optional<image::Image> shadedReference;
    const bool anyShaded = std::any_of(mOptions.methods.begin(), mOptions.methods.end(),
                                       [](const BenchMethod& m) { return m.shaded; });
    if (anyShaded) {
        transfer.shade.setValue(true);
        shadedReference = referenceImage(*root, size, where + " shaded");
        transfer.shade.setValue(false);
    }
    // A shaded method's frames turn the view by a ten-thousandth of a radian about its up axis
    // through the focal point, back and forth, so every frame lights the volume again, as an
    // orbit in the viewer does: what shading costs while the view moves.
    const sg::Rotation still = camera.orientation.value();
    const glm::vec3 position = camera.position.value();
    const float distance = camera.focalDistance.value();
    const glm::vec3 focus = position + camera.viewDirection() * distance;
    const auto orbit = [&](int frame) {
        const glm::quat turn = glm::angleAxis(frame % 2 == 0 ? 0.0f : 1e-4f,
                                              still.quaternion() * glm::vec3(0.0f, 1.0f, 0.0f)) *
                               still.quaternion();
        camera.orientation.setValue(sg::Rotation(glm::axis(turn), glm::angle(turn)));
        camera.position.setValue(focus - (turn * glm::vec3(0.0f, 0.0f, -1.0f)) * distance);
    };
#ifdef TEXSPLAT_WITH_GL
    const bool withGl = std::find(mOptions.backends.begin(), mOptions.backends.end(),
                                  render::Backend::Gl) != mOptions.backends.end();
    std::optional<FillRateCeiling> ceiling;
    if (withGl) {
        ceiling.emplace(size.x, size.y);
    }
#endif
    std::vector<image::Image> images;
    const std::size_t first = results.size();
    for (const BenchMethod& method : mOptions.methods) {
        const sg::Node::Ptr node = method.makeNode(fullList.size());
        root->replaceChild(3, node);
        transfer.shade.setValue(method.shaded);
        const BeforeFrame beforeFrame = method.shaded ? BeforeFrame(orbit) : BeforeFrame();
        for (const render::Backend backend : mOptions.backends) {
            const std::string stage = where + ": " + method.name() +
                                      (mOptions.backends.size() > 1 ? " " + backendName(backend)
                                                                    : std::string());
            BenchResult result;
            result.dataset = dataset.name();
            result.width = size.x;
            result.height = size.y;
            result.method = method.name();
            result.backend = backendName(backend);
            result.isFullQuality = method.isFullQuality();
            result.isShaded = method.shaded;
#ifdef TEXSPLAT_WITH_GL
            if (backend == render::Backend::Gl) {
                auto& splatNode = static_cast<nodes::ScalarSplat&>(*node);
                // The ceiling draws the very list this method draws (the full list, or its
                // octree cut) as quads of the scalar splat's size (vector splats' marks are
                // thinner: their ceiling is the scalar splats').
                const float extent = splatNode.size.value();
                octree::SplatList cutList;
                if (method.budget > 0.0) {
                    emitCut(source, static_cast<std::size_t>(splatNode.maxSplats.value()),
                            splatNode.splatReach(), cutList);
                }
                const octree::SplatList& drawn = method.budget > 0.0 ? cutList : fullList;
                images.push_back(measureGl(*root, size, *ceiling, source.view, extent, drawn,
                                           stage, result, beforeFrame));
            } else
#endif
            {
                images.push_back(measureCpu(*root, size, stage, result, beforeFrame));
            }
            report(stage, 1.0);
            const std::optional<image::Image>& matching = method.shaded ? shadedReference
                                                                        : reference;
            if (matching) {
                compare(*matching, images.back(), result.referenceRmse, result.referencePsnr);
            }
            results.push_back(std::move(result));
        }
        camera.orientation.setValue(still);
        camera.position.setValue(position);
    }
    transfer.shade.setValue(false);
    compareWithinRun(images, results, first);
}

std::optional<image::Image> BenchRunner::referenceImage(sg::Node& root, const glm::ivec2& size,
                                                        const std::string& where) const {
    if (!mOptions.reference) {
        return std::nullopt;
    }
    const std::string stage = where + ": reference (RayCastAction)";
    sg::RayCastAction rayCast(size.x, size.y);
    rayCast.setThreadCount(mOptions.threads);
    rayCast.setProgress([&](double fraction) {
        report(stage, fraction);
        return true;
    });
    rayCast.render(root);
    return imageFromRgba(rayCast.readColor(), size);
}

std::vector<BenchResult> BenchRunner::runScene(sg::Node& root, const std::string& name,
                                               const std::vector<double>& budgets) {
    if (std::find(mOptions.backends.begin(), mOptions.backends.end(), render::Backend::Gl) !=
        mOptions.backends.end()) {
        throw Error("bench: a scene is measured on the CPU backend only (--backend cpu)");
    }
    for (const double budget : budgets) {
        if (!(budget > 0.0 && budget <= 1.0)) {
            throw DataError("bench: a budget is a fraction of the full-resolution splats in "
                            "(0, 1], got " + budgetText(budget));
        }
    }
    nodes::registerNodeTypes();
    SceneSplatNodes nodes(root, name);
    std::vector<BenchResult> results;
    for (const glm::ivec2& size : mOptions.sizes) {
        const std::string where = name + " " + sizeText(size);
        report(where + ": load and classify", 0.0);
        nodes.countFullResolution(size);
        report(where + ": load and classify", 1.0);
        const std::optional<image::Image> reference = referenceImage(root, size, where);
        std::vector<image::Image> images;
        const std::size_t first = results.size();
        for (const double budget : budgets) {
            nodes.setBudget(budget);
            BenchResult result;
            result.dataset = name;
            result.width = size.x;
            result.height = size.y;
            result.method = budget < 1.0 ? "scene@" + budgetText(budget) : "scene";
            result.backend = backendName(render::Backend::Cpu);
            result.isFullQuality = budget >= 1.0;
            const std::string stage = where + ": " + result.method;
            images.push_back(measureCpu(root, size, stage, result));
            report(stage, 1.0);
            if (reference) {
                compare(*reference, images.back(), result.referenceRmse, result.referencePsnr);
            }
            results.push_back(std::move(result));
        }
        compareWithinRun(images, results, first);
    }
    return results;
}

#ifdef TEXSPLAT_WITH_GL
image::Image BenchRunner::measureGl(sg::Node& root, const glm::ivec2& size,
                                    FillRateCeiling& ceiling, const render::SplatView& view,
                                    float extent, const octree::SplatList& drawn,
                                    const std::string& stage, BenchResult& result,
                                    const BeforeFrame& beforeFrame) const {
    ceiling.upload(drawn);
    // Frames and ceiling draws alternate, so that load from other processes on a shared
    // machine hits both alike; each ratio pairs a frame with the ceiling draw after it.
    render::FrameAction action(size.x, size.y);
    render::GlRenderer renderer;
    int frame = 0;
    const auto renderFrame = [&] {
        if (beforeFrame) {
            beforeFrame(frame++);
        }
        renderer.render(action.collect(root), action.statistics());
    };
    const int frames = mOptions.warmup + mOptions.repeat;
    for (int i = 0; i < mOptions.warmup; ++i) {
        report(stage, static_cast<double>(i) / frames);
        renderFrame();
        ceiling.draw(view, extent);
    }
    std::vector<double> frameTimes;
    std::vector<double> ceilingTimes;
    std::vector<double> frameRatios;
    std::vector<double> drawRatios;
    std::vector<std::vector<double>> phaseTimes(sg::kRenderPhaseCount);
    for (int i = 0; i < mOptions.repeat; ++i) {
        report(stage, static_cast<double>(mOptions.warmup + i) / frames);
        const Clock::time_point start = Clock::now();
        renderFrame();
        frameTimes.push_back(secondsSince(start));
        for (std::size_t phase = 0; phase < sg::kRenderPhaseCount; ++phase) {
            phaseTimes[phase].push_back(action.statistics().seconds[phase]);
        }
        ceilingTimes.push_back(ceiling.draw(view, extent));
        frameRatios.push_back(frameTimes.back() / ceilingTimes.back());
        drawRatios.push_back(action.statistics().time(sg::RenderPhase::Draw) /
                             ceilingTimes.back());
    }
    result.splats = action.statistics().splats;
    result.frameSeconds = median(frameTimes);
    for (std::size_t phase = 0; phase < sg::kRenderPhaseCount; ++phase) {
        result.phaseSeconds[phase] = median(phaseTimes[phase]);
    }
    result.ceilingSeconds = median(ceilingTimes);
    result.frameRatio = median(frameRatios);
    result.drawRatio = median(drawRatios);
    if (drawn.size() != result.splats) {
        log(LogLevel::Warning, stage + ": the fill-rate ceiling draws " +
                                   std::to_string(drawn.size()) + " quads, the method " +
                                   std::to_string(result.splats) + " splats");
    }
    result.ceilingFragments = ceiling.fragments(view, extent);
    std::optional<image::Image> image;
    result.fragments = detail::countSamplesPassed(
        [&] { image = renderer.draw(action.collect(root), action.statistics()); });
    return std::move(*image);
}
#endif

image::Image BenchRunner::measureCpu(sg::Node& root, const glm::ivec2& size,
                                     const std::string& stage, BenchResult& result,
                                     const BeforeFrame& beforeFrame) const {
    render::FrameAction action(size.x, size.y);
    const render::cpu::CpuRenderer renderer(mOptions.cpuThreads);
    const int frames = mOptions.warmup + mOptions.repeat;
    std::optional<image::Image> image;
    std::vector<double> frameTimes;
    std::vector<std::vector<double>> phaseTimes(sg::kRenderPhaseCount);
    for (int i = 0; i < frames; ++i) {
        report(stage, static_cast<double>(i) / frames);
        if (beforeFrame) {
            beforeFrame(i);
        }
        const Clock::time_point start = Clock::now();
        image = renderer.draw(action.collect(root), action.statistics());
        if (i < mOptions.warmup) {
            continue;
        }
        frameTimes.push_back(secondsSince(start));
        for (std::size_t phase = 0; phase < sg::kRenderPhaseCount; ++phase) {
            phaseTimes[phase].push_back(action.statistics().seconds[phase]);
        }
    }
    result.splats = action.statistics().splats;
    result.frameSeconds = median(frameTimes);
    for (std::size_t phase = 0; phase < sg::kRenderPhaseCount; ++phase) {
        result.phaseSeconds[phase] = median(phaseTimes[phase]);
    }
    return std::move(*image);
}

// Per backend, every image against that backend's full-quality image and every frame time
// against its frame time; every frame time against the same method's on GL.
void BenchRunner::compareWithinRun(const std::vector<image::Image>& images,
                                   std::vector<BenchResult>& results, std::size_t first) const {
    const std::size_t count = images.size();
    for (std::size_t i = 0; i < count; ++i) {
        BenchResult& result = results[first + i];
        for (std::size_t j = 0; j < count; ++j) {
            const BenchResult& other = results[first + j];
            if (other.backend == result.backend && other.isFullQuality) {
                if (!result.isShaded) { // a shaded image shows other colours
                    compare(images[j], images[i], result.fullRmse, result.fullPsnr);
                }
                result.fullFrameRatio = result.frameSeconds / other.frameSeconds;
            }
            if (other.method == result.method && other.backend == backendName(render::Backend::Gl)) {
                result.glFrameRatio = result.frameSeconds / other.frameSeconds;
            }
        }
    }
}

} // namespace texsplat::bench
