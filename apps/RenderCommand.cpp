#include "apps/Commands.h"
#include "apps/DataFileOptions.h"
#include "apps/ImageAnnotations.h"
#include "apps/MemoryLimitOption.h"
#include "apps/SceneSetup.h"
#include "apps/ThreadLimit.h"
#include "apps/WorkProgressPrinter.h"

#include "nodes/image/ImageIo.h"
#include "nodes/render/BackendChoice.h"
#include "nodes/render/RayCastImage.h"
#include "nodes/render/SceneRenderer.h"
#include "octree/Splat.h"
#include "scenegraph/AtomicFile.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/actions/RayCastAction.h"
#include "scenegraph/actions/Seconds.h"
#include "scenegraph/engines/SceneTime.h"

#ifdef TEXSPLAT_WITH_MPI
#include "apps/MpiSession.h"
#include "nodes/distributed/LargestOnRanks.h"
#include "nodes/distributed/RankAgreement.h"
#include "nodes/distributed/SceneRenderer.h"
#endif

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

namespace texsplat::apps {
namespace {

using Clock = sg::TimingClock;
using sg::secondsSince;

constexpr int kMaxFrames = 1000000;
constexpr int kMaxThreads = 1024;
// What to do when reading the volumes runs out of memory.
constexpr const char* kReadAdvice = "use a volume of lower resolution";
// What to do when drawing a frame runs out of memory.
constexpr const char* kRenderAdvice =
    "use a smaller --size, a splat budget (--max-splats), or --backend cpu";

struct RenderArguments {
    std::string scene;
    std::string output;
    std::string size = "512x512";
    Framing framing;
    std::string frames = "1";
    std::string fps = "24";
    bool timeReport = false;
    bool rayCast = false;
    float rayCastStep = sg::RayCastAction::kDefaultStepSize;
    std::string backend = "auto";
    int threads = 0;
    std::string background = "black";
    AnnotationOptions annotations;
    std::string memoryLimit;
    BudgetOverride budget;
    HeaderlessOptions headerless;
    std::vector<std::string> dataRoots;
    std::string compositing = "radix-k";
};

// The output name of each frame. A name with one printf-style integer conversion is a pattern:
// `%d`, `%i` or `%u`, optionally with the flags `0` (pad with zeros) or `-` (pad on the right)
// and a width of one or two digits (`%04d`); `%%` stands for a '%'. Nothing else may follow a
// '%': the name is checked here, never handed to printf.
class OutputPattern {
public:
    // Throws DataError when `frames` > 1 and `output` is not such a pattern. With a single
    // frame, a name that is not a pattern is used as it is (as before --frames existed).
    static OutputPattern parse(const std::string& output, int frames) {
        OutputPattern pattern;
        pattern.mOutput = output;
        int conversions = 0;
        std::optional<std::string> unsupported;
        for (std::size_t i = 0; i < output.size() && !unsupported; ++i) {
            std::string& text = conversions == 0 ? pattern.mPrefix : pattern.mSuffix;
            if (output[i] != '%') {
                text += output[i];
                continue;
            }
            if (i + 1 < output.size() && output[i + 1] == '%') {
                text += '%';
                ++i;
                continue;
            }
            std::size_t end = i + 1;
            bool leftAligned = false;
            bool zeroPadded = false;
            for (; end < output.size() && (output[end] == '0' || output[end] == '-'); ++end) {
                (output[end] == '-' ? leftAligned : zeroPadded) = true;
            }
            const std::size_t widthStart = end;
            while (end < output.size() && output[end] >= '0' && output[end] <= '9') {
                ++end;
            }
            const std::size_t widthDigits = end - widthStart;
            if (end == output.size() || widthDigits > 2 ||
                std::string("diu").find(output[end]) == std::string::npos) {
                unsupported = conversionAt(output, i);
                break;
            }
            if (++conversions == 1) {
                pattern.mWidth =
                    widthDigits == 0 ? 0 : std::stoul(output.substr(widthStart, widthDigits));
                pattern.mFill = zeroPadded && !leftAligned ? '0' : ' ';
                pattern.mLeftAligned = leftAligned;
            }
            i = end;
        }
        pattern.mIsPattern = !unsupported && conversions == 1;
        if (frames > 1) {
            if (unsupported) {
                throw DataError("--output: '" + *unsupported + "' in '" + output +
                                "' is not a frame number; use %d, %04d (4 digits, zero-padded) "
                                "or %% for a '%'");
            }
            if (conversions > 1) {
                throw DataError("--output: '" + output + "' has " + std::to_string(conversions) +
                                " %d-style numbers; a frame name needs exactly one");
            }
            if (conversions == 0) {
                throw DataError("--frames " + std::to_string(frames) +
                                " needs an output name with one %d-style frame number (e.g. "
                                "out%04d.png), got '" +
                                output + "'");
            }
        }
        return pattern;
    }

