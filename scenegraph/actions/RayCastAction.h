#pragma once

#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace texsplat::sg {

/// @brief What RayCastAction::render() throws when its progress callback answered false.
class RenderCancelled : public Error {
public:
    using Error::Error;
};

/// @brief One ray of RayCastAction in the traversal root's space: `origin + t * direction`,
/// `direction` of unit length, so `t` is a root-space distance.
struct RayCastRay {
    glm::vec3 origin{0.0f};    ///< where the ray starts (the eye, or the near plane)
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; ///< unit direction
};

/// @brief An opaque surface queued by a node for RayCastAction: rays stop at its first hit.
/// Implementations must be safe to call from several threads at once (const, no shared
/// mutable state).
class RayCastSurface {
public:
    virtual ~RayCastSurface();

    /// @brief The nearest hit with `tMin < t < tMax`: returns true, sets `t` and the shaded,
    /// opaque premultiplied color; false when the ray misses within the range.
    virtual bool intersect(const RayCastRay& ray, float tMin, float tMax, float& t,
                           glm::vec4& color) const = 0;
};

/// @brief A participating medium queued by a node for RayCastAction: emission c(x) and
/// extinction τ(x) along a ray. Implementations must be safe to call from several threads.
class RayCastMedium {
public:
    /// @brief A stretch `[t0, t1]` of a ray where the medium may be non-zero, with the
    /// integration step (root-space length) to use there.
    struct Interval {
        float t0 = 0.0f;
        float t1 = 0.0f;
        float step = 1.0f;
    };

    /// @brief Emission (xyz, premultiplied color per unit root-space length) and extinction
    /// (w, per unit root-space length), both finite and non-negative.
    using Sample = glm::vec4;

    virtual ~RayCastMedium();

    /// @brief Appends to `out`, in increasing `t`, disjoint intervals of `[tMin, tMax]` outside
    /// of which the medium is zero along `ray` (empty-space skipping), each with its step for
    /// `stepVoxels` steps per voxel.
    virtual void intervals(const RayCastRay& ray, float tMin, float tMax, float stepVoxels,
                           std::vector<Interval>& out) const = 0;

    /// @brief c and τ at `ray.origin + t * ray.direction`.
    virtual Sample sample(const RayCastRay& ray, float t) const = 0;
};

/// @brief The CPU reference renderer (docs/design.md, "The model"): for every pixel, integrates
/// emission–absorption exactly through the reconstructed fields of the volumes the splat nodes
/// draw, up to the first opaque surface.
///
/// Like the nodes library's FrameAction, the traversal only *collects* work: node methods
/// registered in `methods()` (by the nodes library) queue RayCastSurface and RayCastMedium objects in the
/// traversal root's space and set the camera. `render()` then traces one ray through each
/// pixel centre, on several threads (rows interleaved), so pixel (i, j) sees the same ray as
/// the backends' pixel (i, j) for the same camera and size.
///
/// Integration (docs/raycast.md): along a ray, the media's intervals are walked in steps Δs;
/// at the midpoint of each step c and τ (summed over overlapping media) are taken constant and
/// the step is exact: I ← I + T·c·Δs·φ(τΔs), T ← T·e^(−τΔs) with
/// φ(x) = (1 − e^(−x))/x = −expm1(−x)/x (→ 1 as x → 0, no cancellation). Colors are
/// premultiplied; the background is composited under the result.
class RayCastAction : public Action {
public:
    /// @brief An action rendering `width` x `height` pixels.
    /// @throws DataError "RayCastAction: image size W x H is not positive" (or too large).
    RayCastAction(int width, int height);
    ~RayCastAction() override;

    /// @brief The table of this action; the nodes library adds its nodes' rayCast methods
    /// (`nodes::registerNodeTypes()`). Unregistered nodes use `Node::doAction()`.
    static MethodTable& methods();

    /// @brief Premultiplied color behind everything; default transparent black.
    void setBackground(const glm::vec4& premultipliedColor) { mBackground = premultipliedColor; }

    /// @brief The background color.
    const glm::vec4& background() const { return mBackground; }

