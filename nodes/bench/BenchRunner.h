#pragma once

#include "nodes/bench/BenchDataset.h"
#include "nodes/bench/BenchMethod.h"
#include "nodes/bench/BenchResult.h"
#include "nodes/image/Image.h"
#include "nodes/render/BackendChoice.h"
#include "nodes/render/SplatView.h"
#include "octree/Fwd.h"
#include "scenegraph/Fwd.h"

#include <glm/vec2.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace texsplat::bench {

class FillRateCeiling;

/// @brief What BenchRunner measures and how often.
struct BenchOptions {
    std::vector<BenchDataset> datasets; ///< volumes to draw
    std::vector<glm::ivec2> sizes;      ///< image sizes (width, height)
    std::vector<BenchMethod> methods;   ///< drawing methods, measured in this order
    int warmup = 1;  ///< untimed frames first (the first classifies and builds the octree), >= 1
    int repeat = 5;  ///< timed frames; the median is reported, >= 1
    bool reference = true;  ///< ray cast the reference image (RayCastAction) per dataset and size
    int threads = 0;        ///< RayCastAction threads (0: all cores)
    /// @brief Backends measured, each method on each in this order; GL needs a current context.
    std::vector<render::Backend> backends{render::Backend::Gl};
    int cpuThreads = 0; ///< CPU backend threads (0: all cores)
    /// @brief The datasets' camera (a SCENE keeps its own or is framed by the caller).
    render::FramingCamera camera = render::FramingCamera::Perspective;
};

/// @brief Runs `texsplat bench`: for every dataset and image size, renders the RayCastAction
/// reference once, then each method on each backend: warm-up, then `repeat` timed frames. On
/// GL each frame is followed by one timed draw of the fill-rate ceiling (FillRateCeiling) of
/// the same splat list, so that load from other processes hits both alike, then one more frame
/// is counted with a GL_SAMPLES_PASSED query. Every image is compared with the reference and
/// with the full-quality texture-splat image of its backend; every frame time with the same
/// method's on GL.
///
/// Needs a current GL context for run() when the backends include GL; registers the node types
/// itself.
class BenchRunner {
public:
    /// @brief Called with what is being done ("ml128 512x512: reference") and the fraction of
    /// it done, in [0, 1]; the application shows it (the library does not print).
    using Progress = std::function<void(const std::string& stage, double fractionDone)>;

    /// @brief A runner for `options`.
    /// @throws DataError when a list is empty or warmup / repeat is below 1.
    explicit BenchRunner(BenchOptions options);

    /// @brief Sets the progress callback.
    void setProgress(Progress progress) { mProgress = std::move(progress); }

    /// @brief Measures a user's scene (`texsplat bench SCENE.iv`) instead of the datasets and
    /// methods: for every image size, the ray-cast reference once (when `reference`), then the
    /// scene at each of @p budgets, on the CPU backend. A budget is a fraction in (0, 1] of the
    /// splats each splat node draws at full resolution, set as its `maxSplats` (1: full
    /// resolution, the full-quality row every other is compared with); the nodes' error
    /// thresholds are set to 0, so the budget alone chooses the cut. Results are named
    /// `scene` and `scene@FRACTION`, in the order size, budget; the dataset is @p name.
    /// @throws DataError for a budget outside (0, 1] or a scene without splat nodes; Error when
    /// the backends include GL (not measured for scenes yet).
    std::vector<BenchResult> runScene(sg::Node& root, const std::string& name,
                                      const std::vector<double>& budgets);

    /// @brief Measures everything; results are in the order dataset, size, method.
    /// @throws GlError when no context is current or GL fails; what loading or rendering
    /// throws (DataError, sg::RenderCancelled never: the progress callback cannot cancel).
    std::vector<BenchResult> run();

private:
    void runOne(const BenchDataset& dataset, const glm::ivec2& size,
                std::vector<BenchResult>& results);
    void report(const std::string& stage, double fractionDone) const;
    std::optional<image::Image> referenceImage(sg::Node& root, const glm::ivec2& size,
                                               const std::string& where) const;
    // Called before each frame a measurement draws, with the frame's number.
    using BeforeFrame = std::function<void(int frame)>;
#ifdef TEXSPLAT_WITH_GL
    image::Image measureGl(sg::Node& root, const glm::ivec2& size, FillRateCeiling& ceiling,
                           const render::SplatView& view, float extent,
                           const octree::SplatList& drawn, const std::string& stage,
                           BenchResult& result, const BeforeFrame& beforeFrame = {}) const;
#endif
    image::Image measureCpu(sg::Node& root, const glm::ivec2& size, const std::string& stage,
                            BenchResult& result, const BeforeFrame& beforeFrame = {}) const;
    void compareWithinRun(const std::vector<image::Image>& images,
                          std::vector<BenchResult>& results, std::size_t first) const;

    BenchOptions mOptions;
    Progress mProgress;
};

} // namespace texsplat::bench
