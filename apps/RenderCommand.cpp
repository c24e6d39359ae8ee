#include "apps/Commands.h"
#include "apps/SceneSetup.h"

#include "nodes/image/ImageIo.h"
#include "nodes/render/RayCastImage.h"
#include "nodes/render/RenderedImage.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/RayCastAction.h"
#include "scenegraph/actions/RenderAction.h"
#include "scenegraph/gl/EglContext.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include <unistd.h>

namespace texsplat::apps {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct RenderArguments {
    std::string scene;
    std::string output;
    std::string size = "512x512";
    std::string camera;
    std::string direction;
    bool timeReport = false;
    bool rayCast = false;
    float rayCastStep = sg::RayCastAction::kDefaultStepSize;
};

// The times before rendering: reading the scene file and, for a scene without a camera, framing
// it. Framing takes the scene's bounding box, which loads (or generates) its volumes and meshes:
// that time is loading, so the reports count it as such.
struct SetupTimes {
    double readScene = 0.0;
    double frame = 0.0;
    bool framed = false; ///< whether the scene had no camera and got one
};

void printTimes(const sg::RenderStatistics& statistics, const SetupTimes& setup, double context,
                const gl::ContextInfo& contextInfo, double write) {
    std::printf("time report (wall seconds):\n");
    std::printf("  %-10s %9.4f  (scene file)\n", "read", setup.readScene);
    std::printf("  %-10s %9.4f  (%s: %s)\n", "context", context, contextInfo.platform.c_str(),
                contextInfo.summary().c_str());
    for (std::size_t phase = 0; phase < sg::kRenderPhaseCount; ++phase) {
        const auto name = std::string(sg::toString(static_cast<sg::RenderPhase>(phase)));
        if (static_cast<sg::RenderPhase>(phase) == sg::RenderPhase::Load && setup.framed) {
            std::printf("  %-10s %9.4f  (%.4f of it while framing the scene)\n", name.c_str(),
                        statistics.seconds[phase] + setup.frame, setup.frame);
        } else {
            std::printf("  %-10s %9.4f\n", name.c_str(), statistics.seconds[phase]);
        }
    }
    std::printf("  %-10s %9.4f  (encode and rename)\n", "write", write);
    std::printf("  splats %zu, triangles %zu\n", statistics.splats, statistics.triangles);
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

// The reference image of --raycast: no GL context; the same camera, size and background as
// the GL render, so the two images compare pixel by pixel.
void runRayCast(const RenderArguments& arguments, sg::Node& root, glm::ivec2 size,
                image::ImageFormat format, const SetupTimes& setup) {
    sg::RayCastAction action(size.x, size.y);
    action.setBackground(format == image::ImageFormat::Png ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)
                                                           : glm::vec4(0.0f));
    action.setStepSize(arguments.rayCastStep);
    action.setProgress(RayCastProgress());
    Clock::time_point start = Clock::now();
    action.render(root);
    const double integrate = secondsSince(start) + setup.frame;
    const image::Image image = render::rayCastImage(action);
    start = Clock::now();
    image::writeImage(image, arguments.output);
    const double write = secondsSince(start);
    if (arguments.timeReport) {
        std::printf("time report (wall seconds):\n");
        std::printf("  %-10s %9.4f  (scene file)\n", "read", setup.readScene);
        std::printf("  %-10s %9.4f  (load, classify, integrate: ray cast, %u threads)\n",
                    "ray cast", integrate, std::max(1u, std::thread::hardware_concurrency()));
        std::printf("  %-10s %9.4f  (encode and rename)\n", "write", write);
    }
}

void runRender(const RenderArguments& arguments) {
    const glm::ivec2 size = parseSize(arguments.size);
    // Refuse a bad output name or option before any work, so nothing is left half-done.
    const image::ImageFormat format = image::supportedImageFormatOf(arguments.output);
    if (!arguments.rayCast && arguments.rayCastStep != sg::RayCastAction::kDefaultStepSize) {
        throw DataError("--raycast-step: only with --raycast");
    }
    SetupTimes setup;
    Clock::time_point start = Clock::now();
    const sg::Node::Ptr scene = loadScene(arguments.scene);
    setup.readScene = secondsSince(start);
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    start = Clock::now();
    const sg::Node::Ptr root =
        withCamera(scene, Framing{arguments.scene, arguments.camera, arguments.direction}, aspect);
    setup.frame = secondsSince(start);
    setup.framed = root != scene;

    if (arguments.rayCast) {
        runRayCast(arguments, *root, size, format, setup);
        return;
    }
    start = Clock::now();
    gl::EglContext context;
    const double contextTime = secondsSince(start);
    sg::RenderAction action(size.x, size.y);
    // PNG stores straight alpha, which cannot hold light from a transparent medium (alpha 0,
    // color > 0): composite over opaque black. EXR keeps the premultiplied layer with its alpha.
    action.setBackground(format == image::ImageFormat::Png ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)
                                                           : glm::vec4(0.0f));
    action.render(*root);
    const image::Image image = render::renderedImage(
        action, format == image::ImageFormat::Exr ? render::DepthReadback::With
                                                  : render::DepthReadback::Without);
    start = Clock::now();
    image::writeImage(image, arguments.output);
    const double write = secondsSince(start);
    if (arguments.timeReport) {
        printTimes(action.statistics(), setup, contextTime, context.info(), write);
    }
}

} // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto arguments = std::make_shared<RenderArguments>();
    CLI::App* command = app.add_subcommand(
        "render", "Render a scene file (or the built-in tornado scene) to a PNG or OpenEXR image, "
                  "headless");
    command->add_option("scene", arguments->scene,
                        "Inventor scene file (.iv); none: the built-in tornado with fibers");
    command->add_option("-o,--output", arguments->output, "Output image: .png or .exr (float RGBA, Z)")
        ->required();
    command->add_option("--size", arguments->size, "Image size WxH")->capture_default_str();
    command->add_option("--camera", arguments->camera,
                        "perspective|orthographic: the camera that frames a scene without one "
                        "(default perspective)");
    command->add_option("--direction", arguments->direction,
                        "x,y,z: viewing direction of that camera");
    command->add_flag("--time-report", arguments->timeReport,
                      "Print where the time went (read, context, load, classify, order, upload, "
                      "draw, read back, write)");
    command->add_flag("--raycast", arguments->rayCast,
                      "Render the reference with the CPU ray caster (exact emission-absorption of "
                      "the same reconstructed field, no GL context; progress on stderr)");
    command->add_option("--raycast-step", arguments->rayCastStep,
                        "Integration step of --raycast in voxels")
        ->capture_default_str();
    command->callback([arguments, &exitCode] {
        runRender(*arguments);
        exitCode = kExitOk;
    });
}

} // namespace texsplat::apps