    // The file of frame `frame` (>= 0).
    std::string name(int frame) const {
        if (!mIsPattern) {
            return mOutput;
        }
        const std::string digits = std::to_string(frame);
        const std::string padding(std::max<std::size_t>(mWidth, digits.size()) - digits.size(),
                                  mFill);
        return mPrefix + (mLeftAligned ? digits + padding : padding + digits) + mSuffix;
    }

private:
    // The printf conversion that starts at output[percent], for messages: up to its conversion
    // letter (`%s`, `%.3d`, `%ld`) or the end.
    static std::string conversionAt(const std::string& output, std::size_t percent) {
        const auto isLengthModifier = [](char c) {
            return std::string("hlLqjzt").find(c) != std::string::npos;
        };
        std::size_t end = percent + 1;
        while (end < output.size() &&
               (!std::isalpha(static_cast<unsigned char>(output[end])) ||
                isLengthModifier(output[end]))) {
            ++end;
        }
        return output.substr(percent, std::min(end + 1, output.size()) - percent);
    }

    std::string mOutput;
    bool mIsPattern = false;
    std::string mPrefix; // before the conversion, %% turned into %
    std::string mSuffix; // after it, likewise
    std::size_t mWidth = 0;
    char mFill = ' ';
    bool mLeftAligned = false;
};

// --frames and --fps: which frames to render, at which scene times, into which files.
struct Animation {
    int frames = 1;
    double fps = 24.0;
    OutputPattern output;

    // Frame k shows the scene at k / fps seconds: SimulatedClock::setTime(k / fps) is the time a
    // TimerSensor computes for its k-th trigger, so no error accumulates over a long movie.
    double time(int frame) const { return static_cast<double>(frame) / fps; }

    // "frame 3/10 (t = 0.0833 s): out0002.png", as the progress line and errors name a frame.
    std::string describe(int frame) const {
        char text[64];
        std::snprintf(text, sizeof text, "frame %d/%d (t = %.6g s): ", frame + 1, frames,
                      time(frame));
        return text + output.name(frame);
    }

