#include "scenegraph/actions/RayCastAction.h"

#include "scenegraph/Log.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>

namespace texsplat::sg {
namespace {

// Below this transmittance the rest of a ray cannot change a pixel by more than 1e-9 of what
// the medium behind could emit, so the ray stops (early ray termination).
constexpr double kOpaqueTransmittance = 1e-9;

// Largest image side: keeps width * height * 4 floats addressable and the pixel loops in int.
constexpr int kMaxImageSide = 1 << 15;

// φ(x) = (1 − e^(−x)) / x for x ≥ 0, with φ(0) = 1: expm1 has no cancellation for small x,
// and for x ≫ 1 it is 1/x, so c·Δs·φ(τΔs) = c/τ without forming 0·∞.
double phi(double x) {
    if (x < 1e-300) {
        return 1.0;
    }
    return -std::expm1(-x) / x;
}

// Finite float of a value that can only be non-negative: +inf (a sum past the float range)
// saturates, NaN (never expected) becomes 0 so that no pixel is ever NaN.
float saturate(double value) {
    if (!(value >= 0.0)) {
        return value < 0.0 ? static_cast<float>(std::max(value, -static_cast<double>(
                                                                std::numeric_limits<float>::max())))
                           : 0.0f;
    }
    constexpr double kLargest = std::numeric_limits<float>::max();
    return static_cast<float>(std::min(value, kLargest));
}

} // namespace

RayCastSurface::~RayCastSurface() = default;
RayCastMedium::~RayCastMedium() = default;

RayCastAction::RayCastAction(int width, int height)
    : Action(methods()), mWidth(width), mHeight(height) {
    if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide) {
        throw DataError("RayCastAction: image size " + std::to_string(width) + " x " +
                        std::to_string(height) + " must be positive and at most " +
                        std::to_string(kMaxImageSide) + " per side");
    }
    mColor.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0.0f);
}

RayCastAction::~RayCastAction() = default;

MethodTable& RayCastAction::methods() {
    static MethodTable table;
    return table;
}

void RayCastAction::setStepSize(float voxels) {
    if (!std::isfinite(voxels) || !(voxels > 0.0f)) {
        throw DataError("RayCastAction: step size must be finite and > 0 voxels, got " +
                        std::to_string(voxels));
    }
    mStepSize = voxels;
}

void RayCastAction::setThreadCount(int threads) {
    if (threads < 0) {
        throw DataError("RayCastAction: thread count must be >= 0, got " + std::to_string(threads));
    }
    mThreadCount = threads;
}

void RayCastAction::setCamera(const glm::mat4& view, const glm::mat4& projection) {
    // In double: a perspective projection with a small near distance loses most float digits
    // when inverted.
    mInverseViewProjection = glm::inverse(glm::dmat4(projection) * glm::dmat4(view));
    mHasCamera = true;
}

void RayCastAction::addSurface(std::shared_ptr<const RayCastSurface> surface) {
    if (surface) {
        mSurfaces.push_back(std::move(surface));
    }
}

void RayCastAction::addMedium(std::shared_ptr<const RayCastMedium> medium) {
    if (medium) {
        mMedia.push_back(std::move(medium));
    }
}

void RayCastAction::beginTraversal(Node& /*root*/) {
    mSurfaces.clear();
    mMedia.clear();
    mHasCamera = false;
    mInverseViewProjection = glm::dmat4(1.0);
}

RayCastRay RayCastAction::pixelRay(int x, int y, float& tMin, float& tMax) const {
    // Pixel centres in normalized device coordinates, y up: row 0 is the top row.
    const double ndcX = (static_cast<double>(x) + 0.5) / mWidth * 2.0 - 1.0;
    const double ndcY = 1.0 - (static_cast<double>(y) + 0.5) / mHeight * 2.0;
    const glm::dvec4 nearPoint = mInverseViewProjection * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
    const glm::dvec4 farPoint = mInverseViewProjection * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
    const glm::dvec3 from = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 to = glm::dvec3(farPoint) / farPoint.w;
    const double length = glm::length(to - from);
    RayCastRay ray;
    ray.origin = glm::vec3(from);
    tMin = 0.0f;
    if (!(length > 0.0) || !std::isfinite(length)) {
        tMax = 0.0f;
        return ray;
    }
    ray.direction = glm::vec3((to - from) / length);
    tMax = static_cast<float>(length);
    return ray;
}