    /// @brief Integration step in voxels of each volume, along the ray (default
    /// kDefaultStepSize: RMSE about 1e-5 of the converged image, docs/raycast.md). Any step is
    /// taken as given, except one finer than float positions along a ray can resolve (about
    /// 1.2e-7 of the distance from the near plane), which is lengthened to that with one
    /// warning per render().
    /// @throws DataError when `voxels` is not finite and positive.
    void setStepSize(float voxels);

    /// @brief The integration step in voxels.
    float stepSize() const { return mStepSize; }

    /// @brief Worker threads for render(); 0 (default) = std::thread::hardware_concurrency().
    /// @throws DataError when negative.
    void setThreadCount(int threads);

    /// @brief Called from the thread that called render() with the fraction of rows done, in
    /// [0, 1], at most every 50 ms while the workers integrate and with 1 at the end; returning
    /// false cancels: the workers stop after their current row and render() throws
    /// RenderCancelled (the image is then all zero). What the callback throws is rethrown
    /// after the workers stopped.
    void setProgress(std::function<bool(double fractionDone)> callback) {
        mProgress = std::move(callback);
    }

    /// @brief Traverses `root` to collect work, then integrates every pixel.
    /// @throws RenderCancelled when the progress callback returned false; what the nodes
    /// throw while traversing (e.g. DataError for a missing camera).
    void render(Node& root);

    /// @brief About how many samples integrating the work queued by the last traversal
    /// (apply()) takes at a step of `stepVoxels`: the mean over the rays of at most 32 x 32
    /// pixels spread over the image, times the pixel count. Surfaces and overlaps are not
    /// subtracted, so it errs high. render() logs a warning with it above kSamplesToWarn.
    double estimatedSamples(float stepVoxels) const;

    /// @brief Samples above which render() warns before it integrates (about a minute's work
    /// and more: the default step on a 128³ volume at 512² takes about 10⁸).
    static constexpr double kSamplesToWarn = 1e10;

    /// @brief Premultiplied float RGBA of the last render, width*height*4, top row first.
    std::vector<float> readColor() const;

    /// @brief Image width in pixels.
    int width() const { return mWidth; }

    /// @brief Image height in pixels.
    int height() const { return mHeight; }

    /// @brief Width over height, what cameras need for their projection.
    float aspectRatio() const { return static_cast<float>(mWidth) / static_cast<float>(mHeight); }

    /// @brief Sets the camera (root space to camera space, camera space to clip space); node
    /// methods call it when they queue work. The last call of a traversal wins.
    void setCamera(const glm::mat4& view, const glm::mat4& projection);

    /// @brief Queues an opaque surface (during traversal).
    void addSurface(std::shared_ptr<const RayCastSurface> surface);

    /// @brief Queues a medium (during traversal).
    void addMedium(std::shared_ptr<const RayCastMedium> medium);

    /// @brief The ray through the centre of pixel (`x`, `y`), `y` counted from the top row,
    /// for the current camera, with the range `[tMin, tMax]` inside the view frustum.
    RayCastRay pixelRay(int x, int y, float& tMin, float& tMax) const;

    /// @brief Default integration step in voxels.
    static constexpr float kDefaultStepSize = 0.25f;

protected:
    /// @brief Empties the work lists and the camera.
    void beginTraversal(Node& root) override;

private:
    // Per-thread buffers of tracePixel(), kept across pixels.
    struct Scratch {
        std::vector<RayCastMedium::Interval> intervals;
        std::vector<std::size_t> owners;
        std::vector<float> cuts;
        std::vector<const RayCastMedium*> active;
        bool stepLengthened = false; // a step was limited to the float resolution of t
    };

    glm::vec4 tracePixel(int x, int y, Scratch& scratch) const;
    void integrateRows();

    int mWidth;
    int mHeight;
    glm::vec4 mBackground{0.0f};
    float mStepSize = kDefaultStepSize;
    int mThreadCount = 0;
    std::function<bool(double)> mProgress;
    bool mHasCamera = false;
    glm::dmat4 mInverseViewProjection{1.0};
    std::vector<std::shared_ptr<const RayCastSurface>> mSurfaces;
    std::vector<std::shared_ptr<const RayCastMedium>> mMedia;
    std::vector<float> mColor;
};

} // namespace texsplat::sg