    // Runs frame `frame`'s work; for an animation an error it throws names the frame first, so
    // that a failure in frame 700 of 1000 says which.
    template <class Work> void inFrame(int frame, Work&& work) const {
        if (frames == 1) {
            work();
            return;
        }
        try {
            work();
        } catch (const Error& error) {
            throw Error(describe(frame) + ": " + error.what());
        }
    }
};

int parseFrames(const std::string& text) {
    const bool isWhole = !text.empty() && text.size() <= 7 &&
                         std::all_of(text.begin(), text.end(),
                                     [](char c) { return c >= '0' && c <= '9'; });
    const int frames = isWhole ? std::stoi(text) : 0;
    if (frames < 1 || frames > kMaxFrames) {
        throw DataError("--frames: expected a whole number from 1 to " +
                        std::to_string(kMaxFrames) + ", got '" + text + "'");
    }
    return frames;
}

double parseFramesPerSecond(const std::string& text) {
    double fps = 0.0;
    const char* end = text.data() + text.size();
    const auto [parsed, error] = std::from_chars(text.data(), end, fps);
    if (text.empty() || error != std::errc() || parsed != end || !std::isfinite(fps) ||
        fps <= 0.0) {
        throw DataError("--fps: expected a finite number of frames per second > 0, got '" +
                        text + "'");
    }
    return fps;
}

Animation parseAnimation(const RenderArguments& arguments) {
    Animation animation;
    animation.frames = parseFrames(arguments.frames);
    animation.fps = parseFramesPerSecond(arguments.fps);
    // The scene's time field is a float (SensorQueue::timeField()).
    const double last = animation.time(animation.frames - 1);
    if (!std::isfinite(static_cast<float>(last))) {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", last);
        throw DataError("--fps: at " + arguments.fps + " frames per second frame " +
                        std::to_string(animation.frames - 1) + " would be at " + seconds +
                        " s, beyond the scene's time (a float)");
    }
    animation.output = OutputPattern::parse(arguments.output, animation.frames);
    return animation;
}

// Runs the scene's time through the frames (sg::SceneTime): before each, the scene moves to the
// frame's time, so every engine (ElapsedTime) and every field connected to one holds its value
// for that time. The same options give the same times, hence the same images.
class FrameClock {
public:
    FrameClock(const Animation& animation, sg::Node& root) : mAnimation(animation), mTime(root) {}

    // Moves the scene to frame `frame`'s time (frames in increasing order).
    void moveTo(int frame) {
        const Clock::time_point start = Clock::now();
        mTime.setTime(mAnimation.time(frame));
        mSeconds += secondsSince(start);
    }

    // Reports frame `frame` written (a line on stderr for animations; nothing for one image).
    void reportWritten(int frame) const {
        if (mAnimation.frames > 1) {
            std::fprintf(stderr, "%s\n", mAnimation.describe(frame).c_str());
            std::fflush(stderr);
        }
    }