glm::vec4 RayCastAction::tracePixel(int x, int y, Scratch& scratch) const {
    float tMin = 0.0f;
    float tMax = 0.0f;
    const RayCastRay ray = pixelRay(x, y, tMin, tMax);
    if (!(tMax > tMin)) {
        return mBackground;
    }
    // The nearest opaque hit ends the ray; its shaded color lies behind the media in front.
    float tEnd = tMax;
    glm::vec4 behind = mBackground;
    for (const auto& surface : mSurfaces) {
        float t = tEnd;
        glm::vec4 color(0.0f);
        if (surface->intersect(ray, tMin, tEnd, t, color)) {
            tEnd = t;
            behind = color;
        }
    }

    // Each medium's non-empty stretches; then the union is walked piece by piece between the
    // breakpoints of all of them: within a piece the set of media is fixed, their c and τ add
    // up, and the step is the smallest of theirs.
    scratch.intervals.clear();
    scratch.owners.clear();
    for (std::size_t m = 0; m < mMedia.size(); ++m) {
        mMedia[m]->intervals(ray, tMin, tEnd, mStepSize, scratch.intervals);
        scratch.owners.resize(scratch.intervals.size(), m);
    }
    scratch.cuts.clear();
    for (RayCastMedium::Interval& interval : scratch.intervals) {
        interval.t0 = std::max(interval.t0, tMin);
        interval.t1 = std::min(interval.t1, tEnd);
        if (interval.t1 > interval.t0 && interval.step > 0.0f) {
            scratch.cuts.push_back(interval.t0);
            scratch.cuts.push_back(interval.t1);
        }
    }
    std::sort(scratch.cuts.begin(), scratch.cuts.end());
    scratch.cuts.erase(std::unique(scratch.cuts.begin(), scratch.cuts.end()), scratch.cuts.end());

    double transmittance = 1.0;
    glm::dvec3 color(0.0);
    for (std::size_t c = 0; c + 1 < scratch.cuts.size() && transmittance > kOpaqueTransmittance;
         ++c) {
        const double a = scratch.cuts[c];
        const double b = scratch.cuts[c + 1];
        double step = std::numeric_limits<double>::infinity();
        scratch.active.clear();
        for (std::size_t i = 0; i < scratch.intervals.size(); ++i) {
            const RayCastMedium::Interval& interval = scratch.intervals[i];
            if (interval.t1 > interval.t0 && interval.step > 0.0f && interval.t0 <= a &&
                interval.t1 >= b) {
                step = std::min(step, static_cast<double>(interval.step));
                scratch.active.push_back(mMedia[scratch.owners[i]].get());
            }
        }
        if (scratch.active.empty()) {
            continue; // a gap between the stretches: empty space
        }
        // Equal steps ending exactly at b, as many as the step asks for: a piece can be long (a
        // run of active bricks, up to the grid's diagonal). The one limit: a step is not shorter
        // than FLT_EPSILON·t at the piece's far end (one to two spacings of floats there), since
        // sample() takes t as a float and a shorter step would only revisit the same positions.
        // That also bounds the count by 1 / FLT_EPSILON = 2^23 per piece (t >= 0), so no step
        // size can overflow it; when the limit applies, render() logs one warning.
        const double finest =
            std::max(std::abs(a), std::abs(b)) * std::numeric_limits<float>::epsilon();
        const double most = std::max(1.0, std::floor((b - a) / finest));
        double count = std::max(1.0, std::ceil((b - a) / step));
        if (count > most) {
            count = most;
            scratch.stepLengthened = true;
        }
        const auto steps = static_cast<std::int64_t>(count);
        const double ds = (b - a) / count;
        for (std::int64_t s = 0; s < steps; ++s) {
            const double t = a + (static_cast<double>(s) + 0.5) * ds;
            glm::dvec4 medium(0.0);
            for (const RayCastMedium* active : scratch.active) {
                medium += glm::dvec4(active->sample(ray, static_cast<float>(t)));
            }
            // The exact step for constant c and τ over ds:
            // I += T·c·ds·φ(τ·ds), T *= e^(−τ·ds).
            const double depth = medium.a * ds;
            color += (transmittance * ds * phi(depth)) * glm::dvec3(medium);
            transmittance *= std::exp(-depth);
            if (transmittance <= kOpaqueTransmittance) {
                break;
            }
        }
    }
    if (transmittance <= kOpaqueTransmittance) {
        transmittance = 0.0;
    }
    return glm::vec4(saturate(color.r + transmittance * behind.r),
                     saturate(color.g + transmittance * behind.g),
                     saturate(color.b + transmittance * behind.b),
                     std::clamp(saturate(1.0 - transmittance + transmittance * behind.a), 0.0f,
                                1.0f));
}