    // Wall seconds spent moving the clock and running the queue.
    double seconds() const { return mSeconds; }

private:
    const Animation& mAnimation;
    sg::SceneTime mTime;
    double mSeconds = 0.0;
};

// The times before rendering: reading the scene file and, for a scene without a camera, framing
// it. Framing takes the scene's bounding box, which loads (or generates) its volumes and meshes:
// that time is loading, so the reports count it as such.
struct SetupTimes {
    double readScene = 0.0;
    double frame = 0.0;
    bool framed = false; ///< whether the scene had no camera and got one
};

// A time report line of what every frame does: for an animation the total over all frames,
// then the mean per frame.
void printFrameTime(const char* name, double total, int frames, const std::string& note = "") {
    std::printf("  %-10s %9.4f", name, total);
    if (frames > 1) {
        std::printf("  %9.4f per frame", total / frames);
    }
    std::printf("%s\n", note.empty() ? "" : ("  (" + note + ")").c_str());
}

void printReportHeader(const SetupTimes& setup, const Animation& animation) {
    if (animation.frames > 1) {
        std::printf("time report (wall seconds; %d frames: totals over the frames, then the "
                    "mean per frame):\n",
                    animation.frames);
    } else {
        std::printf("time report (wall seconds):\n");
    }
    std::printf("  %-10s %9.4f  (scene file)\n", "read", setup.readScene);
}

void printAnimateTime(const FrameClock& clock, const Animation& animation) {
    if (animation.frames > 1) {
        printFrameTime("animate", clock.seconds(), animation.frames,
                       "clock and sensor queue: engines, connected fields");
    }
}

// The backend a render used, for the time report: what it is and why it was chosen.
struct BackendReport {
    std::string name;      // "GL (EGL surfaceless: 4.5 ... | llvmpipe ...)" or "CPU (AVX2, 2 threads)"
    std::string reason;    // "asked for", "auto: ..."
    double contextSeconds; // making or trying a GL context
};

void printTimes(const sg::RenderStatistics& statistics, const SetupTimes& setup,
                const BackendReport& backend, double write, const FrameClock& clock,
                const Animation& animation, std::size_t imageBytes) {
    const int frames = animation.frames;
    printReportHeader(setup, animation);
    std::printf("  backend    %s (%s)\n", backend.name.c_str(), backend.reason.c_str());
    std::printf("  %-10s %9.4f\n", "context", backend.contextSeconds);
    printAnimateTime(clock, animation);
    for (std::size_t phase = 0; phase < sg::kRenderPhaseCount; ++phase) {
        const auto name = std::string(sg::toString(static_cast<sg::RenderPhase>(phase)));
        if (static_cast<sg::RenderPhase>(phase) == sg::RenderPhase::Load && setup.framed) {
            char note[64];
            std::snprintf(note, sizeof note, "%.4f of it while framing the scene", setup.frame);
            printFrameTime(name.c_str(), statistics.seconds[phase] + setup.frame, frames, note);
        } else {
            printFrameTime(name.c_str(), statistics.seconds[phase], frames);
        }
    }
    printFrameTime("write", write, frames, "encode and rename");
    if (frames > 1) {
        std::printf("  splats %zu, triangles %zu (all frames)\n", statistics.splats,
                    statistics.triangles);
    } else {
        std::printf("  splats %zu, triangles %zu\n", statistics.splats, statistics.triangles);
    }
    // What the largest frame data weigh against the process's peak, so a backend's overhead is
    // measured rather than assumed.
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double mebibyte = 1024.0 * 1024.0;
    const sg::FrameMemory& bytes = statistics.memory;
    const auto mib = [&](std::uint64_t count) { return static_cast<double>(count) / mebibyte; };
    std::printf("  memory: peak %.1f MiB resident; largest frame: grids %.1f, classified %.1f, "
                "octree %.1f, splat lists %.1f, textures %.1f, image %.1f MiB\n",
                static_cast<double>(usage.ru_maxrss) * 1024.0 / mebibyte, mib(bytes.grids),
                mib(bytes.classified), mib(bytes.octree), mib(bytes.splats), mib(bytes.textures),
                mib(imageBytes));
}

// Progress of a ray cast on stderr: one updating line on a terminal; otherwise, once the render
// has run for a few seconds, a line every 10% (batch logs stay short for small images).
class RayCastProgress {
public:
    RayCastProgress() : mTerminal(isatty(STDERR_FILENO) == 1), mStart(Clock::now()) {}