double RayCastAction::estimatedSamples(float stepVoxels) const {
    if (!mHasCamera || mMedia.empty()) {
        return 0.0;
    }
    const int columns = std::min(mWidth, 32);
    const int rows = std::min(mHeight, 32);
    std::vector<RayCastMedium::Interval> intervals;
    double samples = 0.0;
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            float tMin = 0.0f;
            float tMax = 0.0f;
            const RayCastRay ray = pixelRay(column * mWidth / columns, row * mHeight / rows,
                                            tMin, tMax);
            if (!(tMax > tMin)) {
                continue;
            }
            intervals.clear();
            for (const auto& medium : mMedia) {
                medium->intervals(ray, tMin, tMax, stepVoxels, intervals);
            }
            // As tracePixel() counts a piece's steps, at most one per float spacing of t.
            for (const RayCastMedium::Interval& interval : intervals) {
                const double a = std::max(interval.t0, tMin);
                const double b = std::min(interval.t1, tMax);
                if (!(b > a) || !(interval.step > 0.0f)) {
                    continue;
                }
                const double finest =
                    std::max(std::abs(a), std::abs(b)) * std::numeric_limits<float>::epsilon();
                samples += std::min(std::max(1.0, std::floor((b - a) / finest)),
                                    std::max(1.0, std::ceil((b - a) / interval.step)));
            }
        }
    }
    return samples / (static_cast<double>(columns) * rows) * mWidth * mHeight;
}

void RayCastAction::render(Node& root) {
    apply(root);
    const double samples = estimatedSamples(mStepSize);
    if (samples > kSamplesToWarn) {
        std::ostringstream message;
        message << "RayCastAction: about " << std::setprecision(2) << samples
                << " samples to integrate (" << mWidth << " x " << mHeight
                << " pixels at a step of " << mStepSize << " voxels; the default step of "
                << kDefaultStepSize << " takes about " << estimatedSamples(kDefaultStepSize)
                << "): this may take hours";
        log(LogLevel::Warning, message.str());
    }
    std::fill(mColor.begin(), mColor.end(), 0.0f);
    if (!mHasCamera) {
        for (std::size_t i = 0; i < mColor.size(); i += 4) {
            for (std::size_t c = 0; c < 4; ++c) {
                mColor[i + c] = mBackground[static_cast<glm::length_t>(c)];
            }
        }
        mSurfaces.clear();
        mMedia.clear();
        if (mProgress && !mProgress(1.0)) {
            throw RenderCancelled("RayCastAction::render(): cancelled by the progress callback");
        }
        return;
    }
    integrateRows();
}

void RayCastAction::integrateRows() {
    unsigned threadCount = mThreadCount > 0 ? static_cast<unsigned>(mThreadCount)
                                            : std::max(1u, std::thread::hardware_concurrency());
    threadCount = std::min(threadCount, static_cast<unsigned>(mHeight));

    std::atomic<int> nextRow{0};
    std::atomic<int> rowsDone{0};
    std::atomic<bool> cancelled{false};
    std::atomic<bool> stepLengthened{false};
    std::mutex mutex;
    std::condition_variable finished;
    unsigned running = threadCount;

    auto work = [&] {
        Scratch scratch;
        for (int y = nextRow.fetch_add(1);
             y < mHeight && !cancelled.load(std::memory_order_relaxed);
             y = nextRow.fetch_add(1)) {
            float* row = mColor.data() + static_cast<std::size_t>(y) * mWidth * 4;
            for (int x = 0; x < mWidth; ++x) {
                const glm::vec4 color = tracePixel(x, y, scratch);
                row[4 * x + 0] = color.r;
                row[4 * x + 1] = color.g;
                row[4 * x + 2] = color.b;
                row[4 * x + 3] = color.a;
            }
            rowsDone.fetch_add(1, std::memory_order_relaxed);
        }
        if (scratch.stepLengthened) {
            stepLengthened.store(true, std::memory_order_relaxed);
        }
        const std::lock_guard<std::mutex> lock(mutex);
        --running;
        finished.notify_all();
    };

    // Stops and joins the workers however this function is left (a failed thread start, a
    // progress callback that throws), so that no std::thread is destroyed while joinable.
    struct Workers {
        std::vector<std::thread> threads;
        std::atomic<bool>& cancelled;
        ~Workers() {
            cancelled = true;
            for (std::thread& thread : threads) {
                if (thread.joinable()) {
                    thread.join();
                }
            }
        }
    } workers{{}, cancelled};
    workers.threads.reserve(threadCount);
    for (unsigned i = 0; i < threadCount; ++i) {
        try {
            workers.threads.emplace_back(work);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(mutex);
            running -= threadCount - static_cast<unsigned>(workers.threads.size());
            throw;
        }
    }

    // This thread reports progress while the workers integrate.
    bool wasCancelled = false;
    double lastReported = -1.0;
    {
        std::unique_lock<std::mutex> lock(mutex);
        while (running > 0) {
            finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return running == 0; });
            if (running == 0 || !mProgress || wasCancelled) {
                continue;
            }
            const double fraction = static_cast<double>(rowsDone.load()) / mHeight;
            if (fraction > lastReported) {
                lastReported = fraction;
                lock.unlock();
                const bool goOn = mProgress(fraction);
                lock.lock();
                if (!goOn) {
                    cancelled = true;
                    wasCancelled = true;
                }
            }
        }
    }
    for (std::thread& thread : workers.threads) {
        thread.join();
    }
    mSurfaces.clear();
    mMedia.clear();
    if (!wasCancelled && mProgress && !mProgress(1.0)) {
        wasCancelled = true;
    }
    if (wasCancelled) {
        std::fill(mColor.begin(), mColor.end(), 0.0f);
        throw RenderCancelled("RayCastAction::render(): cancelled by the progress callback after " +
                              std::to_string(rowsDone.load()) + " of " + std::to_string(mHeight) +
                              " rows");
    }
    // Once per render, not per ray: the workers only raise a flag (joined above).
    if (stepLengthened.load()) {
        std::ostringstream message;
        message << "RayCastAction: the step of " << mStepSize
                << " voxels is finer than float positions along some rays can resolve; there it "
                   "was lengthened to the float spacing (about 1.2e-7 of the distance from the "
                   "near plane)";
        log(LogLevel::Warning, message.str());
    }
}

std::vector<float> RayCastAction::readColor() const { return mColor; }

} // namespace texsplat::sg