    bool operator()(double fraction) {
        const int percent = static_cast<int>(fraction * 100.0);
        if (mTerminal) {
            if (percent != mLastPercent) {
                std::fprintf(stderr, "\rray casting: %3d%%%s", percent, fraction >= 1.0 ? "\n" : "");
            }
        } else if (secondsSince(mStart) > 2.0 && percent / 10 != mLastPercent / 10) {
            std::fprintf(stderr, "ray casting: %d%%\n", percent / 10 * 10);
        }
        mLastPercent = percent;
        return true;
    }

private:
    bool mTerminal;
    Clock::time_point mStart;
    int mLastPercent = -1;
};

// The reference images of --raycast: no GL context; the same camera, size and background as
// the GL render, so the two images compare pixel by pixel.
void runRayCast(const RenderArguments& arguments, const Animation& animation, sg::Node& root,
                glm::ivec2 size, const glm::vec4& background, const SetupTimes& setup,
                const annotation::ImageAnnotations& annotations) {
    sg::RayCastAction action(size.x, size.y);
    action.setBackground(background);
    action.setStepSize(arguments.rayCastStep);
    action.setWorkProgress(WorkProgressPrinter());
    FrameClock clock(animation, root);
    double integrate = setup.frame;
    double write = 0.0;
    for (int frame = 0; frame < animation.frames; ++frame) {
        animation.inFrame(frame, [&] {
            clock.moveTo(frame);
            action.setProgress(RayCastProgress());
            Clock::time_point start = Clock::now();
            action.render(root);
            integrate += secondsSince(start);
            const image::Image image = render::rayCastImage(action);
            start = Clock::now();
            annotations.write(image, animation.output.name(frame));
            write += secondsSince(start);
        });
        clock.reportWritten(frame);
    }
    if (arguments.timeReport) {
        printReportHeader(setup, animation);
        printAnimateTime(clock, animation);
        char note[80];
        std::snprintf(note, sizeof note, "load, classify, integrate: ray cast, %u threads",
                      std::max(1u, std::thread::hardware_concurrency()));
        printFrameTime("ray cast", integrate, animation.frames, note);
        printFrameTime("write", write, animation.frames, "encode and rename");
    }
}

Framing framingOf(const RenderArguments& arguments) {
    Framing framing = arguments.framing;
    framing.sceneName = arguments.scene;
    return framing;
}

// The option values of `render`, as checkRenderOptions() parsed them.
struct RenderOptions {
    glm::ivec2 size;
    Animation animation;
    image::ImageFormat format;
    render::BackendRequest request;
    glm::vec4 background;
    std::uint64_t memoryLimit;
    SceneSource source;
};

RenderOptions checkRenderOptions(const RenderArguments& arguments) {
    const glm::ivec2 size = parseSize(arguments.size);
    // Refuse a bad output name or option before any work, so nothing is left half-done.
    const Animation animation = parseAnimation(arguments);
    // The extension of a pattern is the extension of every frame's name: a frame number has no
    // letters, so a conversion inside the extension leaves no valid one either way.
    const image::ImageFormat format = image::supportedImageFormatOf(arguments.output);
    requireWritableFile(animation.output.name(0), "the image");
    if (!arguments.rayCast && arguments.rayCastStep != sg::RayCastAction::kDefaultStepSize) {
        throw DataError("--raycast-step: only with --raycast");
    }
    const render::BackendRequest request = render::parseBackendRequest(arguments.backend);
    // The same background for PNG and EXR: opaque black unless asked. A transparent PNG stores
    // straight alpha, which cannot hold light from a fully transparent medium (alpha 0, colour
    // > 0); EXR keeps the premultiplied layer exactly.
    const glm::vec4 background = parseBackground(arguments.background);
    checkSceneOptions(arguments.framing, arguments.budget);
    annotationRequest(arguments.annotations, background); // checked before any work
    if (arguments.threads < 0 || arguments.threads > kMaxThreads) {
        throw DataError("--threads: expected 0 (one per hardware thread) to " +
                        std::to_string(kMaxThreads) + ", got " +
                        std::to_string(arguments.threads));
    }
    SceneSource source;
    source.path = arguments.scene;
    source.headerless = headerlessLayout(arguments.headerless);
    source.headerlessArguments = headerlessArguments(arguments.headerless);
    if (source.headerless && arguments.scene.empty()) {
        throw DataError("--dims: names the layout of a headerless raw file given as the scene");
    }
    return {size,       animation,
            format,     request,
            background, memoryLimitOf(arguments.memoryLimit),
            std::move(source)};
}

// What the picture is rendered over: the layer alone when the outline's back edges go under it
// (ImageAnnotations composites the background then).
glm::vec4 renderBackgroundOf(const RenderArguments& arguments, const RenderOptions& options) {
    return annotationRequest(arguments.annotations, options.background).renderBackground();
}

render::SceneRenderOptions sceneRenderOptions(const RenderArguments& arguments,
                                              const RenderOptions& options) {
    render::SceneRenderOptions renderOptions;
    renderOptions.width = options.size.x;
    renderOptions.height = options.size.y;
    renderOptions.background = renderBackgroundOf(arguments, options);
    renderOptions.backend = options.request;
    renderOptions.threads = arguments.threads;
    renderOptions.advice = kRenderAdvice;
    return renderOptions;
}

// The scene as drawn: read, its budgets set, `prepare` run on it, framed when it has no camera;
// the times in `setup`.
sg::Node::Ptr readFramedScene(const RenderArguments& arguments, const RenderOptions& options,
                              SetupTimes& setup,
                              const std::function<void(sg::Node&)>& prepare = {}) {
    const glm::ivec2 size = options.size;
    Clock::time_point start = Clock::now();
    SceneSource source = options.source;
    source.dataRoots = dataRootsOf(arguments.dataRoots);
    const sg::Node::Ptr scene = loadScene(source);
    applyBudget(*scene, arguments.budget);
    if (prepare) {
        prepare(*scene);
    }
    setup.readScene = secondsSince(start);
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    start = Clock::now();
    // Framing takes the bounding box, which reads the volumes.
    const sg::Node::Ptr root =
        withMemoryStage("reading the scene's volumes", 0, kReadAdvice,
                        [&] {
                            return withCamera(scene, framingOf(arguments), aspect,
                                              WorkProgressPrinter());
                        });
    setup.frame = secondsSince(start);
    setup.framed = root != scene;
    return root;
}

#ifdef TEXSPLAT_WITH_MPI
// The time report of a render split over processes: each step's slowest rank, totals over the
// frames.
void printDistributedTimes(const distributed::SceneRenderer& renderer, const SetupTimes& setup,
                           const Animation& animation, const std::vector<double>& seconds,
                           double write, std::size_t splats, const FrameClock& clock) {
    const std::vector<distributed::LargestOnRank> slowest =
        distributed::largestOnRanks(MPI_COMM_WORLD, seconds);
    const distributed::LargestOnRank memory =
        distributed::largestOnRanks(MPI_COMM_WORLD, {renderer.statistics().peakMebibytes})[0];
    const std::vector<distributed::LargestOnRank> voxels =
        distributed::largestOnRanks(MPI_COMM_WORLD, {double(renderer.statistics().voxels)});
    std::uint64_t allSplats = splats;
    MPI_Allreduce(MPI_IN_PLACE, &allSplats, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    if (renderer.rank() != 0) {
        return;
    }
    printReportHeader(setup, animation);
    const render::BackendChoice& backend = renderer.backend();
    std::printf("  backend    %s (%s), on each of %d ranks\n", renderer.description().c_str(),
                backend.reason.c_str(), renderer.size());
    printAnimateTime(clock, animation);
    for (std::size_t step = 0; step < distributed::kStepCount; ++step) {
        const auto name = std::string(distributed::toString(static_cast<distributed::Step>(step)));
        std::string note = "slowest: rank " + std::to_string(slowest[step].rank);
        if (static_cast<distributed::Step>(step) == distributed::Step::Composite) {
            note += "; " + distributed::toString(renderer.compositing()) + " over " +
                    std::to_string(renderer.size()) + " ranks";
        }
        printFrameTime(name.c_str(), slowest[step].value, animation.frames, note);
    }
    printFrameTime("write", write, animation.frames, "rank 0: encode and rename");
    std::printf("  splats %llu (all ranks%s); largest brick %.0f voxels (rank %d)\n",
                static_cast<unsigned long long>(allSplats),
                animation.frames > 1 ? ", all frames" : "", voxels[0].value, voxels[0].rank);
    std::printf("  memory: peak %.1f MiB resident on rank %d (the largest)\n", memory.value,
                memory.rank);
}

// `render` under mpirun: the scene split over the processes (distributed::SceneRenderer), the
// image written by rank 0. Every step ends with the ranks agreeing on failures, so that each
// rank ends with the same error.
void runDistributedRender(const RenderArguments& arguments, const RenderOptions& options) {
    MPI_Comm comm = MPI_COMM_WORLD;
    const Animation& animation = options.animation;
    distributed::runAgreed(comm, [&] {
        if (arguments.rayCast) {
            throw DataError("--raycast: the reference is drawn by one process; run it without "
                            "mpirun");
        }
    });
    const distributed::Compositing compositing = distributed::runAgreed(comm, [&] {
        return distributed::parseCompositing(arguments.compositing, "--compositing");
    });
    auto renderer = distributed::runAgreed(comm, [&] {
        return std::make_unique<distributed::SceneRenderer>(
            comm, sceneRenderOptions(arguments, options), compositing);
    });
    SetupTimes setup;
    const sg::Node::Ptr root = distributed::runAgreed(comm, [&] {
        return readFramedScene(arguments, options, setup,
                               &distributed::SceneRenderer::prepareBricks);
    });
    const bool isWriter = renderer->rank() == 0;
    if (isWriter) {
        renderer->setWorkProgress(WorkProgressPrinter());
    }
    const bool withDepth = options.format == image::ImageFormat::Exr;
    FrameClock clock(animation, *root);
    std::optional<annotation::ImageAnnotations> annotations;
    std::vector<double> seconds(distributed::kStepCount, 0.0);
    std::size_t splats = 0;
    double write = 0.0;
    for (int frame = 0; frame < animation.frames; ++frame) {
        animation.inFrame(frame, [&] {
            clock.moveTo(frame);
            const std::optional<image::Image> image = renderer->render(*root, withDepth);
            for (std::size_t step = 0; step < distributed::kStepCount; ++step) {
                seconds[step] += renderer->statistics().seconds[step];
            }
            splats += renderer->statistics().splats;
            distributed::runAgreed(comm, [&] {
                if (!isWriter) {
                    return;
                }
                const Clock::time_point writeStart = Clock::now();
                // Made after the first frame: a legend's range is the whole data's, which the
                // render gathered.
                if (!annotations) {
                    annotations.emplace(
                        imageAnnotations(arguments.annotations, *root, options.background));
                }
                annotations->write(*image, animation.output.name(frame));
                write += secondsSince(writeStart);
            });
        });
        if (isWriter) {
            clock.reportWritten(frame);
        }
    }
    if (arguments.timeReport) {
        printDistributedTimes(*renderer, setup, animation, seconds, write, splats, clock);
    }
}
#endif

void runRender(const RenderArguments& arguments, const RenderOptions& options) {
    const glm::ivec2 size = options.size;
    const Animation& animation = options.animation;
    setMemoryLimit(options.memoryLimit);
    const ThreadLimit threadLimit(arguments.threads);
#ifdef TEXSPLAT_WITH_MPI
    if (isDistributed()) {
        runDistributedRender(arguments, options);
        return;
    }
#endif
    std::optional<render::SceneRenderer> renderer;
    if (!arguments.rayCast) {
        renderer.emplace(sceneRenderOptions(arguments, options));
    }
    SetupTimes setup;
    const sg::Node::Ptr root = readFramedScene(arguments, options, setup);

    const annotation::ImageAnnotations annotations =
        imageAnnotations(arguments.annotations, *root, options.background);
    if (arguments.rayCast) {
        runRayCast(arguments, animation, *root, size, renderBackgroundOf(arguments, options), setup,
                   annotations);
        return;
    }
    const bool withDepth = options.format == image::ImageFormat::Exr;
    FrameClock clock(animation, *root);
    sg::RenderStatistics total;
    double write = 0.0;
    renderer->setWorkProgress(WorkProgressPrinter());
    for (int frame = 0; frame < animation.frames; ++frame) {
        animation.inFrame(frame, [&] {
            clock.moveTo(frame);
            const image::Image image = renderer->render(*root, withDepth);
            total += renderer->statistics();
            const Clock::time_point writeStart = Clock::now();
            annotations.write(image, animation.output.name(frame));
            write += secondsSince(writeStart);
        });
        clock.reportWritten(frame);
    }
    if (arguments.timeReport) {
        const render::BackendChoice& backend = renderer->backend();
        const BackendReport report{renderer->description(), backend.reason,
                                   backend.contextSeconds};
        printTimes(total, setup, report, write, clock, animation,
                   static_cast<std::size_t>(renderer->imageBytes()));
    }
}

} // namespace

void addRenderCommand(CLI::App& app, int& exitCode, CommandMode mode) {
    auto arguments = std::make_shared<RenderArguments>();
    CLI::App* command = app.add_subcommand(
        "render", "Render a scene file (or the built-in tornado scene) to a PNG or OpenEXR image, "
                  "or an animation to numbered images, headless");
    command->add_option("scene", arguments->scene,
                        "Inventor scene file (.iv), or a data file (texsplat-raw, .npy, NRRD, "
                        "NetCDF, .vdb; raw values with --dims) drawn with the scene `texsplat info "
                        "FILE --scene` prints; none: the built-in tornado with fibers");
    command->add_option("-o,--output", arguments->output,
                        "Output image: .png or .exr (float RGBA, Z); with --frames a name with "
                        "one frame number such as out%04d.png (%% for a '%')")
        ->required();
    command->add_option("--size", arguments->size, "Image size WxH")->capture_default_str();
    addViewOptions(*command, arguments->framing);
    command->add_option("--frames", arguments->frames,
                        "Render N frames of the scene's animation, frame k at scene time k/fps "
                        "(engines such as ElapsedTime follow a simulated clock: every run gives "
                        "the same images)")
        ->type_name("N")
        ->capture_default_str();
    command->add_option("--fps", arguments->fps, "Frames per second of scene time for --frames")
        ->type_name("F")
        ->capture_default_str();
    command->add_flag("--time-report", arguments->timeReport,
                      "Print where the time went (read, context, load, classify, order, upload, "
                      "draw, read back, write; with --frames the totals and the mean per frame)");
    command->add_option("--backend", arguments->backend,
                        "cpu|gl|auto: what draws the splats. cpu: the SIMD splat rasterizer, no "
                        "GL; gl: instanced quads through OpenGL; auto: GL on a GPU, the CPU when "
                        "GL is a software rasterizer (llvmpipe) or unavailable")
        ->capture_default_str();
    command->add_option("--threads", arguments->threads,
                        "Threads of the CPU backend (0: one per hardware thread); the image is "
                        "the same for any count")
        ->capture_default_str();
    command->add_option("--max-splats", arguments->budget.maxSplats,
                        "Set every splat node's maxSplats (the octree cut's splat budget; 0: "
                        "none) without editing the scene")
        ->type_name("N");
    command->add_option("--error-threshold", arguments->budget.errorThreshold,
                        "Set every splat node's errorThreshold without editing the scene: the "
                        "largest deviation a splat may carry, as a fraction of the largest "
                        "classified colour or extinction (0: full resolution; 1: one splat)")
        ->type_name("E");
    command->add_option("--background", arguments->background,
                        "black|white|transparent|r,g,b: what the scene is composited over, the "
                        "same for PNG and EXR (transparent: the premultiplied layer alone, for "
                        "compositing; EXR keeps it exactly)")
        ->capture_default_str();
    addAnnotationOptions(*command, arguments->annotations);
    command->add_flag("--raycast", arguments->rayCast,
                      "Render the reference with the CPU ray caster (exact emission-absorption of "
                      "the same reconstructed field, no GL context; progress on stderr)");
    command->add_option("--raycast-step", arguments->rayCastStep,
                        "Integration step of --raycast in voxels")
        ->capture_default_str();
    addMemoryLimitOption(*command, arguments->memoryLimit);
    addHeaderlessOptions(*command, arguments->headerless);
    addDataRootOption(*command, arguments->dataRoots);
#ifdef TEXSPLAT_WITH_MPI
    command
        ->add_option("--compositing", arguments->compositing,
                     "radix-k|reduce: how the ranks' images are composited under mpirun "
                     "(docs/distributed.md): radix-k rounds over point-to-point messages, or "
                     "MPI_Reduce with a non-commutative \"over\"")
        ->capture_default_str();
#endif
    command->callback([arguments, mode, &exitCode] {
        const RenderOptions options = checkRenderOptions(*arguments);
        if (mode == CommandMode::Run) {
            runRender(*arguments, options);
        }
        exitCode = kExitOk;
    });
}

} // namespace texsplat::apps
